#include "viewer/viewer.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "gl/timer_query.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/threads.h"
#include "render/image.h"
#include "render/window_frame.h"

namespace isotrack::viewer {
namespace {

constexpr int kDeterministicCellsPerFrame = 4096;
constexpr int kIdleFramesBeforeSleeping = 3;
constexpr double kIdleWaitSeconds = 0.25;
// While only the worker (or playback, waiting for its next step) has something
// to do, frames come no faster than this, so that the frame loop (and llvmpipe,
// and the X server) leave the worker the CPU.
constexpr std::chrono::milliseconds kWaitingFramePeriod{16};

int extractionThreads(int requested) { return requested > 0 ? requested : defaultInteractiveThreadCount(); }

std::uint64_t memoryBudget(double gib) {
    return gib > 0 ? static_cast<std::uint64_t>(gib * double(std::uint64_t(1) << 30)) : defaultMemoryBudget();
}

}  // namespace

Viewer::Viewer(const ViewerOptions& options, std::optional<Script> script)
    : options_(options),
      window_(options.width, options.height, "isotrack", !options.noVsync && !script && !options.deterministic),
      renderer_(std::make_unique<render::Renderer>()),
      profiler_(gl::timerQueriesAvailable()),
      extraction_(extractionThreads(options.threads), memoryBudget(options.memoryBudgetGiB), scene_, *renderer_,
                  profiler_, status_),
      time_(extraction_, scene_),
      clicks_(scene_, *renderer_, picker_, profiler_, extraction_, growth_, status_),
      actionHandler_(extraction_, scene_, growth_, time_, camera_, panel_, status_, requests_, options.frame),
      report_(ReportSources{window_, *renderer_, profiler_, scene_, picker_, viewCache_, extraction_, growth_, time_,
                            status_, clicks_, layout_, totals_},
              options.deterministic),
      host_(SessionParts{extraction_, scene_, growth_, time_, actionHandler_, clicks_, report_, profiler_, camera_,
                         layout_, requests_}) {
    if (options.methodGiven) extraction_.setMethodChosen();
    if (!options.volumePath.empty()) {
        VolumeSource source = VolumeSource::file(options.volumePath, options.raw);
        source.series = options.series;
        source.array = options.array;
        source.time = options.time;
        extraction_.setSource(source);
    } else {
        extraction_.setSource(VolumeSource::field(options.fieldSpec.empty() ? kDefaultField : options.fieldSpec));
    }
    extraction_.setTable(options.table);
    extraction_.setMethod(options.method);
    if (options.iso) extraction_.setIso(*options.iso);
    // A new volume: the default view of its box.
    extraction_.onNewVolume([this] {
        const render::FrameOptions frame = layout_.frameOptions(scene_);
        camera_ = render::frameBounds(scene_.volumeBounds(), float(frame.width) / float(frame.height));
    });
    if (options.deterministic) growth_.setCellsPerFrame(kDeterministicCellsPerFrame);
    if (!options.profile.empty()) profiler_.startRecording(options.profile);
    status_.setQuiet(script.has_value());  // a script's session keeps stderr for its errors
    if (script) {
        script_ = std::make_unique<ScriptRunner>(std::move(*script), host_);
        extraction_.attachScript(script_.get());
    }
    layout_.update(window_);
    if (!script_ || !script_->loadsFirst()) extraction_.submit();  // a script that loads first skips the default volume
}

Viewer::~Viewer() = default;

int Viewer::run() {
    auto lastFrame = Profiler::Clock::now();
    while (!requests_.quit && !window_.shouldClose()) {
        // Waiting happens outside frames: it is not counted as frame time.
        if (idle() && ++idleFrames_ > kIdleFramesBeforeSleeping) {
            Window::waitEvents(kIdleWaitSeconds);
        } else if (!idle()) {
            idleFrames_ = 0;
        }
        if ((extraction_.busy() || time_.playing()) && !(scene_.anyGrowing() && growth_.playing())) {
            std::this_thread::sleep_until(lastFrame + kWaitingFramePeriod);
        }
        lastFrame = Profiler::Clock::now();
        frame();
    }
    if (profiler_.recording()) profiler_.writeTrace();
    if (options_.json && requests_.exitCode == 0) std::printf("%s\n", summary().dump(2).c_str());
    return requests_.exitCode;
}

bool Viewer::idle() const {
    if (script_ || extraction_.busy() || time_.playing() || (scene_.anyGrowing() && growth_.playing())) return false;
    const ImGuiIO& io = ImGui::GetIO();
    return !(io.MouseDown[0] || io.MouseDown[1] || io.MouseDown[2]);
}

// An error at the frame boundary: a script's failure, else the status line.
void Viewer::fail(const std::exception& error) {
    if (script_) {
        script_->fail(error.what());
    } else {
        status_.show(error.what());
    }
}

void Viewer::drawView() {
    const render::FrameOptions window = layout_.frameOptions(scene_);
    render::FrameOptions cached = window;
    cached.x = cached.y = 0;
    if (viewCache_.needsRedraw(scene_.signature(camera_, cached), cached.width, cached.height)) {
        profiler_.beginGpu();
        viewCache_.bind();
        scene_.draw(*renderer_, render::Renderer::frameView(camera_, cached, scene_.drawBounds()), cached);
        totals_.drawn = renderer_->takeCounters();
        profiler_.endGpu();
    }
    render::beginWindowFrame(layout_.framebufferWidth(), layout_.framebufferHeight(), window.background);
    viewCache_.present(window.x, window.y);
}

// Events, the camera, the keys and a click.
void Viewer::input() {
    ViewInput input;
    {
        Profiler::Scope scope(profiler_, Stage::Input);
        Window::pollEvents();
        layout_.update(window_);
        Window::beginImGuiFrame();
        input = controller_.update(camera_, layout_.view(), window_.takeKeyPresses());
        if (input.moveSelection != glm::vec3(0.0f)) {
            if (SurfaceStructure* selected = scene_.selection()) {
                selected->userOffset += input.moveSelection;
                scene_.refreshOffsets();
            }
        }
        for (KeyCommand key : input.keys) actionHandler_.applyKey(key);
    }
    if (input.click) {
        const float scale = layout_.pixelScale();
        clicks_.click(layout_.frameView(camera_, scene_), input.click->x * scale, input.click->y * scale,
                      input.trackClick);
    }
}

void Viewer::frame() {
    profiler_.beginFrame();
    growth_.beginFrame();
    totals_.beginFrame();
    const std::size_t uploadedBefore = render::GpuMesh::uploadedTotal();
    try {
        input();
        if (script_) {
            Profiler::Scope scope(profiler_, Stage::Script);
            script_->advance();
        }
        extraction_.takeResult();
        time_.update();
        growth_.grow(scene_, profiler_);
        {
            Profiler::Scope scope(profiler_, Stage::Ui);
            const ui::PanelState state = report_.panelState();
            actions_.clear();
            panel_.build(state, actions_);
            for (const ui::Action& action : actions_) actionHandler_.apply(action);
            if (const auto track = extraction_.takeConfirmedTrack()) clicks_.trackConfirmed(*track);
        }
    } catch (const std::exception& e) {
        fail(e);
    }
    {
        Profiler::Scope scope(profiler_, Stage::Ui);
        Window::finishImGuiFrame();
    }
    {
        Profiler::Scope scope(profiler_, Stage::Draw);
        drawView();
        Window::drawImGui();
    }
    if (requests_.screenshotPath) screenshot();
    {
        Profiler::Scope scope(profiler_, Stage::Present);
        window_.swapBuffers();
    }
    totals_.endFrame(render::GpuMesh::uploadedTotal() - uploadedBefore);
    countFrame();
}

void Viewer::screenshot() {
    Profiler::Scope scope(profiler_, Stage::Screenshot);
    const std::string path = *requests_.screenshotPath;
    requests_.screenshotPath.reset();
    try {
        render::writePng(render::readWindowImage(layout_.framebufferWidth(), layout_.framebufferHeight()), path);
    } catch (const std::exception& e) {
        fail(e);
    }
}

// The frame's counters, for a recorded trace only.
void Viewer::countFrame() {
    FrameCounters counters;
    if (profiler_.recording()) {
        counters.surfaces = scene_.surfaces().size();
        for (const auto& surface : scene_.surfaces()) counters.triangles += surface->mesh().triangleCount();
        counters.grownCells = growth_.grownCells();
        counters.growing = scene_.anyGrowing();
        counters.extracting = extraction_.busy();
        counters.cpuBytes = report_.cpuBytes();
        counters.gpuBytes = report_.gpuBytes();
        counters.isoShown = extraction_.shownIso();
        counters.isoRequested = extraction_.currentIso();
        counters.extractionsApplied = extraction_.appliedCount();
        counters.drawCalls = totals_.drawn.drawCalls;
        counters.trianglesDrawn = totals_.drawn.triangles;
        counters.uploadedBytes = totals_.uploaded;
        const render::ArenaStats arena = renderer_->arena().stats();
        counters.arenaPages = arena.pages;
        counters.arenaFreeBytes = arena.freeBytes;
        counters.arenaFragmentation = arena.fragmentation;
        counters.arenaMoves = arena.moves;
        counters.arenaMovedBytes = arena.movedBytes;
    }
    profiler_.endFrame(counters);
    time_.noteFrame(profiler_.lastFrameMs());
}

int runViewer(const ViewerOptions& options) {
    std::optional<Script> script;
    if (!options.script.empty()) script = parseScript(options.script);
    if (!options.volumePath.empty()) {
        std::error_code error;
        const bool folder = std::filesystem::is_directory(options.volumePath, error);
        std::FILE* file = folder ? nullptr : std::fopen(options.volumePath.c_str(), "rb");
        const bool numbered = !folder && file == nullptr && options.volumePath.find('%') != std::string::npos;
        if (!folder && file == nullptr && !numbered)
            throw InputError("--volume " + options.volumePath + ": cannot open the file");
        if (file) std::fclose(file);
        if (!options.raw && !volumeFormatOf(options.volumePath)) {
            throw InputError("--volume " + options.volumePath +
                             ": unknown volume format (the viewer reads .nrrd .nhdr .nii .nii.gz .mhd .mha .vtk .vti, "
                             ".pvd and numbered files (step_%04d.nrrd) as time series, "
                             "DICOM: .dcm, a folder or DICOMDIR; or raw samples with --dims and --type)");
        }
    }
    Viewer viewer(options, std::move(script));
    return viewer.run();
}

}  // namespace isotrack::viewer
