#pragma once
// Time series in the viewer: the step asked for and the step shown, playback,
// and what each step showed (the selected surface's area and enclosed volume
// for the panel's plot, and the --json summary).
//
// A step is asked of the ExtractionController (setTimeStep): the worker reads
// it (a TimeStepReader, with the step after it prefetched) and extracts it with
// core's follow module told it is the next step (FollowRequest::nextStep), so
// every surface keeps its id, colour, visibility, offset and selection, and a
// tracked surface follows its seed. Playback asks for the next step once the
// one asked for is on screen and 1/speed seconds have passed since the last
// step was asked for: it never skips a step, and goes no faster than the
// extraction. It stops at its last step, or when a step fails.
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "ui/panel_state.h"
#include "viewer/extraction_controller.h"
#include "viewer/scene.h"

namespace isotrack::viewer {

class TimePlayer {
public:
    TimePlayer(ExtractionController& extraction, const Scene& scene) : extraction_(extraction), scene_(scene) {}

    // A time series of several steps is open.
    bool active() const { return extraction_.series() != nullptr; }
    std::size_t steps() const;
    std::size_t step() const { return extraction_.source().time; }  // asked for
    std::size_t shownStep() const { return extraction_.shownStep(); }
    double timeOf(std::size_t step) const;  // the series' time value (0 for a single volume)

    // Asks for `step` (InputError past the last step); a step asked for by
    // hand stops playback.
    void setStep(std::size_t step);
    // The step `delta` steps from the one asked for, clamped to the series (keys, buttons).
    void stepBy(int delta);
    // Plays `count` steps from the one asked for (nullopt: to the last step;
    // from the last step, from the first again).
    void play(std::optional<std::size_t> count = std::nullopt);
    void pause() { playing_ = false; }
    void togglePlay();
    bool playing() const { return playing_; }
    double speed() const { return speed_; }  // steps per second
    void setSpeed(double stepsPerSecond);

    // Once a frame, after the worker's results are taken: notes a step newly
    // shown, and moves playback on. Another series (a load) starts afresh.
    void update();

    // The frame loop's time for one frame (the profiler's), counted while playing.
    void noteFrame(double ms);
    // How many steps were shown (results of another step applied) while playing.
    std::size_t shownDuringPlay() const { return shownDuringPlay_; }
    ui::TimeState panelState() const;
    nlohmann::json summary() const;

private:
    using Clock = std::chrono::steady_clock;
    void record();
    void ask(std::size_t step);

    // What one result shown looked like: the step, and the selected surface.
    struct Shown {
        std::size_t step = 0;
        bool duringPlay = false;
        std::optional<std::uint32_t> selected;
        std::array<float, 3> colour{};
        bool tracked = false;
        bool present = false;   // the selected surface has a mesh at this step
        Vec3d centre{0, 0, 0};  // of its bounding box, in grid coordinates
        std::size_t triangles = 0;
        double area = 0.0;
        std::optional<double> volume;
    };
    // One surface at one step, for the plot.
    struct Sample {
        double area = 0.0;
        std::optional<double> volume;
    };

    ExtractionController& extraction_;
    const Scene& scene_;
    std::shared_ptr<const TimeSeries> series_;  // the series the rest is about
    bool playing_ = false;
    double speed_ = 4.0;
    std::size_t playLast_ = 0;   // the step playback stops at
    Clock::time_point asked_{};  // when playback last asked for a step
    std::size_t applied_ = 0;    // the controller's results applied, at the last update
    std::size_t shownDuringPlay_ = 0;
    std::vector<float> playFrameMs_;  // frame times while playing (the first kMaxPlayFrames)
    std::vector<Shown> shown_;
    std::map<std::uint32_t, std::map<std::size_t, Sample>> samples_;  // by surface id, then step
};

}  // namespace isotrack::viewer
