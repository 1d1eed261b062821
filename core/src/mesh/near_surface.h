#pragma once
// Whether points lie within a distance of a triangle mesh: decimation's check
// that no vertex of the original ended up farther than its error bound from
// the decimated surface.
#include <cstdint>
#include <vector>

#include "isotrack/mesh.h"

namespace isotrack::detail {

class NearSurface {
public:
    // The triangles indices[0 .. count) over `vertices`, within `reach` of which
    // points are asked about.
    NearSurface(const Buffer<Vertex>& vertices, const std::vector<std::uint32_t>& indices, double reach);
    // True when some triangle lies within `reach` of p.
    bool near(const float* p) const { return near(p, reach_); }
    // True when some triangle lies within `radius` (at most `reach`) of p.
    bool near(const float* p, double radius) const;
    // An upper bound of the distance from p to the triangles: the exact
    // distance, or the first one found at most `close`; infinity when none
    // lies within `reach`.
    double distanceBound(const float* p, double close) const;

private:
    // Calls visit(t) for the triangles binned in the cells within reach of p
    // (some twice) until it returns true; true when one did.
    template <class Visit>
    bool forTrianglesNear(const float* p, Visit&& visit) const;
    long cellOf(double c, int axis) const;
    const Buffer<Vertex>& vertices_;
    const std::vector<std::uint32_t>& indices_;
    double reach_;
    double lo_[3], cell_[3];
    long n_[3];
    std::vector<std::uint32_t> first_, triangles_;  // cell c's: triangles_[first_[c] .. first_[c + 1])
    // A triangle binned in several cells is tested once a query: the query
    // that last tested it (so one NearSurface answers one query at a time).
    mutable std::vector<std::uint32_t> testedBy_;
    mutable std::uint32_t query_ = 0;
};

}  // namespace isotrack::detail
