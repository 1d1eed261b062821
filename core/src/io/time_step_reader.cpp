// A time series read one step ahead (isotrack/time_step_reader.h).
#include "isotrack/time_step_reader.h"

#include <cstdio>
#include <utility>

namespace isotrack {
namespace {

std::string dimsText(const Dims& d) {
    return std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]);
}

std::string vecText(const Vec3d& v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g)", v[0], v[1], v[2]);
    return text;
}

std::string matText(const Mat3d& m) { return "[" + vecText(m[0]) + ", " + vecText(m[1]) + ", " + vecText(m[2]) + "]"; }

}  // namespace

TimeStepReader::TimeStepReader(const std::string& path, std::string array)
    : TimeStepReader(readTimeSeries(path), std::move(array)) {}

TimeStepReader::TimeStepReader(TimeSeries series, std::string array)
    : series_(std::move(series)), array_(std::move(array)) {}

TimeStepReader::~TimeStepReader() {
    if (next_.valid()) next_.wait();
}

void TimeStepReader::prefetch(std::size_t step) {
    if (step >= series_.steps.size()) return;
    prefetched_ = step;
    // The series and the array name outlive the task: the destructor waits for it.
    next_ = std::async(std::launch::async, [this, step] { return loadTimeStep(series_, step, array_); });
}

std::shared_ptr<const Volume> TimeStepReader::checked(std::size_t step, Volume volume) {
    const Grid grid{volume.dims(), volume.spacing(), volume.origin(), volume.direction()};
    if (!first_) {
        first_ = grid;
    } else {
        const std::string where =
            series_.steps[step].file + ": time step " + std::to_string(step) + " of " + series_.path + ": ";
        const std::string tail = ": every step must share the first step's grid";
        if (grid.dims != first_->dims)
            throw GridMismatch(where + "dims " + dimsText(grid.dims) + ", the first step's " + dimsText(first_->dims) +
                               tail);
        if (grid.spacing != first_->spacing)
            throw GridMismatch(where + "spacing " + vecText(grid.spacing) + ", the first step's " +
                               vecText(first_->spacing) + tail);
        if (grid.origin != first_->origin)
            throw GridMismatch(where + "origin " + vecText(grid.origin) + ", the first step's " +
                               vecText(first_->origin) + tail);
        if (grid.direction != first_->direction)
            throw GridMismatch(where + "direction " + matText(grid.direction) + ", the first step's " +
                               matText(first_->direction) + tail);
    }
    return std::make_shared<const Volume>(std::move(volume));
}

std::shared_ptr<const Volume> TimeStepReader::load(std::size_t step) {
    Volume volume;
    if (next_.valid() && prefetched_ == step) {
        volume = next_.get();  // rethrows the background read's error
    } else {
        if (next_.valid()) next_.wait();  // another step was asked for: that read is dropped
        next_ = {};
        volume = loadTimeStep(series_, step, array_);
    }
    // The grid of step 0 is the reference: read it first when the caller starts elsewhere.
    if (!first_ && step != 0) {
        const Volume zero = loadTimeStep(series_, 0, array_);
        first_ = Grid{zero.dims(), zero.spacing(), zero.origin(), zero.direction()};
    }
    std::shared_ptr<const Volume> out = checked(step, std::move(volume));
    prefetch(step + 1);
    return out;
}

}  // namespace isotrack
