#include "viewer/surface_clicks.h"

#include "isotrack/tracking.h"
#include "render/palette.h"
#include "render/pick_target.h"

namespace isotrack::viewer {

void SurfaceClicks::note(nlohmann::json pick) {
    if (picks_.size() >= kPicksKept) picks_.erase(picks_.begin());
    picks_.push_back(std::move(pick));
}

void SurfaceClicks::click(const render::FrameView& view, float x, float y, bool track) {
    if (!scene_.volume()) return;
    PickHit hit;
    {
        Profiler::Scope scope(profiler_, Stage::Pick);
        hit = picker_.pickSurface(scene_, renderer_, view, x, y);
    }
    const bool tracking = track || extraction_.method() == Method::Track;
    nlohmann::json pick = {{"view_pixel", {x, y}},
                           {"hit_surface", hit.surface ? nlohmann::json(*hit.surface) : nlohmann::json(nullptr)},
                           {"track", tracking}};
    if (hit.point) pick["point"] = *hit.point;
    note(std::move(pick));
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
    const double iso = extraction_.shownIso();
    if (!point) {
        glm::vec3 origin, direction;
        render::pixelRay(view, x + 0.5f, y + 0.5f, origin, direction);
        point = firstIsoCrossing(scene_.volume()->volume, iso, origin, direction);
    }
    if (!point) {
        status_.show("no surface at isovalue " + std::to_string(iso) + " under the click");
        return;
    }
    picks_.back()["point"] = *point;
    trackFrom(*point, hit.surface);
}

void SurfaceClicks::trackPoint(const Vec3d& point) {
    note({{"point", point}, {"track", true}, {"hit_surface", nullptr}});
    trackFrom(point, std::nullopt);
}

// Tracks the surface through `point` and keeps every other surface. A click on
// a surface of `all` turns that surface into a tracked one in place (same id,
// style and list position), growing again from the seed; otherwise the tracked
// surface is added at the end of the list.
void SurfaceClicks::trackFrom(const Vec3d& point, std::optional<std::uint32_t> hit) {
    const std::shared_ptr<const LoadedVolume> volume = scene_.volume();
    const double iso = extraction_.shownIso();
    const GridEdge seed = nearestCrossedEdge(volume->volume, iso, point);
    picks_.back()["seed_edge"] = {seed.x, seed.y, seed.z, seed.axis};
    for (const auto& surface : scene_.surfaces()) {
        if (surface->tracked() && surface->presence() == Presence::Shown && surface->containsEdge(seed)) {
            scene_.selected = surface->id();
            return;
        }
    }
    if (extraction_.askBeforeTracking(*volume, {point, hit})) return;
    SurfaceStructure* clicked = hit ? scene_.find(*hit) : nullptr;
    const TableKind table = extraction_.table();
    const bool every = extraction_.method() == Method::All || extraction_.method() == Method::Tree;
    if (clicked != nullptr && !clicked->tracked() && every && clicked->containsEdge(seed)) {
        clicked->startTracking(volume, iso, table, seed, point, extraction_.threads());
        scene_.selected = clicked->id();
        picks_.back()["tracked_surface"] = clicked->id();
    } else {
        auto surface =
            std::make_unique<SurfaceStructure>(renderer_.arena(), scene_.newId(), volume, iso, table, seed, point,
                                               render::surfaceColour(extraction_.takeColour()), extraction_.threads());
        scene_.selected = surface->id();
        picks_.back()["tracked_surface"] = surface->id();
        scene_.add(std::move(surface));
    }
    scene_.refreshOffsets();
    growth_.play();
    // A re-extraction on its way (an isovalue change) must include this seed.
    if (extraction_.busy()) extraction_.submit();
}

}  // namespace isotrack::viewer
