// Throughput of the exhaustive marching-cubes pass (Mvoxels/s, Mtriangles/s).
#include <benchmark/benchmark.h>

#include <fstream>
#include <string>

#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"

namespace {

void runMarchingCubes(benchmark::State& state, const isotrack::Volume& volume, double iso) {
    isotrack::triangleTable(isotrack::TableKind::Consistent);  // generated once, outside the timing
    std::size_t triangles = 0;
    for (auto _ : state) {
        const isotrack::Mesh mesh = isotrack::marchingCubes(volume, iso);
        triangles = mesh.triangleCount();
        benchmark::DoNotOptimize(mesh.indices.data());
    }
    const double iterations = double(state.iterations());
    state.counters["triangles"] = double(triangles);
    state.counters["Mvoxels/s"] =
        benchmark::Counter(double(volume.sampleCount()) * iterations / 1e6, benchmark::Counter::kIsRate);
    state.counters["Mtriangles/s"] =
        benchmark::Counter(double(triangles) * iterations / 1e6, benchmark::Counter::kIsRate);
}

void fieldBenchmark(benchmark::State& state, const char* spec) {
    const isotrack::FieldSpec field = isotrack::parseFieldSpec(spec);
    const isotrack::Volume volume = isotrack::makeField(field);
    runMarchingCubes(state, volume, isotrack::fieldDefaultIso(field.name));
}

void ctBenchmark(benchmark::State& state) {
    const std::string path = std::string(ISOTRACK_SOURCE_DIR) + "/assets/ct/cranium.nrrd";
    if (!std::ifstream(path)) {
        state.SkipWithError("assets/ct/cranium.nrrd is missing: run scripts/get_ct.sh");
        return;
    }
    runMarchingCubes(state, isotrack::loadVolume(path), 400.5);
}

}  // namespace

BENCHMARK_CAPTURE(fieldBenchmark, sphere256, "sphere:256")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fieldBenchmark, gyroid256, "gyroid:256")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(fieldBenchmark, blobs256, "blobs:256")->Unit(benchmark::kMillisecond);
BENCHMARK(ctBenchmark)->Name("ct_skull_iso400.5")->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
