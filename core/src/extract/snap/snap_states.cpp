// The samples' states for the 3-state table (snap_march.h: snapStates).
//
// Pass 1 snaps: a sample is at the isovalue when it equals it or when a
// crossing on one of its six grid edges lies within kSnapDistance of it.
// Pass 2 keeps every surface: a sample that snapped stays at the isovalue only
// if one of its six neighbours is on its side and did not snap. Two such
// samples are joined by an edge the surface does not cross, so they bound the
// same surface, whose crossings around the one that did not snap stay at
// least kSnapDistance away from it: the surface keeps triangles of positive
// area, where snapping every sample inside a small surface (a single sample
// above the isovalue among samples below it, say) would shrink it to a point.
// Pass 3 keeps sheets apart: where two sheets of surface meet a grid edge (or a
// face's diagonal) whose two samples are at the isovalue, from two sides (the
// 2-state surfaces of the cells around it come near it from alternate
// sectors), snapping both samples would lay four triangles on that segment.
// Every such segment is found
// with the states of the round, and every sample of one that only snapped (it
// does not equal the isovalue) goes back to below or above; rounds repeat until
// no segment changes. A round reads only the states the round before left, so the
// result does not depend on the order of the scan, and extractions that visit
// different cells agree. Segments whose two samples equal the isovalue stay as
// they are: there the surface itself touches itself.
//
// Threads: pass 1 writes each slice of samples on its own; pass 2 and each
// round of pass 3 read only the states before them and collect the samples to
// release per slice (per run of candidates), applied once all are collected
// in scan order, so the states are the same on any number of threads.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

#include "extract/snap/snap_march.h"
#include "isotrack/cube.h"
#include "support/parallel.h"
#include "support/working_memory.h"

namespace isotrack::detail {
namespace {

// Where each table corner of a cell lies (the sample it is on or starts from,
// as offsets) and its slot (0..2: the edge's axis; 3: the sample itself);
// and the cube vertex at each offset (x + 2y + 4z). Computed once.
struct CornerPlaces {
    std::array<std::array<int, 3>, kSnapCornerCentre> offset{};
    std::array<std::uint64_t, kSnapCornerCentre> slot{};
    std::array<int, 8> vertexAt{};
};

const CornerPlaces& cornerPlaces() {
    static const CornerPlaces places = [] {
        CornerPlaces out;
        for (int corner = 0; corner < kSnapCornerCentre; ++corner) {
            const bool edge = corner < kSnapCornerVertex;
            out.offset[std::size_t(corner)] =
                edge ? cube::edgeOrigin(corner) : cube::kVertexOffset[std::size_t(corner - kSnapCornerVertex)];
            out.slot[std::size_t(corner)] = edge ? std::uint64_t(cube::edgeAxis(corner)) : 3;
        }
        for (int v = 0; v < cube::kVertexCount; ++v) {
            const auto& o = cube::kVertexOffset[std::size_t(v)];
            out.vertexAt[std::size_t(o[0] + 2 * o[1] + 4 * o[2])] = v;
        }
        return out;
    }();
    return places;
}

// Per snap table entry, how many of its triangles lie on each segment between
// two of its cube vertices: two bits per pair of vertices (pairIndex), three
// meaning three or more. A word each (512 KiB), where the entries run to a
// hundred bytes: pass 3 reads these for every segment it checks.
int pairIndex(int u, int v) {
    if (u > v) std::swap(u, v);
    return v * (v - 1) / 2 + u;  // 0..27
}

const std::vector<std::uint64_t>& segmentCounts() {
    static const std::vector<std::uint64_t> counts = [] {
        const auto& table = snapTable();
        std::vector<std::uint64_t> out(table.size(), 0);
        for (std::size_t c = 0; c < table.size(); ++c) {
            std::uint64_t word = 0;
            for (int t = 0; t < table[c].count; ++t) {
                const auto& tri = table[c].triangles[std::size_t(t)];
                for (int k = 0; k < 3; ++k) {
                    const int u = tri[std::size_t(k)] - kSnapCornerVertex,
                              v = tri[std::size_t((k + 1) % 3)] - kSnapCornerVertex;
                    if (u < 0 || v < 0 || u >= cube::kVertexCount || v >= cube::kVertexCount) continue;
                    const int shift = 2 * pairIndex(u, v);
                    if ((word >> shift & 3u) < 3u) word += std::uint64_t(1) << shift;
                }
            }
            out[c] = word;
        }
        return out;
    }();
    return counts;
}

// Pass 3 marks its candidates in their states' third bit while it runs (the
// marks then come with the states a check reads, where a separate array would
// cost a read of its own); every mark is cleared before it returns.
constexpr std::uint8_t kQueuedBit = 4;
constexpr bool isQueued(SampleState s) { return std::uint8_t(s) & kQueuedBit; }
constexpr SampleState queued(SampleState s, bool mark) {
    return SampleState(mark ? std::uint8_t(s) | kQueuedBit : std::uint8_t(s) & ~kQueuedBit);
}

struct StateGrid {
    const std::vector<SampleState>& states;
    Dims n;
    std::size_t index(int x, int y, int z) const {
        return std::size_t(x) + std::size_t(n[0]) * (std::size_t(y) + std::size_t(n[1]) * std::size_t(z));
    }
    // A corner of cell (x, y, z) as the extractors key its vertex.
    std::uint64_t cornerKey(const CornerPlaces& places, int corner, int x, int y, int z) const {
        if (corner >= kSnapCornerCentre) return index(x, y, z) * 8 + 4 + std::uint64_t(corner - kSnapCornerCentre);
        const auto& o = places.offset[std::size_t(corner)];
        return index(x + o[0], y + o[1], z + o[2]) * 8 + places.slot[std::size_t(corner)];
    }
};

// The 3x3x3 samples around sample p, by local index x + 3y + 9z (p is 13, a
// neighbour's index is its offset from p plus one on each axis): their states,
// read once for all the segments from p, those outside the volume below
// (never at); and the table entries of the eight cells around p (cell
// p - 1 + d for d in {0, 1}^3, d's bits x, y, z), null outside the volume,
// looked up when a segment needs them.
class SamplesAround {
public:
    static constexpr int kCentre = 13;

    SamplesAround(const StateGrid& grid, const std::array<int, 3>& p) : grid_(grid), p_(p) {
        const Dims& n = grid.n;
        const bool interior = p[0] > 0 && p[1] > 0 && p[2] > 0 && p[0] + 1 < n[0] && p[1] + 1 < n[1] && p[2] + 1 < n[2];
        if (interior) {
            // Nine rows of three.
            const auto* first =
                reinterpret_cast<const std::uint8_t*>(grid.states.data()) + grid.index(p[0] - 1, p[1] - 1, p[2] - 1);
            const std::size_t rowStride = std::size_t(n[0]), sliceStride = rowStride * std::size_t(n[1]);
            for (int row = 0; row < 9; ++row) {
                std::memcpy(state_.data() + 3 * row,
                            first + std::size_t(row % 3) * rowStride + std::size_t(row / 3) * sliceStride, 3);
            }
        } else {
            for (int j = 0; j < 27; ++j) {
                const int q[3] = {p[0] + j % 3 - 1, p[1] + j / 3 % 3 - 1, p[2] + j / 9 - 1};
                const bool inside = q[0] >= 0 && q[1] >= 0 && q[2] >= 0 && q[0] < n[0] && q[1] < n[1] && q[2] < n[2];
                state_[std::size_t(j)] = inside ? std::uint8_t(grid.states[grid.index(q[0], q[1], q[2])]) : 0;
            }
        }
        for (int j = 0; j < 27; ++j) atMask_ |= std::uint32_t(state_[std::size_t(j)] >> 1 & 1u) << j;
    }

    // Bit j: sample j is at the isovalue.
    std::uint32_t atMask() const { return atMask_; }
    // Whether sample j is a candidate of the round (isQueued).
    bool queued(int j) const { return isQueued(SampleState(state_[std::size_t(j)])); }

    // The entry index (snapCaseIndex) of cell d (see above), -1 outside the volume.
    int config(int d) {
        int& config = config_[std::size_t(d)];
        if (config == kUnread) config = readConfig(d);
        return config;
    }

    // The entry of cell d, null outside the volume.
    const SnapCase* entry(int d) {
        const int index = config(d);
        return index < 0 ? nullptr : &snapTable()[std::size_t(index)];
    }

private:
    static constexpr int kUnread = -2;

    int readConfig(int d) const {
        const int dx = d & 1, dy = d >> 1 & 1, dz = d >> 2;
        for (int k = 0; k < 3; ++k) {
            const int c = p_[std::size_t(k)] - 1 + (d >> k & 1);
            if (c < 0 || c + 1 >= grid_.n[std::size_t(k)]) return -1;
        }
        unsigned above = 0, at = 0;
        for (int v = 0; v < cube::kVertexCount; ++v) {
            const auto& o = cube::kVertexOffset[std::size_t(v)];
            const std::uint8_t s = state_[std::size_t((dx + o[0]) + 3 * (dy + o[1]) + 9 * (dz + o[2]))];
            above |= unsigned(s & 1u) << v;
            at |= unsigned(s >> 1 & 1u) << v;
        }
        return snapCaseIndex(std::uint8_t(above), std::uint8_t(at));
    }

    const StateGrid& grid_;
    std::array<int, 3> p_;
    std::array<std::uint8_t, 27> state_{};
    std::uint32_t atMask_ = 0;
    std::array<int, 8> config_{kUnread, kUnread, kUnread, kUnread, kUnread, kUnread, kUnread, kUnread};
};

// For each neighbour j of p (SamplesAround's local index), the cells around p
// that hold both (SamplesAround's d) and the cube vertices p and j are in
// each: at most four cells (a grid edge's), computed at compile time.
struct SegmentCells {
    int count = 0;
    std::array<std::array<int, 3>, 4> cell{};  // d, p's vertex, the neighbour's vertex
};

constexpr std::array<SegmentCells, 27> segmentCells() {
    std::array<int, 8> vertexAt{};  // the cube vertex at offset x + 2y + 4z
    for (int v = 0; v < cube::kVertexCount; ++v) {
        const auto& o = cube::kVertexOffset[std::size_t(v)];
        vertexAt[std::size_t(o[0] + 2 * o[1] + 4 * o[2])] = v;
    }
    std::array<SegmentCells, 27> out{};
    for (int j = 0; j < 27; ++j) {
        if (j == SamplesAround::kCentre) continue;   // p itself
        const int q[3] = {j % 3, j / 3 % 3, j / 9};  // p is (1, 1, 1)
        for (int d = 0; d < 8; ++d) {
            const int o[3] = {q[0] - (d & 1), q[1] - (d >> 1 & 1), q[2] - (d >> 2)};  // q's offset in the cell
            if (o[0] < 0 || o[0] > 1 || o[1] < 0 || o[1] > 1 || o[2] < 0 || o[2] > 1) continue;
            SegmentCells& cells = out[std::size_t(j)];
            // p is at offset 1 - d in the cell.
            cells.cell[std::size_t(cells.count++)] = {d, vertexAt[std::size_t(7 - d)],
                                                      vertexAt[std::size_t(o[0] + 2 * o[1] + 4 * o[2])]};
        }
    }
    return out;
}

constexpr std::array<SegmentCells, 27> kSegmentCells = segmentCells();

// fn(d, a, b) for each cell d around p that holds p and its neighbour j, a
// and b the table corners of p and of the neighbour in it.
template <class Fn>
void forCellsOnSegment(int j, Fn&& fn) {
    const SegmentCells& cells = kSegmentCells[std::size_t(j)];
    for (int c = 0; c < cells.count; ++c) {
        const auto& [d, a, b] = cells.cell[std::size_t(c)];
        fn(d, kSnapCornerVertex + a, kSnapCornerVertex + b);
    }
}

bool hasCorner(const std::array<std::int8_t, 3>& triangle, int corner) {
    return triangle[0] == corner || triangle[1] == corner || triangle[2] == corner;
}

// The triangles left on the segment between sample p and its neighbour `j`
// (SamplesAround's local index) once pairs over the same three vertices
// cancel, over the cells that hold both. The count does not depend on the
// order of the cells: a key stays when it is found an odd number of times.
int trianglesOnSegment(const StateGrid& grid, SamplesAround& around, const std::array<int, 3>& p, int j) {
    // Keys of the triangles found, only the first `count` of them set (left
    // uninitialised: this runs for every pair of neighbours at the isovalue).
    std::array<std::array<std::uint64_t, 3>, 4 * kMaxSnapTriangles> found;
    std::size_t count = 0;
    const CornerPlaces& places = cornerPlaces();
    forCellsOnSegment(j, [&](int d, int a, int b) {
        const SnapCase* cased = around.entry(d);
        if (!cased) return;
        const int c[3] = {p[0] - 1 + (d & 1), p[1] - 1 + (d >> 1 & 1), p[2] - 1 + (d >> 2)};
        for (int t = 0; t < cased->count; ++t) {
            const auto& tri = cased->triangles[std::size_t(t)];
            if (!hasCorner(tri, a) || !hasCorner(tri, b)) continue;
            std::array<std::uint64_t, 3> key{};
            for (int k = 0; k < 3; ++k)
                key[std::size_t(k)] = grid.cornerKey(places, tri[std::size_t(k)], c[0], c[1], c[2]);
            std::sort(key.begin(), key.end());
            const auto end = found.begin() + std::ptrdiff_t(count);
            const auto twin = std::find(found.begin(), end, key);
            if (twin != end)
                *twin = found[--count];
            else
                found[count++] = key;
        }
    });
    return int(count);
}

// Whether snapping both p and its neighbour `j` lays more than two triangles
// on their segment (trianglesOnSegment). Cancelling pairs only lowers the
// count, so where the cells hold two triangles on it or fewer in all, the
// triangles need no keys.
bool sheetsMeet(const StateGrid& grid, SamplesAround& around, const std::array<int, 3>& p, int j) {
    const std::vector<std::uint64_t>& counts = segmentCounts();
    unsigned drawn = 0;
    forCellsOnSegment(j, [&](int d, int a, int b) {
        const int config = around.config(d);
        if (config < 0) return;
        const int shift = 2 * pairIndex(a - kSnapCornerVertex, b - kSnapCornerVertex);
        drawn += unsigned(counts[std::size_t(config)] >> shift & 3u);
    });
    return drawn > 2 && trianglesOnSegment(grid, around, p, j) > 2;
}

// Concatenated in order.
std::vector<std::size_t> joined(const std::vector<std::vector<std::size_t>>& parts) {
    std::size_t total = 0;
    for (const auto& part : parts) total += part.size();
    std::vector<std::size_t> all;
    all.reserve(total);
    for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
    return all;
}

// Pass 2 (see the top of the file), over the samples pass 1 snapped, by slice
// (`snapped`); returns those that stay snapped, in sample order.
std::vector<std::size_t> keepSurfaces(std::vector<SampleState>& states, const std::vector<SampleState>& unsnapped,
                                      const Dims& n, int threads, std::vector<std::vector<std::size_t>>& snapped) {
    const std::size_t strides[3] = {1, std::size_t(n[0]), std::size_t(n[0]) * std::size_t(n[1])};
    std::vector<std::vector<std::size_t>> release(static_cast<std::size_t>(n[2]));
    parallelFor(n[2], threads, [&](int z) {
        std::vector<std::size_t>& kept = snapped[std::size_t(z)];
        std::size_t keptCount = 0;
        for (const std::size_t i : kept) {
            const std::size_t inSlice = i - std::size_t(z) * strides[2];
            const int p[3] = {int(inSlice % strides[1]), int(inSlice / strides[1]), z};
            bool anchored = false;
            for (int k = 0; k < 3 && !anchored; ++k) {
                for (int side = 0; side < 2 && !anchored; ++side) {
                    if (side == 0 ? p[k] == 0 : p[k] + 1 >= n[k]) continue;
                    const std::size_t other = side == 0 ? i - strides[k] : i + strides[k];
                    anchored = !isAt(states[other]) && isAbove(states[other]) == isAbove(unsnapped[i]);
                }
            }
            if (anchored)
                kept[keptCount++] = i;
            else
                release[std::size_t(z)].push_back(i);
        }
        kept.resize(keptCount);
    });
    for (const auto& slice : release)
        for (const std::size_t r : slice) states[r] = unsnapped[r];
    return joined(snapped);
}

// Asks the processor for the nine rows of states around sample i (SamplesAround).
constexpr std::size_t kFetchAhead = 4;
void fetchRows(const std::vector<SampleState>& states, std::size_t i, const std::size_t strides[3]) {
    const auto* base = reinterpret_cast<const char*>(states.data());
    const std::size_t below = strides[1] + strides[2] + 1;  // to sample (x - 1, y - 1, z - 1)
    if (i < below || i + below >= states.size()) return;
    for (int row = 0; row < 9; ++row)
        __builtin_prefetch(base + i - below + std::size_t(row % 3) * strides[1] + std::size_t(row / 3) * strides[2]);
}

// Pass 3 (see the top of the file), from the samples still snapped after pass 2
// (`candidates`, in sample order).
void keepSheetsApart(std::vector<SampleState>& states, const std::vector<SampleState>& unsnapped, const Dims& n,
                     int threads, std::vector<std::size_t> candidates) {
    // The samples to check: every one that snapped, then, after a round, those a
    // released sample can change the cells of (within two samples of it).
    for (const std::size_t c : candidates) states[c] = queued(states[c], true);
    const std::size_t strides[3] = {1, std::size_t(n[0]), std::size_t(n[0]) * std::size_t(n[1])};
    for (;;) {
        const StateGrid grid{states, n};
        // Runs of candidates, each checked on one thread.
        constexpr std::size_t kRun = 4096;
        std::vector<std::vector<std::size_t>> released((candidates.size() + kRun - 1) / kRun);
        parallelFor(int(released.size()), threads, [&](int run) {
            std::vector<std::size_t>& release = released[std::size_t(run)];
            const std::size_t first = std::size_t(run) * kRun, last = std::min(first + kRun, candidates.size());
            for (std::size_t c = first; c < last; ++c) {
                // The rows of a candidate a few ahead, fetched early: candidates lie far apart.
                if (c + kFetchAhead < last) fetchRows(states, candidates[c + kFetchAhead], strides);
                const std::size_t i = candidates[c];
                if (!isAt(states[i])) continue;
                const std::array<int, 3> p{int(i % strides[1]), int(i / strides[1] % std::size_t(n[1])),
                                           int(i / strides[2])};
                SamplesAround around(grid, p);
                // Neighbours at the isovalue; a segment between two candidates
                // is checked from its first end only.
                for (std::uint32_t at = around.atMask() & ~(1u << SamplesAround::kCentre); at; at &= at - 1) {
                    const int neighbour = __builtin_ctz(at);
                    if (neighbour < SamplesAround::kCentre && around.queued(neighbour)) continue;
                    if (!sheetsMeet(grid, around, p, neighbour)) continue;
                    const std::size_t other =
                        grid.index(p[0] + neighbour % 3 - 1, p[1] + neighbour / 3 % 3 - 1, p[2] + neighbour / 9 - 1);
                    release.push_back(i);
                    if (!isAt(unsnapped[other])) release.push_back(other);
                }
            }
        });
        const std::vector<std::size_t> release = joined(released);
        for (const std::size_t c : candidates) states[c] = queued(states[c], false);
        if (release.empty()) return;
        for (const std::size_t r : release) states[r] = unsnapped[r];
        candidates.clear();
        for (const std::size_t r : release) {
            const int p[3] = {int(r % strides[1]), int(r / strides[1] % std::size_t(n[1])), int(r / strides[2])};
            for (int z = std::max(p[2] - 2, 0); z <= std::min(p[2] + 2, n[2] - 1); ++z) {
                for (int y = std::max(p[1] - 2, 0); y <= std::min(p[1] + 2, n[1] - 1); ++y) {
                    for (int x = std::max(p[0] - 2, 0); x <= std::min(p[0] + 2, n[0] - 1); ++x) {
                        const std::size_t s = grid.index(x, y, z);
                        if (isQueued(states[s]) || !isAt(states[s]) || isAt(unsnapped[s])) continue;
                        states[s] = queued(states[s], true);
                        candidates.push_back(s);
                    }
                }
            }
        }
    }
}

// Pass 1's sides: each sample's state before snapping (at when it equals
// `iso`, else its side), slice by slice, in loops without branches.
template <class T>
void sampleSides(const T* samples, double iso, const Dims& n, int threads, std::vector<SampleState>& sides) {
    const std::size_t slice = std::size_t(n[0]) * std::size_t(n[1]);
    auto* out = reinterpret_cast<std::uint8_t*>(sides.data());
    if constexpr (std::is_integral_v<T>) {
        // Integers (every one a double exactly): compared as T, which vectorises
        // where the comparison as doubles does not. At or above `iso` is at or
        // above its ceiling; equal only where `iso` is an integer in T's range.
        const double ceiling = std::ceil(iso);
        if (!(ceiling <= double(std::numeric_limits<T>::max()))) return;  // every sample below (NaN too)
        const T threshold =
            ceiling <= double(std::numeric_limits<T>::min()) ? std::numeric_limits<T>::min() : T(ceiling);
        const bool integer = ceiling == iso && iso >= double(std::numeric_limits<T>::min());
        const std::uint8_t atFlag = integer ? 1 : 0;
        const T equal = integer ? T(iso) : T(0);
        parallelFor(n[2], threads, [&](int z) {
            // Locals, which the byte stores cannot alias: the loop then vectorises.
            const T* in = samples + std::size_t(z) * slice;
            std::uint8_t* side = out + std::size_t(z) * slice;
            const std::size_t count = slice;
            const T above = threshold, at = equal;
            const std::uint8_t flag = atFlag;
            for (std::size_t i = 0; i < count; ++i)
                side[i] = std::uint8_t(std::uint8_t(in[i] >= above) | (std::uint8_t(in[i] == at) & flag) << 1);
        });
    } else {
        parallelFor(n[2], threads, [&](int z) {
            const T* in = samples + std::size_t(z) * slice;
            std::uint8_t* side = out + std::size_t(z) * slice;
            const std::size_t count = slice;
            const double level = iso;
            for (std::size_t i = 0; i < count; ++i) {
                const double value = static_cast<double>(in[i]);
                side[i] = std::uint8_t(std::uint8_t(value >= level) | std::uint8_t(value == level) << 1);
            }
        });
    }
}

// Pass 1 for a sample with a crossed grid edge: at when it equals `iso` or
// snaps towards one of its six neighbours; a sample that snapped is listed in
// its slice's `snapped`.
template <class T>
void snapSample(const T* samples, double iso, const Dims& n, int x, int y, int z, std::vector<SampleState>& states,
                const std::vector<SampleState>& unsnapped, std::vector<std::vector<std::size_t>>& snapped) {
    const std::size_t strides[3] = {1, std::size_t(n[0]), std::size_t(n[0]) * std::size_t(n[1])};
    const std::size_t i = std::size_t(x) + strides[1] * std::size_t(y) + strides[2] * std::size_t(z);
    const double value = static_cast<double>(samples[i]);
    bool at = value == iso;
    const int p[3] = {x, y, z};
    for (int k = 0; k < 3 && !at; ++k) {
        if (p[k] > 0) at = snapsTowards(value, static_cast<double>(samples[i - strides[k]]), iso);
        if (!at && p[k] + 1 < n[k]) at = snapsTowards(value, static_cast<double>(samples[i + strides[k]]), iso);
    }
    if (!at) return;
    states[i] = static_cast<SampleState>(std::uint8_t(unsnapped[i]) | 2u);
    if (!isAt(unsnapped[i])) snapped[std::size_t(z)].push_back(i);
}

// Marks in `crossed` (one byte per sample of row (y, z)) the samples with a
// grid neighbour on the other side, the only ones that can snap; returns
// whether there is one. Rows of side bits combined, the loop vectorised.
bool markCrossed(const std::vector<SampleState>& sides, const Dims& n, int y, int z,
                 std::vector<std::uint8_t>& crossed) {
    const std::size_t nx = std::size_t(n[0]), slice = nx * std::size_t(n[1]);
    const std::size_t row = std::size_t(z) * slice + std::size_t(y) * nx;
    const auto* side = reinterpret_cast<const std::uint8_t*>(sides.data());
    // Neighbouring rows, the row itself where there is none (no crossing there).
    const std::uint8_t* s = side + row;
    const std::uint8_t* down = y > 0 ? s - nx : s;
    const std::uint8_t* up = y + 1 < n[1] ? s + nx : s;
    const std::uint8_t* back = z > 0 ? s - slice : s;
    const std::uint8_t* front = z + 1 < n[2] ? s + slice : s;
    std::uint8_t* out = crossed.data();
    auto across = [&](std::size_t x, std::uint8_t left, std::uint8_t right) {
        const std::uint8_t here = s[x];
        return std::uint8_t(((left ^ here) | (right ^ here) | (down[x] ^ here) | (up[x] ^ here) | (back[x] ^ here) |
                             (front[x] ^ here)) &
                            1u);
    };
    std::uint8_t any = out[0] = across(0, s[0], s[nx > 1 ? 1 : 0]);
    if (nx < 2) return any;
    for (std::size_t x = 1; x + 1 < nx; ++x) {
        out[x] = across(x, s[x - 1], s[x + 1]);
        any = std::uint8_t(any | out[x]);
    }
    out[nx - 1] = across(nx - 1, s[nx - 2], s[nx - 1]);
    return (any | out[nx - 1]) != 0;
}

}  // namespace

std::vector<SampleState> snapStates(const Volume& volume, double iso, int threads) {
    // states and unsnapped, and a third byte a sample as headroom (pass 3's
    // marks had it before they moved into the states): the refusal stays where it was
    requireWorkingMemory(volume, 3, "the snap table's sample states");
    return visitSamples(volume, [&](const auto* samples) {
        const Dims& n = volume.dims();
        const std::size_t strides[3] = {1, std::size_t(n[0]), std::size_t(n[0]) * std::size_t(n[1])};
        std::vector<SampleState> states(volume.sampleCount(), SampleState::Below);
        std::vector<SampleState> unsnapped(volume.sampleCount(), SampleState::Below);
        std::vector<std::vector<std::size_t>> snapped(static_cast<std::size_t>(n[2]));  // by pass 1, per slice
        sampleSides(samples, iso, n, threads, unsnapped);
        // Each row's crossed samples, whole words of none skipped (the marks
        // padded with zeros to a multiple of eight).
        const std::size_t words = (std::size_t(n[0]) + 7) / 8;
        parallelForWithState(
            n[2], threads, [&] { return std::vector<std::uint8_t>(words * 8, 0); },
            [&](std::vector<std::uint8_t>& crossed, int z) {
                for (int y = 0; y < n[1]; ++y) {
                    const std::size_t row = std::size_t(z) * strides[2] + std::size_t(y) * strides[1];
                    std::copy_n(unsnapped.begin() + std::ptrdiff_t(row), n[0], states.begin() + std::ptrdiff_t(row));
                    if (!markCrossed(unsnapped, n, y, z, crossed)) continue;
                    for (std::size_t word = 0; word < words; ++word) {
                        std::uint64_t marks;
                        std::memcpy(&marks, crossed.data() + 8 * word, sizeof marks);
                        if (!marks) continue;
                        for (int x = int(8 * word), end = std::min(x + 8, n[0]); x < end; ++x) {
                            if (crossed[std::size_t(x)])
                                snapSample(samples, iso, n, x, y, z, states, unsnapped, snapped);
                        }
                    }
                }
            });
        keepSheetsApart(states, unsnapped, n, threads, keepSurfaces(states, unsnapped, n, threads, snapped));
        return states;
    });
}

}  // namespace isotrack::detail
