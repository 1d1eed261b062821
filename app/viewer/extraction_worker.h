#pragma once
// Long work off the frame loop: loading a volume (or building a field) and
// extracting its surfaces run on one worker std::thread, so the window keeps
// drawing while they run. The frame loop submits a request describing the whole
// scene it wants (source, isovalue, table, method, tracking seeds); a newer
// request replaces one still waiting, and the worker checks the generation
// between passes, dropping work that a newer request has made stale. Finished
// results wait for the frame loop to poll() them and upload them on the main
// thread (GL objects are created only there).
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "isotrack/tables.h"
#include "isotrack/tracking.h"
#include "isotrack/volume.h"
#include "ui/panel_state.h"

namespace isotrack::viewer {

// A built-in field ("blobs:128") or a volume file.
struct SourceSpec {
    enum Kind { Field, File } kind = Field;
    std::string text;
    friend bool operator==(const SourceSpec& a, const SourceSpec& b) { return a.kind == b.kind && a.text == b.text; }
    friend bool operator!=(const SourceSpec& a, const SourceSpec& b) { return !(a == b); }
};

// A loaded volume and what the panel shows about it.
struct LoadedVolume {
    SourceSpec source;
    Volume volume;
    std::array<double, 2> range{0.0, 0.0};
    std::vector<float> histogram;  // sample counts in kHistogramBins bins across `range`
    double defaultIso = 0.0;
};

inline constexpr std::size_t kHistogramBins = 128;

struct ExtractionRequest {
    std::uint64_t generation = 0;
    SourceSpec source;
    std::optional<double> iso;  // nullopt: the field's default, or the middle of a file's range
    TableKind table = TableKind::Consistent;
    ui::Method method = ui::Method::All;
    std::vector<Vec3d> seeds;  // track: re-track the surface nearest each point
};

struct ExtractionResult {
    std::uint64_t generation = 0;
    std::shared_ptr<const LoadedVolume> volume;
    double iso = 0.0;
    TableKind table = TableKind::Consistent;
    ui::Method method = ui::Method::All;
    std::vector<Surface> surfaces;            // mc: one; all: largest first; track: one per distinct seed
    std::vector<std::optional<Vec3d>> seeds;  // per surface: the point it was tracked from (track)
    double loadMs = 0.0, extractMs = 0.0;
    std::chrono::steady_clock::time_point started{}, finished{};  // on the worker
    std::string error;  // set when loading or extracting failed; then only `generation` is meaningful
};

struct WorkerProgress {
    bool busy = false;
    std::string what;
    double seconds = 0.0;
    float fraction = -1.0f;  // < 0: unknown
};

class ExtractionWorker {
public:
    explicit ExtractionWorker(int threads);
    ~ExtractionWorker();  // waits for the current pass to end
    ExtractionWorker(const ExtractionWorker&) = delete;
    ExtractionWorker& operator=(const ExtractionWorker&) = delete;

    void submit(ExtractionRequest request);
    // Drops the waiting request and marks the running one stale: nothing
    // submitted before reaches poll().
    void cancel(std::uint64_t generation);
    // The newest finished result, if one is waiting.
    std::optional<ExtractionResult> poll();
    WorkerProgress progress() const;
    // True while a request is waiting or being worked on.
    bool busy() const;

private:
    using Clock = std::chrono::steady_clock;

    void run();
    ExtractionResult work(const ExtractionRequest& request);
    std::shared_ptr<const LoadedVolume> volumeFor(const SourceSpec& source, double& loadMs);
    void extract(const ExtractionRequest& request, const LoadedVolume& volume, ExtractionResult& result);
    bool stale(std::uint64_t generation) const { return generation != latest_.load(); }
    void setPhase(const std::string& what, double expectedMs);

    const int threads_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<ExtractionRequest> pending_;
    std::optional<ExtractionResult> finished_;
    bool working_ = false;
    bool stop_ = false;
    std::atomic<std::uint64_t> latest_{0};

    // Progress of the current pass (guarded by mutex_).
    std::string phase_;
    Clock::time_point phaseStart_{};
    double expectedMs_ = 0.0;
    std::atomic<int> seedsDone_{0}, seedsTotal_{0};

    // Worker-thread only.
    std::shared_ptr<const LoadedVolume> cache_;
    std::map<std::string, double> lastMs_;  // per source and method: how long extraction took last time

    std::thread thread_;
};

}  // namespace isotrack::viewer
