// Generation of the 3-state (SnapMC) table from the consistent table; the
// construction is described in isotrack/snap_table.h.
#include "isotrack/snap_table.h"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

#include "isotrack/continuation.h"
#include "isotrack/cube.h"

namespace isotrack {
namespace {

using Corners = std::array<std::int8_t, 3>;
using Loop = std::vector<std::int8_t>;

// The corner a crossing on `edge` lands on: the edge's at end if it has one;
// its end above the isovalue if both are at (where a sample equals the
// isovalue, the crossing is exactly there).
std::int8_t snappedCorner(int edge, std::uint8_t aboveMask, std::uint8_t atMask) {
    int corner = edge;
    for (int end : cube::kEdgeVertices[std::size_t(edge)]) {
        if ((atMask >> end & 1u) && (corner == edge || (aboveMask >> end & 1u))) corner = kSnapCornerVertex + end;
    }
    return static_cast<std::int8_t>(corner);
}

// A corner's position in the cube, doubled so that edge midpoints are integers.
std::array<int, 3> doubledPosition(int corner) {
    if (corner >= kSnapCornerVertex) {
        const auto& o = cube::kVertexOffset[std::size_t(corner - kSnapCornerVertex)];
        return {2 * o[0], 2 * o[1], 2 * o[2]};
    }
    const auto& a = cube::kVertexOffset[std::size_t(cube::kEdgeVertices[std::size_t(corner)][0])];
    const auto& b = cube::kVertexOffset[std::size_t(cube::kEdgeVertices[std::size_t(corner)][1])];
    return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

// The face all of `corners` lie on, or -1.
int commonFace(const Loop& corners) {
    for (int f = 0; f < cube::kFaceCount; ++f) {
        const int axis = cube::faceAxis(f), level = 2 * cube::faceSide(f);
        if (std::all_of(corners.begin(), corners.end(),
                        [&](std::int8_t c) { return doubledPosition(c)[std::size_t(axis)] == level; }))
            return f;
    }
    return -1;
}

// The boundary of a piece's triangles (a fanned polygon), in order and winding.
Loop pieceLoop(const CaseContinuation& cased, const Piece& piece) {
    std::vector<std::pair<int, int>> sides;
    for (int t = piece.firstTriangle; t < piece.firstTriangle + piece.triangleCount; ++t) {
        const auto& tri = cased.triangles[std::size_t(t)];
        for (int k = 0; k < 3; ++k) sides.emplace_back(tri[std::size_t(k)], tri[std::size_t((k + 1) % 3)]);
    }
    std::array<int, 12> next{};
    next.fill(-1);
    for (const auto& [from, to] : sides) {
        const bool inner = std::find(sides.begin(), sides.end(), std::make_pair(to, from)) != sides.end();
        if (!inner) next[std::size_t(from)] = to;
    }
    Loop loop;
    const int start = sides.empty() ? -1 : sides.front().first;
    int c = start;
    while (c >= 0 && next[std::size_t(c)] >= 0 && loop.size() < 12) {
        loop.push_back(static_cast<std::int8_t>(c));
        c = next[std::size_t(c)];
        if (c == start) return loop;
    }
    throw std::logic_error("snap table: a consistent piece is not bounded by one polygon");
}

// Splits a closed polygon where it passes a corner twice; loops of fewer than three corners go.
void splitLoop(const Loop& loop, std::vector<Loop>& out) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
        for (std::size_t j = i + 1; j < loop.size(); ++j) {
            if (loop[i] != loop[j]) continue;
            splitLoop(Loop(loop.begin() + std::ptrdiff_t(i), loop.begin() + std::ptrdiff_t(j)), out);
            Loop rest(loop.begin(), loop.begin() + std::ptrdiff_t(i));
            rest.insert(rest.end(), loop.begin() + std::ptrdiff_t(j), loop.end());
            splitLoop(rest, out);
            return;
        }
    }
    if (loop.size() >= 3) out.push_back(loop);
}

// Fans a simple loop. A loop on one cube face is fanned from its corner first
// in the face's own coordinates, so the cube across the face, drawing the same
// loop reversed, draws the same triangles; any other loop from its first corner
// whose fan lays no triangle and no diagonal flat on a face (the cube across
// the face may draw the same diagonal where the surface passes between its
// two ends), else around the loop's centre.
std::vector<Corners> triangulate(const Loop& loop, int centre) {
    const std::size_t n = loop.size();
    auto fan = [&](std::size_t start) {
        std::vector<Corners> triangles;
        for (std::size_t k = 1; k + 1 < n; ++k)
            triangles.push_back({loop[start], loop[(start + k) % n], loop[(start + k + 1) % n]});
        return triangles;
    };
    const int face = commonFace(loop);
    if (face >= 0) {
        const int u = (cube::faceAxis(face) + 1) % 3, w = (cube::faceAxis(face) + 2) % 3;
        auto key = [&](std::int8_t c) {
            const auto p = doubledPosition(c);
            return std::make_pair(p[std::size_t(std::min(u, w))], p[std::size_t(std::max(u, w))]);
        };
        std::size_t first = 0;
        for (std::size_t i = 1; i < n; ++i) {
            if (key(loop[i]) < key(loop[first])) first = i;
        }
        return fan(first);
    }
    for (std::size_t start = 0; start < n; ++start) {
        bool flat = false;
        for (std::size_t k = 1; k + 1 < n && !flat; ++k) {
            flat = commonFace(Loop{loop[start], loop[(start + k) % n], loop[(start + k + 1) % n]}) >= 0 ||
                   (k > 1 && commonFace(Loop{loop[start], loop[(start + k) % n]}) >= 0);
        }
        if (!flat) return fan(start);
    }
    // Around the centre: corner kSnapCornerCentre + centre.
    std::vector<Corners> triangles;
    const auto c = static_cast<std::int8_t>(kSnapCornerCentre + centre);
    for (std::size_t k = 0; k < n; ++k) triangles.push_back({c, loop[k], loop[(k + 1) % n]});
    return triangles;
}

bool sameCorners(Corners a, Corners b) {
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    return a == b;
}

SnapCase buildCase(int index) {
    SnapCase out;
    out.aboveMask = std::uint8_t(index & 0xff);
    out.atMask = std::uint8_t(index >> 8);
    const CaseContinuation& cased = continuationTable(TableKind::Consistent)[out.aboveMask];
    std::vector<Corners> kept;
    std::vector<std::int8_t> pieceOf;
    for (int p = 0; p < cased.pieceCount; ++p) {
        Loop snapped;
        for (const std::int8_t edge : pieceLoop(cased, cased.pieces[std::size_t(p)])) {
            const std::int8_t corner = snappedCorner(edge, out.aboveMask, out.atMask);
            if (snapped.empty() || snapped.back() != corner) snapped.push_back(corner);
        }
        while (snapped.size() > 1 && snapped.front() == snapped.back()) snapped.pop_back();
        std::vector<Loop> loops;
        splitLoop(snapped, loops);
        for (const Loop& loop : loops) {
            std::vector<Corners> triangles = triangulate(loop, out.centreCount);
            if (triangles.size() == loop.size()) {
                if (out.centreCount == kMaxSnapCentres) throw std::logic_error("snap table: too many centred loops");
                auto& corners = out.centres[out.centreCount++];
                corners.fill(-1);
                std::copy(loop.begin(), loop.end(), corners.begin());
            }
            for (const Corners& t : triangles) {
                kept.push_back(t);
                pieceOf.push_back(static_cast<std::int8_t>(p));
            }
        }
    }
    // A triangle and another over the same corners enclose nothing: both go.
    std::vector<bool> dropped(kept.size(), false);
    for (std::size_t a = 0; a < kept.size(); ++a) {
        for (std::size_t b = a + 1; b < kept.size() && !dropped[a]; ++b) {
            if (!dropped[b] && sameCorners(kept[a], kept[b])) dropped[a] = dropped[b] = true;
        }
    }
    for (std::size_t t = 0; t < kept.size(); ++t) {
        if (dropped[t]) continue;
        if (out.count >= kMaxSnapTriangles) throw std::logic_error("snap table: too many triangles in a case");
        out.triangles[out.count] = kept[t];
        out.piece[out.count] = pieceOf[t];
        ++out.count;
    }
    return out;
}

}  // namespace

const std::vector<SnapCase>& snapTable() {
    static const auto table = [] {
        std::vector<SnapCase> cases(kSnapCaseCount);
        for (int c = 0; c < kSnapCaseCount; ++c) cases[std::size_t(c)] = buildCase(c);
        return cases;
    }();
    return table;
}

}  // namespace isotrack
