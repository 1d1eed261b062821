// Seeds for tracking: whether a grid edge is crossed, the crossed edge nearest a
// world point (searched in growing cubes around the point's voxel), and the
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

// The search scans cubes of samples around the point's voxel, row by row (in
// the order of memory, so a far surface in a mapped volume costs one read of
// each page per cube, not one per shell), doubling the cube's half-width until
// the nearest edge found lies within it. An edge whose sample is r samples
// from the centre (Chebyshev) lies at least (r - 1) x the smallest spacing from
// the point, so once the best distance is at most half-width x that spacing no
// edge outside the cube is nearer. Ties go to the edge of the smaller r, then
// the lower z, y, x and axis: the order in which growing shells would meet them.
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
    struct Found {
        double distance = std::numeric_limits<double>::infinity();
        int ring = 0;
        GridEdge edge;
        bool before(const Found& other) const {  // nearer, or as near and met first
            if (distance != other.distance) return distance < other.distance;
            if (ring != other.ring) return ring < other.ring;
            const int a[4] = {edge.z, edge.y, edge.x, edge.axis};
            const int b[4] = {other.edge.z, other.edge.y, other.edge.x, other.edge.axis};
            return std::lexicographical_compare(a, a + 4, b, b + 4);
        }
    };
    Found best;
    const int maxRadius = std::max({n[0], n[1], n[2]});
    for (int half = 1;; half = half > maxRadius / 2 ? maxRadius : 2 * half) {
        int lo[3], hi[3];
        for (int k = 0; k < 3; ++k) lo[k] = std::max(centre[k] - half, 0), hi[k] = std::min(centre[k] + half, n[k] - 1);
        for (int z = lo[2]; z <= hi[2]; ++z) {
            for (int y = lo[1]; y <= hi[1]; ++y) {
                for (int x = lo[0]; x <= hi[0]; ++x) {
                    for (int axis = 0; axis < 3; ++axis) {
                        const GridEdge e{x, y, z, axis};
                        if (!edgeInside(volume, e) || !worker->crossed(e)) continue;
                        Found here;
                        here.edge = e;
                        const int q[3] = {x, y, z};
                        double d2 = 0.0;
                        for (int k = 0; k < 3; ++k) {
                            const double mid = q[k] + (k == axis ? 0.5 : 0.0);
                            d2 += (mid - p[k]) * (mid - p[k]) * s[k] * s[k];
                            here.ring = std::max(here.ring, std::abs(q[k] - centre[k]));
                        }
                        here.distance = std::sqrt(d2);
                        if (here.before(best)) best = here;
                    }
                }
            }
        }
        if (best.distance <= half * minSpacing || half >= maxRadius) break;
    }
    if (!std::isfinite(best.distance)) {
        throw InputError("no surface at iso " + isoText(iso) + ": no grid edge crosses it");
    }
    return best.edge;
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
