// SurfaceTracker: one surface grown a budget at a time, breadth-first from its
// seed, for a viewer to show it growing. With the trilinear table the walk is
// trilinear_track.cpp's, a budget of (cell, piece) pairs at a time, and the
// figures of the surface so far are measured as the steps add to it. With the
// snap table the walk is snap_march.cpp's, behind the same interface.
#include <algorithm>
#include <limits>
#include <memory>

#include "extract/snap/snap_march.h"
#include "extract/tracking/track_walker.h"
#include "extract/trilinear/trilinear_march.h"
#include "isotrack/tracking.h"

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

namespace {

bool usesOwnWalk(TableKind table) { return table == TableKind::Trilinear || table == TableKind::Snap; }

}  // namespace

struct SurfaceTracker::Impl {
    const Volume* volume;
    double iso;
    TableKind table;
    int threads;                          // for the snap states and the closing check; the walk is on one
    std::unique_ptr<TrackWorker> worker;  // null with the trilinear and snap tables
    TrackState state;
    std::unique_ptr<detail::TrilinearWalk> trilinear;  // once started, with the trilinear or snap table
    // The trilinear walk's figures so far: its vertices and triangles before these are measured.
    detail::SurfaceMeasure measure;
    std::size_t measuredVertices = 0, measuredIndices = 0;

    const Mesh& mesh() const { return trilinear ? trilinear->mesh() : state.walker.mesh; }
    void measureNew();
};

void SurfaceTracker::Impl::measureNew() {
    const Mesh& m = trilinear->mesh();
    for (; measuredVertices < m.vertices.size(); ++measuredVertices)
        measure.addVertex(m.vertices[measuredVertices], m.vertexEdges[measuredVertices], volume->dims());
    for (; measuredIndices < m.indices.size(); measuredIndices += 3) {
        const std::uint32_t* t = m.indices.data() + measuredIndices;
        measure.triangles.add(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
    }
}

SurfaceTracker::SurfaceTracker(const Volume& volume, double iso, TableKind table, int threads)
    : impl_(std::make_unique<Impl>(
          Impl{&volume, iso, table, std::max(threads, 1), usesOwnWalk(table) ? nullptr : makeWorker(volume, iso, table),
               TrackState(volume.dims(), WalkOrder::BreadthFirst), nullptr, detail::SurfaceMeasure{}, 0, 0})) {}
SurfaceTracker::~SurfaceTracker() = default;
SurfaceTracker::SurfaceTracker(SurfaceTracker&&) noexcept = default;
SurfaceTracker& SurfaceTracker::operator=(SurfaceTracker&&) noexcept = default;

void SurfaceTracker::start(const GridEdge& seed) {
    if (usesOwnWalk(impl_->table)) {
        impl_->trilinear = impl_->table == TableKind::Snap
                               ? detail::startSnap(*impl_->volume, impl_->iso, seed, impl_->threads)
                               : detail::startTrilinear(*impl_->volume, impl_->iso, seed);
        impl_->measure = detail::SurfaceMeasure{};
        impl_->measuredVertices = impl_->measuredIndices = 0;
        return;
    }
    checkSeed(*impl_->volume, impl_->iso, *impl_->worker, seed);
    impl_->state = TrackState(impl_->volume->dims(), WalkOrder::BreadthFirst);
    queueSeed(*impl_->volume, seed, *impl_->worker, impl_->state.blocks, impl_->state.walker);
}

SurfaceTracker::Step SurfaceTracker::step(std::size_t cellBudget) {
    TrackState& s = impl_->state;
    const Mesh& mesh = impl_->mesh();
    Step step{mesh.vertices.size(), 0, mesh.indices.size(), 0, 0};
    if (impl_->trilinear)
        step.cellsVisited = impl_->trilinear->advance(cellBudget);
    else if (impl_->worker)
        step.cellsVisited = impl_->worker->advance(s.blocks, s.denseVisited, s.walker, cellBudget);
    step.vertexCount = mesh.vertices.size() - step.firstVertex;
    step.indexCount = mesh.indices.size() - step.firstIndex;
    return step;
}

SurfaceTracker::Step SurfaceTracker::stepFor(std::chrono::nanoseconds budget) {
    const auto deadline = Clock::now() + budget;
    const Mesh& mesh = impl_->mesh();
    Step total{mesh.vertices.size(), 0, mesh.indices.size(), 0, 0};
    do {
        total.cellsVisited += step(512).cellsVisited;
    } while (!done() && Clock::now() < deadline);
    total.vertexCount = mesh.vertices.size() - total.firstVertex;
    total.indexCount = mesh.indices.size() - total.firstIndex;
    return total;
}

bool SurfaceTracker::done() const {
    return impl_->trilinear ? impl_->trilinear->done() : impl_->state.walker.queue.empty();
}
const Mesh& SurfaceTracker::mesh() const { return impl_->mesh(); }
std::size_t SurfaceTracker::cellsVisited() const {
    return impl_->trilinear ? impl_->trilinear->piecesVisited() : impl_->state.walker.cellsVisited;
}
std::size_t SurfaceTracker::workingBytes() const {
    if (impl_->trilinear) return impl_->trilinear->workingBytes();
    return impl_->state.blocks.byteSize() + impl_->state.walker.queue.byteSize();
}
SurfaceStats SurfaceTracker::stats() const {
    if (impl_->trilinear) {
        impl_->measureNew();
        SurfaceStats stats = detail::measuredStats(impl_->trilinear->mesh(), impl_->measure);
        stats.cellsVisited = impl_->trilinear->piecesVisited();
        return stats;
    }
    const Walker& walker = impl_->state.walker;
    SurfaceStats stats = detail::measuredStats(walker.mesh, walker.measure);
    stats.cellsVisited = walker.cellsVisited;
    return stats;
}
Surface SurfaceTracker::takeSurface() {
    if (impl_->trilinear && impl_->table == TableKind::Snap)
        return detail::finishedSnap(*impl_->trilinear, *impl_->volume, impl_->threads);
    if (impl_->trilinear) return detail::finishedTrilinear(*impl_->trilinear, *impl_->volume, impl_->threads);
    return finishedSurface(impl_->state.walker, impl_->table);
}

}  // namespace isotrack
