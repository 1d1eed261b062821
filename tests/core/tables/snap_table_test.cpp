#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "isotrack/continuation.h"
#include "isotrack/cube.h"
#include "isotrack/snap_table.h"
#include "isotrack/tables.h"

using namespace isotrack;

namespace {

using Side = std::pair<int, int>;
using Position = std::array<double, 3>;

// A corner's position in the cube (a centre: the mean of its loop's corners).
Position cornerPosition(const SnapCase& cased, int corner) {
    if (corner >= kSnapCornerCentre) {
        Position sum{0, 0, 0};
        int count = 0;
        for (const std::int8_t c : cased.centres[std::size_t(corner - kSnapCornerCentre)]) {
            if (c < 0) break;
            const Position p = cornerPosition(cased, c);
            for (int k = 0; k < 3; ++k) sum[std::size_t(k)] += p[std::size_t(k)];
            ++count;
        }
        for (double& s : sum) s /= count;
        return sum;
    }
    if (corner >= kSnapCornerVertex) {
        const auto& o = cube::kVertexOffset[std::size_t(corner - kSnapCornerVertex)];
        return {double(o[0]), double(o[1]), double(o[2])};
    }
    const auto& a = cube::kVertexOffset[std::size_t(cube::kEdgeVertices[std::size_t(corner)][0])];
    const auto& b = cube::kVertexOffset[std::size_t(cube::kEdgeVertices[std::size_t(corner)][1])];
    return {(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0, (a[2] + b[2]) / 2.0};
}

// Directed sides of the case's triangles whose reverse no triangle has.
std::multiset<Side> boundary(const SnapCase& cased) {
    std::multiset<Side> sides;
    for (int t = 0; t < cased.count; ++t) {
        const auto& tri = cased.triangles[std::size_t(t)];
        for (int k = 0; k < 3; ++k) sides.insert({tri[std::size_t(k)], tri[std::size_t((k + 1) % 3)]});
    }
    std::multiset<Side> open;
    for (const Side& s : sides) {
        if (sides.count({s.second, s.first}) == 0) open.insert(s);
    }
    return open;
}

int rotateCorner(int corner, const cube::Rotation& r) {
    if (corner >= kSnapCornerCentre) return corner;
    if (corner >= kSnapCornerVertex) return kSnapCornerVertex + r.vertex[std::size_t(corner - kSnapCornerVertex)];
    return r.edge[std::size_t(corner)];
}

bool onFace(const Position& p, int face) { return p[std::size_t(cube::faceAxis(face))] == cube::faceSide(face); }

}  // namespace

TEST_CASE("snap table: with no sample at the isovalue, the consistent table's surface", "[core][tables][snap]") {
    const auto& snap = snapTable();
    const auto& continuation = continuationTable(TableKind::Consistent);
    for (int above = 0; above < 256; ++above) {
        const SnapCase& cased = snap[std::size_t(snapCaseIndex(std::uint8_t(above), 0))];
        const CaseContinuation& consistent = continuation[std::size_t(above)];
        CaseTriangles reference;
        reference.count = static_cast<std::uint8_t>(triangleTable(TableKind::Consistent)[std::uint8_t(above)].count);
        SnapCase asSnap;
        asSnap.count = reference.count;
        for (int t = 0; t < reference.count; ++t)
            asSnap.triangles[std::size_t(t)] = consistent.triangles[std::size_t(t)];
        INFO("configuration " << above);
        CHECK(boundary(cased) == boundary(asSnap));
        CHECK(cased.count == reference.count);
        CHECK(cased.centreCount == 0);
        for (int t = 0; t < cased.count; ++t) {
            const auto& tri = cased.triangles[std::size_t(t)];
            CHECK(consistent.pieceOfEdge[std::size_t(tri[0])] == cased.piece[std::size_t(t)]);
        }
    }
}

TEST_CASE("snap table: every entry is a surface closed inside the cube, of proper triangles", "[core][tables][snap]") {
    const auto& snap = snapTable();
    std::size_t centred = 0;
    for (int index = 0; index < kSnapCaseCount; ++index) {
        const SnapCase& cased = snap[std::size_t(index)];
        INFO("entry " << index);
        centred += cased.centreCount;
        std::set<std::array<std::int8_t, 3>> seen;
        for (int t = 0; t < cased.count; ++t) {
            auto tri = cased.triangles[std::size_t(t)];
            // Three corners at three places, not on one line.
            const Position a = cornerPosition(cased, tri[0]), b = cornerPosition(cased, tri[1]),
                           c = cornerPosition(cased, tri[2]);
            const Position u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
            const Position n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
            CHECK(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] > 1e-12);
            // A corner on an edge only where neither end of the edge is at the isovalue
            // and the edge is crossed; a vertex corner only at a sample at the isovalue.
            for (const std::int8_t corner : tri) {
                if (corner >= kSnapCornerCentre) continue;
                if (corner >= kSnapCornerVertex) {
                    CHECK((cased.atMask >> (corner - kSnapCornerVertex) & 1u));
                    continue;
                }
                const auto& ends = cube::kEdgeVertices[std::size_t(corner)];
                CHECK_FALSE(((cased.atMask >> ends[0] | cased.atMask >> ends[1]) & 1u));
                CHECK(((cased.aboveMask >> ends[0]) & 1u) != ((cased.aboveMask >> ends[1]) & 1u));
            }
            std::sort(tri.begin(), tri.end());
            CHECK(seen.insert(tri).second);  // no two triangles over the same corners
        }
        // Where the surface is open, it continues across a face.
        for (const Side& s : boundary(cased)) {
            const Position a = cornerPosition(cased, s.first), b = cornerPosition(cased, s.second);
            bool face = false;
            for (int f = 0; f < cube::kFaceCount; ++f) face |= onFace(a, f) && onFace(b, f);
            CHECK(face);
        }
    }
    CHECK(centred > 0);
}

TEST_CASE("snap table: rotating an entry gives the entry of the rotated states", "[core][tables][snap]") {
    const auto& snap = snapTable();
    for (int index = 0; index < kSnapCaseCount; ++index) {
        const SnapCase& cased = snap[std::size_t(index)];
        const std::multiset<Side> open = boundary(cased);
        for (const cube::Rotation& r : cube::rotations()) {
            const SnapCase& turned = snap[std::size_t(
                snapCaseIndex(cube::rotateConfig(cased.aboveMask, r), cube::rotateConfig(cased.atMask, r)))];
            std::multiset<Side> moved;
            for (const Side& s : open) moved.insert({rotateCorner(s.first, r), rotateCorner(s.second, r)});
            INFO("entry " << index);
            CHECK(boundary(turned) == moved);
            CHECK(turned.count == cased.count);
            CHECK(turned.centreCount == cased.centreCount);
        }
    }
}

TEST_CASE("snap table: two cubes sharing a face draw the same segments on it, or cancelling triangles",
          "[core][tables][snap]") {
    // Cube A at the origin, cube B across A's +x face (face 1); B's vertices 0, 3, 4, 7 are A's 1, 2, 5, 6.
    const auto& snap = snapTable();
    std::mt19937 rng(1);
    std::uniform_int_distribution<int> state(0, 3);
    const std::array<int, 4> shared{1, 2, 5, 6}, across{0, 3, 4, 7};
    for (int trial = 0; trial < 200000; ++trial) {
        std::array<int, 8> a{}, b{};
        for (int& s : a) s = state(rng);
        for (int& s : b) s = state(rng);
        for (int k = 0; k < 4; ++k) b[std::size_t(across[std::size_t(k)])] = a[std::size_t(shared[std::size_t(k)])];
        auto entry = [&](const std::array<int, 8>& states) -> const SnapCase& {
            unsigned above = 0, at = 0;
            for (int v = 0; v < 8; ++v) {
                above |= unsigned(states[std::size_t(v)] & 1) << v;
                at |= unsigned(states[std::size_t(v)] >> 1) << v;
            }
            return snap[std::size_t(snapCaseIndex(std::uint8_t(above), std::uint8_t(at)))];
        };
        const SnapCase& ca = entry(a);
        const SnapCase& cb = entry(b);
        using Triangle = std::array<Position, 3>;
        auto triangles = [](const SnapCase& cased, double shift) {
            std::vector<Triangle> out;
            for (int t = 0; t < cased.count; ++t) {
                Triangle tri{};
                for (int k = 0; k < 3; ++k) {
                    tri[std::size_t(k)] = cornerPosition(cased, cased.triangles[std::size_t(t)][std::size_t(k)]);
                    tri[std::size_t(k)][0] += shift;
                }
                out.push_back(tri);
            }
            return out;
        };
        std::vector<Triangle> ta = triangles(ca, 0.0), tb = triangles(cb, 1.0);
        // Triangles of A and B over the same three points cancel.
        auto sorted = [](Triangle t) {
            std::sort(t.begin(), t.end());
            return t;
        };
        for (auto i = ta.begin(); i != ta.end();) {
            const auto twin =
                std::find_if(tb.begin(), tb.end(), [&](const Triangle& t) { return sorted(t) == sorted(*i); });
            if (twin == tb.end()) {
                ++i;
                continue;
            }
            tb.erase(twin);
            i = ta.erase(i);
        }
        // Directed open sides strictly inside the plane x = 1 (not along the face's border).
        auto openInFace = [](const std::vector<Triangle>& tris) {
            std::multiset<std::pair<Position, Position>> sides, open;
            for (const Triangle& t : tris)
                for (int k = 0; k < 3; ++k) sides.insert({t[std::size_t(k)], t[std::size_t((k + 1) % 3)]});
            for (const auto& [p, q] : sides) {
                if (sides.count({q, p})) continue;
                if (p[0] != 1.0 || q[0] != 1.0) continue;
                const bool alongBorder =
                    (p[1] == q[1] && (p[1] == 0.0 || p[1] == 1.0)) || (p[2] == q[2] && (p[2] == 0.0 || p[2] == 1.0));
                if (!alongBorder) open.insert({p, q});
            }
            return open;
        };
        std::multiset<std::pair<Position, Position>> fromB;
        for (const auto& [p, q] : openInFace(tb)) fromB.insert({q, p});
        INFO("A states " << a[0] << a[1] << a[2] << a[3] << a[4] << a[5] << a[6] << a[7] << ", B states " << b[0]
                         << b[1] << b[2] << b[3] << b[4] << b[5] << b[6] << b[7]);
        REQUIRE(openInFace(ta) == fromB);
    }
}
