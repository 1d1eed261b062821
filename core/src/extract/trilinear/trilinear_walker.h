#pragma once
// What the trilinear walk's units share: one thread's share of a walk, and the
// walk for a volume's sample type (trilinear_track.cpp), which
// trilinear_together.cpp runs on several threads. The tiles, the mailboxes
// and the ring are the consistent tracker's (extract/common/sparse_blocks.h,
// extract/tracking/walk_exchange.h and piece_queue.h).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "extract/common/sparse_blocks.h"
#include "extract/tracking/piece_queue.h"
#include "extract/tracking/walk_exchange.h"
#include "isotrack/mesh.h"
#include "isotrack/volume.h"
#include "support/parallel.h"

namespace isotrack::detail {

// A cell to walk, entered through cube edge `edge`; it may have been walked
// already (the walk checks when it takes it).
struct TrilinearEntry {
    SparseBlocks::Block* block;
    std::uint16_t cell;  // local index in the block
    std::uint8_t edge;
};

// One thread's share of a walk: its queue, breadth-first, and the vertices and
// triangles it emits. A vertex id is the vertex's index in the part's mesh,
// with the part's thread in the id's top bits when several walk. Each part has
// cache lines of its own: its queue and mesh change every cell.
struct alignas(128) TrilinearPart {
    Mesh mesh;
    Ring<TrilinearEntry> queue;
    std::size_t piecesVisited = 0;
    int thread = 0;                               // the tiles it walks, and its arena in the sparse blocks
    std::uint32_t idBase = 0;                     // thread << the width of an index
    std::uint32_t indexMask = ~std::uint32_t(0);  // the index bits of an id
    bool shared = false;                          // several threads walk: vertices on tile seams are claimed
    int tileMask = 0;                             // a tile's side less one, when shared
};

// The walk for the volume's sample type.
class TrilinearWalker {
public:
    virtual ~TrilinearWalker() = default;
    // Queues a cell holding the seed edge, entered through it.
    virtual void queueSeed(SparseBlocks& blocks, TrilinearPart& part, const GridEdge& seed) const = 0;
    // Walks the part's queue on one thread until `pieceBudget` pieces are
    // emitted or the queue is empty; returns how many it emitted.
    virtual std::size_t advance(SparseBlocks& blocks, TrilinearPart& part, std::size_t pieceBudget) const = 0;
    // Walks the part's tiles as one of several threads sharing `blocks`, until no piece is left.
    virtual void walkShared(SparseBlocks& blocks, TrilinearPart& part, Exchange& exchange) const = 0;
};

// The parts' meshes in one, in thread order, vertex ids made indices; in
// parallel. A part is a TrilinearPart or the like: a mesh whose vertex ids
// hold the part's number above `idShift`, and the index bits' mask.
template <class Part>
Mesh joinWalkParts(const std::vector<Part>& parts, int idShift, int threads) {
    std::vector<std::size_t> firstVertex(parts.size() + 1, 0), firstIndex(parts.size() + 1, 0);
    for (std::size_t t = 0; t < parts.size(); ++t) {
        firstVertex[t + 1] = firstVertex[t] + parts[t].mesh.vertices.size();
        firstIndex[t + 1] = firstIndex[t] + parts[t].mesh.indices.size();
    }
    Mesh mesh;
    mesh.vertices.resize(firstVertex.back());
    mesh.vertexEdges.resize(firstVertex.back());
    mesh.indices.resize(firstIndex.back());
    const std::uint32_t indexMask = parts[0].indexMask;
    // Each part in `threads` slices, so that every thread has a share of the copying.
    const int slices = threads;
    parallelFor(int(parts.size()) * slices, threads, [&](int task) {
        const std::size_t t = std::size_t(task / slices), slice = std::size_t(task % slices);
        const Mesh& part = parts[t].mesh;
        const std::size_t vertexCount = part.vertices.size(), indexCount = part.indices.size();
        const std::size_t vBegin = vertexCount * slice / std::size_t(slices),
                          vEnd = vertexCount * (slice + 1) / std::size_t(slices);
        // Whole triangles to a slice.
        const std::size_t iBegin = indexCount / 3 * slice / std::size_t(slices) * 3,
                          iEnd = indexCount / 3 * (slice + 1) / std::size_t(slices) * 3;
        std::copy(part.vertices.begin() + std::ptrdiff_t(vBegin), part.vertices.begin() + std::ptrdiff_t(vEnd),
                  mesh.vertices.begin() + std::ptrdiff_t(firstVertex[t] + vBegin));
        std::copy(part.vertexEdges.begin() + std::ptrdiff_t(vBegin), part.vertexEdges.begin() + std::ptrdiff_t(vEnd),
                  mesh.vertexEdges.begin() + std::ptrdiff_t(firstVertex[t] + vBegin));
        for (std::size_t i = iBegin; i < iEnd; ++i) {
            const std::uint32_t id = part.indices[i];
            mesh.indices[firstIndex[t] + i] = static_cast<std::uint32_t>(firstVertex[id >> idShift] + (id & indexMask));
        }
    });
    return mesh;
}

// InputError when the seed edge is outside the volume or not crossed at `iso`.
void checkTrilinearSeed(const Volume& volume, double iso, const GridEdge& seed);

std::unique_ptr<TrilinearWalker> makeTrilinearWalker(const Volume& volume, double iso);

// The surface from `seed` walked on `threads` (> 1) threads, each walking its
// own tiles, its parts joined into one mesh (trilinear_together.cpp);
// `piecesByThread` gets the pieces each thread emitted.
Mesh walkTrilinearTogether(const Volume& volume, const TrilinearWalker& walker, const GridEdge& seed, int threads,
                           std::vector<std::size_t>& piecesByThread);

}  // namespace isotrack::detail
