#pragma once
// Vertices at one position made one. At an isovalue a sample equals exactly,
// the extractors put a vertex on each of that sample's crossed edges, all at
// the sample, joined by zero-area triangles: smoothing would pull them apart
// into slivers and decimation would see seams. Welding keeps one vertex per
// position (the first in position order, with its grid edge) and drops the
// triangles that collapse.
#include "isotrack/mesh.h"

namespace isotrack::detail {

void weldCoincidentVertices(Mesh& mesh);

// Drops the vertices no triangle uses; the rest keep their order and grid edges.
void dropUnusedVertices(Mesh& mesh);

}  // namespace isotrack::detail
