// isotrack tree: the contour tree of a volume, summarised, as JSON or as an SVG plot.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "cli/commands.h"
#include "cli/source.h"
#include "cli/timed_extraction.h"
#include "isotrack/contour_tree.h"
#include "isotrack/errors.h"
#include "isotrack/safe_write.h"

namespace isotrack::cli {
namespace {

struct TreeOptions {
    SourceOptions source;
    std::optional<double> at;
    std::string out;
    double minPersistence = 0.0;
    std::size_t minSize = 0;
    int threads = std::max(1, int(std::thread::hardware_concurrency()));
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

// Nodes placed left to right by a walk of the kept tree from its lowest node:
// leaves take the next column, inner nodes the middle of their children's.
std::vector<double> nodeColumns(const ContourTree& tree, double& columns) {
    const std::size_t n = tree.nodes.size();
    std::vector<std::vector<std::size_t>> adjacent(n);
    for (const ContourTree::Arc& arc : tree.arcs) {
        if (arc.pruned) continue;
        adjacent[arc.lower].push_back(arc.upper);
        adjacent[arc.upper].push_back(arc.lower);
    }
    std::vector<double> x(n, -1.0);
    std::size_t root = 0;
    for (std::size_t k = 0; k < n; ++k) {
        if (!adjacent[k].empty() && (adjacent[root].empty() || tree.nodes[k].value < tree.nodes[root].value)) root = k;
    }
    columns = 0.0;
    // Iterative post-order walk: (node, parent, next child).
    struct Frame {
        std::size_t node, parent, next;
    };
    std::vector<Frame> stack{{root, n, 0}};
    while (!stack.empty()) {
        Frame& f = stack.back();
        if (f.next < adjacent[f.node].size()) {
            const std::size_t child = adjacent[f.node][f.next++];
            if (child != f.parent) stack.push_back({child, f.node, 0});
            continue;
        }
        double sum = 0.0;
        int children = 0;
        for (const std::size_t c : adjacent[f.node]) {
            if (c != f.parent) sum += x[c], ++children;
        }
        x[f.node] = children ? sum / children : columns++;
        stack.pop_back();
    }
    return x;
}

std::string treeSvg(const ContourTree& tree, double at) {
    double columns = 0.0;
    const std::vector<double> x = nodeColumns(tree, columns);
    double lo = INFINITY, hi = -INFINITY;
    for (const ContourTree::Node& node : tree.nodes) {
        if (std::isfinite(node.value)) lo = std::min(lo, node.value), hi = std::max(hi, node.value);
    }
    if (!(hi > lo)) hi = lo + 1.0;
    const double width = 800, height = 600, margin = 40;
    auto px = [&](std::size_t node) {
        return margin + (width - 2 * margin) * (x[node] + 0.5) / std::max(columns, 1.0);
    };
    auto py = [&](double v) {
        const double t = std::isfinite(v) ? (v - lo) / (hi - lo) : 0.0;
        return height - margin - (height - 2 * margin) * t;
    };
    std::ostringstream svg;
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\">\n"
        << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    const std::vector<std::size_t> alive = tree.arcsAt(at);
    std::vector<char> isAlive(tree.arcs.size(), 0);
    for (const std::size_t a : alive) isAlive[a] = 1;
    for (std::size_t a = 0; a < tree.arcs.size(); ++a) {
        const ContourTree::Arc& arc = tree.arcs[a];
        if (arc.pruned) continue;
        // Colours as the viewer's: by rank among the arcs at v, golden-angle hues.
        const double hue = isAlive[a] ? std::fmod(double(a) * 137.508, 360.0) : 0.0;
        svg << "<line x1=\"" << px(arc.lower) << "\" y1=\"" << py(tree.nodes[arc.lower].value) << "\" x2=\""
            << px(arc.upper) << "\" y2=\"" << py(tree.nodes[arc.upper].value) << "\" stroke=\""
            << (isAlive[a] ? "hsl(" + std::to_string(int(hue)) + ",70%,45%)" : std::string("#999"))
            << "\" stroke-width=\"" << (isAlive[a] ? 2 : 1) << "\"><title>arc " << a << "</title></line>\n";
    }
    svg << "<line x1=\"0\" x2=\"" << width << "\" y1=\"" << py(at) << "\" y2=\"" << py(at)
        << "\" stroke=\"black\" stroke-dasharray=\"4 3\"/>\n"
        << "<text x=\"4\" y=\"" << py(at) - 4 << "\" font-size=\"12\">iso " << at << ": " << alive.size()
        << " surfaces</text>\n"
        << "<text x=\"4\" y=\"14\" font-size=\"12\">" << hi << "</text><text x=\"4\" y=\"" << height - 4
        << "\" font-size=\"12\">" << lo << "</text>\n</svg>\n";
    return svg.str();
}

int runTree(const TreeOptions& options) {
    const bool svg = options.out.size() >= 4 && options.out.compare(options.out.size() - 4, 4, ".svg") == 0;
    const bool json = options.out.size() >= 5 && options.out.compare(options.out.size() - 5, 5, ".json") == 0;
    if (!options.out.empty() && !svg && !json)
        throw InputError("--out " + options.out + ": the tree is written as .json or .svg");
    const Source source = loadSource(options.source);
    const double at = options.at.value_or(source.iso);
    ContourTree tree;
    const double seconds = secondsOf([&] { tree = computeContourTree(source.volume, options.threads); });
    const double simplifySeconds =
        secondsOf([&] { simplifyContourTree(tree, options.minPersistence, options.minSize); });
    std::size_t kept = 0;
    for (const ContourTree::Arc& arc : tree.arcs) kept += arc.pruned ? 0 : 1;
    std::printf(
        "%s: contour tree of %zu nodes, %zu arcs (%zu kept) in %.3f ms (simplified in %.3f ms), %.1f MB; %zu surfaces "
        "at iso %g\n",
        source.name.c_str(), tree.nodes.size(), tree.arcs.size(), kept, seconds * 1e3, simplifySeconds * 1e3,
        double(tree.byteSize()) / 1e6, tree.arcsAt(at).size(), at);
    if (json) writeFileSafely(options.out, treeJson(tree, at).dump() + "\n");
    if (svg) writeFileSafely(options.out, treeSvg(tree, at));
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
    command->add_option("--threads", options->threads, "Threads (the tree uses at most two)")
        ->check(CLI::Range(1, 256));
    return [options] { return runTree(*options); };
}

}  // namespace isotrack::cli
