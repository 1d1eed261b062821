#pragma once
// extract --all-times --out-dir D: every step of a time series, its surfaces
// followed from step to step (core's SurfaceTimeline, isotrack/follow_time.h),
// one mesh per surface per step and D/track.json with every surface's id.
#include <cstddef>
#include <string>
#include <vector>

#include "cli/source.h"
#include "isotrack/extract.h"
#include "isotrack/orientation.h"
#include "isotrack/tables.h"

namespace isotrack::cli {

struct AllTimesOptions {
    SourceOptions source;
    Method method = Method::All;
    TableKind table = TableKind::Consistent;
    std::vector<double> seed;  // method track: in `frame`, on the first step
    int threads = 1;
    std::string outDir;
    std::string extension = ".ply";  // of the mesh files
    WorldFrame frame = WorldFrame::Lps;
    bool json = false;
    double minPersistence = 0.0;  // method tree
    std::size_t minSize = 0;
};

// The arguments alone: --out-dir given, a method that gives surfaces, a --volume.
void checkAllTimesOptions(const AllTimesOptions& options);

// Writes D/step_SSSS/surface_IIII.EXT (IIII the surface's id) and D/track.json;
// prints a line per step (or one JSON object with --json).
int runAllTimes(const AllTimesOptions& options);

}  // namespace isotrack::cli
