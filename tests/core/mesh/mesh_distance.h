#pragma once
// A test helper, independent of the decimator: the symmetric Hausdorff distance
// between two triangle meshes, sampled. Points are taken on each mesh (every
// vertex, and `perTriangle` points per triangle at fixed pseudo-random
// barycentric coordinates); each point's distance to the other mesh is the
// exact distance to its nearest triangle (Ericson, "Real-Time Collision
// Detection", 5.1.5), found through a uniform grid of triangle bounding boxes.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "isotrack/mesh.h"

namespace isotrack::test {

using P3 = std::array<double, 3>;

inline P3 sub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline double dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline P3 along(const P3& a, const P3& d, double t) { return {a[0] + t * d[0], a[1] + t * d[1], a[2] + t * d[2]}; }

// The point of triangle abc nearest to p.
inline P3 nearestOnTriangle(const P3& p, const P3& a, const P3& b, const P3& c) {
    const P3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const P3 bp = sub(p, b);
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return along(a, ab, d1 / (d1 - d3));
    const P3 cp = sub(p, c);
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return along(a, ac, d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return along(b, sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = 1.0 / (va + vb + vc);
    const double v = vb * denom, w = vc * denom;
    return {a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w};
}

class TriangleGrid {
public:
    explicit TriangleGrid(const Mesh& mesh) : mesh_(mesh) {
        for (int a = 0; a < 3; ++a) lo_[a] = std::numeric_limits<double>::max(), hi_[a] = -lo_[a];
        for (const Vertex& v : mesh.vertices)
            for (int a = 0; a < 3; ++a)
                lo_[a] = std::min(lo_[a], double(v.position[a])), hi_[a] = std::max(hi_[a], double(v.position[a]));
        const double volume = std::max(1e-12, (hi_[0] - lo_[0]) * (hi_[1] - lo_[1]) * (hi_[2] - lo_[2]));
        cell_ = std::max(1e-9, std::cbrt(volume / std::max<double>(1.0, double(mesh.triangleCount()) / 4.0)));
        for (int a = 0; a < 3; ++a) n_[a] = std::max(1, int((hi_[a] - lo_[a]) / cell_) + 1);
        cells_.resize(std::size_t(n_[0]) * std::size_t(n_[1]) * std::size_t(n_[2]));
        for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t) {
            int from[3], to[3];
            for (int a = 0; a < 3; ++a) {
                double mn = std::numeric_limits<double>::max(), mx = -mn;
                for (int k = 0; k < 3; ++k) {
                    const double c = mesh.vertices[mesh.indices[3 * t + std::size_t(k)]].position[a];
                    mn = std::min(mn, c), mx = std::max(mx, c);
                }
                from[a] = cellOf(mn, a), to[a] = cellOf(mx, a);
            }
            for (int z = from[2]; z <= to[2]; ++z)
                for (int y = from[1]; y <= to[1]; ++y)
                    for (int x = from[0]; x <= to[0]; ++x) cells_[index(x, y, z)].push_back(t);
        }
    }

    // Distance from p to the nearest triangle: rings of cells around p's cell,
    // until the ring's distance exceeds the best found.
    double distance(const P3& p) const {
        int centre[3];
        for (int a = 0; a < 3; ++a) centre[a] = cellOf(p[a], a);
        double outside = 0.0;  // how far p lies outside the grid's box
        for (int a = 0; a < 3; ++a) outside = std::max({outside, lo_[a] - p[a], p[a] - hi_[a]});
        double best = std::numeric_limits<double>::max();
        const int maxRing = std::max({n_[0], n_[1], n_[2]});
        for (int ring = 0; ring <= maxRing; ++ring) {
            if (best < std::max(double(ring - 1) * cell_, outside)) break;
            for (int z = centre[2] - ring; z <= centre[2] + ring; ++z)
                for (int y = centre[1] - ring; y <= centre[1] + ring; ++y)
                    for (int x = centre[0] - ring; x <= centre[0] + ring; ++x) {
                        const int d =
                            std::max({std::abs(x - centre[0]), std::abs(y - centre[1]), std::abs(z - centre[2])});
                        if (d != ring || x < 0 || y < 0 || z < 0 || x >= n_[0] || y >= n_[1] || z >= n_[2]) continue;
                        for (std::uint32_t t : cells_[index(x, y, z)]) best = std::min(best, toTriangle(p, t));
                    }
        }
        return best;
    }

private:
    int cellOf(double c, int a) const { return std::clamp(int((c - lo_[a]) / cell_), 0, n_[a] - 1); }
    std::size_t index(int x, int y, int z) const {
        return std::size_t(x) + std::size_t(n_[0]) * (std::size_t(y) + std::size_t(n_[1]) * std::size_t(z));
    }
    P3 corner(std::uint32_t t, int k) const {
        const float* q = mesh_.vertices[mesh_.indices[3 * t + std::uint32_t(k)]].position;
        return {q[0], q[1], q[2]};
    }
    double toTriangle(const P3& p, std::uint32_t t) const {
        const P3 d = sub(p, nearestOnTriangle(p, corner(t, 0), corner(t, 1), corner(t, 2)));
        return std::sqrt(dot(d, d));
    }
    const Mesh& mesh_;
    double lo_[3], hi_[3], cell_ = 1.0;
    int n_[3];
    std::vector<std::vector<std::uint32_t>> cells_;
};

// Points on the mesh: its vertices, then perTriangle points in each triangle.
inline std::vector<P3> samplePoints(const Mesh& mesh, int perTriangle) {
    std::vector<P3> points;
    for (const Vertex& v : mesh.vertices) points.push_back({v.position[0], v.position[1], v.position[2]});
    std::uint64_t state = 0x9e3779b97f4a7c15ull;
    auto unit = [&] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) * 0x1.0p-53;
    };
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        for (int s = 0; s < perTriangle; ++s) {
            double u = unit(), v = unit();
            if (u + v > 1) u = 1 - u, v = 1 - v;
            P3 p{};
            for (int a = 0; a < 3; ++a) {
                const double c0 = mesh.vertices[mesh.indices[3 * t]].position[a];
                const double c1 = mesh.vertices[mesh.indices[3 * t + 1]].position[a];
                const double c2 = mesh.vertices[mesh.indices[3 * t + 2]].position[a];
                p[a] = c0 + u * (c1 - c0) + v * (c2 - c0);
            }
            points.push_back(p);
        }
    return points;
}

// The largest distance from a sample of `from` to `to`.
inline double directedHausdorff(const Mesh& from, const Mesh& to, int perTriangle = 2) {
    const TriangleGrid grid(to);
    double worst = 0.0;
    for (const P3& p : samplePoints(from, perTriangle)) worst = std::max(worst, grid.distance(p));
    return worst;
}

inline double hausdorff(const Mesh& a, const Mesh& b, int perTriangle = 2) {
    return std::max(directedHausdorff(a, b, perTriangle), directedHausdorff(b, a, perTriangle));
}

}  // namespace isotrack::test
