// isotrack render: a PNG of the isosurfaces, drawn headless through EGL (a GPU
// or Mesa's surfaceless platform) or OSMesa; see docs/headless.md.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <vector>

#include "cli/commands.h"
#include "cli/source.h"
#include "cli/timed_extraction.h"
#include "command_line/vocabulary.h"
#include "headless/headless_context.h"
#include "isotrack/errors.h"
#include "isotrack/extract.h"
#include "isotrack/tables.h"
#include "render/image.h"
#include "render/snapshot.h"

namespace isotrack::cli {
namespace {

constexpr int kMaxImageSide = 8192;

struct RenderOptions {
    SourceOptions source;
    TableKind table = TableKind::Consistent;
    Method method = Method::Exhaustive;
    std::string seed;
    std::string out;
    std::string size = "640x480";
    std::string camera;
    bool wireframe = false;
    bool noBox = false;
    std::optional<std::size_t> select;
    std::string gl = "auto";
    bool json = false;
    int frames = 0;
    bool oneCallPerSurface = false;
};

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

int parseSide(const std::string& text, const std::string& whole) {
    int value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || ptr != end || value < 1 || value > kMaxImageSide) {
        throw InputError("--size \"" + whole + "\": each side must be an integer in 1.." +
                         std::to_string(kMaxImageSide));
    }
    return value;
}

void parseSize(const std::string& text, int& width, int& height) {
    const std::size_t x = text.find('x');
    if (x == std::string::npos) throw InputError("--size \"" + text + "\": expected WIDTHxHEIGHT, e.g. 640x480");
    width = parseSide(text.substr(0, x), text);
    height = parseSide(text.substr(x + 1), text);
}

Vec3d parsePoint(const std::string& text) {
    Vec3d point{};
    std::size_t start = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const std::size_t comma = axis < 2 ? text.find(',', start) : text.size();
        if (comma == std::string::npos) break;
        const std::string field = text.substr(start, comma - start);
        const char* end = field.data() + field.size();
        const auto [ptr, error] = std::from_chars(field.data(), end, point[axis]);
        if (field.empty() || error != std::errc() || ptr != end || !std::isfinite(point[axis])) break;
        if (axis == 2) return point;
        start = comma + 1;
    }
    throw InputError("--seed \"" + text + "\": expected three finite numbers X,Y,Z (a world-space point)");
}

// --seed as a world point; empty without one.
std::vector<double> seedPoint(const RenderOptions& options) {
    if (options.seed.empty()) return {};
    const Vec3d point = parsePoint(options.seed);
    return {point.begin(), point.end()};
}

// The meshes to draw, largest first for "all", on one thread (a tracked
// surface's vertex order is then the same from run to run); seconds in *seconds.
std::vector<Mesh> extractSurfaces(const RenderOptions& options, const Source& source, double* seconds) {
    const std::vector<double> seed = seedInGrid(source.volume, seedPoint(options), WorldFrame::Lps);
    TimedExtraction run =
        extractTimed(source.volume, extractRequest(options.method, source.iso, options.table, 1, seed));
    *seconds = run.seconds;
    std::vector<Mesh> meshes;
    for (Surface& surface : run.surfaces) meshes.push_back(std::move(surface.mesh));
    return meshes;
}

bool endsWithPng(const std::string& path) {
    if (path.size() < 4) return false;
    std::string extension = path.substr(path.size() - 4);
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".png";
}

int runRender(const RenderOptions& options) {
    // Everything that depends on the arguments alone, before the volume is read.
    checkSourceOptions(options.source);
    render::SnapshotOptions snapshotOptions;
    parseSize(options.size, snapshotOptions.width, snapshotOptions.height);
    if (!options.camera.empty()) snapshotOptions.camera = render::parseCamera(options.camera);
    checkMethodSeed(options.method, seedPoint(options));
    if (!endsWithPng(options.out)) throw InputError("--out " + options.out + ": render writes a .png file");
    snapshotOptions.wireframe = options.wireframe;
    snapshotOptions.boundingBox = !options.noBox;
    snapshotOptions.selected = options.select;
    snapshotOptions.timedFrames = options.frames;
    snapshotOptions.oneCallPerSurface = options.oneCallPerSurface;

    const Source source = loadSource(options.source);
    double extractSeconds = 0.0;
    const std::vector<Mesh> meshes = extractSurfaces(options, source, &extractSeconds);
    const double extractMs = extractSeconds * 1e3;
    if (options.select && *options.select >= meshes.size()) {
        throw InputError(
            "--select " + std::to_string(*options.select) + ": out of range, there " +
            (meshes.size() == 1 ? std::string("is 1 surface") : "are " + std::to_string(meshes.size()) + " surfaces") +
            " (0 is the largest)");
    }

    auto start = Clock::now();
    const headless::HeadlessContext context(headless::parseBackend(options.gl));
    const double contextMs = millisecondsSince(start);
    if (!context.fallbackReason().empty()) {
        std::fprintf(stderr, "isotrack: --gl auto: %s; drawing with OSMesa\n", context.fallbackReason().c_str());
    }
    std::vector<const Mesh*> surfaces;
    std::size_t triangles = 0;
    for (const Mesh& mesh : meshes) {
        surfaces.push_back(&mesh);
        triangles += mesh.triangleCount();
    }
    start = Clock::now();
    const render::Snapshot snapshot =
        render::renderSnapshot(surfaces, render::volumeBounds(source.volume), snapshotOptions);
    const double drawMs = millisecondsSince(start);
    render::writePng(snapshot.image, options.out);

    const gl::ContextInfo& info = context.info();
    const char* backend = headless::backendName(context.backend());
    if (options.json) {
        nlohmann::json report{{"out", options.out},
                              {"width", snapshot.image.width},
                              {"height", snapshot.image.height},
                              {"source", source.name},
                              {"method", methodName(options.method)},
                              {"surfaces", meshes.size()},
                              {"triangles", triangles},
                              {"camera", render::formatCamera(snapshot.camera)},
                              {"backend", backend},
                              {"platform", context.platform()},
                              {"renderer", info.renderer},
                              {"version", info.version},
                              {"vendor", info.vendor},
                              {"extract_ms", extractMs},
                              {"context_ms", contextMs},
                              {"draw_ms", drawMs},
                              {"draw_calls", snapshot.counters.drawCalls},
                              {"triangles_drawn", snapshot.counters.triangles}};
        if (options.frames > 0) {
            report["frames"] = options.frames;
            report["frame_ms"] = median(snapshot.frameMs);
            report["submit_ms"] = median(snapshot.submitMs);
        }
        std::printf("%s\n", report.dump(2).c_str());
        return 0;
    }
    std::printf(
        "%s: %dx%d, %s %s, %zu surface%s, %zu triangles, --camera %s; extract %.1f ms, render %.1f ms "
        "(context %.1f, draw %.1f)\n",
        options.out.c_str(), snapshot.image.width, snapshot.image.height, source.name.c_str(),
        methodName(options.method), meshes.size(), meshes.size() == 1 ? "" : "s", triangles,
        render::formatCamera(snapshot.camera).c_str(), extractMs, contextMs + drawMs, contextMs, drawMs);
    std::printf("drawn in %zu draw call%s", snapshot.counters.drawCalls, snapshot.counters.drawCalls == 1 ? "" : "s");
    if (options.frames > 0) {
        std::printf("; %d more frames, median %.2f ms (issuing the GL calls %.2f ms)", options.frames,
                    median(snapshot.frameMs), median(snapshot.submitMs));
    }
    std::printf("\n");
    std::printf("gl: %s, %s: %s, OpenGL %s\n", backend, context.platform().c_str(), info.renderer.c_str(),
                info.version.c_str());
    return 0;
}

}  // namespace

RunCommand addRenderCommand(CLI::App& app) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* command =
        app.add_subcommand("render", "Draw the isosurfaces into a PNG, headless (EGL or OSMesa, no display needed)");
    addSourceOptions(*command, options->source);
    command_line::addMethodOption(
        *command, options->method,
        "mc (default): every cell as one surface; track: the surface through --seed (required); all: "
        "every surface, each in its own colour, largest first",
        {Method::Exhaustive, Method::Track, Method::All});
    command->add_option("--seed", options->seed,
                        "X,Y,Z: world point near the surface to track, required by --method track (and used by it "
                        "only)");
    command_line::addTableOption(*command, options->table);
    command->add_option("--out", options->out, "The PNG file to write")->required();
    command->add_option("--size", options->size, "WIDTHxHEIGHT in pixels, each 1..8192 (default 640x480)");
    command->add_option("--camera", options->camera,
                        "yaw,pitch,distance,tx,ty,tz[,fov]: orbit angles in degrees (z up), distance to and "
                        "position of the target in world units, vertical field of view (default 30); "
                        "default: framing the volume. The camera used is printed.");
    command->add_flag("--wireframe", options->wireframe, "Draw triangle edges over the surfaces");
    command->add_flag("--no-box", options->noBox, "Leave out the volume's bounding box");
    command->add_option("--select", options->select, "Highlight surface INDEX (0 = the largest)");
    command
        ->add_option("--gl", options->gl,
                     "auto: an EGL GPU device if there is one, else OSMesa; egl: an EGL device, else Mesa's "
                     "surfaceless EGL (no display either way); osmesa: Mesa on the CPU, the golden images' "
                     "reference (default auto)")
        ->check(CLI::IsMember({"auto", "egl", "osmesa"}));
    command
        ->add_option("--frames", options->frames,
                     "Benchmark: draw the picture N more times, each timed to the end of the GPU's work; the "
                     "median is printed (frame_ms in --json)")
        ->check(CLI::Range(0, 100000));
    command->add_flag("--one-call-per-surface", options->oneCallPerSurface,
                      "Draw each surface with its own call instead of one call per GPU page (a reference for "
                      "benchmarks; the picture is the same)");
    command->add_flag("--json", options->json,
                      "Print one JSON object on stdout: sizes, triangles, GL backend, renderer, version, timings");
    return [options] { return runRender(*options); };
}

}  // namespace isotrack::cli
