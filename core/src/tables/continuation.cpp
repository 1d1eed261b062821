// Generation of the continuation table from a triangle table.
//
// For each configuration: union the cube edges of every triangle to find its
// pieces (at most four), regroup the triangles piece by piece, and for each piece
// and face find the segments the piece draws on that face: the triangle sides
// that belong to one triangle only and whose two ends lie on the face. The cube
// across the face draws the same segment, so either end is an entry edge there.
#include "isotrack/continuation.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "isotrack/cube.h"
#include "isotrack/errors.h"
#include "isotrack/snap_table.h"
#include "isotrack/trilinear.h"

namespace isotrack {
namespace {

using Triangle = std::array<std::int8_t, 3>;

int findRoot(std::array<int, 12>& parent, int e) {
    while (parent[e] != e) e = parent[e] = parent[parent[e]];
    return e;
}

// The sides (pairs of cube edges) used by exactly one of `triangles`.
std::vector<std::pair<int, int>> boundarySides(const std::vector<Triangle>& triangles) {
    std::map<std::pair<int, int>, int> uses;
    for (const Triangle& t : triangles) {
        for (int k = 0; k < 3; ++k) {
            const int a = t[k], b = t[(k + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    std::vector<std::pair<int, int>> sides;
    for (const auto& [side, count] : uses) {
        if (count == 1) sides.push_back(side);
    }
    return sides;
}

CaseContinuation buildCase(const CaseTriangles& cased, TableKind kind) {
    CaseContinuation out;
    out.pieceOfEdge.fill(-1);
    std::array<int, 12> parent{};
    for (int e = 0; e < 12; ++e) parent[e] = e;
    std::uint16_t used = 0;
    for (int t = 0; t < cased.count; ++t) {
        const Triangle& tri = cased.triangles[t];
        for (int k = 0; k < 3; ++k) {
            used = static_cast<std::uint16_t>(used | 1u << tri[k]);
            parent[findRoot(parent, tri[k])] = findRoot(parent, tri[(k + 1) % 3]);
        }
    }
    // Number pieces in order of their smallest edge, so the table is deterministic.
    std::array<int, 12> pieceOfRoot{};
    pieceOfRoot.fill(-1);
    for (int e = 0; e < 12; ++e) {
        if (!(used >> e & 1u)) continue;
        int& piece = pieceOfRoot[findRoot(parent, e)];
        if (piece < 0) {
            if (out.pieceCount == kMaxPieces) throw std::logic_error("continuation: more than four pieces");
            piece = out.pieceCount++;
        }
        out.pieceOfEdge[e] = static_cast<std::int8_t>(piece);
        out.pieces[piece].edgeMask = static_cast<std::uint16_t>(out.pieces[piece].edgeMask | 1u << e);
    }
    int next = 0;
    for (int p = 0; p < out.pieceCount; ++p) {
        Piece& piece = out.pieces[p];
        std::vector<Triangle> own;
        for (int t = 0; t < cased.count; ++t) {
            if (out.pieceOfEdge[cased.triangles[t][0]] == p) own.push_back(cased.triangles[t]);
        }
        piece.firstTriangle = static_cast<std::uint8_t>(next);
        piece.triangleCount = static_cast<std::uint8_t>(own.size());
        for (const Triangle& t : own) out.triangles[next++] = t;
        for (auto& exits : piece.exits) exits.fill(-1);
        std::array<int, 6> exitCount{};
        auto addExit = [&](int face, int edge) {
            piece.exits[face][exitCount[face]++] = static_cast<std::int8_t>(edge);
        };
        if (kind == TableKind::Consistent) {
            for (const auto& [a, b] : boundarySides(own)) {
                for (int f = 0; f < cube::kFaceCount; ++f) {
                    if (cube::edgeOnFace(a, f) && cube::edgeOnFace(b, f)) addExit(f, a);
                }
            }
        } else {
            for (int e = 0; e < cube::kEdgeCount; ++e) {
                if (!(piece.edgeMask >> e & 1u)) continue;
                for (int f = 0; f < cube::kFaceCount; ++f) {
                    if (cube::edgeOnFace(e, f)) addExit(f, e);
                }
            }
        }
    }
    return out;
}

std::array<CaseContinuation, 256> buildTable(TableKind kind) {
    std::array<CaseContinuation, 256> table{};
    const TriangleTable& triangles = triangleTable(kind);
    for (int c = 0; c < 256; ++c) table[c] = buildCase(triangles[static_cast<std::uint8_t>(c)], kind);
    return table;
}

}  // namespace

void prepareTables(TableKind kind) {
    if (kind == TableKind::Trilinear) {
        trilinearTable();
    } else if (kind == TableKind::Snap) {
        snapTable();
    } else {
        continuationTable(kind);
    }
}

const std::array<CaseContinuation, 256>& continuationTable(TableKind kind) {
    if (kind == TableKind::Trilinear) throw InputError(kTrilinearNoContinuationTable);
    static const auto consistent = buildTable(TableKind::Consistent);
    static const auto classic = buildTable(TableKind::Classic);
    return kind == TableKind::Classic ? classic : consistent;
}

}  // namespace isotrack
