// isotrack extract: one mesh out of a volume, as PLY and/or a JSON summary.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include "isotrack/errors.h"
#include "isotrack/mapped_file.h"

#include "cli/all_times.h"
#include "cli/commands.h"
#include "cli/dask_handoff.h"
#include "cli/dicom_report.h"
#include "cli/source.h"
#include "cli/timed_extraction.h"
#include "cli/tree_progress.h"
#include "command_line/vocabulary.h"
#include "isotrack/continuation.h"
#include "isotrack/contour_tree.h"
#include "isotrack/extract.h"
#include "isotrack/follow.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/mesh_processing.h"
#include "isotrack/orientation.h"
#include "isotrack/tables.h"
#include "isotrack/threads.h"
#include "isotrack/tracking.h"

namespace isotrack::cli {
namespace {

struct ExtractOptions {
    SourceOptions source;
    TableKind table = TableKind::Consistent;
    Method method = Method::Exhaustive;
    std::vector<double> seed;
    int threads = defaultThreadCount();
    int repeat = 1;
    std::string out;
    std::string outDir;                  // --method all: one file per surface
    std::string outFormat;               // of the --out-dir files: ply, obj or stl
    WorldFrame frame = WorldFrame::Lps;  // of the written meshes, the seed and the bounds
    bool json = false;
    double minPersistence = 0.0;      // --method tree: prune the tree's leaf branches below it
    std::size_t minSize = 0;          // --method tree: prune leaf branches sweeping fewer samples
    std::size_t largestArcs = 0;      // --method tree: only the surfaces of the arcs sweeping the most samples
    std::vector<std::string> arcIso;  // --method tree: I:V, surface I at its own isovalue V
    std::string scheduler;            // a Dask scheduler: the extraction runs there (dask_handoff.h)
    bool cap = false;                 // close the surfaces the border cuts
    MeshProcessing processing;        // --smooth, --passband, --decimate, --decimate-error
    bool allTimes = false;            // every step of a time series, surfaces followed (cli/all_times.h)
};

struct Extraction {
    Mesh mesh;
    std::vector<std::int32_t> faceComponent;  // for --method all
    std::optional<std::size_t> components;
    std::optional<std::size_t> cellsVisited;
    nlohmann::json surfaces = nlohmann::json::array();
    std::vector<std::string> surfaceFiles;                   // for --out-dir
    std::size_t triangles = 0, vertices = 0, meshBytes = 0;  // of every surface together
    std::vector<double> seconds;                             // one per run
    std::size_t residentBefore = 0, residentPeak = 0;        // bytes, around the first run
    double treeSeconds =
        0.0;  // --method tree: building (and simplifying) the contour tree, not timed with the extraction
    std::array<double, 4> treePhases{};  // its build's phases (ContourTreeProgress::seconds)
    double processSeconds = 0.0;         // --smooth and --decimate, not timed with the extraction
    std::optional<MeshQuality> quality;  // --method mc with --json: the mesh's
};

nlohmann::json qualityJson(const MeshQuality& q) {
    return {{"degenerate_triangles", q.degenerateTriangles}, {"boundary_edges", q.boundaryEdges},
            {"non_manifold_edges", q.nonManifoldEdges},      {"min_angle_below_1", q.minAngleBelow1},
            {"min_angle_below_10", q.minAngleBelow10},       {"min_angle_below_20", q.minAngleBelow20}};
}

nlohmann::json surfaceJson(const SurfaceStats& s) {
    nlohmann::json j{{"triangles", s.triangles}, {"vertices", s.vertices}, {"cells_visited", s.cellsVisited},
                     {"bytes", s.bytes},         {"seconds", s.seconds},   {"bounds", {s.boundsMin, s.boundsMax}},
                     {"area", s.area},           {"closed", s.closed},     {"touches_border", s.touchesBorder}};
    j["enclosed_volume"] = s.enclosedVolume ? nlohmann::json(*s.enclosedVolume) : nlohmann::json(nullptr);
    if (s.euler) j["euler"] = *s.euler;
    if (s.borderLoops) j["border_loops"] = *s.borderLoops;
    if (s.genus) j["genus"] = *s.genus;
    if (s.arc) j["arc"] = *s.arc;
    if (s.persistence)
        j["persistence"] = std::isfinite(*s.persistence) ? nlohmann::json(*s.persistence) : nlohmann::json(nullptr);
    return j;
}

// One --arc-iso item, I:V: the surface's rank and its isovalue.
std::pair<std::size_t, double> parseArcIso(const std::string& item) {
    const std::size_t colon = item.find(':');
    try {
        if (colon == std::string::npos) throw std::invalid_argument(item);
        std::size_t used = 0;
        const std::string indexText = item.substr(0, colon), isoText = item.substr(colon + 1);
        const std::size_t index = std::stoul(indexText, &used);
        if (used != indexText.size() || indexText.find('-') != std::string::npos) throw std::invalid_argument(item);
        const double iso = std::stod(isoText, &used);
        if (used != isoText.size() || !std::isfinite(iso)) throw std::invalid_argument(item);
        return {index, iso};
    } catch (const std::exception&) {
        throw InputError("--arc-iso " + item + ": expected SURFACE:ISOVALUE, e.g. 0:350");
    }
}

// --arc-iso I:V: surface I (its rank at --iso) at its own isovalue V, followed
// along the contour tree (isotrack/follow.h); the other surfaces stay as they are.
void applyArcIsovalues(const ExtractOptions& options, const Volume& volume, const ContourTree& tree,
                       std::vector<Surface>& surfaces, std::vector<double>& isovalues) {
    for (const std::string& item : options.arcIso) {
        const auto [index, iso] = parseArcIso(item);
        if (index >= surfaces.size() || !surfaces[index].stats.arc) {
            throw InputError("--arc-iso " + item + ": there is no surface " + std::to_string(index) + " (" +
                             std::to_string(surfaces.size()) + " at --iso)");
        }
        std::optional<Surface> surface = surfaceAtOwnIsovalue(tree, volume, *surfaces[index].stats.arc, iso);
        if (!surface) throw InputError("--arc-iso " + item + ": the surface vanishes before that isovalue");
        surfaces[index] = std::move(*surface);
        isovalues[index] = iso;
    }
}

// Concatenates surfaces into one mesh, labelling each face with its surface's rank.
void appendSurface(const Surface& surface, std::int32_t component, Extraction& out) {
    const auto base = static_cast<std::uint32_t>(out.mesh.vertices.size());
    out.mesh.vertices.insert(out.mesh.vertices.end(), surface.mesh.vertices.begin(), surface.mesh.vertices.end());
    out.mesh.vertexEdges.insert(out.mesh.vertexEdges.end(), surface.mesh.vertexEdges.begin(),
                                surface.mesh.vertexEdges.end());
    for (std::uint32_t index : surface.mesh.indices) out.mesh.indices.push_back(base + index);
    out.faceComponent.insert(out.faceComponent.end(), surface.mesh.triangleCount(), component);
}

// The --out-dir files' extension: --out-format, else --out's, else .ply.
std::string surfaceExtension(const ExtractOptions& options) {
    if (!options.outFormat.empty()) return "." + options.outFormat;
    return options.out.empty() ? ".ply" : meshFormatExtension(meshFormatOf(options.out));
}

// DIR/surface_000.EXT, DIR/surface_001.EXT, ... largest surface first.
std::vector<std::string> writeSurfaces(const ExtractOptions& options, const std::vector<Surface>& surfaces) {
    std::error_code ec;
    std::filesystem::create_directories(options.outDir, ec);
    if (ec) throw InputError("--out-dir " + options.outDir + ": cannot create: " + ec.message());
    const std::string extension = surfaceExtension(options);
    std::vector<std::string> files;
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        char name[64];
        std::snprintf(name, sizeof name, "surface_%03zu%s", i, extension.c_str());
        files.push_back((std::filesystem::path(options.outDir) / name).string());
        writeMesh(files.back(), surfaces[i].mesh);
    }
    return files;
}

void countMesh(Extraction& out) {
    out.triangles = out.mesh.triangleCount();
    out.vertices = out.mesh.vertices.size();
    out.meshBytes = out.mesh.byteSize();
}

// One run of the chosen method; only extraction is timed (for tree, the
// tree is built once, before, and timed on its own).
Extraction extractOnce(const ExtractOptions& options, const Source& source, TableKind table, const ContourTree* tree) {
    const Method method = options.method;
    const WorldFrame frame = options.frame;
    const std::vector<double> seed = seedInGrid(source.volume, options.seed, frame);
    ExtractRequest request = extractRequest(method, source.iso, table, options.threads, seed);
    request.tree = tree;
    request.largestArcs = options.largestArcs;
    request.cap = options.cap;
    MeshProcessing processing = options.processing;
    applyVolumeDefaults(processing, source.volume);
    TimedExtraction run = extractTimed(source.volume, request);
    Extraction out;
    out.seconds.push_back(run.seconds);
    std::vector<double> isovalues(run.surfaces.size(), source.iso);
    if (tree && !options.arcIso.empty()) applyArcIsovalues(options, source.volume, *tree, run.surfaces, isovalues);
    // Smoothing and decimation, per surface, in the grid frame (timed apart).
    out.processSeconds = secondsOf([&] {
        for (Surface& surface : run.surfaces) processSurface(surface, processing);
    });
    // Meshes leave the grid for the --frame here, after the timing.
    const FrameTransform transform = gridToFrame(source.volume, frame);
    std::vector<MeshQuality> quality;
    for (Surface& surface : run.surfaces) {
        transformSurface(surface, transform);
        if (options.json && method != Method::Exhaustive && !surface.stats.euler) measureTopology(surface);
        if (options.json) quality.push_back(measureQuality(surface.mesh));
    }
    if (method == Method::Exhaustive) {
        if (options.json) out.quality = quality.front();
        out.mesh = std::move(run.surfaces.front().mesh);
        countMesh(out);
        return out;
    }
    if (method == Method::Track) {
        Surface& surface = run.surfaces.front();
        out.components = 1;
        out.cellsVisited = surface.stats.cellsVisited;
        out.surfaces.push_back(surfaceJson(surface.stats));
        if (options.json) out.surfaces.back()["quality"] = qualityJson(quality.front());
        out.mesh = std::move(surface.mesh);
        countMesh(out);
        return out;
    }
    const std::vector<Surface>& surfaces = run.surfaces;
    out.components = surfaces.size();
    std::size_t cells = 0;
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        cells += surfaces[i].stats.cellsVisited;
        out.surfaces.push_back(surfaceJson(surfaces[i].stats));
        if (options.json) out.surfaces.back()["quality"] = qualityJson(quality[i]);
        if (!options.arcIso.empty()) out.surfaces.back()["isovalue"] = isovalues[i];
        // One labelled mesh is only needed for --out; the counts come from the surfaces.
        if (!options.out.empty()) appendSurface(surfaces[i], static_cast<std::int32_t>(i), out);
        out.triangles += surfaces[i].mesh.triangleCount();
        out.vertices += surfaces[i].mesh.vertices.size();
        out.meshBytes += surfaces[i].mesh.byteSize();
    }
    out.cellsVisited = cells;
    if (!options.outDir.empty()) out.surfaceFiles = writeSurfaces(options, surfaces);
    return out;
}

// Resident memory, from Linux's /proc: the current size, and the high-water mark
// since the last reset (writing 5 to clear_refs resets it). Zero where unavailable.
struct ResidentMemory {
    static std::size_t field(const char* name) {
        std::ifstream status("/proc/self/status");
        std::string line;
        const std::size_t length = std::strlen(name);
        while (std::getline(status, line)) {
            if (line.compare(0, length, name) == 0) return std::size_t(std::stoull(line.substr(length + 1))) * 1024;
        }
        return 0;
    }
    static void resetPeak() { std::ofstream("/proc/self/clear_refs") << "5"; }
    static std::size_t current() { return field("VmRSS"); }
    static std::size_t peak() { return field("VmHWM"); }
};

Extraction extract(const ExtractOptions& options, const Source& source, TableKind table) {
    prepareTables(table);  // the tables are generated once, before any timing
    std::vector<double> seconds;
    Extraction out;
    ExtractOptions quiet = options;  // only the last run writes --out-dir files
    quiet.outDir.clear();
    std::size_t before = 0, peak = 0;
    std::optional<ContourTree> tree;
    double treeSeconds = 0.0;
    std::array<double, 4> treePhases{};
    // With --cap the tree is the padded copy's, built inside the extraction.
    if (options.method == Method::Tree && !options.cap) {
        treeSeconds = secondsOf([&] {
            tree = buildContourTree(source.volume, options.threads, &treePhases);
            if (options.minPersistence > 0 || options.minSize > 0)
                simplifyContourTree(*tree, options.minPersistence, options.minSize);
        });
    }
    for (int run = 0; run < options.repeat; ++run) {
        if (run == 0) {
            ResidentMemory::resetPeak();
            before = ResidentMemory::current();
        }
        out = Extraction{};  // the previous run's mesh is freed first, as a re-extraction would
        out = extractOnce(run + 1 == options.repeat ? options : quiet, source, table, tree ? &*tree : nullptr);
        if (run == 0) peak = ResidentMemory::peak();
        seconds.push_back(out.seconds.front());
    }
    out.seconds = seconds;
    out.treeSeconds = treeSeconds;
    out.treePhases = treePhases;
    out.residentBefore = before;
    out.residentPeak = peak;
    return out;
}

bool perSurface(Method method) { return method == Method::All || method == Method::Tree; }

// Everything that depends on the arguments alone, checked before the volume is
// read or generated: a mistake costs no time, however large the volume.
void checkExtractOptions(const ExtractOptions& options) {
    checkSourceOptions(options.source);
    checkMeshProcessing(options.processing);
    const std::string method = methodName(options.method);
    checkMethodSeed(options.method, options.seed);
    if (!options.out.empty()) meshFormatOf(options.out);  // an unknown extension
    if (!options.outDir.empty() && !perSurface(options.method))
        throw InputError("--out-dir writes one file per surface and needs --method all or tree, not " + method);
    const bool treeOptions =
        options.minPersistence > 0 || options.minSize > 0 || options.largestArcs > 0 || !options.arcIso.empty();
    if (treeOptions && options.method != Method::Tree)
        throw InputError("--min-persistence, --min-size, --largest-arcs and --arc-iso need --method tree, not " +
                         method);
    for (const std::string& item : options.arcIso) parseArcIso(item);
    if (options.cap && (!options.arcIso.empty() || options.minPersistence > 0 || options.minSize > 0))
        throw InputError(
            "--cap builds the padded copy's contour tree: not with --arc-iso, --min-persistence or --min-size");
    if (options.method == Method::Tree && options.table != TableKind::Consistent)
        throw InputError(std::string("--method tree works with the consistent table only, not ") +
                         tableKindName(options.table));
}

// --all-times: the options that apply to every step; the others are refused in one line.
AllTimesOptions allTimesOptions(const ExtractOptions& options) {
    const MeshProcessing& processing = options.processing;
    if (!options.out.empty() || options.repeat != 1 || !options.scheduler.empty() || options.cap ||
        processing.smooths() || processing.decimates() || options.largestArcs > 0 || !options.arcIso.empty())
        throw InputError(
            "--all-times writes one file per surface per step: not with --out, --repeat, --scheduler, --cap, "
            "--smooth, --decimate, --largest-arcs or --arc-iso");
    checkSourceOptions(options.source);
    checkMethodSeed(options.method, options.seed);
    if ((options.minPersistence > 0 || options.minSize > 0) && options.method != Method::Tree)
        throw InputError(std::string("--min-persistence and --min-size need --method tree, not ") +
                         methodName(options.method));
    if (options.method == Method::Tree && options.table != TableKind::Consistent)
        throw InputError(std::string("--method tree works with the consistent table only, not ") +
                         tableKindName(options.table));
    AllTimesOptions all;
    all.source = options.source;
    all.method = options.method;
    all.table = options.table;
    all.seed = options.seed;
    all.threads = options.threads;
    all.outDir = options.outDir;
    all.extension = surfaceExtension(options);
    all.frame = options.frame;
    all.json = options.json;
    all.minPersistence = options.minPersistence;
    all.minSize = options.minSize;
    checkAllTimesOptions(all);
    return all;
}

int runExtract(const ExtractOptions& options) {
    if (options.allTimes) return runAllTimes(allTimesOptions(options));
    checkExtractOptions(options);
    if (wantsDask(options.source.volumePath, options.scheduler)) {
        const DaskRequest dask{options.source.volumePath,
                               options.scheduler,
                               options.source.iso,
                               options.method,
                               options.seed,
                               options.out,
                               options.outDir};
        checkDaskRequest(dask, options.table, options.frame, options.json, !options.outFormat.empty());
        runOnDask(dask);
    }
    const TableKind table = options.table;
    const std::string method = methodName(options.method);
    const Source source = loadSource(options.source);
    const Dims& dims = source.volume.dims();

    const Extraction result = namingSource(source, [&] { return extract(options, source, table); });
    const double seconds = median(result.seconds);
    if (!options.out.empty())
        writeMesh(options.out, result.mesh, perSurface(options.method) ? &result.faceComponent : nullptr);

    const std::size_t cellsTotal = std::size_t(std::max(dims[0] - 1, 0)) * std::size_t(std::max(dims[1] - 1, 0)) *
                                   std::size_t(std::max(dims[2] - 1, 0));
    // The same triangles as an unindexed soup of positions and normals.
    const std::size_t soupBytes = result.triangles * 3 * sizeof(Vertex);
    if (options.json) {
        nlohmann::json report{
            {"source", source.name},
            {"method", method},
            {"table", tableKindName(table)},
            {"isovalue", source.iso},
            {"dims", {dims[0], dims[1], dims[2]}},
            {"spacing", source.volume.spacing()},
            {"frame", worldFrameName(options.frame)},
            {"scalar_type", scalarTypeName(source.volume.type())},
            {"triangles", result.triangles},
            {"vertices", result.vertices},
            {"components", result.components ? nlohmann::json(*result.components) : nlohmann::json(nullptr)},
            {"cells_visited", result.cellsVisited ? nlohmann::json(*result.cellsVisited) : nlohmann::json(nullptr)},
            {"cells_total", cellsTotal},
            {"seconds", seconds},
            {"seconds_all", result.seconds},
            {"threads",
             options.method == Method::Track ? std::min(options.threads, kMaxTrackThreads) : options.threads},
            {"mesh_bytes", result.meshBytes},
            {"soup_bytes", soupBytes},
            {"mesh_to_soup", soupBytes ? double(result.meshBytes) / double(soupBytes) : 0.0},
            {"resident_before_bytes", result.residentBefore},
            {"peak_resident_bytes", result.residentPeak},
            {"peak_above_start_bytes",
             result.residentPeak > result.residentBefore ? result.residentPeak - result.residentBefore : 0},
            {"volume_bytes", source.volume.byteSize()},
            // A mapped file: its bytes still in memory after the extraction (for track,
            // every page it touched; streaming passes let passed slices go).
            {"volume_mapped", source.volume.mappedFile() != nullptr},
            {"volume_resident_bytes",
             source.volume.mappedFile() ? source.volume.mappedFile()->residentBytes() : source.volume.byteSize()},
        };
        if (options.method == Method::Tree) {
            report["tree_seconds"] = result.treeSeconds;
            const std::array<double, 4>& p = result.treePhases;
            report["tree_phase_seconds"] = {{"sort", p[0]}, {"sweeps", p[1]}, {"merge", p[2]}, {"arcs", p[3]}};
        }
        report["cap"] = options.cap;
        report["smooth"] = options.processing.smoothIterations;
        report["passband"] = options.processing.passband;
        // The bounds processing used: the options', else core's defaults.
        MeshProcessing used = options.processing;
        applyVolumeDefaults(used, source.volume);
        report["smooth_tolerance"] =
            used.smoothTolerance ? nlohmann::json(*used.smoothTolerance) : nlohmann::json(nullptr);
        report["decimate"] = options.processing.decimateRatio;
        report["decimate_error"] = used.decimateError ? nlohmann::json(*used.decimateError) : nlohmann::json(nullptr);
        report["process_seconds"] = result.processSeconds;
        if (result.quality) report["quality"] = qualityJson(*result.quality);
        if (!options.out.empty()) report["out"] = options.out;
        if (!options.outDir.empty()) report["out_files"] = result.surfaceFiles;
        if (options.method != Method::Exhaustive) report["surfaces"] = result.surfaces;
        if (source.dicom) {
            const DicomSeries& read = source.dicom->series.at(source.dicomSeries);
            report["dicom_series"] = {{"number", source.dicomSeries + 1}, {"uid", read.uid}};
            addSkippedJson(report, *source.dicom);
        }
        std::printf("%s\n", report.dump().c_str());
    } else {
        std::printf("%s: %zu triangles, %zu vertices", source.name.c_str(), result.triangles, result.vertices);
        if (result.components) std::printf(" in %zu surface%s", *result.components, *result.components == 1 ? "" : "s");
        std::printf(" at iso %g (%s table, method %s) in %.3f ms%s%s\n", source.iso, tableKindName(table),
                    method.c_str(), seconds * 1e3, options.out.empty() ? "" : " -> ", options.out.c_str());
        if (options.method == Method::Tree) {
            const std::array<double, 4>& p = result.treePhases;
            std::printf("contour tree built in %.3f ms (sort %.1f, sweeps %.1f, merge %.1f, arcs %.1f ms)\n",
                        result.treeSeconds * 1e3, p[0] * 1e3, p[1] * 1e3, p[2] * 1e3, p[3] * 1e3);
        }
        const MeshProcessing& processing = options.processing;
        if (processing.smooths() || processing.decimates())
            std::printf("%s in %.3f ms (the counts above are after it)\n",
                        processing.smooths() && processing.decimates() ? "smoothed and decimated"
                        : processing.smooths()                         ? "smoothed"
                                                                       : "decimated",
                        result.processSeconds * 1e3);
        if (!options.outDir.empty())
            std::printf("%zu surface file%s in %s\n", result.surfaceFiles.size(),
                        result.surfaceFiles.size() == 1 ? "" : "s", options.outDir.c_str());
    }
    return 0;
}

}  // namespace

RunCommand addExtractCommand(CLI::App& app) {
    auto options = std::make_shared<ExtractOptions>();
    CLI::App* command = app.add_subcommand("extract", "Extract an isosurface and report or save it");
    addSourceOptions(*command, options->source);
    command_line::addTableOption(*command, options->table);
    command_line::addMethodOption(
        *command, options->method,
        "mc (default): every cell, one mesh; track: the one surface through --seed (required); all: every "
        "surface separately; tree: every surface, each from its contour-tree arc's seed");
    command
        ->add_option("--min-persistence", options->minPersistence,
                     "With --method tree: leave out the surfaces of leaf branches less persistent than P")
        ->check(CLI::NonNegativeNumber);
    command->add_option("--min-size", options->minSize,
                        "With --method tree: leave out the surfaces of leaf branches sweeping fewer than N samples");
    command->add_option("--largest-arcs", options->largestArcs,
                        "With --method tree: track only the N arcs crossing --iso that sweep the most samples");
    command
        ->add_option("--arc-iso", options->arcIso,
                     "With --method tree: I:V,... surface I (its rank at --iso, 0 the largest) at its own "
                     "isovalue V, followed along the contour tree; the others stay")
        ->delimiter(',');
    command
        ->add_option("--seed", options->seed,
                     "Point X,Y,Z in --frame, required by --method track (and used by it only): tracking starts at "
                     "the crossed edge nearest to it")
        ->delimiter(',')
        ->expected(3);
    command->add_option("--threads", options->threads, "Threads (default: one per hardware thread)")
        ->check(CLI::Range(1, 256));
    command->add_option("--repeat", options->repeat, "Run the extraction K times; seconds is the median")
        ->check(CLI::Range(1, 1000));
    command->add_option(
        "--out", options->out,
        "Write the mesh to FILE: .ply (binary, with a per-face component for --method all), .obj or .stl");
    auto* outDir = command->add_option(
        "--out-dir", options->outDir,
        "With --method all or tree: write each surface to DIR/surface_000.EXT, largest first (with --all-times: "
        "each step's, see there)");
    command
        ->add_option("--out-format", options->outFormat,
                     "Format of the --out-dir files: ply, obj or stl (default: --out's extension, else ply)")
        ->check(CLI::IsMember({"ply", "obj", "stl"}))
        ->needs(outDir);
    command_line::addFrameOption(
        *command, options->frame,
        "Frame of the written meshes, --seed and bounds: lps (world, default), ras, or voxel (indices)");
    command->add_flag("--json", options->json, "Print one JSON object on stdout");
    command
        ->add_flag("--all-times", options->allTimes,
                   "Every step of a time series (--volume: .pvd, 4D NIfTI or NRRD, numbered files) at one --iso, "
                   "surfaces followed from step to step (method all, tree or track): --out-dir DIR gets "
                   "step_SSSS/surface_IIII.EXT (IIII the surface's id) and track.json")
        ->excludes(command->get_option("--time"));
    command->add_option("--scheduler", options->scheduler,
                        "Run on Dask, one task per chunk: tcp://HOST:PORT, or local:N worker processes (a .zarr "
                        "--volume runs on Dask without it; docs/distributed.md)");
    command->add_flag("--cap", options->cap,
                      "Close the surfaces the volume's border cuts, as if the volume were padded with one layer of "
                      "samples below --iso (its smallest sample)");
    command
        ->add_option("--smooth", options->processing.smoothIterations,
                     "Smooth each surface: N iterations of windowed-sinc smoothing (no shrinkage; borders fixed; "
                     "no vertex moves over half the smallest spacing)")
        ->check(CLI::Range(0, 1000));
    command
        ->add_option("--passband", options->processing.passband,
                     "With --smooth: the filter's pass band in (0, 2), smaller smooths more (default 0.1)")
        ->check(CLI::Range(1e-9, 2.0 - 1e-9));
    command
        ->add_option("--decimate", options->processing.decimateRatio,
                     "Decimate each surface to RATIO (0 < RATIO <= 1) of its triangles (meshoptimizer; borders kept)")
        ->check(CLI::Range(1e-9, 1.0));
    command
        ->add_option("--decimate-error", options->processing.decimateError,
                     "Decimate, keeping the surface within E world units of the original (default with --decimate: "
                     "0.98 of the smallest spacing; alone: decimate as far as E allows)")
        ->check(CLI::NonNegativeNumber);
    return [options] { return runExtract(*options); };
}

}  // namespace isotrack::cli
