#pragma once
// Per-frame profiling: CPU time per stage of the frame loop, the GPU's time
// for the 3D draw (GL_TIME_ELAPSED timer queries, read a few frames late so the
// CPU never waits), a history of frame times for the panel's plot, the median
// for the summary, and a Chrome trace (`--profile FILE.json`, opens in Perfetto
// and chrome://tracing): per frame one "frame" complete event ("ph": "X", ts and
// dur in microseconds) on the main thread's track with one nested event per
// stage, the GPU draw on a "GPU" track, and worker extractions on a "worker"
// track.
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "gl/timer_query.h"

namespace isotrack::viewer {

enum class Stage : std::uint8_t { Input, Script, Pick, Extract, Upload, Ui, Draw, Screenshot, Present, Count };
const char* stageName(Stage stage);
inline constexpr std::size_t kStageCount = static_cast<std::size_t>(Stage::Count);

// What the frame did, for the trace's args.
struct FrameCounters {
    std::size_t surfaces = 0, triangles = 0;
    std::size_t grownCells = 0;  // by growing surfaces this frame
    bool growing = false, extracting = false;
    std::size_t cpuBytes = 0, gpuBytes = 0;
    double isoShown = 0.0, isoRequested = 0.0;      // the surfaces on screen trail the slider while it is dragged
    std::size_t extractionsApplied = 0;             // results shown so far in the session
    std::size_t drawCalls = 0, trianglesDrawn = 0;  // into the 3D view (0 when only its cached image was copied)
    std::size_t uploadedBytes = 0;                  // vertices and indices sent to the GPU
    // The surface arena after the frame (render/surface_arena.h): pages, free
    // bytes, fragmentation, and slots moved GPU-side so far.
    std::size_t arenaPages = 0, arenaFreeBytes = 0, arenaMoves = 0, arenaMovedBytes = 0;
    double arenaFragmentation = 0.0;
};

class Profiler {
public:
    using Clock = std::chrono::steady_clock;
    static constexpr std::size_t kHistory = 300;  // frames in the panel's plot

    explicit Profiler(bool gpuTimers);

    void beginFrame();
    void add(Stage stage, Clock::time_point start, Clock::time_point end);
    void add(Stage stage, Clock::time_point start, std::chrono::nanoseconds duration);
    // Brackets the GPU work to time (the 3D draw).
    void beginGpu();
    void endGpu();
    void endFrame(const FrameCounters& counters);
    // Work done on the worker thread, for the trace.
    void addWorkerSpan(const std::string& name, Clock::time_point start, Clock::time_point end);

    class Scope {
    public:
        Scope(Profiler& profiler, Stage stage) : profiler_(profiler), stage_(stage), start_(Clock::now()) {}
        ~Scope() { profiler_.add(stage_, start_, Clock::now()); }
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;

    private:
        Profiler& profiler_;
        Stage stage_;
        Clock::time_point start_;
    };

    // ---- what the panel and the summary show ----
    std::uint64_t frames() const { return frameIndex_; }
    double lastStageMs(Stage stage) const { return lastStageMs_[static_cast<std::size_t>(stage)]; }
    double lastFrameMs() const { return lastFrameMs_; }
    double lastGpuMs() const { return lastGpuMs_; }
    double fps() const { return fps_; }
    std::vector<float> history() const;  // oldest first
    double medianFrameMs() const;        // over every frame so far (to 0.05 ms)
    bool gpuTimersAvailable() const { return !queries_.empty(); }

    // ---- the trace ----
    // Starts keeping frame records for `path` (written by writeTrace()).
    void startRecording(const std::string& path);
    bool recording() const { return !tracePath_.empty(); }
    std::size_t recordedFrames() const { return records_.size(); }
    // Writes the records to the path given to startRecording and stops recording.
    // Throws std::runtime_error naming the file when it cannot be written.
    void writeTrace();

private:
    struct Span {
        Stage stage;
        double startUs, durationUs;
    };
    struct FrameRecord {
        std::uint64_t index = 0;
        double startUs = 0, durationUs = 0;
        double gpuStartUs = 0, gpuUs = -1;
        std::vector<Span> spans;
        FrameCounters counters;
    };
    struct WorkerSpan {
        std::string name;
        double startUs, durationUs;
    };
    struct PendingQuery {
        std::size_t slot = 0;
        std::uint64_t frame = 0;
        double startUs = 0;
    };

    double microseconds(Clock::time_point t) const;
    void collectGpuResults();

    Clock::time_point epoch_;
    std::uint64_t frameIndex_ = 0;
    Clock::time_point frameStart_{};
    std::array<double, kStageCount> stageMs_{}, lastStageMs_{};
    double lastFrameMs_ = 0.0, lastGpuMs_ = -1.0, fps_ = 0.0;
    std::array<float, kHistory> history_{};
    std::size_t historyCount_ = 0;
    // Frame times in 0.05 ms bins up to 2 s (the last bin holds longer ones): a
    // median without keeping every frame.
    std::vector<std::uint32_t> medianBins_;

    // GPU timers: a ring, so a query is reused only once its result was read.
    std::vector<gl::TimerQuery> queries_;
    std::vector<bool> queryBusy_;
    std::vector<PendingQuery> pending_;
    std::size_t nextQuery_ = 0;
    bool gpuOpen_ = false;
    PendingQuery current_{};

    std::string tracePath_;
    std::vector<FrameRecord> records_;
    std::vector<WorkerSpan> workerSpans_;
    FrameRecord frame_;
};

}  // namespace isotrack::viewer
