// isotrack bench: several methods and thread counts timed in one process,
// interleaved, so that every figure is taken under the same conditions.
//
// A virtual machine runs the same work faster or slower from one minute to the
// next, and one process faster than another by where its memory landed; ratios
// between figures from separate processes carry that noise. Here each of the
// --repeat passes runs every method at every thread count once (the order
// reversed every other pass), and each figure is the median of its runs.
// `stream` reads every sample once and does nothing else (it counts those at or
// above the isovalue): the floor an extraction's time is measured against.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/source.h"
#include "cli/timed_extraction.h"
#include "command_line/vocabulary.h"
#include "isotrack/continuation.h"
#include "isotrack/errors.h"
#include "isotrack/extract.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"

namespace isotrack::cli {
namespace {

// One of core's methods, or none for stream.
using BenchMethod = std::optional<Method>;
constexpr const char* kStream = "stream";

const char* benchMethodName(const BenchMethod& method) { return method ? methodName(*method) : kStream; }

struct BenchOptions {
    SourceOptions source;
    TableKind table = TableKind::Consistent;
    std::vector<BenchMethod> methods{Method::Exhaustive, Method::All, Method::Track};
    std::vector<int> threads{1, 2};
    std::vector<double> seed;
    int repeat = 5;
    bool json = false;
};

struct Config {
    BenchMethod method;
    int threads = 1;
    std::vector<double> seconds;
    std::size_t triangles = 0, vertices = 0, surfaces = 0;
    std::size_t samplesAbove = 0;  // stream
};

int runBench(const BenchOptions& options) {
    checkSourceOptions(options.source);
    const TableKind table = options.table;
    const bool tracks =
        std::find(options.methods.begin(), options.methods.end(), BenchMethod(Method::Track)) != options.methods.end();
    if (tracks && options.seed.size() != 3) throw InputError("--methods track needs --seed X,Y,Z (world coordinates)");
    const Source source = loadSource(options.source);
    prepareTables(table);  // the tables are generated once, before any timing

    std::vector<Config> configs;
    for (const BenchMethod& method : options.methods) {
        for (const int threads : options.threads) {
            const bool track = method == Method::Track;
            configs.push_back({method, track ? std::min(threads, kMaxTrackThreads) : threads, {}, 0, 0, 0});
        }
    }
    const std::vector<double> gridSeed = seedInGrid(source.volume, options.seed, WorldFrame::Lps);  // a world point
    for (int pass = 0; pass < options.repeat; ++pass) {
        for (std::size_t i = 0; i < configs.size(); ++i) {
            Config& config = configs[pass % 2 ? configs.size() - 1 - i : i];
            if (!config.method) {
                config.seconds.push_back(secondsOf(
                    [&] { config.samplesAbove = countSamplesAbove(source.volume, source.iso, config.threads); }));
                continue;
            }
            const TimedExtraction run = extractTimed(
                source.volume, extractRequest(*config.method, source.iso, table, config.threads, gridSeed));
            config.seconds.push_back(run.seconds);
            config.triangles = 0, config.vertices = 0;
            config.surfaces = run.surfaces.size();
            for (const Surface& surface : run.surfaces) {
                config.triangles += surface.mesh.triangleCount();
                config.vertices += surface.mesh.vertices.size();
            }
        }
    }

    if (options.json) {
        nlohmann::json runs = nlohmann::json::array();
        for (const Config& c : configs) {
            nlohmann::json run{{"method", benchMethodName(c.method)},
                               {"threads", c.threads},
                               {"seconds", median(c.seconds)},
                               {"seconds_all", c.seconds}};
            if (!c.method) {
                run["samples_above"] = c.samplesAbove;
            } else {
                run["triangles"] = c.triangles;
                run["vertices"] = c.vertices;
                run["components"] =
                    c.method == Method::Exhaustive ? nlohmann::json(nullptr) : nlohmann::json(c.surfaces);
            }
            runs.push_back(run);
        }
        const Dims& dims = source.volume.dims();
        nlohmann::json report{{"source", source.name},         {"isovalue", source.iso},
                              {"table", tableKindName(table)}, {"dims", {dims[0], dims[1], dims[2]}},
                              {"repeat", options.repeat},      {"runs", runs}};
        std::printf("%s\n", report.dump().c_str());
        return 0;
    }
    std::printf("%s at iso %g (%s table): medians of %d interleaved runs\n", source.name.c_str(), source.iso,
                tableKindName(table), options.repeat);
    for (const Config& c : configs) {
        std::printf("  %-6s %2d thread%s %10.2f ms  ", benchMethodName(c.method), c.threads, c.threads == 1 ? " " : "s",
                    median(c.seconds) * 1e3);
        if (!c.method) {
            std::printf("every sample read once, %zu at or above the isovalue\n", c.samplesAbove);
            continue;
        }
        std::printf("%zu triangles", c.triangles);
        if (c.method != Method::Exhaustive) std::printf(" in %zu surface%s", c.surfaces, c.surfaces == 1 ? "" : "s");
        std::printf("\n");
    }
    return 0;
}

}  // namespace

RunCommand addBenchCommand(CLI::App& app) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* command =
        app.add_subcommand("bench", "Time several methods and thread counts in one process, interleaved (medians)");
    addSourceOptions(*command, options->source);
    command_line::addTableOption(*command, options->table);
    command_line::addMethodListOption(
        *command, "--methods", {Method::Exhaustive, Method::Track, Method::All}, {kStream},
        [options](const std::vector<std::string>& names) {
            options->methods.clear();
            for (const std::string& name : names)
                options->methods.push_back(name == kStream ? BenchMethod() : BenchMethod(parseMethod(name)));
        },
        "Methods to time, e.g. mc,all,track (default: those three); stream reads every sample once");
    command->add_option("--threads", options->threads, "Thread counts to time, e.g. 1,2 (default)")
        ->delimiter(',')
        ->check(CLI::Range(1, 256));
    command->add_option("--seed", options->seed, "World point X,Y,Z for track: the crossed edge nearest to it")
        ->delimiter(',')
        ->expected(3);
    command->add_option("--repeat", options->repeat, "Passes over every method and thread count; figures are medians")
        ->check(CLI::Range(1, 1000));
    command->add_flag("--json", options->json, "Print one JSON object on stdout");
    return [options] { return runBench(*options); };
}

}  // namespace isotrack::cli
