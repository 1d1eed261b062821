// Seeds for tracking: whether a grid edge is crossed, the crossed edge nearest a
// world point (searched in growing shells around the point's voxel), and the
// grid edge behind a picked vertex or triangle.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "extract/tracking/track_walker.h"
#include "isotrack/errors.h"
#include "isotrack/tracking.h"

namespace isotrack {

using detail::edgeInside;
using detail::isoText;
using detail::makeWorker;

bool edgeIsCrossed(const Volume& volume, double iso, const GridEdge& edge) {
    if (!edgeInside(volume, edge)) return false;
    return makeWorker(volume, iso, TableKind::Consistent)->crossed(edge);
}

GridEdge nearestCrossedEdge(const Volume& volume, double iso, const Vec3d& worldPoint) {
    const Dims& n = volume.dims();
    const Vec3d& s = volume.spacing();
    const Vec3d& o = volume.origin();
    const auto worker = makeWorker(volume, iso, TableKind::Consistent);
    int centre[3];
    double p[3];
    for (int k = 0; k < 3; ++k) {
        p[k] = (worldPoint[k] - o[k]) / s[k];
        const double clamped = std::clamp(std::isfinite(p[k]) ? p[k] : 0.0, 0.0, double(n[k] - 1));
        centre[k] = static_cast<int>(std::lround(clamped));
    }
    const double minSpacing = std::min({s[0], s[1], s[2]});
    double best = std::numeric_limits<double>::infinity();
    GridEdge bestEdge;
    const int maxRadius = std::max({n[0], n[1], n[2]});
    for (int r = 0; r <= maxRadius; ++r) {
        if (std::isfinite(best) && (r - 1) * minSpacing > best) break;
        const int lo[3] = {centre[0] - r, centre[1] - r, centre[2] - r};
        const int hi[3] = {centre[0] + r, centre[1] + r, centre[2] + r};
        for (int z = std::max(lo[2], 0); z <= std::min(hi[2], n[2] - 1); ++z) {
            for (int y = std::max(lo[1], 0); y <= std::min(hi[1], n[1] - 1); ++y) {
                const bool shellYZ = z == lo[2] || z == hi[2] || y == lo[1] || y == hi[1];
                for (int x = std::max(lo[0], 0); x <= std::min(hi[0], n[0] - 1);
                     x += (shellYZ || x == hi[0]) ? 1 : std::max(1, hi[0] - x)) {
                    for (int axis = 0; axis < 3; ++axis) {
                        const GridEdge e{x, y, z, axis};
                        if (!edgeInside(volume, e) || !worker->crossed(e)) continue;
                        double d2 = 0.0;
                        const int q[3] = {x, y, z};
                        for (int k = 0; k < 3; ++k) {
                            const double mid = q[k] + (k == axis ? 0.5 : 0.0);
                            d2 += (mid - p[k]) * (mid - p[k]) * s[k] * s[k];
                        }
                        if (std::sqrt(d2) < best) {
                            best = std::sqrt(d2);
                            bestEdge = e;
                        }
                    }
                }
            }
        }
    }
    if (!std::isfinite(best)) {
        throw InputError("no surface at iso " + isoText(iso) + ": no grid edge crosses it");
    }
    return bestEdge;
}

GridEdge edgeOfVertex(const Mesh& mesh, std::uint32_t vertex) {
    if (vertex >= mesh.vertexEdges.size())
        throw InputError("picked vertex " + std::to_string(vertex) + " is not in the mesh");
    return mesh.vertexEdges[vertex];
}

GridEdge edgeOfTriangle(const Mesh& mesh, std::size_t triangle, const Vec3d& worldPoint) {
    if (triangle >= mesh.triangleCount())
        throw InputError("picked triangle " + std::to_string(triangle) + " is not in the mesh");
    std::uint32_t nearest = mesh.indices[3 * triangle];
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = mesh.indices[3 * triangle + std::size_t(k)];
        double d2 = 0.0;
        for (int i = 0; i < 3; ++i)
            d2 += (mesh.vertices[v].position[i] - worldPoint[i]) * (mesh.vertices[v].position[i] - worldPoint[i]);
        if (d2 < best) best = d2, nearest = v;
    }
    return edgeOfVertex(mesh, nearest);
}

}  // namespace isotrack
