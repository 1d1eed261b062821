#pragma once
// The continuation table: for each of the 256 configurations, the separate pieces
// of surface a cube holds and through which faces each piece continues.
//
// Generated from a triangle table (never written by hand): triangles that share a
// cube edge belong to the same piece; a piece continues through a face when it
// has an edge on that face. For each face it records one edge per segment that
// the piece draws on the face, because with the consistent table the cube across
// the face draws the same segment in one of its pieces and is entered through
// that edge. The classic table's neighbours may cut a shared face differently, so
// there every edge of the piece on the face is an entry edge.
#include <array>
#include <cstdint>

#include "isotrack/tables.h"

namespace isotrack {

constexpr int kMaxPieces = 4;

struct Piece {
    std::uint16_t edgeMask = 0;  // bit e: the piece crosses cube edge e
    std::uint8_t triangleCount = 0;
    std::uint8_t firstTriangle = 0;  // into the table's triangles for the configuration
    // Per face, the entry edges into the cube across it; -1 when unused.
    std::array<std::array<std::int8_t, 4>, 6> exits{};
};

struct CaseContinuation {
    std::uint8_t pieceCount = 0;
    std::array<Piece, kMaxPieces> pieces{};
    std::array<std::int8_t, 12> pieceOfEdge{};  // -1 for edges the surface does not cross
    // The configuration's triangles, grouped by piece.
    std::array<std::array<std::int8_t, 3>, kMaxCaseTriangles> triangles{};
};

// Throws InputError (kTrilinearNoContinuationTable) for TableKind::Trilinear:
// its subcases' pieces are found per cell as it is tracked (trackSurface,
// SurfaceTracker, extractAllSurfaces: trilinear_track.cpp), not looked up, so
// the walks built on this table refuse it. TableKind::Snap gives the consistent
// table: the snap table's walks follow it over the 2-state configurations.
const std::array<CaseContinuation, 256>& continuationTable(TableKind kind);

// Generates the tables extractions with `kind` use (the continuation table, or
// the trilinear subcases), so that timing them leaves the generation out.
void prepareTables(TableKind kind);

constexpr const char* kTrilinearNoContinuationTable =
    "the trilinear table has no continuation table: its pieces are found cell by cell (trackSurface, "
    "SurfaceTracker, extractAllSurfaces); use the consistent or classic table here";

}  // namespace isotrack
