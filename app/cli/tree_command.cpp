// isotrack tree: the contour tree of a volume, summarised, as JSON or as an SVG plot.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/source.h"
#include "cli/timed_extraction.h"
#include "cli/tree_progress.h"
#include "cli/tree_svg.h"
#include "isotrack/contour_tree.h"
#include "isotrack/errors.h"
#include "isotrack/safe_write.h"
#include "isotrack/threads.h"
#include "isotrack/tree_layout.h"
#include "render/palette.h"

namespace isotrack::cli {
namespace {

struct TreeOptions {
    SourceOptions source;
    std::optional<double> at;
    std::string out;
    double minPersistence = 0.0;
    std::size_t minSize = 0;
    std::size_t maxBranches = 1000;
    int threads = defaultThreadCount();
};

nlohmann::json treeJson(const ContourTree& tree, double at) {
    nlohmann::json nodes = nlohmann::json::array(), arcs = nlohmann::json::array();
    const Dims& d = tree.dims;
    for (const ContourTree::Node& n : tree.nodes) {
        const std::uint32_t x = n.sample % std::uint32_t(d[0]),
                            y = n.sample / std::uint32_t(d[0]) % std::uint32_t(d[1]),
                            z = n.sample / (std::uint32_t(d[0]) * std::uint32_t(d[1]));
        nodes.push_back({{"sample", {x, y, z}},
                         {"value", std::isnan(n.value) ? nlohmann::json(nullptr) : nlohmann::json(n.value)},
                         {"up", n.up},
                         {"down", n.down}});
    }
    for (std::size_t a = 0; a < tree.arcs.size(); ++a) {
        const ContourTree::Arc& arc = tree.arcs[a];
        const double p = tree.persistence(a);
        arcs.push_back({{"lower", arc.lower},
                        {"upper", arc.upper},
                        {"samples", arc.size()},
                        {"persistence", std::isfinite(p) ? nlohmann::json(p) : nlohmann::json(nullptr)},
                        {"pruned", arc.pruned}});
    }
    return {{"dims", {d[0], d[1], d[2]}}, {"at", at}, {"arcs_at", tree.arcsAt(at)}, {"nodes", nodes}, {"arcs", arcs}};
}

// The surfaces at `at` in the viewer's order (largest first) and colours, on their arcs.
std::vector<PlottedSurface> plottedSurfaces(const ContourTree& tree, const Volume& volume, double at, int threads) {
    std::vector<std::size_t> arcs;
    trackTreeSurfaces(tree, volume, at, threads, &arcs);
    std::vector<PlottedSurface> surfaces;
    for (std::size_t rank = 0; rank < arcs.size(); ++rank) {
        const glm::vec3 colour = render::surfaceColour(rank);
        surfaces.push_back({arcs[rank], {colour.r, colour.g, colour.b}, at});
    }
    return surfaces;
}

int runTree(const TreeOptions& options) {
    const bool svg = options.out.size() >= 4 && options.out.compare(options.out.size() - 4, 4, ".svg") == 0;
    const bool json = options.out.size() >= 5 && options.out.compare(options.out.size() - 5, 5, ".json") == 0;
    if (!options.out.empty() && !svg && !json)
        throw InputError("--out " + options.out + ": the tree is written as .json or .svg");
    if (options.at && !std::isfinite(*options.at)) throw InputError("--at: must be a finite number");
    checkSourceOptions(options.source);
    const Source source = loadSource(options.source);
    const double at = options.at.value_or(source.iso);
    ContourTree tree;
    std::array<double, 4> phases{};
    const double seconds = secondsOf([&] {
        tree = namingSource(source, [&] { return buildContourTree(source.volume, options.threads, &phases); });
    });
    const double simplifySeconds =
        secondsOf([&] { simplifyContourTree(tree, options.minPersistence, options.minSize); });
    std::size_t kept = 0;
    for (const ContourTree::Arc& arc : tree.arcs) kept += arc.pruned ? 0 : 1;
    std::printf(
        "%s: contour tree of %zu nodes, %zu arcs (%zu kept) in %.3f ms (simplified in %.3f ms), %.1f MB; %zu surfaces "
        "at iso %g\n",
        source.name.c_str(), tree.nodes.size(), tree.arcs.size(), kept, seconds * 1e3, simplifySeconds * 1e3,
        double(tree.byteSize()) / 1e6, tree.arcsAt(at).size(), at);
    std::printf("build phases: sort %.1f ms, sweeps %.1f ms, merge %.1f ms, arcs %.1f ms\n", phases[0] * 1e3,
                phases[1] * 1e3, phases[2] * 1e3, phases[3] * 1e3);
    if (json) writeFileSafely(options.out, treeJson(tree, at).dump() + "\n");
    if (svg) {
        TreeLayout layout;
        const double layoutSeconds = secondsOf([&] { layout = layoutContourTree(tree, options.maxBranches); });
        std::printf("plot: %zu branches, %zu arcs drawn, %zu hidden, laid out in %.3f ms\n", layout.branches,
                    layout.segments.size(), layout.hiddenArcs + layout.prunedArcs, layoutSeconds * 1e3);
        writeFileSafely(options.out, treeSvg(layout, plottedSurfaces(tree, source.volume, at, options.threads), at));
    }
    return 0;
}

}  // namespace

RunCommand addTreeCommand(CLI::App& app) {
    auto options = std::make_shared<TreeOptions>();
    CLI::App* command =
        app.add_subcommand("tree", "Compute a volume's contour tree; report it, or write it as JSON or SVG");
    addSourceOptions(*command, options->source);
    command->add_option("--at", options->at,
                        "Isovalue V whose surfaces (arcs) are counted and marked (default: --iso's)");
    command->add_option("--out", options->out, "Write the tree to FILE.json (nodes and arcs) or FILE.svg (a plot)");
    command->add_option("--min-persistence", options->minPersistence, "Prune leaf branches less persistent than P")
        ->check(CLI::NonNegativeNumber);
    command->add_option("--min-size", options->minSize, "Prune leaf branches sweeping fewer than N samples");
    command
        ->add_option("--max-branches", options->maxBranches,
                     "The SVG draws the N most persistent branches (default 1000); the rest are counted")
        ->check(CLI::Range(std::size_t(1), std::size_t(1) << 30));
    command
        ->add_option("--threads", options->threads,
                     "Threads (the sort and the classes use them all, the arcs up to 4, the two sweeps one each)")
        ->check(CLI::Range(1, 256));
    return [options] { return runTree(*options); };
}

}  // namespace isotrack::cli
