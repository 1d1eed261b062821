#pragma once
// What the trilinear walk's units share: one thread's share of a walk, and the
// walk for a volume's sample type (trilinear_track.cpp), which
// trilinear_together.cpp runs on several threads. The tiles, the mailboxes
// and the ring are the consistent tracker's (extract/common/sparse_blocks.h,
// extract/tracking/walk_exchange.h and piece_queue.h).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "extract/common/sparse_blocks.h"
#include "extract/tracking/piece_queue.h"
#include "extract/tracking/walk_exchange.h"
#include "isotrack/mesh.h"
#include "isotrack/volume.h"

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

// InputError when the seed edge is outside the volume or not crossed at `iso`.
void checkTrilinearSeed(const Volume& volume, double iso, const GridEdge& seed);

std::unique_ptr<TrilinearWalker> makeTrilinearWalker(const Volume& volume, double iso);

// The surface from `seed` walked on `threads` (> 1) threads, each walking its
// own tiles, its parts joined into one mesh (trilinear_together.cpp);
// `piecesByThread` gets the pieces each thread emitted.
Mesh walkTrilinearTogether(const Volume& volume, const TrilinearWalker& walker, const GridEdge& seed, int threads,
                           std::vector<std::size_t>& piecesByThread);

}  // namespace isotrack::detail
