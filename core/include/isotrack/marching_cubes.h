#pragma once
// Exhaustive marching cubes: every cell of the volume, one indexed mesh.
#include <cstddef>

#include "isotrack/mesh.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack {

// Each grid edge crossed by the surface yields exactly one vertex (no welding
// pass); positions are in world units; normals point from above to below.
// `threads` > 1 splits the volume into chunks of slabs marched in parallel; the
// mesh is the same up to the order of its vertices and triangles.
Mesh marchingCubes(const Volume& volume, double iso, TableKind table = TableKind::Consistent, int threads = 1);

// The number of grid edges whose ends lie on different sides of `iso`.
std::size_t countCrossedEdges(const Volume& volume, double iso);

// The number of samples at or above `iso` (isotrack's one classification rule),
// counted in a single pass over the samples on `threads` threads: reading every
// sample once, the least any extraction over the whole volume does, and the
// floor its time is measured against.
std::size_t countSamplesAbove(const Volume& volume, double iso, int threads = 1);

}  // namespace isotrack
