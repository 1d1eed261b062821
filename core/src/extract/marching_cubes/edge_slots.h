#pragma once
// The exhaustive march's per-edge lookups (marching_cubes.cpp): for each cube
// edge its axis, first corner and offset within a slice, and per cell
// configuration the edges it crosses, all derived from isotrack/cube.h.
#include <array>
#include <cstddef>
#include <cstdint>

#include "isotrack/cube.h"

namespace isotrack::detail {

struct EdgeSlots {
    // config of the cell whose two x-columns of four flags (bits: row y at z, row
    // y+1 at z, row y at z+1, row y+1 at z+1) are `left | right << 4`.
    std::array<std::uint8_t, 256> configOfColumns{};
    std::array<int, 12> axis{};
    std::array<std::array<int, 3>, 12> origin{};  // the edge's first corner, from the cell's
    std::array<std::size_t, 12> offset{};         // within a slice, from the cell's origin sample
    std::array<std::uint16_t, 256> crossed{};
};

inline EdgeSlots edgeSlots(int nx) {
    EdgeSlots s;
    for (int e = 0; e < cube::kEdgeCount; ++e) {
        const auto& o = cube::edgeOrigin(e);
        s.origin[e] = o;
        s.axis[e] = cube::edgeAxis(e);
        s.offset[e] = std::size_t(o[0]) + std::size_t(nx) * std::size_t(o[1]);
    }
    for (int columns = 0; columns < 256; ++columns) {
        const int l = columns & 15, r = columns >> 4;
        s.configOfColumns[columns] =
            static_cast<std::uint8_t>((l & 1) | (r & 1) << 1 | (r >> 1 & 1) << 2 | (l >> 1 & 1) << 3 |
                                      (l >> 2 & 1) << 4 | (r >> 2 & 1) << 5 | (r >> 3 & 1) << 6 | (l >> 3 & 1) << 7);
    }
    for (int c = 0; c < 256; ++c) {
        unsigned mask = 0;
        for (int e = 0; e < cube::kEdgeCount; ++e) {
            if ((c >> cube::kEdgeVertices[e][0] & 1) != (c >> cube::kEdgeVertices[e][1] & 1)) mask |= 1u << e;
        }
        s.crossed[c] = static_cast<std::uint16_t>(mask);
    }
    return s;
}

}  // namespace isotrack::detail
