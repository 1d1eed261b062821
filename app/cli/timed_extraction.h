#pragma once
// One timed extraction, shared by `extract`, `bench` and `render`.
#include <chrono>
#include <vector>

#include "isotrack/extract.h"
#include "isotrack/volume.h"

namespace isotrack::cli {

struct TimedExtraction {
    double seconds = 0.0;           // extraction only
    std::vector<Surface> surfaces;  // as isotrack::extract gives them (mc: one, unmeasured)
};

// The seconds fn() takes, on a steady clock.
template <class Fn>
double secondsOf(Fn&& fn) {
    const auto start = std::chrono::steady_clock::now();
    fn();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// --method track needs --seed X,Y,Z, and nothing else uses one: InputError for
// a track without a seed or a seed without track (it would be ignored). An
// arguments-only check, made before any volume is read.
void checkMethodSeed(Method method, const std::vector<double>& seed);

// The request for `method` at `iso`; for track, `seed` (a world point, given as
// --seed) must hold 3 values, and finding the crossed edge nearest it is timed too.
ExtractRequest extractRequest(Method method, double iso, TableKind table, int threads, const std::vector<double>& seed);

// isotrack::extract, timed.
TimedExtraction extractTimed(const Volume& volume, const ExtractRequest& request);

// The median of `values` (the mean of the middle two for an even count); 0 when empty.
double median(std::vector<double> values);

}  // namespace isotrack::cli
