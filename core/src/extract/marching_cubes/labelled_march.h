#pragma once
// The exhaustive pass with its connected surfaces labelled on the way, for
// extractAllSurfaces to split in parallel.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "isotrack/extract.h"
#include "isotrack/mesh.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

// A chunk of slabs marched by one thread: its vertices and triangles are
// contiguous in the mesh. Its triangles may use vertices of the next chunk (on
// the slice between them), never of others.
struct MarchedChunk {
    std::size_t vertexBegin = 0, vertexEnd = 0;
    std::size_t triangleBegin = 0, triangleEnd = 0;
    std::vector<std::uint32_t> borderVertices;  // its vertices on the volume's border (edgeOnVolumeBorder)
};

// A vertex's tally: kTalliedPiece per cell piece counted at it, plus the pieces'
// triangles (a vertex is in at most 4 cell pieces, each of at most 5 triangles).
constexpr unsigned kTalliedPiece = 32, kTalliedTriangles = kTalliedPiece - 1;

struct LabelledMesh {
    Mesh mesh;
    std::vector<MarchedChunk> chunks;
    // Per vertex, its parent in a union-find forest of the connected surfaces: a
    // surface's root is its smallest vertex id, its own parent; parents are never
    // above their children, so a vertex's root is the end of a descending walk.
    Buffer<std::uint32_t> parent;
    Buffer<std::uint8_t> tally;  // per vertex, the cell pieces and triangles counted at it (kTalliedPiece)
};

// Its slabs are added to `progress` when given (ExtractProgress).
LabelledMesh marchLabelled(const Volume& volume, double iso, TableKind table, int threads,
                           ExtractProgress* progress = nullptr);

}  // namespace isotrack::detail
