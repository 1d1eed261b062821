#include "viewer/extraction_worker.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>

#include "isotrack/errors.h"
#include "isotrack/extract.h"
#include "isotrack/source.h"

namespace isotrack::viewer {
namespace {

constexpr int kWorkerNice = 5;

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

bool supersedes(const ExtractionRequest& newer, const ExtractionRequest& older) {
    return !sameSeries(newer.source, older.source) || newer.method != older.method || newer.table != older.table;
}

ExtractionWorker::ExtractionWorker(int threads, std::uint64_t memoryBudget, std::size_t plotBranches)
    : threads_(std::max(threads, 1)),
      memoryBudget_(memoryBudget),
      cache_(memoryBudget, plotBranches),
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
                          !finished_->volume || !sameSeries(finished_->volume->source, request.source))) {
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
    } catch (const WorkingMemoryError& e) {  // core names no file: name the one open
        result.error = displayName(request.source) + ": " + e.what();
    } catch (const std::exception& e) {
        result.error = e.what();
    }
    if (!result.error.empty()) result.next = NextExtraction{};
    result.finished = Clock::now();
    return result;
}

std::shared_ptr<const LoadedVolume> ExtractionWorker::volumeFor(const ExtractionRequest& request, double& loadMs) {
    const VolumeSource& source = request.source;
    if (std::shared_ptr<const LoadedVolume> kept = cache_.find(source)) return kept;
    setPhase(source.kind == VolumeSource::Kind::Field ? "building " + source.text : "loading " + displayName(source),
             0.0);
    const auto start = Clock::now();
    std::shared_ptr<const LoadedVolume> loaded = cache_.load(source, request.iso.has_value(), request.series);
    loadMs = msSince(start);
    return loaded;
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
    follow.nextStep = request.nextStep;
    follow.cancel = &cancel_;
    follow.progress = &follow_;
    const bool tree = request.method == Method::Tree && request.table == TableKind::Consistent;
    if (request.onlyOwnIsovalues) {
        const bool any = std::any_of(request.surfaces.begin(), request.surfaces.end(),
                                     [](const PreviousSurface& s) { return s.own.has_value(); });
        if (tree && any) follow.tree = treeOf(request.minPersistence).tree;
        result.treeBuild = std::exchange(built_, std::nullopt);
        result.next = extractNext(follow);
        result.extractMs = msSince(start);
        return;
    }
    if (readsWholeVolume(request.method, request.table) && loaded.overBudget && !request.confirmed) {
        result.confirmBytes = loaded.mappedBytes;  // the viewer asks first; seeds wait too
        return;
    }
    if (tree) {
        const VolumeCache::Tree built = treeOf(request.minPersistence);
        follow.tree = built.tree;
        result.treeLayout = built.layout;
        result.treeBuild = std::exchange(built_, std::nullopt);
        setPhase(request.work, expectedMs);
    }
    result.next = extractNext(follow);
    result.extractMs = msSince(start);
    lastMs_[key] = result.extractMs;
}

// The volume's contour tree, built once (the phase says so while it is built,
// and a new volume or method cancels it), simplified as asked.
VolumeCache::Tree ExtractionWorker::treeOf(double minPersistence) {
    if (!cache_.hasTree()) {
        setPhase("building the contour tree", lastMs_.count("tree") ? lastMs_["tree"] : 0.0);
        const auto start = Clock::now();
        treeBuild_.cancel = &cancel_;
        buildingTree_ = true;
        try {
            cache_.buildTree(threads_, &treeBuild_);
        } catch (...) {
            buildingTree_ = false;
            throw;
        }
        buildingTree_ = false;
        lastMs_["tree"] = msSince(start);
        built_ = TreeBuildTimes{start, treeBuild_.seconds, lastMs_["tree"] / 1000.0};
    }
    return cache_.tree(minPersistence);
}

}  // namespace isotrack::viewer
