// The 3-state table's sample states (detail::snapStates) against a reference
// written the plain way: every sample and every pair of neighbours visited
// with simple loops, values read one at a time, the triangles on a segment
// keyed and counted from the table itself. snapStates decides pass 1 row by
// row, pass 3 from each candidate's 27 samples with a table of counts, and
// removes fins among the triangles drawn on cell faces only: none of that is
// here, so a state it got wrong would differ.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <tuple>
#include <vector>

#include "core/extract/snap/random_integers.h"
#include "extract/snap/snap_march.h"
#include "isotrack/cube.h"
#include "isotrack/snap_table.h"
#include "mesh/manifold.h"

using namespace isotrack;

namespace {

// A vertex as the extractors weld it: (x, y, z, slot), slot 0..2 a grid edge
// from the sample along that axis, 3 the sample itself, 4 + i the i-th centre
// of cell (x, y, z).
using Key = std::tuple<int, int, int, int>;

struct Reference {
    std::vector<SampleState> states;
    std::size_t releasedToKeepSurfaces = 0, releasedToKeepSheetsApart = 0;
};

class ReferenceStates {
public:
    ReferenceStates(const Volume& v, double iso) : v_(v), n_(v.dims()), iso_(iso) {}

    Reference run() {
        Reference out;
        const std::size_t count = v_.sampleCount();
        unsnapped_.assign(count, SampleState::Below);
        out.states.assign(count, SampleState::Below);
        // Pass 1: the side (at when equal), then at when a neighbour's crossing is near.
        forEachSample([&](int x, int y, int z) {
            const double value = v_.value(x, y, z);
            const std::size_t i = index(x, y, z);
            unsnapped_[i] = value == iso_ ? SampleState::At : value >= iso_ ? SampleState::Above : SampleState::Below;
            bool at = value == iso_;
            forEachFaceNeighbour(x, y, z,
                                 [&](int a, int b, int c) { at = at || snapsTowards(value, v_.value(a, b, c), iso_); });
            out.states[i] = at ? SampleState(std::uint8_t(unsnapped_[i]) | 2u) : unsnapped_[i];
        });
        // Pass 2: a sample that snapped needs a neighbour on its side that did not.
        const std::vector<SampleState> snapped = out.states;
        forEachSample([&](int x, int y, int z) {
            const std::size_t i = index(x, y, z);
            if (!isAt(snapped[i]) || isAt(unsnapped_[i])) return;
            bool anchored = false;
            forEachFaceNeighbour(x, y, z, [&](int a, int b, int c) {
                const SampleState s = snapped[index(a, b, c)];
                anchored = anchored || (!isAt(s) && isAbove(s) == isAbove(unsnapped_[i]));
            });
            if (!anchored) {
                out.states[i] = unsnapped_[i];
                ++out.releasedToKeepSurfaces;
            }
        });
        // Pass 3: rounds over every segment of two samples at the isovalue, not
        // both equal to it, until no segment has more than two triangles.
        for (;;) {
            const std::vector<SampleState> round = out.states;
            std::vector<std::size_t> release;
            forEachSample([&](int x, int y, int z) {
                const std::size_t i = index(x, y, z);
                for (int dz = -1; dz <= 1; ++dz)
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                            const std::array<int, 3> q{x + dx, y + dy, z + dz};
                            if (!inside(q) || index(q[0], q[1], q[2]) <= i) continue;  // each pair once
                            const std::size_t j = index(q[0], q[1], q[2]);
                            if (!isAt(round[i]) || !isAt(round[j]) || (isAt(unsnapped_[i]) && isAt(unsnapped_[j])))
                                continue;
                            if (trianglesOnSegment(round, {x, y, z}, q) <= 2) continue;
                            if (!isAt(unsnapped_[i])) release.push_back(i);
                            if (!isAt(unsnapped_[j])) release.push_back(j);
                        }
            });
            if (release.empty()) return out;
            for (const std::size_t r : release) {
                out.releasedToKeepSheetsApart += out.states[r] != unsnapped_[r];
                out.states[r] = unsnapped_[r];
            }
        }
    }

private:
    std::size_t index(int x, int y, int z) const {
        return std::size_t(x) + std::size_t(n_[0]) * (std::size_t(y) + std::size_t(n_[1]) * std::size_t(z));
    }
    bool inside(const std::array<int, 3>& p) const {
        for (int k = 0; k < 3; ++k)
            if (p[std::size_t(k)] < 0 || p[std::size_t(k)] >= n_[std::size_t(k)]) return false;
        return true;
    }
    template <class Fn>
    void forEachSample(Fn&& fn) const {
        for (int z = 0; z < n_[2]; ++z)
            for (int y = 0; y < n_[1]; ++y)
                for (int x = 0; x < n_[0]; ++x) fn(x, y, z);
    }
    template <class Fn>
    void forEachFaceNeighbour(int x, int y, int z, Fn&& fn) const {
        for (int k = 0; k < 3; ++k)
            for (const int step : {-1, 1}) {
                std::array<int, 3> q{x, y, z};
                q[std::size_t(k)] += step;
                if (inside(q)) fn(q[0], q[1], q[2]);
            }
    }

    Key keyOf(int corner, const std::array<int, 3>& cell) const {
        if (corner >= kSnapCornerCentre) return {cell[0], cell[1], cell[2], 4 + corner - kSnapCornerCentre};
        if (corner >= kSnapCornerVertex) {
            const auto& o = cube::kVertexOffset[std::size_t(corner - kSnapCornerVertex)];
            return {cell[0] + o[0], cell[1] + o[1], cell[2] + o[2], 3};
        }
        const auto& o = cube::edgeOrigin(corner);
        return {cell[0] + o[0], cell[1] + o[1], cell[2] + o[2], cube::edgeAxis(corner)};
    }

    // Triangles over the segment p-q, over every cell that holds both, each
    // set of three vertices counted once if drawn an odd number of times.
    int trianglesOnSegment(const std::vector<SampleState>& states, const std::array<int, 3>& p,
                           const std::array<int, 3>& q) const {
        std::map<std::array<Key, 3>, int> drawn;
        const Key kp{p[0], p[1], p[2], 3}, kq{q[0], q[1], q[2], 3};
        for (int cz = std::max(p[2], q[2]) - 1; cz <= std::min(p[2], q[2]); ++cz)
            for (int cy = std::max(p[1], q[1]) - 1; cy <= std::min(p[1], q[1]); ++cy)
                for (int cx = std::max(p[0], q[0]) - 1; cx <= std::min(p[0], q[0]); ++cx) {
                    const std::array<int, 3> cell{cx, cy, cz};
                    if (cx < 0 || cy < 0 || cz < 0 || cx + 1 >= n_[0] || cy + 1 >= n_[1] || cz + 1 >= n_[2]) continue;
                    unsigned above = 0, at = 0;
                    for (int v = 0; v < 8; ++v) {
                        const auto& o = cube::kVertexOffset[std::size_t(v)];
                        const SampleState s = states[index(cx + o[0], cy + o[1], cz + o[2])];
                        above |= unsigned(isAbove(s)) << v;
                        at |= unsigned(isAt(s)) << v;
                    }
                    const SnapCase& entry =
                        snapTable()[std::size_t(snapCaseIndex(std::uint8_t(above), std::uint8_t(at)))];
                    for (int t = 0; t < entry.count; ++t) {
                        std::array<Key, 3> keys;
                        for (int k = 0; k < 3; ++k)
                            keys[std::size_t(k)] = keyOf(entry.triangles[std::size_t(t)][std::size_t(k)], cell);
                        const bool hasP = keys[0] == kp || keys[1] == kp || keys[2] == kp;
                        const bool hasQ = keys[0] == kq || keys[1] == kq || keys[2] == kq;
                        if (!hasP || !hasQ) continue;
                        std::sort(keys.begin(), keys.end());
                        ++drawn[keys];
                    }
                }
        int count = 0;
        for (const auto& [keys, times] : drawn) count += times % 2;
        return count;
    }

    const Volume& v_;
    Dims n_;
    double iso_;
    std::vector<SampleState> unsnapped_;
};

// Samples of a smooth field (two overlapping balls, like bone in a CT),
// rounded to integers of `type`, with integer noise.
Volume ctLike(const Dims& dims, ScalarType type, std::mt19937& rng) {
    Volume v(dims, type);
    std::uniform_int_distribution<int> noise(-3, 3);
    for (int z = 0; z < dims[2]; ++z)
        for (int y = 0; y < dims[1]; ++y)
            for (int x = 0; x < dims[0]; ++x) {
                const double a = std::hypot(x - 8.0, y - 9.0, z - 7.0), b = std::hypot(x - 15.0, y - 11.0, z - 10.0);
                const double value = 800.0 / (1.0 + 0.02 * a * a) + 500.0 / (1.0 + 0.05 * b * b);
                v.setValue(x, y, z, std::round(value) + noise(rng));
            }
    return v;
}

std::size_t snappedCount(const std::vector<SampleState>& states, const Volume& v, double iso) {
    std::size_t snapped = 0, i = 0;
    for (int z = 0; z < v.dims()[2]; ++z)
        for (int y = 0; y < v.dims()[1]; ++y)
            for (int x = 0; x < v.dims()[0]; ++x, ++i) snapped += isAt(states[i]) && v.value(x, y, z) != iso;
    return snapped;
}

}  // namespace

TEST_CASE("snap states: the reference's, on 1, 2 and 3 threads", "[core][snap][threads]") {
    std::mt19937 rng(43);
    struct Case {
        const char* name;
        Volume volume;
        std::vector<double> isos;
    };
    std::vector<Case> cases;
    cases.push_back({"float noise", test::randomFloats({23, 19, 17}, rng), {0.0, 0.1, -0.35}});
    cases.push_back({"integers in [-3, 3]", test::randomIntegers({24, 21, 19}, rng, 3), {0.0, 0.5, 1.0}});
    cases.push_back({"integers in [-1, 1]", test::randomIntegers({20, 18, 16}, rng, 1), {0.0, -1.0}});
    // Thin volumes: rows of one and two samples, a single slice, no cell at all.
    for (const Dims& thin : {Dims{1, 6, 5}, Dims{2, 2, 2}, Dims{3, 1, 7}, Dims{9, 5, 1}, Dims{2, 7, 3}})
        cases.push_back({"a thin volume", test::randomIntegers(thin, rng, 2), {0.0, 0.5}});
    for (const ScalarType type : {ScalarType::Int16, ScalarType::UInt16, ScalarType::Int32, ScalarType::UInt32})
        cases.push_back({"CT-like integers", ctLike({26, 22, 20}, type, rng), {400.0, 400.5, 399.5, 120.0}});
    // uint8: isovalues at and past the ends of the type's range.
    Volume bytes({18, 17, 15}, ScalarType::UInt8);
    std::uniform_int_distribution<int> pickByte(0, 255), pickEnd(0, 3);
    for (int z = 0; z < 15; ++z)
        for (int y = 0; y < 17; ++y)
            for (int x = 0; x < 18; ++x) {
                const int end = pickEnd(rng);
                bytes.setValue(x, y, z, end == 0 ? 0 : end == 1 ? 255 : pickByte(rng));
            }
    cases.push_back({"uint8 with its ends", std::move(bytes), {0.0, 255.0, 254.5, 0.5, -1.0, 256.0, 128.0}});
    Volume int8({17, 16, 15}, ScalarType::Int8);
    std::uniform_int_distribution<int> pickSigned(-128, 127);
    for (int z = 0; z < 15; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 17; ++x) {
                const int end = pickEnd(rng);
                int8.setValue(x, y, z, end == 0 ? -128 : end == 1 ? 127 : pickSigned(rng));
            }
    cases.push_back({"int8 with its ends", std::move(int8), {-128.0, 127.0, -1.0, -129.0, 127.5, 0.5}});

    std::size_t keptSurfaces = 0, keptSheetsApart = 0;
    for (const Case& c : cases) {
        for (const double iso : c.isos) {
            INFO(c.name << " at iso " << iso);
            const Reference reference = ReferenceStates(c.volume, iso).run();
            keptSurfaces += reference.releasedToKeepSurfaces;
            keptSheetsApart += reference.releasedToKeepSheetsApart;
            for (int threads = 1; threads <= 3; ++threads) {
                INFO(threads << " threads");
                const std::vector<SampleState> states = detail::snapStates(c.volume, iso, threads);
                REQUIRE(states.size() == reference.states.size());
                std::size_t differ = 0;
                for (std::size_t i = 0; i < states.size(); ++i) differ += states[i] != reference.states[i];
                CHECK(differ == 0);
            }
        }
    }
    // The fields exercise every pass: samples snapped, and released by passes 2 and 3.
    const Volume& integers = cases[1].volume;
    CHECK(snappedCount(ReferenceStates(integers, 0.5).run().states, integers, 0.5) > 100);
    CHECK(keptSurfaces > 0);
    CHECK(keptSheetsApart > 0);
}

TEST_CASE("snap: fins removed among the suspects are removeFins' fins", "[core][snap]") {
    std::mt19937 rng(5);
    std::uniform_int_distribution<std::uint32_t> vertex(0, 40);
    for (int trial = 0; trial < 50; ++trial) {
        // Triangles of distinct vertices; some copied, reversed or rotated, once or twice.
        std::vector<std::uint32_t> indices;
        for (int t = 0; t < 300; ++t) {
            std::uint32_t a = vertex(rng), b = vertex(rng), c = vertex(rng);
            while (b == a) b = vertex(rng);
            while (c == a || c == b) c = vertex(rng);
            indices.insert(indices.end(), {a, b, c});
        }
        std::uniform_int_distribution<std::size_t> pick(0, 299);
        for (int copy = 0; copy < 60; ++copy) {
            const std::size_t t = pick(rng);
            const std::uint32_t a = indices[3 * t], b = indices[3 * t + 1], c = indices[3 * t + 2];
            indices.insert(indices.end(), {copy % 2 ? c : b, copy % 2 ? b : c, a});
        }
        // Every triangle that shares its vertices with another is a suspect, and a third of the others.
        std::map<std::array<std::uint32_t, 3>, int> sets;
        auto setOf = [&](std::size_t t) {
            std::array<std::uint32_t, 3> key{indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]};
            std::sort(key.begin(), key.end());
            return key;
        };
        const std::size_t count = indices.size() / 3;
        for (std::size_t t = 0; t < count; ++t) ++sets[setOf(t)];
        std::vector<std::uint32_t> suspects;
        for (std::size_t t = 0; t < count; ++t)
            if (sets[setOf(t)] > 1 || t % 3 == 0) suspects.push_back(std::uint32_t(t));
        std::vector<std::uint32_t> expected = indices;
        detail::removeFins(expected);
        std::vector<std::uint32_t> got = indices;
        got.resize(detail::removeFinsAmong(got.data(), got.size(), suspects));
        REQUIRE(expected.size() < indices.size());
        CHECK(got == expected);
    }
}
