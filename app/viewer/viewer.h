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
#include <algorithm>
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
#include "viewer/camera_controller.h"
#include "viewer/extraction_controller.h"
#include "viewer/picker.h"
#include "viewer/profiler.h"
#include "viewer/scene.h"
#include "viewer/script.h"
#include "viewer/script_runner.h"
#include "viewer/view_cache.h"
#include "viewer/window.h"

namespace isotrack::viewer {

struct ViewerOptions {
    std::string volumePath;
    std::optional<RawLayout> raw;  // --dims and friends: read volumePath as raw samples
    std::string series;            // --series: the DICOM series to read, empty for the default
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
inline constexpr std::size_t kPicksKept = 16;  // the last clicks, for the summary

class Viewer : private ScriptHost {
public:
    // Opens the window (throws DisplayError without a display).
    Viewer(const ViewerOptions& options, std::optional<Script> script);
    ~Viewer() override;
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    // Runs frames until the window closes or the script quits; returns the exit
    // status (1 after a script error, which has been printed).
    int run();
    // The --json summary of the session so far.
    nlohmann::json summary() const;

private:
    void frame();
    bool idle() const;

    // viewer_scene.cpp: extraction requests, growth, picking
    void submit();
    void grow();
    void click(float x, float y, bool track);
    void trackFrom(const Vec3d& point, std::optional<std::uint32_t> hit);
    double currentIso() const;  // the isovalue asked for (the slider)
    double shownIso() const;    // the isovalue of the surfaces on screen
    std::vector<PreviousSurface> previousSurfaces(bool footprints) const;
    void setSurfaceIso(std::uint32_t id, double iso);

    // viewer_results.cpp: results applied so that surfaces keep who they are
    void takeResult();
    void applyResult(ExtractionResult result);
    void placeSurfaces(NextSurfaces next, bool onlyOwnIsovalues);

    // viewer_actions.cpp
    void apply(const ui::Action& action) override;
    void applyKey(KeyCommand key);
    void frameCamera(bool selectionOnly) override;
    void exportSurface(std::uint32_t id, const std::string& path) override;
    void processMesh(const ui::ProcessMesh& request);

    // viewer_report.cpp: panel state, summary, screenshots
    ui::PanelState panelState() const;
    std::size_t gpuOtherBytes() const;
    std::size_t cpuBytes() const;
    std::size_t gpuBytes() const;
    nlohmann::json memoryJson() const;
    nlohmann::json volumeJson() const;
    void writeScreenshot(const std::string& path) const;

    // viewer_script.cpp: the ScriptHost a --script session drives (the rest
    // of it is apply, frameCamera and exportSurface above)
    bool extracting() const override;
    bool growing() const override;
    bool sourceShown() const override;
    bool hasVolume() const override;
    bool screenshotPending() const override;
    std::size_t surfaceCount() const override;
    std::uint32_t surfaceId(std::size_t index) const override;
    void load(const VolumeSource& source) override;
    void clickView(float fx, float fy, bool track) override;
    void trackPoint(const Vec3d& point) override;
    void requestScreenshot(const std::string& path) override;
    void startProfile(const std::string& path) override;
    void checkpoint(const std::string& name, int line) override;
    void setCamera(const std::string& spec) override;
    void quit() override;
    void fail(const std::string& message) override;

    void layout();
    void drawView();
    render::FrameOptions frameOptions() const;
    render::FrameView frameView() const;
    void status(const std::string& message);
    void reportSkipped(const LoadedVolume& volume);

    ViewerOptions options_;
    Window window_;
    std::unique_ptr<render::Renderer> renderer_;
    Profiler profiler_;
    Scene scene_;
    Picker picker_;
    ViewCache viewCache_;
    CameraController controller_;
    render::Camera camera_;
    ui::Panel panel_;
    std::vector<ui::Action> actions_;

    // What the user asked for; the worker makes it so.
    ExtractionController extraction_;
    std::size_t nextColour_ = 0;                    // palette rank for the next new surface
    std::shared_ptr<const TreeLayout> treeLayout_;  // the volume's contour tree laid out (method tree)
    std::string extractionError_;
    std::string status_;

    // A volume over the memory budget: the method that reads it whole waits
    // for the user's Extract (or Cancel: back to track).
    std::uint64_t memoryBudget_ = 0;
    struct Confirmation {
        ui::Method method = ui::Method::All;
        std::uint64_t bytes = 0;
    };
    std::optional<Confirmation> confirmation_;
    bool methodChosen_ = false;  // --method, or a method picked since: not switched to track on its own
    void askConfirmation(const ExtractionResult& result);

    // Growth.
    bool playing_ = true;
    bool stepOnce_ = false;
    int cellsPerFrame_ = 0;
    float growthBudgetMs_ = 4.0f;
    std::size_t grownCells_ = 0;  // this frame

    // What the last frame drew and uploaded, and the most any frame did.
    struct SessionCounters {
        std::size_t maxDrawCalls = 0, maxTrianglesDrawn = 0, maxUploadedBytes = 0, uploadedBytes = 0;
        void note(const render::DrawCounters& drawn, std::size_t uploaded) {
            maxDrawCalls = std::max(maxDrawCalls, drawn.drawCalls);
            maxTrianglesDrawn = std::max(maxTrianglesDrawn, drawn.triangles);
            maxUploadedBytes = std::max(maxUploadedBytes, uploaded);
            uploadedBytes += uploaded;
        }
    };
    render::DrawCounters drawn_;
    std::size_t uploaded_ = 0;
    SessionCounters sessionCounters_;

    // Layout, in window pixels and framebuffer pixels.
    int windowWidth_ = 1, windowHeight_ = 1, framebufferWidth_ = 1, framebufferHeight_ = 1;
    ViewRect view_;
    float pixelScale_ = 1.0f;

    std::unique_ptr<ScriptRunner> script_;
    std::optional<std::string> screenshotPath_;
    int screenshots_ = 0;  // taken with F12
    nlohmann::json checkpoints_ = nlohmann::json::array();
    nlohmann::json picks_ = nlohmann::json::array();  // the last few clicks, for the summary
    bool quit_ = false;
    int exitCode_ = 0;
    int idleFrames_ = 0;
};

// Runs the viewer for `isotrack` without a subcommand; returns the exit status.
int runViewer(const ViewerOptions& options);

}  // namespace isotrack::viewer
