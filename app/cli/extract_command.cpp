// isotrack extract: one mesh out of a volume, as PLY and/or a JSON summary.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

#include "isotrack/errors.h"
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/source.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tables.h"
#include "isotrack/tracking.h"

namespace isotrack::cli {
namespace {

struct ExtractOptions {
    SourceOptions source;
    std::string table = "consistent";
    std::string method = "mc";
    std::vector<double> seed;
    std::string out;
    bool json = false;
};

struct Extraction {
    Mesh mesh;
    std::vector<std::int32_t> faceComponent;  // for --method all
    std::optional<std::size_t> components;
    std::optional<std::size_t> cellsVisited;
    nlohmann::json surfaces = nlohmann::json::array();
    double seconds = 0.0;
};

nlohmann::json surfaceJson(const SurfaceStats& s) {
    nlohmann::json j{{"triangles", s.triangles},
                     {"vertices", s.vertices},
                     {"cells_visited", s.cellsVisited},
                     {"bytes", s.bytes},
                     {"seconds", s.seconds},
                     {"bounds", {s.boundsMin, s.boundsMax}},
                     {"area", s.area},
                     {"closed", s.closed},
                     {"touches_border", s.touchesBorder}};
    j["enclosed_volume"] = s.enclosedVolume ? nlohmann::json(*s.enclosedVolume) : nlohmann::json(nullptr);
    return j;
}

// Concatenates surfaces into one mesh, labelling each face with its surface's rank.
void appendSurface(const Surface& surface, std::int32_t component, Extraction& out) {
    const auto base = static_cast<std::uint32_t>(out.mesh.vertices.size());
    out.mesh.vertices.insert(out.mesh.vertices.end(), surface.mesh.vertices.begin(), surface.mesh.vertices.end());
    out.mesh.vertexEdges.insert(out.mesh.vertexEdges.end(), surface.mesh.vertexEdges.begin(), surface.mesh.vertexEdges.end());
    for (std::uint32_t index : surface.mesh.indices) out.mesh.indices.push_back(base + index);
    out.faceComponent.insert(out.faceComponent.end(), surface.mesh.triangleCount(), component);
}

Extraction extract(const ExtractOptions& options, const Source& source, TableKind table) {
    Extraction out;
    using Clock = std::chrono::steady_clock;
    if (options.method == "mc") {
        const auto start = Clock::now();
        out.mesh = marchingCubes(source.volume, source.iso, table);
        out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        return out;
    }
    if (options.method == "track") {
        if (options.seed.size() != 3) throw InputError("--method track needs --seed X,Y,Z (world coordinates)");
        const auto start = Clock::now();
        const GridEdge seed = nearestCrossedEdge(source.volume, source.iso, {options.seed[0], options.seed[1], options.seed[2]});
        Surface surface = trackSurface(source.volume, source.iso, seed, table);
        out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        out.components = 1;
        out.cellsVisited = surface.stats.cellsVisited;
        out.surfaces.push_back(surfaceJson(surface.stats));
        out.mesh = std::move(surface.mesh);
        return out;
    }
    const auto start = Clock::now();
    const std::vector<Surface> surfaces = extractAllSurfaces(source.volume, source.iso, table);
    out.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    out.components = surfaces.size();
    std::size_t cells = 0;
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        cells += surfaces[i].stats.cellsVisited;
        out.surfaces.push_back(surfaceJson(surfaces[i].stats));
        if (!options.out.empty()) appendSurface(surfaces[i], static_cast<std::int32_t>(i), out);
        else out.mesh.indices.resize(out.mesh.indices.size() + surfaces[i].mesh.indices.size()),
             out.mesh.vertices.resize(out.mesh.vertices.size() + surfaces[i].mesh.vertices.size());
    }
    out.cellsVisited = cells;
    return out;
}

int runExtract(const ExtractOptions& options) {
    const TableKind table = parseTableKind(options.table);
    const Source source = loadSource(options.source);
    const Dims& dims = source.volume.dims();

    const Extraction result = extract(options, source, table);
    const Mesh& mesh = result.mesh;
    const double seconds = result.seconds;
    if (!options.out.empty()) writePly(options.out, mesh, options.method == "all" ? &result.faceComponent : nullptr);

    const std::size_t cellsTotal =
        std::size_t(std::max(dims[0] - 1, 0)) * std::size_t(std::max(dims[1] - 1, 0)) * std::size_t(std::max(dims[2] - 1, 0));
    if (options.json) {
        nlohmann::json report{
            {"source", source.name},
            {"method", options.method},
            {"table", tableKindName(table)},
            {"isovalue", source.iso},
            {"dims", {dims[0], dims[1], dims[2]}},
            {"spacing", source.volume.spacing()},
            {"scalar_type", scalarTypeName(source.volume.type())},
            {"triangles", mesh.triangleCount()},
            {"vertices", mesh.vertices.size()},
            {"components", result.components ? nlohmann::json(*result.components) : nlohmann::json(nullptr)},
            {"cells_visited", result.cellsVisited ? nlohmann::json(*result.cellsVisited) : nlohmann::json(nullptr)},
            {"cells_total", cellsTotal},
            {"seconds", seconds},
            {"mesh_bytes", mesh.byteSize()},
            {"volume_bytes", source.volume.byteSize()},
        };
        if (!options.out.empty()) report["out"] = options.out;
        if (options.method != "mc") report["surfaces"] = result.surfaces;
        std::printf("%s\n", report.dump().c_str());
    } else {
        std::printf("%s: %zu triangles, %zu vertices", source.name.c_str(), mesh.triangleCount(), mesh.vertices.size());
        if (result.components) std::printf(" in %zu surface%s", *result.components, *result.components == 1 ? "" : "s");
        std::printf(" at iso %g (%s table, method %s) in %.3f ms%s%s\n", source.iso, tableKindName(table),
                    options.method.c_str(), seconds * 1e3, options.out.empty() ? "" : " -> ", options.out.c_str());
    }
    return 0;
}

}  // namespace

RunCommand addExtractCommand(CLI::App& app) {
    auto options = std::make_shared<ExtractOptions>();
    CLI::App* command = app.add_subcommand("extract", "Extract an isosurface and report or save it");
    addSourceOptions(*command, options->source);
    command->add_option("--table", options->table, "Triangle table: consistent (default) or classic")
        ->check(CLI::IsMember({"consistent", "classic"}));
    command->add_option("--method", options->method,
                        "mc: every cell, one mesh; track: the one surface through --seed; all: every surface separately")
        ->check(CLI::IsMember({"mc", "track", "all"}));
    command->add_option("--seed", options->seed, "World point X,Y,Z: tracking starts at the crossed edge nearest to it")
        ->delimiter(',')
        ->expected(3);
    command->add_option("--out", options->out, "Write the mesh to FILE.ply (binary little-endian)");
    command->add_flag("--json", options->json, "Print one JSON object on stdout");
    return [options] { return runExtract(*options); };
}

}  // namespace isotrack::cli
