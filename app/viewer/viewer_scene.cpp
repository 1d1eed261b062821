// The viewer's scene work: requests to the extraction worker and their results,
// growing tracked surfaces within the frame's budget, and clicks (pick, track).
#include <algorithm>

#include "isotrack/errors.h"
#include "render/palette.h"
#include "viewer/viewer.h"

namespace isotrack::viewer {
double Viewer::currentIso() const {
    if (extraction_.iso()) return *extraction_.iso();
    return scene_.volume() ? scene_.volume()->defaultIso : 0.0;
}

double Viewer::shownIso() const { return extraction_.shownIso().value_or(currentIso()); }

// The scene's surfaces as core's follow.h names them; the worker gets them
// without footprints, applyResult with them.
std::vector<PreviousSurface> Viewer::previousSurfaces(bool footprints) const {
    std::vector<PreviousSurface> previous;
    previous.reserve(scene_.surfaces().size());
    for (const auto& surface : scene_.surfaces()) {
        PreviousSurface p;
        p.id = surface->id();
        p.seed = surface->seedPoint();
        if (surface->ownIso) {
            const OwnIso& own = *surface->ownIso;
            p.own = OwnIsovalue{own.wanted, own.arc, own.origin, own.wanted != own.shown};
        }
        p.arc = surface->stats().arc;
        if (footprints) p.footprint = &surface->footprint();
        previous.push_back(p);
    }
    return previous;
}

void Viewer::submit() {
    extraction_.submit(previousSurfaces(false));
    if (script_) script_->noteSubmitted();
}

// Flexible isosurfaces: the surface gets an isovalue of its own and only it is
// tracked again, along its contour-tree arc; the others keep theirs.
void Viewer::setSurfaceIso(std::uint32_t id, double iso) {
    SurfaceStructure* surface = scene_.find(id);
    if (!surface) return;
    if (extraction_.method() != ui::Method::Tree || (!surface->stats().arc && !surface->ownIso) || surface->tracked()) {
        const std::string message = "surface " + std::to_string(id) +
                                    " is on no contour-tree arc: an isovalue of its own needs the method tree";
        if (script_) throw InputError(message);
        status(message);
        return;
    }
    if (!surface->ownIso) surface->ownIso = OwnIso{iso, shownIso(), *surface->stats().arc, *surface->stats().arc};
    surface->ownIso->wanted = iso;
    extraction_.submit(previousSurfaces(false), true);
    if (script_) script_->noteSubmitted();
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
    const bool tracking = track || extraction_.method() == ui::Method::Track;
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
        if (surface != nullptr && surface->tracked()) {  // already a tracked surface
            scene_.selected = hit.surface;
            return;
        }
    }
    std::optional<Vec3d> point = hit.point;
    if (!point) {
        glm::vec3 origin, direction;
        render::pixelRay(view, x + 0.5f, y + 0.5f, origin, direction);
        point = firstIsoCrossing(scene_.volume()->volume, shownIso(), origin, direction);
    }
    if (!point) {
        status("no surface at isovalue " + std::to_string(shownIso()) + " under the click");
        return;
    }
    picks_.back()["point"] = *point;
    trackFrom(*point, hit.surface);
}

// Tracks the surface through `point` and keeps every other surface. A click on
// a surface of `all` turns that surface into a tracked one in place (same id,
// style and list position), growing again from the seed; otherwise the tracked
// surface is added at the end of the list.
void Viewer::trackFrom(const Vec3d& point, std::optional<std::uint32_t> hit) {
    const std::shared_ptr<const LoadedVolume> volume = scene_.volume();
    const double iso = shownIso();
    const GridEdge seed = nearestCrossedEdge(volume->volume, iso, point);
    picks_.back()["seed_edge"] = {seed.x, seed.y, seed.z, seed.axis};
    for (const auto& surface : scene_.surfaces()) {
        if (surface->tracked() && surface->presence() == Presence::Shown && surface->containsEdge(seed)) {
            scene_.selected = surface->id();
            return;
        }
    }
    SurfaceStructure* clicked = hit ? scene_.find(*hit) : nullptr;
    const TableKind table = extraction_.table();
    const bool every = extraction_.method() == ui::Method::All || extraction_.method() == ui::Method::Tree;
    if (clicked != nullptr && !clicked->tracked() && every && clicked->containsEdge(seed)) {
        clicked->startTracking(volume, iso, table, seed, point);
        scene_.selected = clicked->id();
        picks_.back()["tracked_surface"] = clicked->id();
    } else {
        auto surface = std::make_unique<SurfaceStructure>(renderer_->arena(), scene_.newId(), volume, iso, table, seed,
                                                          point, render::surfaceColour(nextColour_++));
        scene_.selected = surface->id();
        picks_.back()["tracked_surface"] = surface->id();
        scene_.add(std::move(surface));
    }
    scene_.refreshOffsets();
    playing_ = true;
    // A re-extraction on its way (an isovalue change) must include this seed.
    if (extraction_.busy()) submit();
}

}  // namespace isotrack::viewer
