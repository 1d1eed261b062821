#include "viewer/profiler.h"

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "isotrack/safe_write.h"

namespace isotrack::viewer {
namespace {

constexpr std::size_t kGpuQueries = 4;
constexpr double kMedianBinMs = 0.05;
constexpr std::size_t kMedianBins = 40000;  // 2 s
constexpr std::size_t kFpsFrames = 30;

}  // namespace

const char* stageName(Stage stage) {
    switch (stage) {
        case Stage::Input: return "input";
        case Stage::Script: return "script";
        case Stage::Pick: return "pick";
        case Stage::Extract: return "extract";
        case Stage::Upload: return "upload";
        case Stage::Ui: return "ui";
        case Stage::Draw: return "draw";
        case Stage::Screenshot: return "screenshot";
        case Stage::Present: return "present";
        case Stage::Count: break;
    }
    return "?";
}

Profiler::Profiler(bool gpuTimers) : epoch_(Clock::now()), medianBins_(kMedianBins, 0) {
    if (gpuTimers) {
        for (std::size_t i = 0; i < kGpuQueries; ++i) queries_.emplace_back();
        queryBusy_.assign(kGpuQueries, false);
    }
}

double Profiler::microseconds(Clock::time_point t) const {
    return std::chrono::duration<double, std::micro>(t - epoch_).count();
}

void Profiler::beginFrame() {
    frameStart_ = Clock::now();
    stageMs_.fill(0.0);
    frame_.spans.clear();
    frame_.index = frameIndex_;
    frame_.startUs = microseconds(frameStart_);
    frame_.gpuUs = -1.0;
    frame_.gpuStartUs = 0.0;
}

void Profiler::add(Stage stage, Clock::time_point start, Clock::time_point end) {
    add(stage, start, std::chrono::duration_cast<std::chrono::nanoseconds>(end - start));
}

void Profiler::add(Stage stage, Clock::time_point start, std::chrono::nanoseconds duration) {
    const double ms = std::chrono::duration<double, std::milli>(duration).count();
    stageMs_[static_cast<std::size_t>(stage)] += ms;
    frame_.spans.push_back(Span{stage, microseconds(start), ms * 1000.0});
}

void Profiler::beginGpu() {
    if (queries_.empty() || queryBusy_[nextQuery_]) return;  // all in flight: skip timing this frame
    queries_[nextQuery_].begin();
    current_ = PendingQuery{nextQuery_, frameIndex_, microseconds(Clock::now())};
    gpuOpen_ = true;
}

void Profiler::endGpu() {
    if (!gpuOpen_) return;
    queries_[current_.slot].end();
    queryBusy_[current_.slot] = true;
    pending_.push_back(current_);
    nextQuery_ = (nextQuery_ + 1) % queries_.size();
    gpuOpen_ = false;
}

void Profiler::collectGpuResults() {
    while (!pending_.empty() && queries_[pending_.front().slot].resultReady()) {
        const PendingQuery done = pending_.front();
        pending_.erase(pending_.begin());
        queryBusy_[done.slot] = false;
        const double us = static_cast<double>(queries_[done.slot].nanoseconds()) / 1000.0;
        lastGpuMs_ = us / 1000.0;
        if (done.frame == frame_.index) {
            frame_.gpuUs = us;
            frame_.gpuStartUs = done.startUs;
        } else if (!records_.empty() && done.frame >= records_.front().index &&
                   done.frame - records_.front().index < records_.size()) {
            FrameRecord& record = records_[done.frame - records_.front().index];
            record.gpuUs = us;
            record.gpuStartUs = done.startUs;
        }
    }
}

void Profiler::endFrame(const FrameCounters& counters) {
    const Clock::time_point end = Clock::now();
    lastFrameMs_ = std::chrono::duration<double, std::milli>(end - frameStart_).count();
    lastStageMs_ = stageMs_;
    collectGpuResults();

    history_[historyCount_ % kHistory] = static_cast<float>(lastFrameMs_);
    ++historyCount_;
    const std::size_t recent = std::min(historyCount_, kFpsFrames);
    double total = 0.0;
    for (std::size_t i = 0; i < recent; ++i) total += history_[(historyCount_ - 1 - i) % kHistory];
    fps_ = total > 0.0 ? 1000.0 * double(recent) / total : 0.0;
    ++medianBins_[std::min(static_cast<std::size_t>(lastFrameMs_ / kMedianBinMs), kMedianBins - 1)];

    if (recording()) {
        frame_.durationUs = lastFrameMs_ * 1000.0;
        frame_.counters = counters;
        records_.push_back(frame_);
    }
    ++frameIndex_;
}

void Profiler::addWorkerSpan(const std::string& name, Clock::time_point start, Clock::time_point end) {
    if (!recording()) return;
    workerSpans_.push_back(
        WorkerSpan{name, microseconds(start), std::chrono::duration<double, std::micro>(end - start).count()});
}

std::vector<float> Profiler::history() const {
    std::vector<float> values;
    const std::size_t count = std::min(historyCount_, kHistory);
    values.reserve(count);
    for (std::size_t i = historyCount_ - count; i < historyCount_; ++i) values.push_back(history_[i % kHistory]);
    return values;
}

double Profiler::medianFrameMs() const {
    if (frameIndex_ == 0) return 0.0;
    const std::uint64_t half = (frameIndex_ + 1) / 2;
    std::uint64_t seen = 0;
    for (std::size_t bin = 0; bin < medianBins_.size(); ++bin) {
        seen += medianBins_[bin];
        if (seen >= half) return (double(bin) + 0.5) * kMedianBinMs;
    }
    return double(kMedianBins) * kMedianBinMs;
}

void Profiler::startRecording(const std::string& path) {
    if (recording()) writeTrace();
    tracePath_ = path;
    records_.clear();
    workerSpans_.clear();
}

void Profiler::writeTrace() {
    if (!recording()) return;
    using nlohmann::json;
    json events = json::array();
    auto metadata = [&](int tid, const char* name) {
        events.push_back({{"name", "thread_name"}, {"ph", "M"}, {"pid", 1}, {"tid", tid}, {"args", {{"name", name}}}});
    };
    events.push_back({{"name", "process_name"}, {"ph", "M"}, {"pid", 1}, {"args", {{"name", "isotrack viewer"}}}});
    metadata(1, "frame loop (CPU)");
    metadata(2, "GPU (timer queries)");
    metadata(3, "extraction worker");
    // A complete ("X") event: a span of `dur` microseconds from `ts` on thread `tid`.
    auto complete = [](const std::string& name, const char* category, int tid, double ts, double dur) {
        return json{{"name", name}, {"cat", category}, {"ph", "X"}, {"pid", 1}, {"tid", tid}, {"ts", ts}, {"dur", dur}};
    };
    for (const FrameRecord& record : records_) {
        const FrameCounters& c = record.counters;
        json frame = complete("frame", "frame", 1, record.startUs, record.durationUs);
        frame["args"] = {{"frame", record.index},
                         {"surfaces", c.surfaces},
                         {"triangles", c.triangles},
                         {"growing", c.growing},
                         {"grown_cells", c.grownCells},
                         {"extracting", c.extracting},
                         {"iso_shown", c.isoShown},
                         {"iso_requested", c.isoRequested},
                         {"extractions_applied", c.extractionsApplied},
                         {"draw_calls", c.drawCalls},
                         {"triangles_drawn", c.trianglesDrawn},
                         {"uploaded_bytes", c.uploadedBytes},
                         {"arena_pages", c.arenaPages},
                         {"arena_free_bytes", c.arenaFreeBytes},
                         {"arena_fragmentation", c.arenaFragmentation},
                         {"arena_moves", c.arenaMoves},
                         {"arena_moved_bytes", c.arenaMovedBytes},
                         {"gpu_ms", record.gpuUs >= 0.0 ? json(record.gpuUs / 1000.0) : json(nullptr)}};
        events.push_back(std::move(frame));
        for (const Span& span : record.spans)
            events.push_back(complete(stageName(span.stage), "stage", 1, span.startUs, span.durationUs));
        if (record.gpuUs >= 0.0) events.push_back(complete("gpu draw", "gpu", 2, record.gpuStartUs, record.gpuUs));
        events.push_back({{"name", "memory"},
                          {"ph", "C"},
                          {"pid", 1},
                          {"ts", record.startUs},
                          {"args", {{"cpu_bytes", c.cpuBytes}, {"gpu_bytes", c.gpuBytes}}}});
    }
    for (const WorkerSpan& span : workerSpans_)
        events.push_back(complete(span.name, "worker", 3, span.startUs, span.durationUs));
    const json trace = {{"traceEvents", events}, {"displayTimeUnit", "ms"}};
    writeFileSafely(tracePath_, trace.dump() + '\n');
    tracePath_.clear();
    records_.clear();
    workerSpans_.clear();
}

}  // namespace isotrack::viewer
