#pragma once
// One timed extraction by method name, shared by `extract`, `bench` and `render`.
#include <chrono>
#include <string>
#include <vector>

#include "isotrack/marching_cubes.h"
#include "isotrack/tables.h"
#include "isotrack/tracking.h"
#include "isotrack/volume.h"

namespace isotrack::cli {

struct TimedExtraction {
    double seconds = 0.0;           // extraction only
    Mesh mesh;                      // mc: the one mesh
    std::vector<Surface> surfaces;  // track: the one surface; all: every surface, largest first
};

// The seconds fn() takes, on a steady clock.
template <class Fn>
double secondsOf(Fn&& fn) {
    const auto start = std::chrono::steady_clock::now();
    fn();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// method "mc", "all" or "track" (from the crossed edge nearest `seed`, a world
// point, which must then hold 3 values; finding that edge is timed too).
TimedExtraction extractTimed(const Volume& volume, double iso, const std::string& method, TableKind table, int threads,
                             const std::vector<double>& seed);

// The median of `values` (the mean of the middle two for an even count); 0 when empty.
double median(std::vector<double> values);

}  // namespace isotrack::cli
