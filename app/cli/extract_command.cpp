// isotrack extract: one mesh out of a volume, as PLY and/or a JSON summary.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/source.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tables.h"

namespace isotrack::cli {
namespace {

struct ExtractOptions {
    SourceOptions source;
    std::string table = "consistent";
    std::string method = "mc";
    std::string out;
    bool json = false;
};

int runExtract(const ExtractOptions& options) {
    const TableKind table = parseTableKind(options.table);
    const Source source = loadSource(options.source);
    const Dims& dims = source.volume.dims();

    const auto start = std::chrono::steady_clock::now();
    const Mesh mesh = marchingCubes(source.volume, source.iso, table);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    if (!options.out.empty()) writePly(options.out, mesh);

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
            {"components", nullptr},
            {"cells_total", cellsTotal},
            {"seconds", seconds},
            {"mesh_bytes", mesh.byteSize()},
            {"volume_bytes", source.volume.byteSize()},
        };
        if (!options.out.empty()) report["out"] = options.out;
        std::printf("%s\n", report.dump().c_str());
    } else {
        std::printf("%s: %zu triangles, %zu vertices at iso %g (%s table, %s) in %.3f ms%s%s\n", source.name.c_str(),
                    mesh.triangleCount(), mesh.vertices.size(), source.iso, tableKindName(table), options.method.c_str(),
                    seconds * 1e3, options.out.empty() ? "" : " -> ", options.out.c_str());
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
    command->add_option("--method", options->method, "mc: every cell (exhaustive marching cubes)")
        ->check(CLI::IsMember({"mc"}));
    command->add_option("--out", options->out, "Write the mesh to FILE.ply (binary little-endian)");
    command->add_flag("--json", options->json, "Print one JSON object on stdout");
    return [options] { return runExtract(*options); };
}

}  // namespace isotrack::cli
