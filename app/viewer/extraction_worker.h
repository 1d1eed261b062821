#pragma once
// Long work off the frame loop: loading a volume (or building a field) and
// extracting its surfaces run on one worker std::thread, so the window keeps
// drawing while they run. The frame loop submits a request describing the whole
// scene it wants (source, isovalue, table, method, the surfaces' seeds and own
// isovalues).
//
// Progressive updates: at most one request waits (a newer one replaces it),
// and the newest finished result is handed to poll() even when a newer request
// is already waiting, so while the isovalue is dragged the view trails the
// slider by about one extraction instead of freezing until the drag ends. A
// request only for another isovalue (or other seeds) lets the running one
// finish, since its result is still worth showing; one for another source,
// method or table makes the running work pointless, and it is cancelled:
// core checks between its passes and between seeds (each seed's surface is
// tracked on all the worker's threads, as `extract --method track` does).
// The extraction is one call to core's extractNext (isotrack/follow.h); the
// frame loop decides who each surface is (continueSurfaces) and uploads the
// meshes on the main thread (GL objects are created only there). With the
// contour tree, a request may ask only for the surfaces with an isovalue of
// their own (flexible isosurfaces): the others are not extracted again.
//
// Volumes bigger than memory: a mapped volume (isotrack/mapped_file.h) whose
// bytes exceed the worker's memory budget is loaded without reading its
// samples (no range, histogram or default isovalue: the request must carry an
// isovalue), and a method that reads the whole volume (mc, all, tree) runs on
// it only when the request is confirmed; unconfirmed, the result carries the
// bytes it would read and no surfaces, for the viewer to ask. While mc or all
// march, progress() reports the slabs done (FollowProgress).
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "isotrack/contour_tree.h"
#include "isotrack/extract.h"
#include "isotrack/follow.h"
#include "isotrack/io.h"
#include "isotrack/mapped_file.h"
#include "isotrack/source.h"
#include "isotrack/tables.h"
#include "isotrack/tracking.h"
#include "isotrack/tree_layout.h"
#include "isotrack/volume.h"
#include "viewer/volume_cache.h"

namespace isotrack::viewer {

struct ExtractionRequest {
    std::uint64_t generation = 0;
    VolumeSource source;
    std::optional<double> iso;  // nullopt: the source's default
    TableKind table = TableKind::Consistent;
    Method method = Method::All;
    std::string work;             // what the progress calls the extraction while it runs
    double minPersistence = 0.0;  // method tree: the tree simplified by this persistence
    // The scene's surfaces by id, with their seeds and own isovalues (no
    // footprints: who each surface is is decided when the result is applied).
    std::vector<PreviousSurface> surfaces;
    bool onlyOwnIsovalues = false;  // extract the surfaces with their own isovalue again, nothing else
    bool confirmed = false;         // mc, all or tree may read a volume over the memory budget
    // A time series of several steps (source.text's), read one step ahead;
    // null for a single volume.
    std::shared_ptr<const TimeSeries> series;
    // The surfaces are another time step's (FollowRequest::nextStep): matched
    // by seed and footprint, not by arc.
    bool nextStep = false;
};

// A contour tree's build: when it began and each phase's wall time
// (ContourTreeProgress::seconds: sorting, sweeping, merging, arcs).
struct TreeBuildTimes {
    std::chrono::steady_clock::time_point start{};
    std::array<double, 4> seconds{};
    double totalSeconds = 0.0;  // the phases and the layout of the plot
};

struct ExtractionResult {
    std::uint64_t generation = 0;
    std::shared_ptr<const LoadedVolume> volume;
    double iso = 0.0;
    TableKind table = TableKind::Consistent;
    Method method = Method::All;
    NextExtraction next;                           // core's extraction, for continueSurfaces (isotrack/follow.h)
    std::shared_ptr<const TreeLayout> treeLayout;  // method tree: the volume's tree laid out for the panel's plot
    std::optional<TreeBuildTimes> treeBuild;       // method tree, when this extraction built the volume's tree
    // Nonzero: the method reads this many bytes of a volume over the memory
    // budget and the request was not confirmed; nothing was extracted.
    std::uint64_t confirmBytes = 0;
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

// A newer request makes an older one's work pointless when it wants another
// volume, method or table (a new isovalue, seed or time step does not: a step
// of the series still shows while the next one is made).
bool supersedes(const ExtractionRequest& newer, const ExtractionRequest& older);

// Whether the method with the table reads every sample of the volume: every
// method but track, and track with the snap table (its sample states cover the
// whole volume). On a volume over the memory budget such work waits for the
// user's word.
inline bool readsWholeVolume(Method method, TableKind table) {
    return method != Method::Track || table == TableKind::Snap;
}

class ExtractionWorker {
public:
    // A contour tree is laid out for a plot of its `plotBranches` most persistent branches.
    ExtractionWorker(int threads, std::uint64_t memoryBudget, std::size_t plotBranches = SIZE_MAX);
    ~ExtractionWorker();  // cancels the current pass and waits for it to end
    ExtractionWorker(const ExtractionWorker&) = delete;
    ExtractionWorker& operator=(const ExtractionWorker&) = delete;

    void submit(ExtractionRequest request);
    // Drops the waiting request and any finished result, and cancels the running
    // one: nothing submitted before reaches poll().
    void cancel();
    // The newest finished result, if one is waiting.
    std::optional<ExtractionResult> poll();
    WorkerProgress progress() const;
    // True while a request is waiting or being worked on, or a result waits.
    bool busy() const;
    // How many passes were cancelled part-way since the worker started.
    std::size_t cancelledCount() const { return cancelled_.load(); }
    // The threads an extraction runs on.
    int threads() const { return threads_; }

private:
    using Clock = std::chrono::steady_clock;

    void run();
    ExtractionResult work(const ExtractionRequest& request);
    std::shared_ptr<const LoadedVolume> volumeFor(const ExtractionRequest& request, double& loadMs);
    void extract(const ExtractionRequest& request, const LoadedVolume& volume, ExtractionResult& result);
    VolumeCache::Tree treeOf(double minPersistence);
    bool cancelling() const { return cancel_.load(std::memory_order_relaxed); }
    void setPhase(const std::string& what, double expectedMs);

    const int threads_;
    const std::uint64_t memoryBudget_;
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<ExtractionRequest> pending_;
    std::optional<ExtractionRequest> running_;  // a copy of what is being worked on (its source, method, table)
    std::optional<ExtractionResult> finished_;
    bool stop_ = false;
    std::atomic<bool> cancel_{false};  // the running pass is pointless now
    std::atomic<std::size_t> cancelled_{0};

    // Progress of the current pass (guarded by mutex_).
    std::string phase_;
    Clock::time_point phaseStart_{};
    double expectedMs_ = 0.0;
    FollowProgress follow_;          // the slabs marched (mc and all) and the seeds followed
    ContourTreeProgress treeBuild_;  // the contour tree's build, while buildingTree_
    std::atomic<bool> buildingTree_{false};

    // Worker-thread only.
    VolumeCache cache_;
    std::map<std::string, double> lastMs_;  // per source and method: how long extraction took last time
    std::optional<TreeBuildTimes> built_;   // the tree treeOf built, for the result that asked for it

    std::thread thread_;
};

}  // namespace isotrack::viewer
