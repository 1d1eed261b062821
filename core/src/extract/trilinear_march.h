#pragma once
// Exhaustive marching cubes with the trilinear table (isotrack/trilinear.h).
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/surface.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

// Every cell, one mesh: one vertex per crossed grid edge, plus a vertex inside
// each cell whose subcase needs one (its vertexEdges entry has axis
// kCellInterior and the cell's first sample).
Mesh marchTrilinear(const Volume& volume, double iso, int threads);

// The surface through `seed` by piecewise continuation over the trilinear
// subcases (one thread); InputError when the seed is outside or not crossed.
Surface trackTrilinear(const Volume& volume, double iso, const GridEdge& seed);

// Every connected surface of marchTrilinear's mesh, most triangles first.
std::vector<Surface> allTrilinear(const Volume& volume, double iso, int threads);

}  // namespace isotrack::detail
