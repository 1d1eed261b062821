// extract --all-times: a time series' surfaces followed through its steps
// (cli/all_times.h). The next step is read while this one is extracted
// (TimeStepReader); who each surface is comes from core (SurfaceTimeline).
#include "cli/all_times.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli/timed_extraction.h"
#include "isotrack/continuation.h"
#include "isotrack/errors.h"
#include "isotrack/follow_time.h"
#include "isotrack/io.h"
#include "isotrack/time_step_reader.h"

namespace isotrack::cli {
namespace {

std::string numbered(const char* format, std::size_t n) {
    char text[48];
    std::snprintf(text, sizeof text, format, n);
    return text;
}

template <class T>
nlohmann::json orNull(const std::optional<T>& value) {
    return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

// One surface's record in track.json (the same keys as Python's follow_through_time).
nlohmann::json surfaceRecord(const StepSurface& s, const std::string& file) {
    nlohmann::json j{{"id", s.id},
                     {"continues", orNull(s.continues)},
                     {"split", s.split},
                     {"presence", presenceName(s.presence)},
                     {"merged_into", orNull(s.mergedInto)},
                     {"ended", s.ended}};
    if (s.surface) {
        const SurfaceStats& stats = s.surface->stats;
        j["triangles"] = s.surface->mesh.triangleCount();
        j["area"] = stats.area;
        j["volume"] = orNull(stats.enclosedVolume);
        j["closed"] = stats.closed;
        j["bounds"] = {stats.boundsMin, stats.boundsMax};
        j["file"] = file;
    } else {
        j["triangles"] = 0;
        j["area"] = 0.0;
        j["volume"] = nullptr;
        j["closed"] = false;
        j["bounds"] = nullptr;
        j["file"] = nullptr;
    }
    return j;
}

void writeTrack(const std::filesystem::path& path, const nlohmann::json& track) {
    std::ofstream out(path);
    out << track.dump(1) << "\n";
    if (!out) throw InputError("--out-dir: cannot write " + path.string());
}

}  // namespace

void checkAllTimesOptions(const AllTimesOptions& options) {
    if (options.outDir.empty())
        throw InputError("--all-times writes one mesh per surface per step: give --out-dir DIR");
    if (options.source.volumePath.empty())
        throw InputError(
            "--all-times reads the steps of a time series: give --volume (a .pvd, 4D NIfTI or NRRD, "
            "or a numbered pattern)");
    if (!options.source.raw.dims.empty() || !options.source.raw.series.empty())
        throw InputError("--all-times reads a time series: not with --dims or --series (one volume)");
    if (options.method == Method::Exhaustive)
        throw InputError("--all-times follows surfaces and needs --method all, tree or track, not mc (one mesh)");
}

int runAllTimes(const AllTimesOptions& options) {
    checkAllTimesOptions(options);
    TimeStepReader reader(options.source.volumePath, options.source.raw.array);
    double readSeconds = 0.0;
    std::shared_ptr<const Volume> volume;
    readSeconds += secondsOf([&] { volume = reader.load(0); });

    TimeFollowOptions follow;
    follow.iso = options.source.iso;  // else the first step's suggested isovalue
    follow.method = options.method;
    follow.table = options.table;
    follow.threads = options.threads;
    follow.minPersistence = options.minPersistence;
    follow.minSize = options.minSize;
    follow.frame = options.frame;
    if (options.method == Method::Track)
        follow.seed = Vec3d{options.seed.at(0), options.seed.at(1), options.seed.at(2)};
    SurfaceTimeline timeline(follow);
    prepareTables(options.table);
    StepSurfaces first = timeline.next(*volume, reader.time(0));
    const double iso = *timeline.iso();

    const std::filesystem::path root(options.outDir);
    std::error_code ec;
    std::filesystem::create_directories(root, ec);
    if (ec) throw InputError("--out-dir " + options.outDir + ": cannot create: " + ec.message());
    const Dims& dims = volume->dims();
    nlohmann::json track{{"source", options.source.volumePath},    {"method", methodName(options.method)},
                         {"table", tableKindName(options.table)},  {"isovalue", iso},
                         {"frame", worldFrameName(options.frame)}, {"dims", {dims[0], dims[1], dims[2]}},
                         {"spacing", volume->spacing()},           {"steps", nlohmann::json::array()}};
    std::vector<double> stepSeconds;
    std::size_t files = 0;
    for (std::size_t k = 0; k < reader.size(); ++k) {
        if (k > 0) readSeconds += secondsOf([&] { volume = reader.load(k); });  // prefetched meanwhile
        StepSurfaces step = k == 0 ? std::move(first) : timeline.next(*volume, reader.time(k));
        stepSeconds.push_back(step.seconds);
        const std::string folder = numbered("step_%04zu", k);
        std::filesystem::create_directories(root / folder, ec);
        if (ec) throw InputError("--out-dir " + (root / folder).string() + ": cannot create: " + ec.message());
        nlohmann::json surfaces = nlohmann::json::array();
        std::size_t triangles = 0, shown = 0;
        for (StepSurface& s : step.surfaces) {
            std::string file;
            if (s.surface) {
                file = folder + "/" + numbered("surface_%04zu", s.id) + options.extension;
                writeMesh((root / file).string(), s.surface->mesh);
                triangles += s.surface->mesh.triangleCount();
                ++shown, ++files;
            }
            surfaces.push_back(surfaceRecord(s, file));
        }
        track["steps"].push_back(
            {{"step", k}, {"time", step.time}, {"seconds", step.seconds}, {"surfaces", std::move(surfaces)}});
        if (!options.json)
            std::printf("step %zu (time %g): %zu surface%s, %zu triangles in %.3f ms\n", k, step.time, shown,
                        shown == 1 ? "" : "s", triangles, step.seconds * 1e3);
        volume.reset();  // this step's samples go before the next is taken
    }
    const std::filesystem::path trackPath = root / "track.json";
    writeTrack(trackPath, track);
    if (options.json) {
        nlohmann::json report{{"source", options.source.volumePath},
                              {"method", methodName(options.method)},
                              {"isovalue", iso},
                              {"steps", reader.size()},
                              {"files", files},
                              {"track", trackPath.string()},
                              {"seconds_per_step", stepSeconds},
                              {"seconds_median", median(stepSeconds)},
                              {"read_wait_seconds", readSeconds}};
        std::printf("%s\n", report.dump().c_str());
    } else {
        std::printf(
            "%zu step%s at iso %g (method %s): %zu surface files and %s; %.3f ms a step (median), "
            "%.3f ms waiting for reads\n",
            reader.size(), reader.size() == 1 ? "" : "s", iso, methodName(options.method), files,
            trackPath.string().c_str(), median(stepSeconds) * 1e3, readSeconds * 1e3);
    }
    return 0;
}

}  // namespace isotrack::cli
