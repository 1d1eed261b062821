// Tracking whole surfaces: the one through a seed (on one thread, or on several
// with walkTogether), and every surface, one at a time, from a scan of the cells.
// The walk is described in track_walker.cpp.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "extract/snap/snap_march.h"
#include "extract/tracking/track_walker.h"
#include "extract/trilinear/trilinear_march.h"
#include "isotrack/continuation.h"
#include "isotrack/tracking.h"

namespace isotrack {

using detail::checkSeed;
using detail::Clock;
using detail::finishedSurface;
using detail::makeWorker;
using detail::queueSeed;
using detail::TrackState;
using detail::TrackWorker;
using detail::walkTogether;

namespace {

// Walks the surface from the queued seed to the end.
Surface walkWhole(const TrackWorker& worker, TrackState& state, TableKind table, Clock::time_point start) {
    while (!state.walker.queue.empty())
        worker.advance(state.blocks, state.denseVisited, state.walker, std::numeric_limits<std::size_t>::max());
    Surface surface = finishedSurface(state.walker, table);
    surface.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return surface;
}

Surface track(const Volume& volume, double iso, const GridEdge& seed, TableKind table, int threads) {
    if (table == TableKind::Trilinear) return detail::trackTrilinear(volume, iso, seed, threads);
    if (table == TableKind::Snap) return detail::trackSnap(volume, iso, seed, threads);
    const auto start = Clock::now();
    // More threads than the volume's tiles can share out would only wait on one another.
    threads = std::min({threads, kMaxTrackThreads, detail::SparseBlocks::usefulThreads(volume.dims())});
    const auto worker = makeWorker(volume, iso, table);
    checkSeed(volume, iso, *worker, seed);
    if (threads > 1) return walkTogether(volume, *worker, seed, table, threads, start);
    TrackState state(volume.dims());
    queueSeed(volume, seed, *worker, state.blocks, state.walker);
    return walkWhole(*worker, state, table, start);
}

}  // namespace

Surface trackSurface(const Volume& volume, double iso, const GridEdge& seed, TableKind table, int threads) {
    Surface surface = track(volume, iso, seed, table, threads);
    volume.throwIfDamaged();  // a mapped file that shrank meanwhile read as zeros
    return surface;
}

std::vector<Surface> trackAllSurfaces(const Volume& volume, double iso, TableKind table) {
    std::vector<Surface> surfaces;
    const Dims& n = volume.dims();
    if (n[0] < 2 || n[1] < 2 || n[2] < 2) return surfaces;
    if (table == TableKind::Snap) return detail::allSnap(volume, iso, 1);
    const auto worker = makeWorker(volume, iso, table);
    const auto& continuation = continuationTable(table);
    std::vector<std::uint8_t> visited(volume.sampleCount(), 0);
    for (int z = 0; z + 1 < n[2]; ++z) {
        for (int y = 0; y + 1 < n[1]; ++y) {
            for (int x = 0; x + 1 < n[0]; ++x) {
                const std::uint8_t config = worker->config(x, y, z);
                if (config == 0 || config == 255) continue;
                const CaseContinuation& cased = continuation[config];
                const std::size_t cell = volume.index(x, y, z);
                for (int p = 0; p < cased.pieceCount; ++p) {
                    if (visited[cell] >> p & 1u) continue;
                    const auto start = Clock::now();
                    TrackState state(n);
                    state.denseVisited = visited.data();
                    int entryEdge = 0;
                    while (!(cased.pieces[p].edgeMask >> entryEdge & 1u)) ++entryEdge;
                    worker->enqueue(state.blocks, state.denseVisited, state.walker, x, y, z, entryEdge);
                    surfaces.push_back(walkWhole(*worker, state, table, start));
                }
            }
        }
    }
    // Discovery order is the order of each surface's first cell; break ties by first grid edge.
    std::vector<std::pair<std::uint64_t, std::size_t>> keys;
    for (std::size_t i = 0; i < surfaces.size(); ++i) keys.push_back({detail::firstEdgeOrder(surfaces[i].mesh, n), i});
    std::sort(keys.begin(), keys.end(), [&](const auto& a, const auto& b) {
        const std::size_t ta = surfaces[a.second].mesh.triangleCount(), tb = surfaces[b.second].mesh.triangleCount();
        return ta != tb ? ta > tb : a.first < b.first;
    });
    std::vector<Surface> sorted;
    sorted.reserve(surfaces.size());
    for (const auto& key : keys) sorted.push_back(std::move(surfaces[key.second]));
    surfaces = std::move(sorted);
    return surfaces;
}

}  // namespace isotrack
