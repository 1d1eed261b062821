// The CT skull (iso 400.5, seeded at 122,122,160) tracked K times on T threads, for counting
// tools: cachegrind's counts of one track are those of `track_skull T 4` less `track_skull T 1`,
// over three (see docs/performance.md, "Tracking one surface on one thread"). Prints the
// median and least process CPU time of the tracks.
//   build/bench/bench_track_skull [THREADS] [TRACKS]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "isotrack/io.h"
#include "isotrack/tracking.h"

using namespace isotrack;

namespace {

double processSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
    const int threads = argc > 1 ? std::atoi(argv[1]) : 1, tracks = argc > 2 ? std::atoi(argv[2]) : 11;
    if (threads < 1 || tracks < 1) {
        std::fprintf(stderr, "usage: bench_track_skull [THREADS >= 1] [TRACKS >= 1]\n");
        return 2;
    }
    const Volume volume = loadVolume(ISOTRACK_SOURCE_DIR "/assets/ct/cranium.nrrd");
    const GridEdge seed = nearestCrossedEdge(volume, 400.5, Vec3d{122, 122, 160});
    std::vector<double> ms;
    std::size_t triangles = 0;
    for (int i = 0; i < tracks; ++i) {
        const double start = processSeconds();
        const Surface surface = trackSurface(volume, 400.5, seed, TableKind::Consistent, threads);
        ms.push_back((processSeconds() - start) * 1e3);
        triangles = surface.mesh.triangleCount();
    }
    std::sort(ms.begin(), ms.end());
    std::printf("skull on %d thread%s: %zu triangles; process CPU per track: median %.2f ms, least %.2f ms\n", threads,
                threads == 1 ? "" : "s", triangles, ms[ms.size() / 2], ms.front());
    return 0;
}
