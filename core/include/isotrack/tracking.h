#pragma once
// Piecewise continuation: extracting one connected isosurface from a seed edge,
// touching only the cells it passes through, or every surface separately.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/surface.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack {

// A seed is a grid edge crossed by the surface.
bool edgeIsCrossed(const Volume& volume, double iso, const GridEdge& edge);

// The crossed grid edge whose midpoint is nearest to a world-space point,
// searching outward from the point's voxel. Throws InputError when the volume has
// no crossed edge at `iso`.
GridEdge nearestCrossedEdge(const Volume& volume, double iso, const Vec3d& worldPoint);

// The grid edge behind a picked vertex, or behind the vertex of a picked triangle
// nearest to a world-space point on it.
GridEdge edgeOfVertex(const Mesh& mesh, std::uint32_t vertex);
GridEdge edgeOfTriangle(const Mesh& mesh, std::size_t triangle, const Vec3d& worldPoint);

// One connected surface, the one through `seed`, measured as it is walked (the
// figures equal measureSurface's). Throws InputError when the seed edge is
// outside the volume or not crossed at `iso`.
//
// On one thread the vertices and triangles come in the order the walk reaches
// them: block by block (8x8x8 cells) from the seed, each block's pieces together
// while its data is in cache. With `threads` > 1 (up to 64) the threads
// walk the surface together: the same triangles and vertices, but in an order
// that varies from run to run (and area and volume may differ in their last bits).
Surface trackSurface(const Volume& volume, double iso, const GridEdge& seed, TableKind table = TableKind::Consistent,
                     int threads = 1);
// trackSurface's most threads (more would only add seams; the vertex ids of each
// keep 2^26 vertices).
constexpr int kMaxTrackThreads = 64;

// Every surface, sorted by triangle count, largest first (ties: the surface with
// the first grid edge in memory order first). Together they hold exactly the
// triangles of marchingCubes with the same table.
//
// trackAllSurfaces scans the cells and tracks each piece not yet visited, one
// surface at a time. extractAllSurfaces gives the same surfaces from the
// exhaustive pass (on `threads` threads) and its connected components, faster;
// its per-surface `seconds` are 0 since the surfaces are not timed one by one.
std::vector<Surface> trackAllSurfaces(const Volume& volume, double iso, TableKind table = TableKind::Consistent);
std::vector<Surface> extractAllSurfaces(const Volume& volume, double iso, TableKind table = TableKind::Consistent,
                                        int threads = 1);

// Grows one surface a budget at a time, breadth-first from the seed, so that a
// viewer can append each step's vertices and indices to GPU buffers. The walk
// is on the caller's thread; `threads` share what is done over the whole volume
// or the whole surface at once: the snap table's sample states when a walk
// starts, and the closing check of takeSurface (trilinear and snap tables).
// The surface is the same on any number.
class SurfaceTracker {
public:
    SurfaceTracker(const Volume& volume, double iso, TableKind table = TableKind::Consistent, int threads = 1);
    ~SurfaceTracker();
    SurfaceTracker(SurfaceTracker&&) noexcept;
    SurfaceTracker& operator=(SurfaceTracker&&) noexcept;

    void start(const GridEdge& seed);

    struct Step {
        std::size_t firstVertex = 0, vertexCount = 0;  // appended to mesh().vertices
        std::size_t firstIndex = 0, indexCount = 0;    // appended to mesh().indices
        std::size_t cellsVisited = 0;
    };
    Step step(std::size_t cellBudget);
    Step stepFor(std::chrono::nanoseconds budget);
    bool done() const;

    const Mesh& mesh() const;
    std::size_t cellsVisited() const;
    // Bytes of the tracker's own bookkeeping (sparse blocks and queue), mesh excluded.
    std::size_t workingBytes() const;
    // The figures of the surface grown so far (touchesBorder once it has reached
    // the volume's border); whether it is closed is known once it is done.
    SurfaceStats stats() const;
    // Once done: the surface and all its figures, as trackSurface gives them.
    Surface takeSurface();

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace isotrack
