#pragma once
// Exhaustive marching cubes with the trilinear table (isotrack/trilinear.h).
#include "isotrack/mesh.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

// Every cell, one mesh: one vertex per crossed grid edge, plus a vertex inside
// each cell whose subcase needs one (its vertexEdges entry has axis
// kCellInterior and the cell's first sample).
Mesh marchTrilinear(const Volume& volume, double iso, int threads);

}  // namespace isotrack::detail
