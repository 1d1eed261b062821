#pragma once
// Room extract/tracking: piecewise continuation, one surface walked from a
// seed edge through the cells it crosses (isotrack/tracking.h). track_walker.*
// walks, piece_queue.h orders the pieces still to walk, track_together.cpp and
// walk_exchange.h walk one surface on several threads, track_surface.cpp tracks
// the surface through a seed and every surface by a scan, surface_tracker.cpp
// grows one a budget at a time, seeds.cpp finds seed edges. Uses
// extract/common, extract/measure (figures measured on the way),
// extract/trilinear (the walk with the trilinear table), support/ and the
// public headers.
//
// What the tracking units share: a walker (one thread's share of a walk), the
// worker that walks for a volume's sample type, and the steps around a walk
// (checking and queueing a seed, finishing the surface). The walk itself is in
// track_walker.cpp.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "extract/common/sparse_blocks.h"
#include "extract/measure/surface_measure.h"
#include "extract/tracking/piece_queue.h"
#include "isotrack/mesh.h"
#include "isotrack/tables.h"
#include "isotrack/tracking.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

using Clock = std::chrono::steady_clock;

class Exchange;

// One thread's share of a walk: its queue, and the vertices and triangles it
// emits with their measure. A vertex id is the vertex's index in the walker's
// mesh, with the walker's thread in the id's top bits when several walk. Each
// walker has cache lines of its own: its queue and measure change every cell.
struct alignas(128) Walker {
    Mesh mesh;
    detail::SurfaceMeasure measure;
    PieceQueue queue;
    std::size_t cellsVisited = 0;
    int thread = 0;                               // the tiles it walks, and its arena in the sparse blocks
    std::uint32_t idBase = 0;                     // thread << the width of an index
    std::uint32_t indexMask = ~std::uint32_t(0);  // the index bits of an id
    int tileMask = SparseBlocks::kRegionMask;     // a tile's side less one: coordinates on tile seams have 0 here
    std::vector<std::size_t> unmeasured;          // triangles (first index) with another thread's corners
};

// A surface walked by one thread, whatever the sample type.
struct TrackState {
    explicit TrackState(const Dims& dims, WalkOrder order = WalkOrder::ByBlock)
        : blocks(dims, 1, SparseBlocks::VertexSlots::Lazy) {
        walker.queue = PieceQueue(order);
    }
    SparseBlocks blocks;
    std::uint8_t* denseVisited = nullptr;  // one bit per piece per cell, for trackAllSurfaces
    Walker walker;
};

// The walk for the volume's sample type (TypedTrackWorker, in track_walker.cpp).
class TrackWorker {
public:
    virtual ~TrackWorker() = default;
    // Queues on `walker` the piece of cell (x, y, z) holding cube edge `edge`, unless it was queued before.
    virtual void enqueue(SparseBlocks& blocks, std::uint8_t* denseVisited, Walker& walker, int x, int y, int z,
                         int edge) const = 0;
    // Walks on one thread for up to `cellBudget` cell pieces; returns how many it walked.
    virtual std::size_t advance(SparseBlocks& blocks, std::uint8_t* denseVisited, Walker& walker,
                                std::size_t cellBudget) const = 0;
    // Walks the walker's tiles as one of several threads sharing `blocks`, until no piece is left.
    virtual void walkShared(SparseBlocks& blocks, Walker& walker, Exchange& exchange) const = 0;
    virtual std::uint8_t config(int x, int y, int z) const = 0;
    virtual bool crossed(const GridEdge& edge) const = 0;
};

std::unique_ptr<TrackWorker> makeWorker(const Volume& volume, double iso, TableKind table);

// Whether the grid edge lies inside the volume, both its ends samples.
bool edgeInside(const Volume& volume, const GridEdge& e);

// Queues the cells around a seed edge, each entered through that edge.
void queueSeed(const Volume& volume, const GridEdge& seed, const TrackWorker& worker, SparseBlocks& blocks,
               Walker& walker);

// Throws InputError when the seed edge is outside the volume or not crossed at `iso`.
void checkSeed(const Volume& volume, double iso, const TrackWorker& worker, const GridEdge& seed);

// The finished surface, its mesh taken from the walk's state.
Surface finishedSurface(Walker& walker, TableKind table);

// Walks the surface from `seed` on `threads` threads, each walking its own
// tiles, then gathers their parts into one mesh (track_together.cpp).
Surface walkTogether(const Volume& volume, const TrackWorker& worker, const GridEdge& seed, TableKind table,
                     int threads, Clock::time_point start);

// For error messages: an isovalue as %g (io_common.h has its own numberText, exact), and a grid edge.
std::string isoText(double v);
std::string edgeText(const GridEdge& e);

}  // namespace isotrack::detail
