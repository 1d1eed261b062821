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
    bool near(const float* p) const;

private:
    long cellOf(double c, int axis) const;
    const Buffer<Vertex>& vertices_;
    const std::vector<std::uint32_t>& indices_;
    double reach_;
    double lo_[3], cell_[3];
    long n_[3];
    std::vector<std::uint32_t> first_, triangles_;  // cell c's: triangles_[first_[c] .. first_[c + 1])
};

}  // namespace isotrack::detail
