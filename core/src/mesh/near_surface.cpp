// NearSurface (near_surface.h): triangles binned by their bounding boxes into a
// grid of cells at least `reach` wide, so a point's triangles within reach lie
// in the cells its box of half-width `reach` overlaps; each is tested by the distance from the point
// to the triangle's plane, then to its sides when the foot falls outside it.
#include "mesh/near_surface.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace isotrack::detail {
namespace {

struct V3 {
    double x, y, z;
};
V3 at(const float* p) { return {p[0], p[1], p[2]}; }
V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// Squared distance from p to the segment ab.
double segmentDistance2(V3 p, V3 a, V3 b) {
    const V3 ab = b - a, ap = p - a;
    const double length2 = dot(ab, ab);
    const double t = length2 > 0 ? std::clamp(dot(ap, ab) / length2, 0.0, 1.0) : 0.0;
    const V3 d{ap.x - t * ab.x, ap.y - t * ab.y, ap.z - t * ab.z};
    return dot(d, d);
}

double triangleDistance2(V3 p, V3 a, V3 b, V3 c) {
    const V3 n = cross(b - a, c - a);
    const double n2 = dot(n, n);
    if (n2 > 0) {
        // The foot of p on the plane is inside when it is left of every side.
        const bool inside =
            dot(cross(b - a, p - a), n) >= 0 && dot(cross(c - b, p - b), n) >= 0 && dot(cross(a - c, p - c), n) >= 0;
        if (inside) {
            const double h = dot(p - a, n);
            return h * h / n2;
        }
    }
    return std::min({segmentDistance2(p, a, b), segmentDistance2(p, b, c), segmentDistance2(p, c, a)});
}

}  // namespace

NearSurface::NearSurface(const Buffer<Vertex>& vertices, const std::vector<std::uint32_t>& indices, double reach)
    : vertices_(vertices), indices_(indices), reach_(std::max(reach, 1e-9)) {
    double hi[3];
    for (int a = 0; a < 3; ++a)
        lo_[a] = std::numeric_limits<double>::max(), hi[a] = std::numeric_limits<double>::lowest();
    for (std::uint32_t i : indices)
        for (int a = 0; a < 3; ++a) {
            lo_[a] = std::min(lo_[a], double(vertices[i].position[a]));
            hi[a] = std::max(hi[a], double(vertices[i].position[a]));
        }
    // Cells at least reach wide and at most 512 an axis; and, for a reach small
    // against the surface, at most kCellsPerTriangle a triangle (wider cells
    // hold more triangles each, but a 512^3 grid for a few thousand triangles
    // took seconds and half a gigabyte).
    constexpr double kCellsPerTriangle = 16.0;
    const double most = std::max(4096.0, kCellsPerTriangle * double(indices.size() / 3));
    double planned = 1.0;
    for (int a = 0; a < 3; ++a) {
        if (indices.empty()) lo_[a] = hi[a] = 0;
        cell_[a] = std::max(reach_, (hi[a] - lo_[a]) / 512.0);
        planned *= double(long((hi[a] - lo_[a]) / cell_[a]) + 1);
    }
    const double grow = planned > most ? std::cbrt(planned / most) * 1.01 : 1.0;
    long cells = 1;
    for (int a = 0; a < 3; ++a) {
        cell_[a] *= grow;
        n_[a] = long((hi[a] - lo_[a]) / cell_[a]) + 1;
        cells *= n_[a];
    }
    first_.assign(std::size_t(cells) + 1, 0);
    auto forCells = [&](std::size_t t, auto&& fn) {
        long from[3], to[3];
        for (int a = 0; a < 3; ++a) {
            double mn = std::numeric_limits<double>::max(), mx = std::numeric_limits<double>::lowest();
            for (int k = 0; k < 3; ++k) {
                const double c = vertices[indices[3 * t + std::size_t(k)]].position[a];
                mn = std::min(mn, c), mx = std::max(mx, c);
            }
            from[a] = cellOf(mn, a), to[a] = cellOf(mx, a);
        }
        for (long z = from[2]; z <= to[2]; ++z)
            for (long y = from[1]; y <= to[1]; ++y)
                for (long x = from[0]; x <= to[0]; ++x) fn(std::size_t(x + n_[0] * (y + n_[1] * z)));
    };
    const std::size_t count = indices.size() / 3;
    for (std::size_t t = 0; t < count; ++t) forCells(t, [&](std::size_t c) { ++first_[c + 1]; });
    for (std::size_t c = 0; c + 1 < first_.size(); ++c) first_[c + 1] += first_[c];
    triangles_.resize(first_.back());
    testedBy_.assign(count, 0u);
    std::vector<std::uint32_t> fill(first_.begin(), first_.end() - 1);
    for (std::size_t t = 0; t < count; ++t)
        forCells(t, [&](std::size_t c) { triangles_[fill[c]++] = std::uint32_t(t); });
}

long NearSurface::cellOf(double c, int axis) const {
    return std::clamp(long(std::floor((c - lo_[axis]) / cell_[axis])), 0L, n_[axis] - 1);
}

template <class Visit>
bool NearSurface::forTrianglesNear(const float* p, Visit&& visit) const {
    auto visitCell = [&](long x, long y, long z) {
        const std::size_t c = std::size_t(x + n_[0] * (y + n_[1] * z));
        for (std::uint32_t i = first_[c]; i < first_[c + 1]; ++i) {
            const std::uint32_t t = triangles_[i];
            if (testedBy_[t] == query_) continue;
            testedBy_[t] = query_;
            if (visit(std::size_t(t))) return true;
        }
        return false;
    };
    if (++query_ == 0) std::fill(testedBy_.begin(), testedBy_.end(), 0u), query_ = 1;
    // p's own cell first: the nearest triangles are most often there.
    long from[3], to[3], own[3];
    for (int a = 0; a < 3; ++a)
        from[a] = cellOf(p[a] - reach_, a), to[a] = cellOf(p[a] + reach_, a), own[a] = cellOf(p[a], a);
    if (visitCell(own[0], own[1], own[2])) return true;
    for (long z = from[2]; z <= to[2]; ++z)
        for (long y = from[1]; y <= to[1]; ++y)
            for (long x = from[0]; x <= to[0]; ++x)
                if ((x != own[0] || y != own[1] || z != own[2]) && visitCell(x, y, z)) return true;
    return false;
}

bool NearSurface::near(const float* point, double radius) const {
    const V3 p = at(point);
    const double reach2 = radius * radius;
    return forTrianglesNear(point, [&](std::size_t t) {
        return triangleDistance2(p, at(vertices_[indices_[3 * t]].position),
                                 at(vertices_[indices_[3 * t + 1]].position),
                                 at(vertices_[indices_[3 * t + 2]].position)) <= reach2;
    });
}

double NearSurface::distanceBound(const float* point, double close) const {
    const V3 p = at(point);
    const double close2 = close * close;
    double best2 = reach_ * reach_;
    bool found = false;
    forTrianglesNear(point, [&](std::size_t t) {
        const double d2 =
            triangleDistance2(p, at(vertices_[indices_[3 * t]].position), at(vertices_[indices_[3 * t + 1]].position),
                              at(vertices_[indices_[3 * t + 2]].position));
        if (d2 <= best2) best2 = d2, found = true;
        return best2 <= close2;
    });
    return found ? std::sqrt(best2) : std::numeric_limits<double>::infinity();
}

}  // namespace isotrack::detail
