// A mesh's quality figures: zero-area triangles, border and non-manifold edges
// once coincident vertices are welded, and the spread of smallest angles.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <numeric>
#include <vector>

#include "isotrack/mesh_processing.h"
#include "mesh/flip.h"
#include "mesh/mesh_edges.h"

namespace isotrack {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Twice the area at or below this fraction of the longest side squared is zero
// at float precision: the triangle's corners coincide or lie on one line.
constexpr double kDegenerate = detail::kZeroAreaFraction;

// The triangle's smallest angle in degrees (0 for a degenerate one).
double smallestAngle(const float* p, const float* q, const float* r, bool& degenerate) {
    const float* corners[3] = {p, q, r};
    double side[3][3], length2[3];
    for (int k = 0; k < 3; ++k) {
        const float* a = corners[k];
        const float* b = corners[(k + 1) % 3];
        for (int c = 0; c < 3; ++c) side[k][c] = double(b[c]) - double(a[c]);
        length2[k] = side[k][0] * side[k][0] + side[k][1] * side[k][1] + side[k][2] * side[k][2];
    }
    const double cross[3] = {side[0][1] * side[2][2] - side[0][2] * side[2][1],
                             side[0][2] * side[2][0] - side[0][0] * side[2][2],
                             side[0][0] * side[2][1] - side[0][1] * side[2][0]};
    const double doubleArea = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    const double longest2 = std::max({length2[0], length2[1], length2[2]});
    degenerate = doubleArea <= kDegenerate * longest2;
    if (degenerate) return 0.0;
    // The smallest angle faces the shortest side: sin = 2A / (product of the other two).
    const int shortest = int(std::min_element(length2, length2 + 3) - length2);
    const double others = std::sqrt(length2[(shortest + 1) % 3] * length2[(shortest + 2) % 3]);
    return std::asin(std::min(1.0, doubleArea / others)) * 180.0 / kPi;
}

}  // namespace

MeshQuality measureQuality(const Mesh& mesh) {
    MeshQuality quality;
    const std::size_t triangles = mesh.triangleCount();
    if (triangles == 0) return quality;
    std::size_t below1 = 0, below10 = 0, below20 = 0;
    for (std::size_t t = 0; t < triangles; ++t) {
        bool degenerate = false;
        const double angle =
            smallestAngle(mesh.vertices[mesh.indices[3 * t]].position, mesh.vertices[mesh.indices[3 * t + 1]].position,
                          mesh.vertices[mesh.indices[3 * t + 2]].position, degenerate);
        quality.degenerateTriangles += degenerate;
        below1 += angle < 1.0;
        below10 += angle < 10.0;
        below20 += angle < 20.0;
    }
    quality.minAngleBelow1 = double(below1) / double(triangles);
    quality.minAngleBelow10 = double(below10) / double(triangles);
    quality.minAngleBelow20 = double(below20) / double(triangles);

    const std::vector<std::uint32_t> weld = detail::weldedIds(mesh);
    std::vector<std::uint32_t> welded;
    welded.reserve(mesh.indices.size());
    for (std::size_t t = 0; t < triangles; ++t) {
        const std::uint32_t a = weld[mesh.indices[3 * t]], b = weld[mesh.indices[3 * t + 1]],
                            c = weld[mesh.indices[3 * t + 2]];
        if (a == b || b == c || a == c) continue;  // collapsed by welding
        welded.insert(welded.end(), {a, b, c});
    }
    for (const detail::EdgeUse& e : detail::meshEdges(welded.data(), welded.size() / 3)) {
        quality.boundaryEdges += e.triangles == 1;
        quality.nonManifoldEdges += e.triangles > 2;
    }
    return quality;
}

}  // namespace isotrack
