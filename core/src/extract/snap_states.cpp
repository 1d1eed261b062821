// The samples' states for the 3-state table (snap_march.h: snapStates).
//
// Pass 1 snaps: a sample is at the isovalue when it equals it or when a
// crossing on one of its six grid edges lies within kSnapDistance of it.
// Pass 2 keeps sheets apart: where two sheets of surface meet a grid edge whose
// two samples are at the isovalue from two sides (the 2-state surfaces of
// the four cells around it come near the edge from alternate sectors), snapping
// both samples would lay four triangles on that edge. Every such edge is found
// with the states of the round, and every sample of one that only snapped (it
// does not equal the isovalue) goes back to below or above; rounds repeat until
// no edge changes. A round reads only the states the round before left, so the
// result does not depend on the order of the scan, and extractions that visit
// different cells agree. Edges whose two samples equal the isovalue stay as
// they are: there the surface itself touches itself.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "isotrack/cube.h"
#include "snap_march.h"

namespace isotrack::detail {
namespace {

constexpr std::array<int, 8> kPowerOf3{1, 3, 9, 27, 81, 243, 729, 2187};

struct StateGrid {
    const std::vector<SampleState>& states;
    Dims n;
    std::size_t index(int x, int y, int z) const {
        return std::size_t(x) + std::size_t(n[0]) * (std::size_t(y) + std::size_t(n[1]) * std::size_t(z));
    }
    int config(int x, int y, int z) const {
        int c = 0;
        for (int v = 0; v < cube::kVertexCount; ++v) {
            const auto& o = cube::kVertexOffset[std::size_t(v)];
            c += int(states[index(x + o[0], y + o[1], z + o[2])]) * kPowerOf3[std::size_t(v)];
        }
        return c;
    }
    // A corner of cell (x, y, z) as the extractors key its vertex.
    std::uint64_t cornerKey(int corner, int x, int y, int z) const {
        int p[3] = {x, y, z};
        std::uint64_t slot = 3;
        if (corner >= kSnapCornerCentre) return index(x, y, z) * 8 + 4 + std::uint64_t(corner - kSnapCornerCentre);
        if (corner < kSnapCornerVertex) {
            const auto& o = cube::edgeOrigin(corner);
            for (int k = 0; k < 3; ++k) p[k] += o[std::size_t(k)];
            slot = std::uint64_t(cube::edgeAxis(corner));
        } else {
            const auto& o = cube::kVertexOffset[std::size_t(corner - kSnapCornerVertex)];
            for (int k = 0; k < 3; ++k) p[k] += o[std::size_t(k)];
        }
        return index(p[0], p[1], p[2]) * 8 + slot;
    }
};

// The triangles left on the grid edge from sample (x, y, z) along `axis` once
// pairs over the same three vertices cancel, over the cells around it.
int trianglesOnEdge(const StateGrid& grid, int x, int y, int z, int axis) {
    std::vector<std::array<std::uint64_t, 3>> found;
    const int u = (axis + 1) % 3, w = (axis + 2) % 3;
    for (int du = 0; du < 2; ++du) {
        for (int dw = 0; dw < 2; ++dw) {
            int c[3] = {x, y, z};
            c[u] -= du;
            c[w] -= dw;
            if (c[u] < 0 || c[w] < 0 || c[u] + 1 >= grid.n[std::size_t(u)] || c[w] + 1 >= grid.n[std::size_t(w)])
                continue;
            std::array<int, 3> origin{};
            origin[std::size_t(u)] = du;
            origin[std::size_t(w)] = dw;
            const int edge = cube::edgeAt(origin, axis);
            const int a = kSnapCornerVertex + cube::kEdgeVertices[std::size_t(edge)][0];
            const int b = kSnapCornerVertex + cube::kEdgeVertices[std::size_t(edge)][1];
            const SnapCase& cased = snapTable()[std::size_t(grid.config(c[0], c[1], c[2]))];
            for (int t = 0; t < cased.count; ++t) {
                const auto& tri = cased.triangles[std::size_t(t)];
                if (std::count(tri.begin(), tri.end(), a) == 0 || std::count(tri.begin(), tri.end(), b) == 0) continue;
                std::array<std::uint64_t, 3> key{};
                for (int k = 0; k < 3; ++k) key[std::size_t(k)] = grid.cornerKey(tri[std::size_t(k)], c[0], c[1], c[2]);
                std::sort(key.begin(), key.end());
                const auto twin = std::find(found.begin(), found.end(), key);
                if (twin != found.end())
                    found.erase(twin);
                else
                    found.push_back(key);
            }
        }
    }
    return int(found.size());
}

// Pass 2 (see the top of the file).
void keepSheetsApart(std::vector<SampleState>& states, const std::vector<SampleState>& unsnapped, const Dims& n) {
    std::vector<std::size_t> snapped;
    for (std::size_t i = 0; i < states.size(); ++i) {
        if (states[i] == SampleState::At && unsnapped[i] != SampleState::At) snapped.push_back(i);
    }
    const std::size_t strides[3] = {1, std::size_t(n[0]), std::size_t(n[0]) * std::size_t(n[1])};
    for (;;) {
        const StateGrid grid{states, n};
        std::vector<std::size_t> release;
        for (const std::size_t i : snapped) {
            if (states[i] != SampleState::At) continue;
            const int p[3] = {int(i % strides[1]), int(i / strides[1] % std::size_t(n[1])), int(i / strides[2])};
            for (int axis = 0; axis < 3; ++axis) {
                for (int side = 0; side < 2; ++side) {
                    if (side == 0 ? p[axis] == 0 : p[axis] + 1 >= n[axis]) continue;
                    const std::size_t other = side == 0 ? i - strides[axis] : i + strides[axis];
                    if (states[other] != SampleState::At) continue;
                    int q[3] = {p[0], p[1], p[2]};
                    q[axis] -= side == 0;
                    if (trianglesOnEdge(grid, q[0], q[1], q[2], axis) <= 2) continue;
                    release.push_back(i);
                    if (unsnapped[other] != SampleState::At) release.push_back(other);
                }
            }
        }
        if (release.empty()) return;
        for (const std::size_t i : release) states[i] = unsnapped[i];
    }
}

}  // namespace

std::vector<SampleState> snapStates(const Volume& volume, double iso) {
    return visitSamples(volume, [&](const auto* samples) {
        const Dims& n = volume.dims();
        const std::size_t strides[3] = {1, std::size_t(n[0]), std::size_t(n[0]) * std::size_t(n[1])};
        std::vector<SampleState> states(volume.sampleCount(), SampleState::Below);
        std::vector<SampleState> unsnapped(volume.sampleCount(), SampleState::Below);
        std::size_t i = 0;
        for (int z = 0; z < n[2]; ++z) {
            for (int y = 0; y < n[1]; ++y) {
                for (int x = 0; x < n[0]; ++x, ++i) {
                    const double value = static_cast<double>(samples[i]);
                    unsnapped[i] = value == iso   ? SampleState::At
                                   : value >= iso ? SampleState::Above
                                                  : SampleState::Below;
                    bool at = value == iso;
                    const int p[3] = {x, y, z};
                    for (int k = 0; k < 3 && !at; ++k) {
                        if (p[k] > 0) at = snapsTowards(value, static_cast<double>(samples[i - strides[k]]), iso);
                        if (!at && p[k] + 1 < n[k])
                            at = snapsTowards(value, static_cast<double>(samples[i + strides[k]]), iso);
                    }
                    states[i] = at ? SampleState::At : unsnapped[i];
                }
            }
        }
        keepSheetsApart(states, unsnapped, n);
        return states;
    });
}

}  // namespace isotrack::detail
