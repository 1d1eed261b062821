#pragma once
// Making a decimated mesh closed again where edge collapses pinched it.
#include <cstdint>
#include <vector>

#include "isotrack/mesh.h"

namespace isotrack::detail {

// meshopt_simplify does not check the link condition, so a collapse between
// two sheets a voxel apart can leave (1) "fins", a triangle and its reverse over
// the same three vertices, enclosing nothing, and (2) edges of four or more
// triangles where two sheets touch. This removes the fins, then, at every edge
// with more than two triangles, pairs each side with a reverse one of the same
// sheet (whose corners the fans around the vertex already join) and gives every group of corners the pairing connects
// its own copy of the vertex: a surface closed by index, whose copies at one
// position MeshQuality's welding still counts as non-manifold edges.
void removeFinsAndSplitPinches(Mesh& mesh);

// Step (1) alone, on a list of triangles: both triangles of every pair over the
// same three vertices go.
void removeFins(std::vector<std::uint32_t>& indices);

}  // namespace isotrack::detail
