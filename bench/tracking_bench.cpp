// One surface and every surface, against the exhaustive pass over the same volume.
//
// For each case: the median wall time of several runs, the cells each method
// visits, and the ratios to the exhaustive pass (marchingCubes). Prints a table.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "isotrack/continuation.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"

using namespace isotrack;

namespace {

constexpr int kRuns = 7;

double medianSeconds(const std::function<void()>& run) {
    std::vector<double> times;
    for (int i = 0; i < kRuns; ++i) {
        const auto start = std::chrono::steady_clock::now();
        run();
        times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

struct Row {
    std::string what;
    double seconds;
    std::size_t cells;
    std::size_t triangles;
};

void printCase(const std::string& title, const Volume& volume, double iso,
               const std::vector<std::pair<std::string, Vec3d>>& seeds) {
    const Dims& d = volume.dims();
    const std::size_t cellsTotal = std::size_t(d[0] - 1) * std::size_t(d[1] - 1) * std::size_t(d[2] - 1);
    std::vector<Row> rows;
    std::size_t triangles = 0;
    const double mc = medianSeconds([&] { triangles = marchingCubes(volume, iso).triangleCount(); });
    rows.push_back({"exhaustive (mc)", mc, cellsTotal, triangles});
    std::size_t surfaces = 0, cells = 0;
    const double all = medianSeconds([&] {
        const auto result = extractAllSurfaces(volume, iso);
        surfaces = result.size();
        cells = 0;
        for (const auto& s : result) cells += s.stats.cellsVisited;
    });
    rows.push_back({"every surface (all, " + std::to_string(surfaces) + ")", all, cellsTotal, triangles});
    for (const auto& [name, point] : seeds) {
        const GridEdge seed = nearestCrossedEdge(volume, iso, point);
        Surface surface;
        const double t = medianSeconds([&] { surface = trackSurface(volume, iso, seed); });
        rows.push_back({"track " + name, t, surface.stats.cellsVisited, surface.mesh.triangleCount()});
    }
    std::printf("\n%s: %dx%dx%d, iso %g\n", title.c_str(), d[0], d[1], d[2], iso);
    std::printf("  %-34s %10s %9s %12s %10s %12s\n", "method", "ms", "x mc time", "cells", "x mc cells", "triangles");
    for (const Row& r : rows) {
        std::printf("  %-34s %10.3f %9.4f %12zu %10.5f %12zu\n", r.what.c_str(), r.seconds * 1e3, r.seconds / mc,
                    r.cells, double(r.cells) / double(cellsTotal), r.triangles);
    }
}

}  // namespace

int main() {
    continuationTable(TableKind::Consistent);  // generated once, outside the timing
    std::printf("median of %d runs; 'cells' counts (cell, piece) visits for tracking\n", kRuns);

    const int n = 256;
    auto blobs = blobsFieldBlobs(n);
    std::sort(blobs.begin(), blobs.end(), [](const Blob& a, const Blob& b) { return a.radius < b.radius; });
    auto onBlob = [](const Blob& b) { return Vec3d{b.centre[0] + b.radius, b.centre[1], b.centre[2]}; };
    printCase("blobs:256", makeField({"blobs", n}), fieldDefaultIso("blobs"),
              {{"smallest blob", onBlob(blobs.front())},
               {"median blob", onBlob(blobs[blobs.size() / 2])},
               {"largest blob", onBlob(blobs.back())}});

    const std::string ct = std::string(ISOTRACK_SOURCE_DIR) + "/assets/ct/cranium.nrrd";
    if (std::ifstream(ct)) {
        // The top of the head: the skull is the largest surface at this isovalue.
        printCase("CT skull (assets/ct/cranium.nrrd)", loadVolume(ct), 400.5,
                  {{"skull (top of head)", {122.0, 122.0, 160.0}}});
    } else {
        std::printf("\nCT skipped: run scripts/get_ct.sh to make assets/ct/cranium.nrrd\n");
    }
    return 0;
}
