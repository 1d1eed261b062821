// The topology of a surface: its Euler characteristic V - E + F, the loops of
// its border (edges used by one triangle), and its genus.
#include <algorithm>
#include <numeric>
#include <utility>
#include <vector>

#include "isotrack/surface.h"

namespace isotrack {
namespace {

std::uint32_t loopRoot(std::vector<std::uint32_t>& forest, std::uint32_t v) {
    while (forest[v] != v) v = forest[v] = forest[forest[v]];
    return v;
}

}  // namespace

void measureTopology(Surface& surface) {
    const Mesh& mesh = surface.mesh;
    if (surface.stats.closed) {  // every edge has two triangles: E = 3F / 2, no border
        const long euler = long(mesh.vertices.size()) - long(mesh.triangleCount()) / 2;
        surface.stats.euler = euler;
        surface.stats.borderLoops = 0;
        surface.stats.genus = (2 - euler) / 2;
        return;
    }
    std::vector<std::uint64_t> edges;
    edges.reserve(mesh.indices.size());
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = mesh.indices[3 * f + k], b = mesh.indices[3 * f + (k + 1) % 3];
            edges.push_back(std::uint64_t(std::min(a, b)) << 32 | std::max(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    long edgeCount = 0;
    std::vector<std::uint32_t> forest;  // over border vertices, for counting loops
    std::vector<std::pair<std::uint32_t, std::uint32_t>> border;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i + 1;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        ++edgeCount;
        if (j - i == 1) border.emplace_back(std::uint32_t(edges[i] >> 32), std::uint32_t(edges[i]));
        i = j;
    }
    long loops = 0;
    if (!border.empty()) {
        forest.resize(mesh.vertices.size());
        std::iota(forest.begin(), forest.end(), 0u);
        std::vector<char> onBorder(mesh.vertices.size(), 0);
        for (const auto& [a, b] : border) {
            onBorder[a] = onBorder[b] = 1;
            forest[loopRoot(forest, a)] = loopRoot(forest, b);
        }
        for (std::uint32_t v = 0; v < forest.size(); ++v) loops += onBorder[v] && loopRoot(forest, v) == v;
    }
    const long euler = long(mesh.vertices.size()) - edgeCount + long(mesh.triangleCount());
    surface.stats.euler = euler;
    surface.stats.borderLoops = loops;
    surface.stats.genus = (2 - euler - loops) / 2;
}

}  // namespace isotrack
