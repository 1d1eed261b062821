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
#include "render/window_frame.h"

namespace isotrack::viewer {
namespace {

constexpr int kDeterministicCellsPerFrame = 4096;
constexpr int kIdleFramesBeforeSleeping = 3;
constexpr double kIdleWaitSeconds = 0.25;
// While only the worker has something to do, frames come no faster than this,
// so that the frame loop (and llvmpipe, and the X server) leave it the CPU.
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
      extraction_(extractionThreads(options.threads), memoryBudget(options.memoryBudgetGiB)),
      memoryBudget_(memoryBudget(options.memoryBudgetGiB)),
      methodChosen_(options.methodGiven) {
    if (!options.volumePath.empty()) {
        VolumeSource source = VolumeSource::file(options.volumePath, options.raw);
        source.series = options.series;
        extraction_.setSource(source);
    } else {
        extraction_.setSource(VolumeSource::field(options.fieldSpec.empty() ? kDefaultField : options.fieldSpec));
    }
    extraction_.setTable(options.table);
    extraction_.setMethod(options.method);
    if (options.iso) extraction_.setIso(*options.iso);
    if (options.deterministic) cellsPerFrame_ = kDeterministicCellsPerFrame;
    if (!options.profile.empty()) profiler_.startRecording(options.profile);
    if (script) script_ = std::make_unique<ScriptRunner>(std::move(*script), static_cast<ScriptHost&>(*this));
    layout();
    if (!script_ || !script_->loadsFirst()) submit();  // a script that loads first skips the default volume
}

Viewer::~Viewer() = default;

int Viewer::run() {
    auto lastFrame = Profiler::Clock::now();
    while (!quit_ && !window_.shouldClose()) {
        // Waiting happens outside frames: it is not counted as frame time.
        if (idle() && ++idleFrames_ > kIdleFramesBeforeSleeping) {
            Window::waitEvents(kIdleWaitSeconds);
        } else if (!idle()) {
            idleFrames_ = 0;
        }
        if (extraction_.busy() && !(scene_.anyGrowing() && playing_)) {
            std::this_thread::sleep_until(lastFrame + kWaitingFramePeriod);
        }
        lastFrame = Profiler::Clock::now();
        frame();
    }
    if (profiler_.recording()) profiler_.writeTrace();
    if (options_.json && exitCode_ == 0) std::printf("%s\n", summary().dump(2).c_str());
    return exitCode_;
}

bool Viewer::idle() const {
    if (script_ || extraction_.busy() || (scene_.anyGrowing() && playing_)) return false;
    const ImGuiIO& io = ImGui::GetIO();
    return !(io.MouseDown[0] || io.MouseDown[1] || io.MouseDown[2]);
}

void Viewer::layout() {
    window_.windowSize(windowWidth_, windowHeight_);
    window_.framebufferSize(framebufferWidth_, framebufferHeight_);
    pixelScale_ = windowWidth_ > 0 ? float(framebufferWidth_) / float(windowWidth_) : 1.0f;
    view_.x = ui::Panel::kWidth;
    view_.y = 0.0f;
    view_.width = std::max(float(windowWidth_) - ui::Panel::kWidth, 1.0f);
    view_.height = std::max(float(windowHeight_), 1.0f);
}

render::FrameOptions Viewer::frameOptions() const {
    render::FrameOptions options;
    options.x = static_cast<int>(view_.x * pixelScale_);
    options.y = 0;
    options.width = std::max(framebufferWidth_ - options.x, 1);
    options.height = std::max(framebufferHeight_, 1);
    options.wireframe = scene_.wireframe;
    options.boundingBox = scene_.boundingBox;
    return options;
}

render::FrameView Viewer::frameView() const {
    return render::Renderer::frameView(camera_, frameOptions(), scene_.drawBounds());
}

void Viewer::status(const std::string& message) {
    status_ = message;
    if (!script_) std::fprintf(stderr, "isotrack: %s\n", message.c_str());
}

void Viewer::drawView() {
    const render::FrameOptions window = frameOptions();
    render::FrameOptions cached = window;
    cached.x = cached.y = 0;
    if (viewCache_.needsRedraw(scene_.signature(camera_, cached), cached.width, cached.height)) {
        profiler_.beginGpu();
        viewCache_.bind();
        scene_.draw(*renderer_, render::Renderer::frameView(camera_, cached, scene_.drawBounds()), cached);
        drawn_ = renderer_->takeCounters();
        profiler_.endGpu();
    }
    render::beginWindowFrame(framebufferWidth_, framebufferHeight_, window.background);
    viewCache_.present(window.x, window.y);
}

void Viewer::frame() {
    profiler_.beginFrame();
    grownCells_ = 0;
    drawn_ = render::DrawCounters{};  // a frame that only copies the cached view draws nothing
    const std::size_t uploadedBefore = render::GpuMesh::uploadedTotal();
    try {
        ViewInput input;
        {
            Profiler::Scope scope(profiler_, Stage::Input);
            Window::pollEvents();
            layout();
            Window::beginImGuiFrame();
            input = controller_.update(camera_, view_, window_.takeKeyPresses());
            if (input.moveSelection != glm::vec3(0.0f)) {
                if (SurfaceStructure* selected = scene_.selection()) {
                    selected->userOffset += input.moveSelection;
                    scene_.refreshOffsets();
                }
            }
            for (KeyCommand key : input.keys) applyKey(key);
        }
        if (input.click) click(input.click->x * pixelScale_, input.click->y * pixelScale_, input.trackClick);
        if (script_) {
            Profiler::Scope scope(profiler_, Stage::Script);
            script_->advance();
        }
        takeResult();
        grow();
        {
            Profiler::Scope scope(profiler_, Stage::Ui);
            const ui::PanelState state = panelState();
            actions_.clear();
            panel_.build(state, actions_);
            for (const ui::Action& action : actions_) apply(action);
        }
    } catch (const std::exception& e) {
        if (script_) {
            script_->fail(e.what());
        } else {
            status(e.what());
        }
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
    if (screenshotPath_) {
        Profiler::Scope scope(profiler_, Stage::Screenshot);
        const std::string path = *screenshotPath_;
        screenshotPath_.reset();
        try {
            writeScreenshot(path);
        } catch (const std::exception& e) {
            if (script_)
                script_->fail(e.what());
            else
                status(e.what());
        }
    }
    {
        Profiler::Scope scope(profiler_, Stage::Present);
        window_.swapBuffers();
    }
    uploaded_ = render::GpuMesh::uploadedTotal() - uploadedBefore;
    sessionCounters_.note(drawn_, uploaded_);
    FrameCounters counters;  // only a recorded trace keeps them
    if (profiler_.recording()) {
        counters.surfaces = scene_.surfaces().size();
        for (const auto& surface : scene_.surfaces()) counters.triangles += surface->mesh().triangleCount();
        counters.grownCells = grownCells_;
        counters.growing = scene_.anyGrowing();
        counters.extracting = extraction_.busy();
        counters.cpuBytes = cpuBytes();
        counters.gpuBytes = gpuBytes();
        counters.isoShown = shownIso();
        counters.isoRequested = currentIso();
        counters.extractionsApplied = extraction_.appliedCount();
        counters.drawCalls = drawn_.drawCalls;
        counters.trianglesDrawn = drawn_.triangles;
        counters.uploadedBytes = uploaded_;
        const render::ArenaStats arena = renderer_->arena().stats();
        counters.arenaPages = arena.pages;
        counters.arenaFreeBytes = arena.freeBytes;
        counters.arenaFragmentation = arena.fragmentation;
        counters.arenaMoves = arena.moves;
        counters.arenaMovedBytes = arena.movedBytes;
    }
    profiler_.endFrame(counters);
}

int runViewer(const ViewerOptions& options) {
    std::optional<Script> script;
    if (!options.script.empty()) script = parseScript(options.script);
    if (!options.volumePath.empty()) {
        std::error_code error;
        const bool folder = std::filesystem::is_directory(options.volumePath, error);
        std::FILE* file = folder ? nullptr : std::fopen(options.volumePath.c_str(), "rb");
        if (!folder && file == nullptr) throw InputError("--volume " + options.volumePath + ": cannot open the file");
        if (file) std::fclose(file);
        if (!options.raw && !volumeFormatOf(options.volumePath)) {
            throw InputError("--volume " + options.volumePath +
                             ": unknown volume format (the viewer reads .nrrd .nhdr .nii .nii.gz .mhd .mha .vtk .vti, "
                             ".pvd (its first step), "
                             "DICOM: .dcm, a folder or DICOMDIR; or raw samples with --dims and --type)");
        }
    }
    Viewer viewer(options, std::move(script));
    return viewer.run();
}

}  // namespace isotrack::viewer
