// The viewer's scene work: requests to the extraction worker and their results,
// growing tracked surfaces within the frame's budget, and clicks (pick, track).
#include <algorithm>

#include "isotrack/errors.h"
#include "render/palette.h"
#include "viewer/script_run.h"
#include "viewer/viewer.h"

namespace isotrack::viewer {
namespace {

constexpr std::size_t kPicksKept = 16;

const char* requestName(ui::Method method) {
    switch (method) {
        case ui::Method::Exhaustive: return "marching cubes";
        case ui::Method::Track: return "re-track seeds";
        case ui::Method::All: return "every surface";
    }
    return "extract";
}

}  // namespace

double Viewer::currentIso() const {
    if (iso_) return *iso_;
    return scene_.volume() ? scene_.volume()->defaultIso : 0.0;
}

std::vector<Vec3d> Viewer::trackedSeeds() const {
    std::vector<Vec3d> seeds;
    for (const auto& surface : scene_.surfaces()) {
        if (surface->seedPoint()) seeds.push_back(*surface->seedPoint());
    }
    return seeds;
}

void Viewer::submit() {
    ExtractionRequest request;
    request.generation = ++generation_;
    request.source = source_;
    request.iso = iso_;
    request.table = table_;
    request.method = method_;
    if (method_ == ui::Method::Track) request.seeds = trackedSeeds();
    worker_.submit(std::move(request));
    if (script_) script_->jobCommand = script_->current;
}

void Viewer::cancelExtraction() { worker_.cancel(++generation_); }

void Viewer::takeResult() {
    std::optional<ExtractionResult> result = worker_.poll();
    if (!result || result->generation != generation_) return;
    Profiler::Scope scope(profiler_, Stage::Upload);
    applyResult(std::move(*result));
}

void Viewer::applyResult(ExtractionResult result) {
    profiler_.addWorkerSpan(requestName(result.method), result.started, result.finished);
    if (!result.error.empty()) {
        extractionError_ = result.error;
        if (script_) {
            const ScriptCommand* command = script_->jobCommand ? script_->jobCommand : script_->current;
            throw command ? script_->script.error(*command, result.error) : ScriptError(result.error);
        }
        status(result.error);
        return;
    }
    extractionError_.clear();
    const bool newVolume = scene_.setVolume(result.volume);
    if (newVolume) {  // a new box, and the default view of it
        renderer_->setBounds(scene_.volumeBounds());
        const render::FrameOptions options = frameOptions();
        camera_ = render::frameBounds(scene_.volumeBounds(), float(options.width) / float(options.height));
    }
    iso_ = result.iso;
    table_ = result.table;
    method_ = result.method;
    lastExtractMs_ = result.extractMs;
    scene_.clearSurfaces();
    for (std::size_t i = 0; i < result.surfaces.size(); ++i) {
        const glm::vec3 colour = render::surfaceColour(result.method == ui::Method::Exhaustive ? 0 : i);
        scene_.add(
            std::make_unique<SurfaceStructure>(scene_.newId(), std::move(result.surfaces[i]), colour, result.seeds[i]));
    }
}

void Viewer::grow() {
    if (!playing_ && !stepOnce_) return;
    std::size_t growing = 0;
    for (const auto& surface : scene_.surfaces()) growing += surface->growing() ? 1 : 0;
    if (growing == 0) return;
    GrowthBudget budget;
    if (cellsPerFrame_ > 0) {
        budget.cells = std::max<std::size_t>(std::size_t(cellsPerFrame_) / growing, 1);
    } else {
        const double ms = double(growthBudgetMs_) / double(growing);
        budget.time = std::chrono::nanoseconds(static_cast<std::int64_t>(ms * 1e6));
    }
    for (auto& surface : scene_.surfaces()) {
        if (!surface->growing()) continue;
        const auto start = Profiler::Clock::now();
        const GrowthStep step = surface->grow(budget);
        profiler_.add(Stage::Extract, start, step.extract);
        profiler_.add(Stage::Upload, start + step.extract, step.upload);
        grownCells_ += step.cells;
    }
    if (scene_.explode() != 0.0f) scene_.refreshOffsets();  // growing surfaces move their centres
    stepOnce_ = false;
}

void Viewer::click(float x, float y, bool track) {
    if (!scene_.volume()) return;
    const render::FrameView view = frameView();
    PickHit hit;
    {
        Profiler::Scope scope(profiler_, Stage::Pick);
        hit = picker_.pickSurface(scene_, *renderer_, view, x, y);
    }
    const bool tracking = track || method_ == ui::Method::Track;
    nlohmann::json pick = {{"view_pixel", {x, y}},
                           {"hit_surface", hit.surface ? nlohmann::json(*hit.surface) : nlohmann::json(nullptr)},
                           {"track", tracking}};
    if (hit.point) pick["point"] = *hit.point;
    if (picks_.size() >= kPicksKept) picks_.erase(picks_.begin());
    picks_.push_back(pick);
    if (!tracking) {
        scene_.selected = hit.surface;
        return;
    }
    if (hit.surface) {
        const SurfaceStructure* surface = scene_.find(*hit.surface);
        if (surface != nullptr && surface->tracked()) {  // already its own surface
            scene_.selected = hit.surface;
            return;
        }
    }
    std::optional<Vec3d> point = hit.point;
    if (!point) {
        glm::vec3 origin, direction;
        render::pixelRay(view, x + 0.5f, y + 0.5f, origin, direction);
        point = firstIsoCrossing(scene_.volume()->volume, currentIso(), origin, direction);
    }
    if (!point) {
        status("no surface at isovalue " + std::to_string(currentIso()) + " under the click");
        return;
    }
    picks_.back()["point"] = *point;
    trackFrom(*point);
}

void Viewer::trackFrom(const Vec3d& point) {
    const std::shared_ptr<const LoadedVolume> volume = scene_.volume();
    const double iso = currentIso();
    const GridEdge seed = nearestCrossedEdge(volume->volume, iso, point);
    picks_.back()["seed_edge"] = {seed.x, seed.y, seed.z, seed.axis};
    for (const auto& surface : scene_.surfaces()) {
        if (surface->tracked() && surface->containsEdge(seed)) {
            scene_.selected = surface->id();
            return;
        }
    }
    const bool switching = method_ != ui::Method::Track;
    if (switching) {
        // Tracking replaces the exhaustive result: the scene holds tracked surfaces only.
        method_ = ui::Method::Track;
        cancelExtraction();
        scene_.clearSurfaces();
    }
    const std::size_t tracked = static_cast<std::size_t>(
        std::count_if(scene_.surfaces().begin(), scene_.surfaces().end(), [](const auto& s) { return s->tracked(); }));
    auto surface = std::make_unique<SurfaceStructure>(scene_.newId(), volume, iso, table_, seed, point,
                                                      render::surfaceColour(tracked));
    scene_.selected = surface->id();
    picks_.back()["tracked_surface"] = surface->id();
    scene_.add(std::move(surface));
    playing_ = true;
    // A re-tracking on its way (an isovalue change) must include this seed.
    if (!switching && worker_.busy()) submit();
}

}  // namespace isotrack::viewer
