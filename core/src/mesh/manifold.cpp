// Fins and pinches of a decimated mesh (manifold.h).
#include "mesh/manifold.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace isotrack::detail {
namespace {

std::uint32_t root(std::vector<std::uint32_t>& forest, std::uint32_t c) {
    while (forest[c] != c) c = forest[c] = forest[forest[c]];
    return c;
}

}  // namespace

void removeFinsAndSplitPinches(Mesh& mesh) {
    std::vector<std::uint32_t> indices(mesh.indices.begin(), mesh.indices.end());
    removeFins(indices);
    mesh.indices.assign(indices.begin(), indices.end());
    const std::size_t corners = mesh.indices.size();
    // Sides grouped by their undirected edge: (min, max, forward?, corner of the side's start).
    struct Side {
        std::uint32_t a, b;
        bool forward;
        std::uint32_t corner;
        bool operator<(const Side& o) const { return a != o.a ? a < o.a : b != o.b ? b < o.b : corner < o.corner; }
    };
    std::vector<Side> sides(corners);
    auto nextCorner = [](std::uint32_t c) { return c % 3 == 2 ? c - 2 : c + 1; };
    for (std::uint32_t c = 0; c < corners; ++c) {
        const std::uint32_t from = mesh.indices[c], to = mesh.indices[nextCorner(c)];
        sides[c] = {std::min(from, to), std::max(from, to), from < to, c};
    }
    std::sort(sides.begin(), sides.end());
    // Corners of one vertex joined through paired sides share a copy of it.
    std::vector<std::uint32_t> forest(corners);
    std::iota(forest.begin(), forest.end(), 0u);
    auto join = [&](std::uint32_t c, std::uint32_t d) { forest[root(forest, c)] = root(forest, d); };
    // Manifold edges (one side each way) first; then each side of an edge of more
    // triangles is paired with a reverse side whose corner at the same vertex the
    // fans already join (the same sheet), else with the first one left.
    std::vector<std::pair<std::vector<std::uint32_t>, std::vector<std::uint32_t>>> crowded;
    for (std::size_t i = 0; i < sides.size();) {
        std::size_t j = i;
        std::vector<std::uint32_t> forward, backward;
        while (j < sides.size() && sides[j].a == sides[i].a && sides[j].b == sides[i].b) {
            (sides[j].forward ? forward : backward).push_back(sides[j].corner);
            ++j;
        }
        if (forward.size() == 1 && backward.size() == 1) {
            // Side f runs u -> v from corner f; side g runs v -> u from corner g.
            join(forward[0], nextCorner(backward[0]));
            join(nextCorner(forward[0]), backward[0]);
        } else {
            crowded.emplace_back(std::move(forward), std::move(backward));
        }
        i = j;
    }
    auto pair = [&](std::vector<std::uint32_t>& forward, std::vector<std::uint32_t>& backward, bool anyPair) {
        for (auto f = forward.begin(); f != forward.end(); ++f) {
            auto same = std::find_if(backward.begin(), backward.end(), [&](std::uint32_t g) {
                return root(forest, nextCorner(g)) == root(forest, *f) ||
                       root(forest, g) == root(forest, nextCorner(*f));
            });
            if (same == backward.end() && anyPair && !backward.empty()) same = backward.begin();
            if (same == backward.end()) continue;
            join(*f, nextCorner(*same));
            join(nextCorner(*f), *same);
            backward.erase(same);
            forward.erase(f);
            return true;
        }
        return false;
    };
    // Pairs the fans identify first, one at a time, as each joins more corners;
    // a guess only when none is left.
    for (bool progress = true; progress;) {
        progress = false;
        for (auto& [forward, backward] : crowded) progress = pair(forward, backward, false) || progress;
        if (!progress)
            for (auto& [forward, backward] : crowded)
                if (pair(forward, backward, true)) {
                    progress = true;
                    break;
                }
    }
    // The first group of corners at a vertex keeps it; every other gets a copy.
    std::vector<std::uint32_t> groupVertex(corners, UINT32_MAX);
    std::vector<std::uint32_t> firstGroup(mesh.vertices.size(), UINT32_MAX);
    const bool edges = mesh.vertexEdges.size() == mesh.vertices.size();
    for (std::uint32_t c = 0; c < corners; ++c) {
        const std::uint32_t group = root(forest, c), vertex = mesh.indices[c];
        if (groupVertex[group] == UINT32_MAX) {
            if (firstGroup[vertex] == UINT32_MAX) {
                firstGroup[vertex] = group;
                groupVertex[group] = vertex;
            } else {
                groupVertex[group] = std::uint32_t(mesh.vertices.size());
                mesh.vertices.push_back(mesh.vertices[vertex]);
                if (edges) mesh.vertexEdges.push_back(mesh.vertexEdges[vertex]);
            }
        }
        mesh.indices[c] = groupVertex[group];
    }
}

void removeFins(std::vector<std::uint32_t>& indices) {
    const std::size_t count = indices.size() / 3;
    std::vector<std::pair<std::array<std::uint32_t, 3>, std::uint32_t>> sets(count);
    for (std::size_t t = 0; t < count; ++t) {
        std::array<std::uint32_t, 3> key{indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]};
        std::sort(key.begin(), key.end());
        sets[t] = {key, std::uint32_t(t)};
    }
    std::sort(sets.begin(), sets.end());
    std::vector<char> drop(count, 0);
    for (std::size_t i = 0; i + 1 < count;) {
        if (sets[i].first == sets[i + 1].first) {  // the same three vertices: a fin (or a duplicate)
            drop[sets[i].second] = drop[sets[i + 1].second] = 1;
            i += 2;
        } else {
            ++i;
        }
    }
    std::size_t kept = 0;
    for (std::size_t t = 0; t < count; ++t) {
        if (drop[t]) continue;
        for (int k = 0; k < 3; ++k) indices[kept++] = indices[3 * t + std::size_t(k)];
    }
    indices.resize(kept);
}

}  // namespace isotrack::detail
