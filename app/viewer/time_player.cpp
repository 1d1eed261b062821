#include "viewer/time_player.h"

#include <algorithm>
#include <cmath>

#include "isotrack/errors.h"

namespace isotrack::viewer {
namespace {

constexpr double kMinSpeed = 0.1, kMaxSpeed = 60.0;
constexpr std::size_t kMaxShown = 4096;  // the summary's steps shown: the latest
constexpr std::size_t kMaxPlayFrames = std::size_t(1) << 20;

double median(std::vector<float> values) {
    if (values.empty()) return 0.0;
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

}  // namespace

std::size_t TimePlayer::steps() const { return active() ? extraction_.series()->steps.size() : 1; }

double TimePlayer::timeOf(std::size_t step) const {
    if (!active() || step >= steps()) return 0.0;
    return extraction_.series()->steps[step].time;
}

void TimePlayer::ask(std::size_t step) {
    asked_ = Clock::now();
    extraction_.setTimeStep(step);
}

void TimePlayer::setStep(std::size_t step) {
    playing_ = false;
    ask(step);
}

void TimePlayer::stepBy(int delta) {
    if (!active()) return;
    const long last = long(steps()) - 1;
    setStep(std::size_t(std::clamp(long(step()) + delta, 0L, last)));
}

void TimePlayer::play(std::optional<std::size_t> count) {
    if (!active()) return;
    const std::size_t last = steps() - 1;
    if (step() == last) ask(0);
    if (scene_.volume() && !shown_.empty() && shown_.back().step == shownStep()) {
        shown_.pop_back();  // the step on screen as playback starts (selection, colours since its result)
        record();
    }
    playLast_ = count ? std::min(step() + *count, last) : last;
    playing_ = playLast_ != step() || shownStep() != step();
    asked_ = Clock::now();
}

void TimePlayer::togglePlay() {
    if (playing_) {
        pause();
    } else {
        play();
    }
}

void TimePlayer::setSpeed(double stepsPerSecond) {
    if (std::isfinite(stepsPerSecond)) speed_ = std::clamp(stepsPerSecond, kMinSpeed, kMaxSpeed);
}

void TimePlayer::update() {
    if (extraction_.series() != series_) {  // another series (or none): what was seen was another's
        series_ = extraction_.series();
        playing_ = false;
        shown_.clear();
        samples_.clear();
        playFrameMs_.clear();
        shownDuringPlay_ = 0;
    }
    if (!active()) return;
    const bool applied = extraction_.appliedCount() != applied_;
    applied_ = extraction_.appliedCount();
    if (applied && scene_.volume()) {
        const bool newStep = shown_.empty() || shown_.back().step != shownStep();
        if (playing_ && newStep) ++shownDuringPlay_;
        if (!newStep) shown_.pop_back();  // the same step again (another isovalue): its latest look
        if (shown_.size() == kMaxShown) shown_.erase(shown_.begin());
        record();
    }
    if (!playing_) return;
    if (shownStep() != step()) {
        if (!extraction_.busy()) playing_ = false;  // the step failed: its error is shown
        return;
    }
    if (step() >= playLast_) {
        playing_ = false;
        return;
    }
    const double since = std::chrono::duration<double>(Clock::now() - asked_).count();
    if (since >= 1.0 / speed_) ask(step() + 1);
}

void TimePlayer::noteFrame(double ms) {
    if (playing_ && playFrameMs_.size() < kMaxPlayFrames) playFrameMs_.push_back(float(ms));
}

// The surfaces as this result shows them: every surface's area and volume for
// the plot, and the selected surface for the summary.
void TimePlayer::record() {
    const std::size_t step = shownStep();
    Shown shown;
    shown.step = step;
    shown.duringPlay = playing_;
    shown.selected = scene_.selected;
    for (const auto& surface : scene_.surfaces()) {
        const bool present = surface->presence() == Presence::Shown;
        const SurfaceStats& stats = surface->stats();
        if (present) samples_[surface->id()][step] = Sample{stats.area, stats.enclosedVolume};
        if (surface->id() != scene_.selected) continue;
        const glm::vec3& colour = surface->style().colour;
        shown.colour = {colour.r, colour.g, colour.b};
        shown.tracked = surface->tracked();
        shown.present = present;
        for (int i = 0; i < 3; ++i) shown.centre[i] = 0.5 * (stats.boundsMin[i] + stats.boundsMax[i]);
        shown.triangles = surface->mesh().triangleCount();
        shown.area = stats.area;
        shown.volume = stats.enclosedVolume;
    }
    shown_.push_back(shown);
}

ui::TimeState TimePlayer::panelState() const {
    ui::TimeState state;
    if (!active()) return state;
    state.steps = steps();
    state.step = step();
    state.shownStep = shownStep();
    state.time = timeOf(step());
    state.shownTime = timeOf(shownStep());
    state.playing = playing_;
    state.stepsPerSecond = float(speed_);
    if (!scene_.selected) return state;
    const auto found = samples_.find(*scene_.selected);
    if (found == samples_.end()) return state;
    for (const auto& [step, sample] : found->second) {
        state.plotSteps.push_back(step);
        state.area.push_back(float(sample.area));
        state.volume.push_back(float(sample.volume.value_or(0.0)));
    }
    return state;
}

nlohmann::json TimePlayer::summary() const {
    nlohmann::json shown = nlohmann::json::array();
    for (const Shown& s : shown_) {
        nlohmann::json entry = {{"step", s.step}, {"time", timeOf(s.step)}, {"during_play", s.duringPlay}};
        entry["selected"] = s.selected ? nlohmann::json(*s.selected) : nlohmann::json(nullptr);
        if (s.selected) {
            entry["colour"] = {s.colour[0], s.colour[1], s.colour[2]};
            entry["tracked"] = s.tracked;
            entry["present"] = s.present;
            entry["centre"] = {s.centre[0], s.centre[1], s.centre[2]};
            entry["triangles"] = s.triangles;
            entry["area"] = s.area;
            entry["volume"] = s.volume ? nlohmann::json(*s.volume) : nlohmann::json(nullptr);
        }
        shown.push_back(entry);
    }
    return {{"steps", steps()},
            {"step", step()},
            {"step_shown", shownStep()},
            {"time_shown", timeOf(shownStep())},
            {"playing", playing_},
            {"steps_per_second", speed_},
            {"steps_shown_during_play", shownDuringPlay_},
            {"play_frames", playFrameMs_.size()},
            {"play_median_frame_ms", median(playFrameMs_)},
            {"play_max_frame_ms",
             playFrameMs_.empty() ? 0.0 : double(*std::max_element(playFrameMs_.begin(), playFrameMs_.end()))},
            {"shown", shown}};
}

}  // namespace isotrack::viewer
