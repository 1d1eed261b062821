#pragma once
// Zero-area triangles made whole again by edge flips.
#include "isotrack/mesh.h"

namespace isotrack::detail {

// Twice a triangle's area at or below this fraction of its longest side
// squared is zero at float precision (MeshQuality counts the same).
constexpr double kZeroAreaFraction = 1e-6;

// True when p, q, r lie on one line (or coincide), by kZeroAreaFraction.
bool zeroArea(const float* p, const float* q, const float* r);

// The snap table puts vertices on grid points, so edge collapses can leave a
// triangle whose three corners lie on one grid line: zero area, no normal.
// Its middle corner c lies on its longest side ab; the triangle across ab,
// (b, a, d), and it are replaced by (c, a, d) and (c, d, b), which cover the
// same part of that triangle's plane: the surface, its border and its
// closure do not change. A flip is skipped where ab is a border or has more
// than two triangles, where cd is already an edge, or where d lies on the
// line too; passes repeat while some triangle flips.
void flipZeroAreaTriangles(Mesh& mesh);

}  // namespace isotrack::detail
