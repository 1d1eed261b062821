#pragma once
// The labels of the exhaustive pass's connected surfaces, made as it writes
// them (marching_cubes.cpp).
//
// Labelled (for extractAllSurfaces), the exhaustive pass's writing pass also
// joins the vertices of each cell piece in a union-find over the chunk's own
// vertex range, while they are in cache (looking up only the vertices that
// earlier cells have not joined already, see PieceUnions), and tallies the piece
// and its triangles at one vertex; cells on the volume's border list their
// vertices on it (so that the split need not test every vertex). A seam is
// joined (stitchSeam) by the thread that writes the second of its two chunks,
// while other chunks are marched. The forest is handed on as it is:
// extractAllSurfaces walks each vertex to its root while it numbers the surfaces.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "extract/marching_cubes/labelled_march.h"
#include "isotrack/continuation.h"
#include "isotrack/mesh.h"
#include "isotrack/tables.h"

namespace isotrack::detail {

// A vertex id with this bit is a placeholder the marcher writes for a vertex on
// the next chunk's first slice: not in the forest until the seam is stitched.
constexpr std::uint32_t kSeamBit = 1u << 31;

// Union-find over vertex ids, roots being each set's smallest id (parents are
// never above their children).
inline std::uint32_t findRoot(std::uint32_t* parent, std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

inline std::uint32_t linkRoots(std::uint32_t* parent, std::uint32_t a, std::uint32_t b) {
    return a < b ? (parent[b] = a) : (parent[a] = b);
}

// Which vertices of a cell piece the labelled march looks up in the union-find.
// A cell's crossed edges on its low faces (-x, -y, -z) were met by the cells
// before it. Where such a face is crossed at exactly two edges, the cell across
// it holds both in one piece (every configuration does; tables_test checks it),
// so they are joined already and one of them stands for both. The three edges at
// the cell's high corner are met first by the cell itself: their vertices are
// new, each its own root, and are looked up (in one step). A piece so looks up
// one vertex per group of its low-face edges instead of every vertex.
struct PieceUnions {
    // [config][low faces with a marched cell across them: bit 0 -x, 1 -y, 2 -z][piece]
    std::array<std::array<std::array<std::uint16_t, kMaxPieces>, 8>, 256> lookups{};
};

const PieceUnions& pieceUnions(TableKind kind);

// Where the writing pass labels: the forest and the tallies (one entry per
// vertex of the mesh), and the lookups of the table it marches with. Without
// a forest (`parent` null) the pass does not label.
struct SurfaceLabels {
    const PieceUnions* unions = nullptr;
    std::uint32_t* parent = nullptr;
    std::uint8_t* tally = nullptr;

    // A new vertex: its own root, nothing tallied at it yet.
    void addVertex(std::uint32_t id) const {
        parent[id] = id;
        tally[id] = 0;
    }

    // Joins the vertices of each piece of the cell, a connected patch of surface,
    // and tallies the piece and its triangles at one of its vertices of this chunk
    // (every piece has one: no piece crosses only edges of the next chunk's slice).
    // Only one vertex per group of low-face edges already joined is looked up
    // (PieceUnions); `across` says which low faces have a cell of this chunk across.
    // Placeholders for the next chunk's slice are joined in stitchSeam, through their triangles.
    void unitePieces(unsigned config, const CaseContinuation& cased, const std::array<std::uint32_t, 12>& ids,
                     unsigned across) const {
        constexpr std::uint32_t kNoVertex = ~std::uint32_t(0);
        const std::array<std::uint16_t, kMaxPieces>& lookups = unions->lookups[config][across];
        for (int p = 0; p < cased.pieceCount; ++p) {
            std::uint32_t root = kNoVertex, counted = kNoVertex;
            for (unsigned mask = lookups[std::size_t(p)]; mask != 0; mask &= mask - 1) {
                const std::uint32_t id = ids[std::size_t(__builtin_ctz(mask))];
                if (id & kSeamBit) continue;
                const std::uint32_t r = findRoot(parent, id);
                if (root == kNoVertex) {
                    root = r;
                    counted = id;
                } else if (r != root) {
                    root = linkRoots(parent, root, r);
                }
            }
            tally[counted] = static_cast<std::uint8_t>(tally[counted] + kTalliedPiece + cased.pieces[p].triangleCount);
        }
    }
};

// Joins the surfaces across the seam between a chunk and the next one, once its
// placeholders (at `seamIndices` in the mesh's indices) are resolved: each triangle with a placeholder
// joins its three corners, once (seam indices come in order, a triangle's
// together). It reads and writes the forest of the two chunks and of the chunks
// below joined to them already, all written; the caller joins one seam at a time.
void stitchSeam(const std::vector<std::size_t>& seamIndices, const Mesh& mesh, std::uint32_t* parent);

}  // namespace isotrack::detail
