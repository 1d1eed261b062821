#pragma once
// Exhaustive marching cubes: every cell of the volume, one indexed mesh.
#include <cstdint>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack {

// Each grid edge crossed by the surface yields exactly one vertex (no welding
// pass); positions are in world units; normals point from above to below.
// `threads` > 1 splits the volume into chunks of slabs marched in parallel; the
// mesh is the same up to the order of its vertices and triangles. Each cell's
// triangles are emitted piece by piece; when `pieceStarts` is given it receives
// one bit per triangle (LSB first), set on the first triangle of each piece.
Mesh marchingCubes(const Volume& volume, double iso, TableKind table = TableKind::Consistent, int threads = 1,
                   std::vector<std::uint8_t>* pieceStarts = nullptr);

// The number of grid edges whose ends lie on different sides of `iso`.
std::size_t countCrossedEdges(const Volume& volume, double iso);

}  // namespace isotrack
