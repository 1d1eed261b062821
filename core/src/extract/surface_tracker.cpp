// SurfaceTracker: one surface grown a budget at a time, breadth-first from its
// seed, for a viewer to show it growing.
#include <limits>
#include <memory>

#include "isotrack/tracking.h"
#include "track_walker.h"

namespace isotrack {

using detail::checkSeed;
using detail::Clock;
using detail::finishedSurface;
using detail::makeWorker;
using detail::queueSeed;
using detail::TrackState;
using detail::TrackWorker;
using detail::Walker;
using detail::WalkOrder;

struct SurfaceTracker::Impl {
    const Volume* volume;
    double iso;
    TableKind table;
    std::unique_ptr<TrackWorker> worker;
    TrackState state;
};

SurfaceTracker::SurfaceTracker(const Volume& volume, double iso, TableKind table)
    : impl_(std::make_unique<Impl>(Impl{&volume, iso, table, makeWorker(volume, iso, table),
                                        TrackState(volume.dims(), WalkOrder::BreadthFirst)})) {}
SurfaceTracker::~SurfaceTracker() = default;
SurfaceTracker::SurfaceTracker(SurfaceTracker&&) noexcept = default;
SurfaceTracker& SurfaceTracker::operator=(SurfaceTracker&&) noexcept = default;

void SurfaceTracker::start(const GridEdge& seed) {
    checkSeed(*impl_->volume, impl_->iso, *impl_->worker, seed);
    impl_->state = TrackState(impl_->volume->dims(), WalkOrder::BreadthFirst);
    queueSeed(*impl_->volume, seed, *impl_->worker, impl_->state.blocks, impl_->state.walker);
}

SurfaceTracker::Step SurfaceTracker::step(std::size_t cellBudget) {
    TrackState& s = impl_->state;
    const Mesh& mesh = s.walker.mesh;
    Step step{mesh.vertices.size(), 0, mesh.indices.size(), 0, 0};
    step.cellsVisited = impl_->worker->advance(s.blocks, s.denseVisited, s.walker, cellBudget);
    step.vertexCount = mesh.vertices.size() - step.firstVertex;
    step.indexCount = mesh.indices.size() - step.firstIndex;
    return step;
}

SurfaceTracker::Step SurfaceTracker::stepFor(std::chrono::nanoseconds budget) {
    const auto deadline = Clock::now() + budget;
    const Mesh& mesh = impl_->state.walker.mesh;
    Step total{mesh.vertices.size(), 0, mesh.indices.size(), 0, 0};
    do {
        total.cellsVisited += step(512).cellsVisited;
    } while (!done() && Clock::now() < deadline);
    total.vertexCount = mesh.vertices.size() - total.firstVertex;
    total.indexCount = mesh.indices.size() - total.firstIndex;
    return total;
}

bool SurfaceTracker::done() const { return impl_->state.walker.queue.empty(); }
const Mesh& SurfaceTracker::mesh() const { return impl_->state.walker.mesh; }
std::size_t SurfaceTracker::cellsVisited() const { return impl_->state.walker.cellsVisited; }
std::size_t SurfaceTracker::workingBytes() const {
    return impl_->state.blocks.byteSize() + impl_->state.walker.queue.byteSize();
}
SurfaceStats SurfaceTracker::stats() const {
    const Walker& walker = impl_->state.walker;
    SurfaceStats stats = detail::measuredStats(walker.mesh, walker.measure);
    stats.cellsVisited = walker.cellsVisited;
    return stats;
}
Surface SurfaceTracker::takeSurface() { return finishedSurface(impl_->state.walker, impl_->table); }

}  // namespace isotrack
