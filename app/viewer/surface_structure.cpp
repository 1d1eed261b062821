#include "viewer/surface_structure.h"

#include <algorithm>

#include "isotrack/errors.h"
#include "viewer/extraction_worker.h"

namespace isotrack::viewer {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

SurfaceStructure::SurfaceStructure(render::SurfaceArena& arena, std::uint32_t id, Surface surface,
                                   SurfaceFootprint footprint, const glm::vec3& colour)
    : id_(id),
      mesh_(std::move(surface.mesh)),
      stats_(surface.stats),
      gpu_(arena, mesh_),
      footprint_(std::move(footprint)) {
    style_.colour = colour;
}

void SurfaceStructure::replaceSurface(Surface surface, SurfaceFootprint footprint) {
    tracker_.reset();
    mesh_ = std::move(surface.mesh);
    stats_ = surface.stats;
    beforeProcessing_.clear();
    upload();
    footprint_ = std::move(footprint);
    presence_ = Presence::Shown;
}

void SurfaceStructure::upload() {
    gpu_.clear();
    gpu_.arena().reserve(gpu_.slot(), mesh_.vertices.size(), mesh_.indices.size());
    gpu_.appendNew(mesh_);
}

bool SurfaceStructure::processMesh(const MeshProcessing& processing) {
    if (growing() || presence_ != Presence::Shown || mesh_.indices.empty()) return false;
    Surface surface{mesh_, stats_};
    processSurface(surface, processing);
    beforeProcessing_.push_back(Surface{std::move(mesh_), stats_});
    mesh_ = std::move(surface.mesh);
    stats_ = surface.stats;
    upload();
    return true;
}

bool SurfaceStructure::undoProcessing() {
    if (beforeProcessing_.empty() || growing()) return false;
    mesh_ = std::move(beforeProcessing_.back().mesh);
    stats_ = beforeProcessing_.back().stats;
    beforeProcessing_.pop_back();
    upload();
    return true;
}

void SurfaceStructure::setSeed(const FollowedSeed& seed, double iso) {
    seedPoint_ = seed.point;
    seed_ = seed.edge;
    iso_ = iso;
}

void SurfaceStructure::setAbsent(Presence presence, double iso, std::uint32_t into) {
    tracker_.reset();
    mesh_ = Mesh{};
    stats_ = SurfaceStats{};
    beforeProcessing_.clear();
    gpu_.clear();
    presence_ = presence;
    mergedInto_ = into;
    absentIso_ = iso;
}

void SurfaceStructure::startTracking(std::shared_ptr<const LoadedVolume> volume, double iso, TableKind table,
                                     const GridEdge& seed, const Vec3d& seedPoint, int threads) {
    volume_ = std::move(volume);
    threads_ = threads;
    iso_ = iso;
    table_ = table;
    seed_ = seed;
    seedPoint_ = seedPoint;
    presence_ = Presence::Shown;
    restartGrowth();
}

SurfaceStructure::SurfaceStructure(render::SurfaceArena& arena, std::uint32_t id,
                                   std::shared_ptr<const LoadedVolume> volume, double iso, TableKind table,
                                   const GridEdge& seed, const Vec3d& seedPoint, const glm::vec3& colour, int threads)
    : id_(id),
      gpu_(arena),
      seedPoint_(seedPoint),
      volume_(std::move(volume)),
      iso_(iso),
      table_(table),
      seed_(seed),
      threads_(threads) {
    style_.colour = colour;
    restartGrowth();
}

SurfaceStructure::~SurfaceStructure() = default;

void SurfaceStructure::restartGrowth() {
    if (!volume_ || presence_ != Presence::Shown) return;  // not a tracked surface, or nothing to grow
    std::unique_ptr<SurfaceTracker> tracker;
    try {  // may throw (the snap table's states may not fit): the surface stays as it was
        tracker = std::make_unique<SurfaceTracker>(volume_->volume, iso_, table_, threads_);
        tracker->start(seed_);
    } catch (const WorkingMemoryError& e) {  // core names no file: name the one open
        throw WorkingMemoryError(displayName(volume_->source) + ": " + e.what());
    }
    tracker_ = std::move(tracker);
    mesh_ = Mesh{};
    stats_ = SurfaceStats{};
    gpu_.clear();
}

const Mesh& SurfaceStructure::mesh() const { return tracker_ ? tracker_->mesh() : mesh_; }

GrowthStep SurfaceStructure::grow(const GrowthBudget& budget) {
    GrowthStep result;
    if (!tracker_) return result;
    const auto start = Clock::now();
    const SurfaceTracker::Step step = budget.cells > 0 ? tracker_->step(budget.cells) : tracker_->stepFor(budget.time);
    stats_ = tracker_->stats();
    const auto extracted = Clock::now();
    gpu_.append(tracker_->mesh(), step);
    result.cells = step.cellsVisited;
    result.extract = extracted - start;
    result.upload = Clock::now() - extracted;
    if (tracker_->done()) finishGrowth();
    return result;
}

void SurfaceStructure::finishGrowth() {
    Surface surface = tracker_->takeSurface();
    mesh_ = std::move(surface.mesh);
    stats_ = surface.stats;
    tracker_.reset();    // frees the tracker's visited sets and queues
    gpu_.shrinkToFit();  // and the GPU buffers' spare capacity
    footprint_ = footprintOf(mesh_);
}

bool SurfaceStructure::containsEdge(const GridEdge& edge) const {
    const Buffer<PackedGridEdge>& edges = mesh().vertexEdges;
    return std::any_of(edges.begin(), edges.end(), [&](const PackedGridEdge& e) { return GridEdge(e) == edge; });
}

void SurfaceStructure::setExplode(float factor, const glm::vec3& volumeCentre) {
    explodeOffset_ = factor * (centre() - volumeCentre);
    style_.offset = userOffset + explodeOffset_;
}

glm::vec3 SurfaceStructure::centre() const {
    return {static_cast<float>(0.5 * (stats_.boundsMin[0] + stats_.boundsMax[0])),
            static_cast<float>(0.5 * (stats_.boundsMin[1] + stats_.boundsMax[1])),
            static_cast<float>(0.5 * (stats_.boundsMin[2] + stats_.boundsMax[2]))};
}

std::size_t SurfaceStructure::cpuBytes() const { return mesh().byteSize(); }

void SurfaceStructure::draw(const render::Renderer& renderer, bool selected, bool colourByGrowth) const {
    render::SurfaceShading shading;
    shading.highlighted = selected;
    shading.colourByGrowth = colourByGrowth && tracked();
    renderer.drawSurface(gpu_, style_, shading);
}

void SurfaceStructure::drawWireframe(const render::Renderer& renderer) const {
    renderer.drawSurfaceWireframe(gpu_, style_);
}

void SurfaceStructure::drawPick(const render::Renderer& renderer) const {
    if (style_.visible) renderer.drawSurfaceId(gpu_, style_.offset, pickId());
}

void SurfaceStructure::buildUI(ui::PanelState& state) const {
    ui::SurfaceRow row;
    row.id = id_;
    row.colour = {style_.colour.r, style_.colour.g, style_.colour.b};
    row.visible = style_.visible;
    row.growing = growing();
    row.closed = stats_.closed;
    row.offset = {userOffset.x, userOffset.y, userOffset.z};
    row.triangles = mesh().triangleCount();
    row.vertices = mesh().vertices.size();
    row.cellsVisited = stats_.cellsVisited;
    row.cpuBytes = cpuBytes();
    row.gpuBytes = gpuBytes();
    row.area = stats_.area;
    row.euler = stats_.euler;
    row.borderLoops = stats_.borderLoops;
    row.genus = stats_.genus;
    row.persistence = stats_.persistence;
    row.hasArc = (stats_.arc.has_value() || ownIso.has_value()) && !tracked();
    if (ownIso) {
        row.ownIso = ownIso->shown;
        row.ownIsoWanted = ownIso->wanted;
    }
    row.tracked = tracked();
    if (presence_ == Presence::Gone) {
        row.presence = ui::SurfaceRow::Gone;
        row.absentIso = absentIso_;
    } else if (presence_ == Presence::Merged) {
        row.presence = ui::SurfaceRow::Merged;
        row.absentIso = absentIso_;
        row.mergedInto = mergedInto_;
    }
    state.surfaces.push_back(row);
}

}  // namespace isotrack::viewer
