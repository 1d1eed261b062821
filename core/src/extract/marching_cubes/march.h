#pragma once
// Room extract/marching_cubes: the exhaustive pass (isotrack/marching_cubes.h)
// in its two forms, plain (marching_cubes.cpp, with the per-edge lookups of
// edge_slots.h) and labelled, joining each connected surface's vertices as it
// writes them (labelled_march.h, with the lookups and seam joins of
// surface_labels.h) for extract/surfaces to split. Uses extract/common,
// extract/measure (border and order of edges) and extract/trilinear (the
// exhaustive pass with the trilinear table), support/ and the public headers.
#include "isotrack/extract.h"
#include "isotrack/mesh.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

// marchingCubes, its march reporting to `progress` (consistent and classic tables).
Mesh marchingCubes(const Volume& volume, double iso, TableKind table, int threads, ExtractProgress* progress);

}  // namespace isotrack::detail
