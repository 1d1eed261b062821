#pragma once
// A time series read lazily: the step being processed in memory, the next one
// read on a background thread meanwhile, nothing else. A caller walking the
// steps in order (extract --all-times, Python's load_steps) finds each step
// ready, or waits only for what its reading took longer than the work on the
// step before it.
//
// Geometry. Every step must share the first step's grid: its dims, spacing,
// origin and direction. Surfaces are followed from step to step by the grid
// cells they cross (isotrack/follow.h), which mean nothing across two grids, so
// a step whose grid differs is refused (GridMismatch, one line naming the
// step's file, the field and both values) when it is asked for; the steps
// before it are read as usual. The time values are the series' (TimeSeries).
//
// Memory. At most two steps are held: the one returned last (shared with the
// caller, who may keep it longer) and the one being prefetched. A step whose
// samples are mapped from its file (raw NRRD, .nii: isotrack/mapped_file.h) is
// mapped in the background and its pages read when the extraction touches them.
#include <cstddef>
#include <future>
#include <memory>
#include <optional>
#include <string>

#include "isotrack/errors.h"
#include "isotrack/time_series.h"
#include "isotrack/volume.h"

namespace isotrack {

// A step whose grid differs from the series' first step's.
class GridMismatch : public InputError {
public:
    using InputError::InputError;
};

class TimeStepReader {
public:
    // Reads the series' list of steps (readTimeSeries); no samples yet.
    // `array` picks a .vti's PointData array, as for loadTimeStep.
    explicit TimeStepReader(const std::string& path, std::string array = "");
    explicit TimeStepReader(TimeSeries series, std::string array = "");
    ~TimeStepReader();  // waits for a prefetch still running
    TimeStepReader(const TimeStepReader&) = delete;
    TimeStepReader& operator=(const TimeStepReader&) = delete;

    const TimeSeries& series() const { return series_; }
    std::size_t size() const { return series_.steps.size(); }
    double time(std::size_t step) const { return series_.steps.at(step).time; }

    // Step `step`'s volume: the prefetched one when it is the step after the
    // last asked for, else read now (and step 0 too, for its grid, when it
    // has not been read); then the next step starts reading in the background. Throws what loadTimeStep throws
    // (InputError for a step past the end), and GridMismatch.
    std::shared_ptr<const Volume> load(std::size_t step);

private:
    void prefetch(std::size_t step);
    std::shared_ptr<const Volume> checked(std::size_t step, Volume volume);

    TimeSeries series_;
    std::string array_;
    struct Grid {
        Dims dims;
        Vec3d spacing, origin;
        Mat3d direction;
    };
    std::optional<Grid> first_;
    std::size_t prefetched_ = 0;  // the step `next_` reads, when valid
    std::future<Volume> next_;
};

}  // namespace isotrack
