#pragma once
// The viewer as a --script session's host (script_runner.h's ScriptHost):
// what the runner may look at while it waits, and what its commands do,
// handed to the part of the viewer that does it.
#include <cstddef>
#include <cstdint>
#include <string>

#include "render/camera.h"
#include "viewer/action_handler.h"
#include "viewer/extraction_controller.h"
#include "viewer/frame_requests.h"
#include "viewer/growth.h"
#include "viewer/profiler.h"
#include "viewer/scene.h"
#include "viewer/script_runner.h"
#include "viewer/surface_clicks.h"
#include "viewer/time_player.h"
#include "viewer/view_layout.h"
#include "viewer/viewer_report.h"

namespace isotrack::viewer {

// The parts a script drives.
struct SessionParts {
    ExtractionController& extraction;
    Scene& scene;
    Growth& growth;
    TimePlayer& time;
    ActionHandler& actions;
    SurfaceClicks& clicks;
    ViewerReport& report;
    Profiler& profiler;
    render::Camera& camera;
    const ViewLayout& layout;
    FrameRequests& requests;
};

class SessionHost final : public ScriptHost {
public:
    explicit SessionHost(SessionParts parts) : parts_(parts) {}

    bool extracting() const override;
    bool growing() const override;
    bool sourceShown() const override;
    bool hasVolume() const override;
    bool screenshotPending() const override;
    bool timePlaying() const override;
    std::size_t surfaceCount() const override;
    std::uint32_t surfaceId(std::size_t index) const override;

    void apply(const ui::Action& action) override;
    void load(const VolumeSource& source) override;
    void clickView(float fx, float fy, bool track) override;
    void trackPoint(const Vec3d& point) override;
    void requestScreenshot(const std::string& path) override;
    void startProfile(const std::string& path) override;
    void checkpoint(const std::string& name, int line) override;
    void setCamera(const std::string& spec) override;
    void frameCamera(bool selectionOnly) override;
    void exportSurface(std::uint32_t id, const std::string& path) override;
    void quit() override;
    void fail(const std::string& message) override;

private:
    SessionParts parts_;
};

}  // namespace isotrack::viewer
