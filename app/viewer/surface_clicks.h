#pragma once
// Clicks in the 3D view: a plain click selects the surface under the cursor;
// a ctrl-click (or any click with method track) tracks the surface through
// the clicked point, picked from the pick buffer or, off every surface, the
// first isovalue crossing along the ray. The last clicks are kept for the
// --json summary.
#include <cstddef>
#include <cstdint>
#include <optional>

#include <nlohmann/json.hpp>

#include "render/camera.h"
#include "render/renderer.h"
#include "viewer/extraction_controller.h"
#include "viewer/growth.h"
#include "viewer/picker.h"
#include "viewer/profiler.h"
#include "viewer/scene.h"
#include "viewer/status_line.h"

namespace isotrack::viewer {

inline constexpr std::size_t kPicksKept = 16;  // the last clicks, for the summary

class SurfaceClicks {
public:
    SurfaceClicks(Scene& scene, render::Renderer& renderer, Picker& picker, Profiler& profiler,
                  ExtractionController& extraction, Growth& growth, StatusLine& status)
        : scene_(scene),
          renderer_(renderer),
          picker_(picker),
          profiler_(profiler),
          extraction_(extraction),
          growth_(growth),
          status_(status) {}

    // A click at framebuffer pixel (x, y) of `view`; `track`: a ctrl-click.
    void click(const render::FrameView& view, float x, float y, bool track);
    // As a ctrl-click at that world point (a script's `track X Y Z`).
    void trackPoint(const Vec3d& point);
    // A track that waited for the user's word (ExtractionController::askBeforeTracking).
    void trackConfirmed(const ExtractionController::PendingTrack& track) { trackFrom(track.point, track.hit); }
    const nlohmann::json& picks() const { return picks_; }

private:
    void trackFrom(const Vec3d& point, std::optional<std::uint32_t> hit);
    void note(nlohmann::json pick);

    Scene& scene_;
    render::Renderer& renderer_;
    Picker& picker_;
    Profiler& profiler_;
    ExtractionController& extraction_;
    Growth& growth_;
    StatusLine& status_;
    nlohmann::json picks_ = nlohmann::json::array();  // the last few clicks
};

}  // namespace isotrack::viewer
