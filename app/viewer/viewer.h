#pragma once
// The interactive viewer: a window with the 3D view on the right and the panel
// on the left, driven by ImGui's standard GLFW + OpenGL3 frame loop.
//
// One frame: input (events, camera, clicks and picking), script (the next
// commands of a --script session), extract (the worker's finished results are
// taken; growing surfaces advance within their per-frame budget), upload (new
// meshes and grown ranges go to the GPU), ui (the panel from plain state, its
// actions applied), draw (the scene, timed on the GPU too, then the panel),
// present (swap). Every stage is timed by the Profiler.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "isotrack/extract.h"
#include "isotrack/io.h"
#include "isotrack/orientation.h"
#include "isotrack/tables.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "ui/actions.h"
#include "ui/panel.h"
#include "viewer/action_handler.h"
#include "viewer/camera_controller.h"
#include "viewer/draw_totals.h"
#include "viewer/extraction_controller.h"
#include "viewer/frame_requests.h"
#include "viewer/growth.h"
#include "viewer/picker.h"
#include "viewer/profiler.h"
#include "viewer/scene.h"
#include "viewer/script.h"
#include "viewer/script_runner.h"
#include "viewer/session_host.h"
#include "viewer/status_line.h"
#include "viewer/surface_clicks.h"
#include "viewer/time_player.h"
#include "viewer/view_cache.h"
#include "viewer/view_layout.h"
#include "viewer/viewer_report.h"
#include "viewer/window.h"

namespace isotrack::viewer {

struct ViewerOptions {
    std::string volumePath;
    std::optional<RawLayout> raw;  // --dims and friends: read volumePath as raw samples
    std::string series;            // --series: the DICOM series to read, empty for the default
    std::string array;             // --array: a .vti's PointData array, empty for the first scalar one
    std::size_t time = 0;          // --time: the time series' step to start at
    std::string fieldSpec;         // default when neither is given: kDefaultField
    std::optional<double> iso;
    TableKind table = TableKind::Consistent;
    Method method = Method::All;
    WorldFrame frame = WorldFrame::Lps;  // of exported meshes, as `isotrack extract --frame`
    std::string script;
    bool json = false;
    std::string profile;
    bool deterministic = false;
    bool noVsync = false;  // vsync is on in interactive sessions unless this; scripts never wait for it
    int width = 1280, height = 800;
    int threads = 0;             // extraction threads; 0: defaultInteractiveThreadCount()
    bool methodGiven = false;    // --method was given: a volume over the memory budget asks before it, not track
    double memoryBudgetGiB = 0;  // --memory-budget; 0: defaultMemoryBudget()
};

inline constexpr const char* kDefaultField = "blobs:128";

// The frame loop, wiring the viewer's parts: the scene of surfaces (scene.h),
// the extraction controller (extraction_controller.h: requests, and results
// applied so that surfaces keep who they are), growth (growth.h), clicks
// (surface_clicks.h), the panel's and keys' actions (action_handler.h), the
// reports (viewer_report.h) and a script's host (session_host.h).
class Viewer {
public:
    // Opens the window (throws DisplayError without a display).
    Viewer(const ViewerOptions& options, std::optional<Script> script);
    ~Viewer();
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    // Runs frames until the window closes or the script quits; returns the exit
    // status (1 after a script error, which has been printed).
    int run();
    // The --json summary of the session so far.
    nlohmann::json summary() const { return report_.summary(); }

private:
    void frame();
    void input();
    void drawView();
    void screenshot();
    void countFrame();
    bool idle() const;
    void fail(const std::exception& error);

    ViewerOptions options_;
    Window window_;
    std::unique_ptr<render::Renderer> renderer_;
    Profiler profiler_;
    StatusLine status_;
    FrameRequests requests_;
    ViewLayout layout_;
    DrawTotals totals_;
    Scene scene_;
    Picker picker_;
    ViewCache viewCache_;
    CameraController controller_;
    render::Camera camera_;
    ui::Panel panel_;
    std::vector<ui::Action> actions_;
    Growth growth_;
    ExtractionController extraction_;
    TimePlayer time_;
    SurfaceClicks clicks_;
    ActionHandler actionHandler_;
    ViewerReport report_;
    SessionHost host_;
    std::unique_ptr<ScriptRunner> script_;
    int idleFrames_ = 0;
};

// Runs the viewer for `isotrack` without a subcommand; returns the exit status.
int runViewer(const ViewerOptions& options);

}  // namespace isotrack::viewer
