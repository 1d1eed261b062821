// The local pass before the contour tree's sweeps: each sample classified, in
// the grid's own order, by how the swept part of its neighbourhood is connected.
//
// The sweeps visit the samples in value order, which is a random order in
// space, so every neighbour they read is a cache miss. Most samples need none
// of that: when the neighbours above a sample (the join sweep's face
// neighbours) are connected to each other through samples above it within its
// 3x3x3 neighbourhood, they are one component of the superlevel set, and the
// sample joins that one component; likewise below (the split sweep's 18
// neighbours, 18-connected through samples below it). A path inside the
// neighbourhood is a path in the level set, so this never joins what the
// sweep would keep apart; it may leave apart what is connected farther away,
// and then the sample is a candidate the sweep treats in full.
//
// The neighbourhood is read as an 18-bit mask (faces, then edges; the corners
// are left out, which only makes more candidates), and two tables of 2^18
// bytes, built once by flood fill, give each mask's class: none (an extremum
// of its sweep), one neighbour to join through, or a candidate.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "extract/contour_tree/contour_tree_build.h"

namespace isotrack::detail {
namespace {

constexpr int kPositions = kNeighbourPositions;

// The 18 positions: the 6 faces (-x +x -y +y -z +z), then the 12 edges.
constexpr std::array<std::array<int, 3>, kPositions> kPosition = [] {
    std::array<std::array<int, 3>, kPositions> p{};
    int k = 0;
    for (int axis = 0; axis < 3; ++axis) {
        for (const int d : {-1, 1}) p[k] = {0, 0, 0}, p[k++][axis] = d;
    }
    for (int a = 0; a < 3; ++a) {
        for (int b = a + 1; b < 3; ++b) {
            for (const int da : {-1, 1}) {
                for (const int db : {-1, 1}) p[k] = {0, 0, 0}, p[k][a] = da, p[k++][b] = db;
            }
        }
    }
    return p;
}();

// Masks of the positions adjacent to each, across a face (6) or also across a
// face diagonal (18).
std::array<std::uint32_t, kPositions> adjacency(bool diagonals) {
    std::array<std::uint32_t, kPositions> adjacent{};
    for (int i = 0; i < kPositions; ++i) {
        for (int j = 0; j < kPositions; ++j) {
            int l1 = 0, lmax = 0;
            for (int a = 0; a < 3; ++a) {
                const int d = kPosition[i][a] > kPosition[j][a] ? kPosition[i][a] - kPosition[j][a]
                                                                : kPosition[j][a] - kPosition[i][a];
                l1 += d, lmax = d > lmax ? d : lmax;
            }
            if (l1 == 1 || (diagonals && l1 == 2 && lmax == 1)) adjacent[i] |= 1u << j;
        }
    }
    return adjacent;
}

std::uint32_t lowestBit(std::uint32_t mask) { return std::uint32_t(__builtin_ctz(mask)); }

// The component of `seed` within `mask`.
std::uint32_t flood(std::uint32_t seed, std::uint32_t mask, const std::array<std::uint32_t, kPositions>& adjacent) {
    std::uint32_t component = seed, frontier = seed;
    while (frontier) {
        std::uint32_t grown = 0;
        for (std::uint32_t f = frontier; f; f &= f - 1) grown |= adjacent[lowestBit(f)];
        frontier = grown & mask & ~component;
        component |= frontier;
    }
    return component;
}

// The six face positions' bits in a neighbourhood mask (the join sweep's neighbours).
constexpr std::uint32_t kFaces = 0x3fu;

struct ClassTables {
    std::vector<std::uint8_t> join, split;  // by the mask above (join) or below (split)
    std::array<std::uint32_t, kPositions> face = adjacency(false), face18 = adjacency(true);
    ClassTables() : join(std::size_t(1) << kPositions), split(std::size_t(1) << kPositions) {
        for (std::uint32_t mask = 0; mask < join.size(); ++mask) {
            if (mask & kFaces) {
                const std::uint32_t first = lowestBit(mask & kFaces);
                const bool one = (flood(1u << first, mask, face) & mask & kFaces) == (mask & kFaces);
                join[mask] = one ? std::uint8_t(1 + first) : kJoinCandidate;
            }
            if (mask) {
                const std::uint32_t first = lowestBit(mask);
                split[mask] = flood(1u << first, mask, face18) == mask ? std::uint8_t(1 + first) : kSplitCandidate;
            }
        }
    }
};

const ClassTables& classTables() {
    static const ClassTables tables;
    return tables;
}

// The below masks of a row's inner samples (x from 1 to n - 2) whose
// neighbourhoods lie inside the grid and hold no NaN, a position at a time
// along the row, so that the compiler compares many samples at once.
template <class T>
void interiorRow(const T* values, std::uint32_t first, const std::array<std::int64_t, kPositions>& offset,
                 std::vector<std::uint32_t>& belowRow) {
    const std::size_t n = belowRow.size() - 1;
    const T* __restrict centre = values + first;
    std::uint32_t* __restrict below = belowRow.data();
    std::fill(belowRow.begin(), belowRow.end(), 0u);
    for (int p = 0; p < kPositions; ++p) {
        const T* __restrict neighbour = centre + offset[p];
        const std::uint32_t bit = 1u << p, tie = offset[p] < 0 ? bit : 0u;  // a lower index wins a tie
        for (std::size_t x = 1; x < n; ++x) {
            const T a = neighbour[x], b = centre[x];
            below[x] |= a < b ? bit : (a == b ? tie : 0u);
        }
    }
}

// Whether the planes z0 - 1 to z1 (those a slab's neighbourhoods read) hold a NaN.
template <class T>
bool anyNaN(const T* values, const Dims& dims, int z0, int z1) {
    if constexpr (std::is_floating_point_v<T>) {
        const std::int64_t plane = std::int64_t(dims[0]) * dims[1];
        const T* begin = values + std::max(0, z0 - 1) * plane;
        const T* end = values + std::min(dims[2], z1 + 1) * plane;
        return std::any_of(begin, end, [](T v) { return std::isnan(v); });
    } else {
        return false;
    }
}

template <class T>
void classifyRange(const T* values, const Dims& dims, int z0, int z1, Buffer<std::uint8_t>& out,
                   const CandidateGroups& groups, const BuildProgress& progress) {
    const ClassTables& tables = classTables();
    const SampleOrder<T> cmp{values};
    const std::int64_t row = dims[0], plane = std::int64_t(dims[0]) * dims[1];
    std::array<std::int64_t, kPositions> offset{};
    for (int p = 0; p < kPositions; ++p) {
        offset[p] = kPosition[p][0] + kPosition[p][1] * row + kPosition[p][2] * plane;
    }
    // The positions inside the grid, by which of the six borders the sample is on.
    std::array<std::uint32_t, 64> inside{};
    for (std::uint32_t border = 0; border < 64; ++border) {
        for (int p = 0; p < kPositions; ++p) {
            bool in = true;
            for (int a = 0; a < 3; ++a) {
                if ((kPosition[p][a] < 0 && (border >> (2 * a)) & 1) ||
                    (kPosition[p][a] > 0 && (border >> (2 * a + 1)) & 1)) {
                    in = false;
                }
            }
            if (in) inside[border] |= 1u << p;
        }
    }
    // One position of each group of `targets` that `mask` connects inside the neighbourhood.
    auto firstOfGroups = [](std::uint32_t targets, std::uint32_t mask,
                            const std::array<std::uint32_t, kPositions>& adjacent) {
        std::uint32_t firsts = 0;
        while (targets) {
            const std::uint32_t first = targets & (0u - targets);
            firsts |= first;
            targets &= ~flood(first, mask, adjacent);
        }
        return firsts;
    };
    auto store = [&](std::uint32_t s, std::uint32_t below, std::uint32_t above) {
        const std::uint8_t join = tables.join[above], split = tables.split[below];
        out[s] = std::uint8_t(join | split << 3);
        if (join == kJoinCandidate && groups.join) groups.join[s] = firstOfGroups(above & kFaces, above, tables.face);
        if (split == kSplitCandidate && groups.split) groups.split[s] = firstOfGroups(below, below, tables.face18);
    };
    auto classifyOne = [&](std::uint32_t s, std::uint32_t border) {
        std::uint32_t below = 0, above = 0;
        for (std::uint32_t in = inside[border]; in; in &= in - 1) {
            const std::uint32_t p = lowestBit(in);
            const auto m = std::uint32_t(std::int64_t(s) + offset[p]);
            (cmp.below(m, s) ? below : above) |= 1u << p;
        }
        store(s, below, above);
    };
    std::vector<std::uint32_t> belowRow(static_cast<std::size_t>(dims[0]));
    const bool nan = anyNaN(values, dims, z0, z1);  // then one sample at a time, as SampleOrder orders NaN
    for (int z = z0; z < z1; ++z) {
        progress.check();
        for (int y = 0; y < dims[1]; ++y) {
            const std::uint32_t edgeYZ =
                (y == 0 ? 4u : 0u) | (y + 1 == dims[1] ? 8u : 0u) | (z == 0 ? 16u : 0u) | (z + 1 == dims[2] ? 32u : 0u);
            const std::uint32_t first = std::uint32_t(z * plane + y * row);
            const std::uint32_t last = first + std::uint32_t(dims[0] - 1);
            if (edgeYZ != 0 || dims[0] < 3 || nan) {
                for (std::uint32_t s = first; s <= last; ++s) {
                    classifyOne(s, edgeYZ | (s == first ? 1u : 0u) | (s == last ? 2u : 0u));
                }
                continue;
            }
            interiorRow(values, first, offset, belowRow);
            classifyOne(first, 1u);
            for (std::uint32_t x = 1; x + 1 < std::uint32_t(dims[0]); ++x) {
                store(first + x, belowRow[x], ~belowRow[x] & ((1u << kPositions) - 1));
            }
            classifyOne(last, 2u);
        }
    }
}

}  // namespace

std::int64_t neighbourOffset(const Dims& dims, std::uint8_t position) {
    if (position >= kPositions)
        throw std::logic_error("neighbourOffset: no neighbour position " + std::to_string(position));
    const auto& p = kPosition[position];
    return p[0] + std::int64_t(p[1]) * dims[0] + std::int64_t(p[2]) * dims[0] * dims[1];
}

Buffer<std::uint8_t> classifySamples(const Volume& volume, int threads, const BuildProgress& progress,
                                     const CandidateGroups& groups) {
    const Dims& dims = volume.dims();
    const std::size_t n = volume.sampleCount();
    Buffer<std::uint8_t> out(n);
    classTables();  // built once, before the threads share it
    visitSamples(volume, [&](const auto* values) {
        const int parts = std::max(1, std::min(threads, dims[2]));  // slabs of planes, one a thread
        parallelFor(parts, parts, [&](int part) {
            classifyRange(values, dims, dims[2] * part / parts, dims[2] * (part + 1) / parts, out, groups, progress);
        });
    });
    return out;
}

}  // namespace isotrack::detail
