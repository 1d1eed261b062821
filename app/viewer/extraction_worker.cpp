#include "viewer/extraction_worker.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <limits>

#include "isotrack/errors.h"
#include "isotrack/extract.h"
#include "isotrack/isovalue.h"
#include "isotrack/source.h"

namespace isotrack::viewer {
namespace {

constexpr int kWorkerNice = 5;

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

std::vector<float> histogramOf(const Volume& volume, const std::array<double, 2>& range) {
    const std::vector<std::uint64_t> counts = sampleHistogram(volume, range, kHistogramBins);
    return std::vector<float>(counts.begin(), counts.end());
}

std::string gib(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.3g GiB", double(bytes) / double(std::uint64_t(1) << 30));
    return text;
}

// A volume over the budget has no default isovalue (it would read every sample).
InputError overBudgetWithoutIso(const LoadedVolume& volume, std::uint64_t memoryBudget) {
    return InputError(volume.source.text + ": " + gib(volume.mappedBytes) + " mapped, over the memory budget of " +
                      gib(memoryBudget) + ": give --iso (a default isovalue reads every sample) or a larger " +
                      "--memory-budget");
}

}  // namespace

std::string displayName(const VolumeSource& source) {
    if (source.kind == VolumeSource::Kind::Field) return source.text;
    return std::filesystem::path(source.text).filename().string();
}

bool supersedes(const ExtractionRequest& newer, const ExtractionRequest& older) {
    return newer.source != older.source || newer.method != older.method || newer.table != older.table;
}

std::uint64_t defaultMemoryBudget() { return availableMemoryBytes() / 2; }

// The samples are read (range, histogram, and for a file core's suggested
// isovalue) unless the volume is mapped and over the budget: then nothing is
// read until an extraction goes there, and the isovalue must be given.
std::shared_ptr<LoadedVolume> loadForView(const VolumeSource& source, bool isoGiven, std::uint64_t memoryBudget) {
    LoadedSource read = isotrack::loadSource(source, DefaultIso::Skip);
    auto loaded = std::make_shared<LoadedVolume>();
    loaded->source = source;
    loaded->volume = std::move(read.volume);
    if (read.dicom) loaded->skipped = read.dicom->skipped;
    loaded->mapped = loaded->volume.mappedFile();
    if (loaded->mapped) {
        loaded->mappedBytes = loaded->mapped->size();
        loaded->overBudget = loaded->mappedBytes > memoryBudget;
    }
    if (loaded->overBudget) {
        if (!isoGiven) throw overBudgetWithoutIso(*loaded, memoryBudget);
        loaded->valuesRead = false;
        loaded->defaultIso = std::numeric_limits<double>::quiet_NaN();
        return loaded;
    }
    loaded->range = loaded->volume.range();
    if (!std::isfinite(loaded->range[0])) throw InputError(source.text + ": no finite samples");
    loaded->defaultIso = read.defaultIso ? *read.defaultIso : suggestIsovalue(loaded->volume, loaded->range);
    loaded->histogram = histogramOf(loaded->volume, loaded->range);
    return loaded;
}

ExtractionWorker::ExtractionWorker(int threads, std::uint64_t memoryBudget, std::size_t plotBranches)
    : threads_(std::max(threads, 1)),
      memoryBudget_(memoryBudget),
      plotBranches_(plotBranches),
      thread_([this] { run(); }) {}

ExtractionWorker::~ExtractionWorker() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
        cancel_ = true;  // whatever runs is pointless now
    }
    wake_.notify_all();
    thread_.join();
}

void ExtractionWorker::submit(ExtractionRequest request) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (running_ && supersedes(request, *running_)) cancel_ = true;
        if (finished_ && (finished_->method != request.method || finished_->table != request.table ||
                          !finished_->volume || finished_->volume->source != request.source)) {
            finished_.reset();
        }
        // A flexible surface's request must not drop a waiting request for the whole scene.
        if (request.onlyOwnIsovalues && pending_ && !pending_->onlyOwnIsovalues) request.onlyOwnIsovalues = false;
        pending_ = std::move(request);
    }
    wake_.notify_all();
}

void ExtractionWorker::cancel() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (running_) cancel_ = true;
    pending_.reset();
    finished_.reset();
}

std::optional<ExtractionResult> ExtractionWorker::poll() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::optional<ExtractionResult> result = std::move(finished_);
    finished_.reset();
    return result;
}

bool ExtractionWorker::busy() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return running_.has_value() || pending_.has_value() || finished_.has_value();
}

WorkerProgress ExtractionWorker::progress() const {
    std::lock_guard<std::mutex> lock(mutex_);
    WorkerProgress progress;
    progress.busy = running_.has_value() || pending_.has_value();
    if (!progress.busy) return progress;
    progress.what = running_ ? phase_ : "waiting";
    progress.seconds = running_ ? msSince(phaseStart_) / 1000.0 : 0.0;
    const int total = follow_.seedsTotal.load();
    const std::uint64_t slabs = follow_.march.slabsTotal.load(std::memory_order_relaxed);
    if (running_ && buildingTree_.load()) {
        progress.what = std::string("building the contour tree: ") + contourTreePhaseName(treeBuild_.phase.load());
        progress.fraction = float(treeBuild_.fraction());
    } else if (running_ && slabs > 0) {  // mc, all: how much of the volume has streamed past
        const std::uint64_t done = std::min(follow_.march.slabsDone.load(std::memory_order_relaxed), slabs);
        progress.fraction = float(double(done) / double(slabs));
        if (done == slabs) progress.what += ": marched, finishing";
    } else if (total > 0) {
        progress.fraction = float(follow_.seedsDone.load()) / float(total);
    } else if (expectedMs_ > 0.0) {
        // The same extraction took expectedMs_ last time; never claim to be done.
        progress.fraction = static_cast<float>(std::min(0.95, progress.seconds * 1000.0 / expectedMs_));
    }
    return progress;
}

void ExtractionWorker::setPhase(const std::string& what, double expectedMs) {
    std::lock_guard<std::mutex> lock(mutex_);
    phase_ = what;
    phaseStart_ = Clock::now();
    expectedMs_ = expectedMs;
}

void ExtractionWorker::run() {
    // Below the frame loop and the GL driver's threads (llvmpipe rasterises on
    // the CPU): on a small machine the window keeps its frame rate and the
    // extraction takes the cycles left over.
    setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), kWorkerNice);
    for (;;) {
        ExtractionRequest request;
        {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this] { return stop_ || pending_.has_value(); });
            if (stop_) return;
            request = std::move(*pending_);
            pending_.reset();
            running_ = request;
            running_->surfaces.clear();
            cancel_ = false;
        }
        std::optional<ExtractionResult> result;
        try {
            result = work(request);
        } catch (const Cancelled&) {
            ++cancelled_;
        }
        std::lock_guard<std::mutex> lock(mutex_);
        running_.reset();
        if (result && !cancel_) finished_ = std::move(*result);  // newer than any result not yet polled
    }
}

ExtractionResult ExtractionWorker::work(const ExtractionRequest& request) {
    ExtractionResult result;
    result.started = Clock::now();
    result.generation = request.generation;
    result.table = request.table;
    result.method = request.method;
    try {
        result.volume = volumeFor(request, result.loadMs);
        if (cancelling()) throw Cancelled{};
        if (!request.iso && !result.volume->valuesRead) throw overBudgetWithoutIso(*result.volume, memoryBudget_);
        result.iso = request.iso.value_or(result.volume->defaultIso);
        extract(request, *result.volume, result);
    } catch (const std::bad_alloc&) {
        result.error = "out of memory";
    } catch (const Cancelled&) {
        throw;
    } catch (const std::exception& e) {
        result.error = e.what();
    }
    if (!result.error.empty()) result.next = NextExtraction{};
    result.finished = Clock::now();
    return result;
}

std::shared_ptr<const LoadedVolume> ExtractionWorker::volumeFor(const ExtractionRequest& request, double& loadMs) {
    const VolumeSource& source = request.source;
    if (cache_ && cache_->source == source) return cache_;
    setPhase(source.kind == VolumeSource::Kind::Field ? "building " + source.text : "loading " + displayName(source),
             0.0);
    const auto start = Clock::now();
    cache_.reset();  // the old volume goes before the new one is read
    tree_.reset();
    simplified_.reset();
    treeLayout_.reset();
    fullLayout_.reset();
    simplifiedLayout_.reset();
    cache_ = loadForView(source, request.iso.has_value(), memoryBudget_);
    loadMs = msSince(start);
    return cache_;
}

void ExtractionWorker::extract(const ExtractionRequest& request, const LoadedVolume& loaded, ExtractionResult& result) {
    const std::string key = loaded.source.text + "|" + methodName(request.method);
    const auto known = lastMs_.find(key);
    const double expectedMs = known != lastMs_.end() ? known->second : 0.0;
    setPhase(request.work, expectedMs);
    const Volume& volume = loaded.volume;
    const auto start = Clock::now();
    FollowRequest follow;
    follow.volume = &volume;
    follow.iso = result.iso;
    follow.method = request.method;
    follow.table = request.table;
    follow.threads = threads_;
    follow.previous = request.surfaces;
    follow.onlyOwnIsovalues = request.onlyOwnIsovalues;
    follow.cancel = &cancel_;
    follow.progress = &follow_;
    const bool tree = request.method == Method::Tree && request.table == TableKind::Consistent;
    if (request.onlyOwnIsovalues) {
        const bool any = std::any_of(request.surfaces.begin(), request.surfaces.end(),
                                     [](const PreviousSurface& s) { return s.own.has_value(); });
        if (tree && any) follow.tree = treeOf(volume, request.minPersistence);
        result.next = extractNext(follow);
        result.extractMs = msSince(start);
        return;
    }
    if (request.method != Method::Track && loaded.overBudget && !request.confirmed) {
        result.confirmBytes = loaded.mappedBytes;  // the viewer asks first; seeds wait too
        return;
    }
    if (tree) {
        follow.tree = treeOf(volume, request.minPersistence);
        result.treeLayout = treeLayout_;
        setPhase(request.work, expectedMs);
    }
    result.next = extractNext(follow);
    result.extractMs = msSince(start);
    lastMs_[key] = result.extractMs;
}

// The volume's contour tree, built once (the phase says so while it is built),
// and its copy simplified by the last persistence asked for. Arcs keep their
// numbers in the copy (pruned ones are only marked), so surfaces match across both.
std::shared_ptr<const ContourTree> ExtractionWorker::treeOf(const Volume& volume, double minPersistence) {
    if (!tree_) {
        setPhase("building the contour tree", lastMs_.count("tree") ? lastMs_["tree"] : 0.0);
        const auto start = Clock::now();
        // Its progress shows in the panel; a new volume or method cancels it (Cancelled).
        treeBuild_.cancel = &cancel_;
        buildingTree_ = true;
        try {
            tree_ = std::make_shared<const ContourTree>(computeContourTree(volume, threads_, &treeBuild_));
        } catch (...) {
            buildingTree_ = false;
            throw;
        }
        buildingTree_ = false;
        fullLayout_ = std::make_shared<const TreeLayout>(layoutContourTree(*tree_, plotBranches_));
        lastMs_["tree"] = msSince(start);
    }
    std::shared_ptr<const ContourTree> tree = tree_;
    if (minPersistence > 0.0) {
        if (!simplified_ || simplifiedBy_ != minPersistence) {
            simplified_.reset();
            ContourTree simplified = *tree_;
            simplifyContourTree(simplified, minPersistence);
            simplified_ = std::make_shared<const ContourTree>(std::move(simplified));
            simplifiedLayout_ = std::make_shared<const TreeLayout>(layoutContourTree(*simplified_, plotBranches_));
            simplifiedBy_ = minPersistence;
        }
        tree = simplified_;
    }
    treeLayout_ = tree == simplified_ ? simplifiedLayout_ : fullLayout_;
    return tree;
}

}  // namespace isotrack::viewer
