#pragma once
// Room extract/trilinear: extraction with the trilinear table
// (isotrack/trilinear.h, built in core/src/tables): the exhaustive pass
// (trilinear_march.cpp) and the walk from a seed and every surface
// (trilinear_track.cpp), on several threads with trilinear_together.cpp
// (trilinear_walker.h). Uses extract/common, extract/tracking's queue ring and
// mailboxes, support/ and the public headers.
//
// Exhaustive marching cubes with the trilinear table (isotrack/trilinear.h).
#include <cstddef>
#include <memory>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/surface.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

// Every cell, one mesh: one vertex per crossed grid edge, plus a vertex inside
// each cell whose subcase needs one (its vertexEdges entry has axis
// kCellInterior and the cell's first sample).
Mesh marchTrilinear(const Volume& volume, double iso, int threads);

// The surface through a seed by piecewise continuation over the trilinear
// subcases, walked breadth-first a budget of pieces at a time (trackTrilinear
// and SurfaceTracker's walk with the trilinear table).
class TrilinearWalk {
public:
    virtual ~TrilinearWalk() = default;
    // Emits up to `pieceBudget` more (cell, piece) pairs; returns how many it emitted.
    virtual std::size_t advance(std::size_t pieceBudget) = 0;
    virtual bool done() const = 0;
    virtual Mesh& mesh() = 0;
    virtual const Mesh& mesh() const = 0;
    virtual std::size_t piecesVisited() const = 0;
    // Bytes of the walk's sparse blocks and queue, mesh excluded.
    virtual std::size_t workingBytes() const = 0;
};

// The walk from `seed`, nothing walked yet; InputError when the seed is outside or not crossed.
std::unique_ptr<TrilinearWalk> startTrilinear(const Volume& volume, double iso, const GridEdge& seed);

// The walk's surface (its mesh taken) with measureSurface's figures and its
// pieces visited (the closing check on `threads` threads).
Surface finishedTrilinear(TrilinearWalk& walk, const Volume& volume, int threads = 1);

// The surface through `seed` by piecewise continuation over the trilinear
// subcases, on up to `threads` threads (no more than the consistent table's
// track uses); InputError when the seed is outside or not crossed. The same
// triangles and vertices on every thread count, in an order that varies with
// more than one.
Surface trackTrilinear(const Volume& volume, double iso, const GridEdge& seed, int threads = 1);

// Every connected surface of marchTrilinear's mesh, most triangles first.
std::vector<Surface> allTrilinear(const Volume& volume, double iso, int threads);

}  // namespace isotrack::detail
