#include "viewer/extraction_worker.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <set>

#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"

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

std::shared_ptr<LoadedVolume> load(const SourceSpec& source) {
    auto loaded = std::make_shared<LoadedVolume>();
    loaded->source = source;
    if (source.kind == SourceSpec::Field) {
        const FieldSpec spec = parseFieldSpec(source.text);
        loaded->volume = makeField(spec);
        loaded->defaultIso = fieldDefaultIso(spec.name);
    } else {
        loaded->volume = loadVolume(source.text);
    }
    loaded->range = loaded->volume.range();
    if (source.kind == SourceSpec::File) loaded->defaultIso = 0.5 * (loaded->range[0] + loaded->range[1]);
    loaded->histogram = histogramOf(loaded->volume, loaded->range);
    return loaded;
}

// The surface's smallest grid edge: the same surface tracked from two seeds has the same one.
std::uint64_t surfaceKey(const Mesh& mesh, const Volume& volume) {
    std::uint64_t key = std::numeric_limits<std::uint64_t>::max();
    for (const PackedGridEdge& packed : mesh.vertexEdges) {
        const GridEdge e = packed;
        key = std::min(key, std::uint64_t(volume.index(e.x, e.y, e.z)) * 3 + std::uint64_t(e.axis));
    }
    return key;
}

const char* methodPhase(ui::Method method) {
    switch (method) {
        case ui::Method::Exhaustive: return "marching cubes";
        case ui::Method::Track: return "tracking";
        case ui::Method::All: return "every surface";
    }
    return "extracting";
}

}  // namespace

ExtractionWorker::ExtractionWorker(int threads) : threads_(std::max(threads, 1)), thread_([this] { run(); }) {}

ExtractionWorker::~ExtractionWorker() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
        latest_ = std::numeric_limits<std::uint64_t>::max();  // whatever runs is stale now
    }
    wake_.notify_all();
    thread_.join();
}

void ExtractionWorker::submit(ExtractionRequest request) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        latest_ = request.generation;
        pending_ = std::move(request);
    }
    wake_.notify_all();
}

void ExtractionWorker::cancel(std::uint64_t generation) {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = generation;
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
    return working_ || pending_.has_value() || finished_.has_value();
}

WorkerProgress ExtractionWorker::progress() const {
    std::lock_guard<std::mutex> lock(mutex_);
    WorkerProgress progress;
    progress.busy = working_ || pending_.has_value();
    if (!progress.busy) return progress;
    progress.what = working_ ? phase_ : "waiting";
    progress.seconds = working_ ? msSince(phaseStart_) / 1000.0 : 0.0;
    const int total = seedsTotal_.load();
    if (total > 0) {
        progress.fraction = float(seedsDone_.load()) / float(total);
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
            working_ = true;
        }
        ExtractionResult result = work(request);
        std::lock_guard<std::mutex> lock(mutex_);
        working_ = false;
        if (!stale(request.generation)) finished_ = std::move(result);
    }
}

ExtractionResult ExtractionWorker::work(const ExtractionRequest& request) {
    ExtractionResult result;
    result.started = Clock::now();
    result.generation = request.generation;
    result.table = request.table;
    result.method = request.method;
    try {
        result.volume = volumeFor(request.source, result.loadMs);
        if (stale(request.generation)) return result;
        result.iso = request.iso.value_or(result.volume->defaultIso);
        extract(request, *result.volume, result);
    } catch (const std::bad_alloc&) {
        result.error = "out of memory";
    } catch (const std::exception& e) {
        result.error = e.what();
    }
    if (!result.error.empty()) result.surfaces.clear();
    result.finished = Clock::now();
    return result;
}

std::shared_ptr<const LoadedVolume> ExtractionWorker::volumeFor(const SourceSpec& source, double& loadMs) {
    if (cache_ && cache_->source == source) return cache_;
    setPhase(source.kind == SourceSpec::Field ? "building " + source.text : "loading " + source.text, 0.0);
    const auto start = Clock::now();
    cache_.reset();  // the old volume goes before the new one is read
    cache_ = load(source);
    loadMs = msSince(start);
    return cache_;
}

void ExtractionWorker::extract(const ExtractionRequest& request, const LoadedVolume& loaded, ExtractionResult& result) {
    const std::string key = loaded.source.text + "|" + ui::methodName(request.method);
    const auto known = lastMs_.find(key);
    setPhase(methodPhase(request.method), known != lastMs_.end() ? known->second : 0.0);
    const Volume& volume = loaded.volume;
    const auto start = Clock::now();
    const bool consistent = request.table == TableKind::Consistent;
    switch (request.method) {
        case ui::Method::Exhaustive: {
            Surface surface;
            surface.mesh = marchingCubes(volume, result.iso, request.table, threads_);
            if (stale(request.generation)) return;
            surface.stats = measureSurface(surface.mesh, volume, consistent);
            result.surfaces.push_back(std::move(surface));
            result.seeds.emplace_back();
            break;
        }
        case ui::Method::All:
            result.surfaces = extractAllSurfaces(volume, result.iso, request.table, threads_);
            result.seeds.resize(result.surfaces.size());
            break;
        case ui::Method::Track: {
            seedsTotal_ = static_cast<int>(request.seeds.size());
            seedsDone_ = 0;
            std::set<std::uint64_t> seen;
            for (const Vec3d& point : request.seeds) {
                if (stale(request.generation)) break;
                ++seedsDone_;
                GridEdge seed;
                try {
                    seed = nearestCrossedEdge(volume, result.iso, point);
                } catch (const InputError&) {
                    continue;  // no surface at this isovalue any more
                }
                Surface surface = trackSurface(volume, result.iso, seed, request.table, threads_);
                if (!seen.insert(surfaceKey(surface.mesh, volume)).second) continue;
                result.surfaces.push_back(std::move(surface));
                result.seeds.emplace_back(point);
            }
            seedsTotal_ = 0;
            break;
        }
    }
    result.extractMs = msSince(start);
    lastMs_[key] = result.extractMs;
}

}  // namespace isotrack::viewer
