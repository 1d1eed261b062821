#include "cli/timed_extraction.h"

#include <algorithm>

#include "isotrack/errors.h"

namespace isotrack::cli {

TimedExtraction extractTimed(const Volume& volume, double iso, const std::string& method, TableKind table, int threads,
                             const std::vector<double>& seed) {
    if (method == "track" && seed.size() != 3) throw InputError("--method track needs --seed X,Y,Z (world coordinates)");
    if (method != "mc" && method != "track" && method != "all") throw InputError("unknown method " + method + " (mc, all or track)");
    TimedExtraction out;
    out.seconds = secondsOf([&] {
        if (method == "mc") {
            out.mesh = marchingCubes(volume, iso, table, threads);
        } else if (method == "track") {
            const GridEdge edge = nearestCrossedEdge(volume, iso, {seed[0], seed[1], seed[2]});
            out.surfaces.push_back(trackSurface(volume, iso, edge, table, threads));
        } else {
            out.surfaces = extractAllSurfaces(volume, iso, table, threads);
        }
    });
    return out;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.0;
}

}  // namespace isotrack::cli
