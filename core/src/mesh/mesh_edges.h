#pragma once
// The undirected edges of a triangle mesh and how many triangles use each, as
// smoothing (which vertices are fixed, who neighbours whom) and the quality
// figures (border and non-manifold edges) need them.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "isotrack/mesh.h"

namespace isotrack::detail {

struct EdgeUse {
    std::uint32_t a = 0, b = 0;  // a < b
    std::uint32_t triangles = 0;
};

// Every edge of the triangles indices[0 .. 3 * triangleCount), once, sorted,
// with its triangle count; a triangle's side from a vertex to itself is no edge.
inline std::vector<EdgeUse> meshEdges(const std::uint32_t* indices, std::size_t triangleCount) {
    std::vector<std::uint64_t> keys;
    keys.reserve(3 * triangleCount);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t a = indices[3 * t + k], b = indices[3 * t + (k + 1) % 3];
            if (a != b) keys.push_back(std::uint64_t(std::min(a, b)) << 32 | std::max(a, b));
        }
    }
    std::sort(keys.begin(), keys.end());
    std::vector<EdgeUse> edges;
    for (std::size_t i = 0; i < keys.size();) {
        std::size_t j = i + 1;
        while (j < keys.size() && keys[j] == keys[i]) ++j;
        edges.push_back({std::uint32_t(keys[i] >> 32), std::uint32_t(keys[i]), std::uint32_t(j - i)});
        i = j;
    }
    return edges;
}

// One id per distinct position: vertices at identical positions share the
// id of the first of them in position order.
inline std::vector<std::uint32_t> weldedIds(const Mesh& mesh) {
    std::vector<std::uint32_t> order(mesh.vertices.size());
    std::iota(order.begin(), order.end(), 0u);
    auto key = [&](std::uint32_t v) {
        const float* p = mesh.vertices[v].position;
        return std::array<float, 3>{p[0], p[1], p[2]};
    };
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    std::vector<std::uint32_t> ids(mesh.vertices.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        ids[order[i]] = i > 0 && key(order[i]) == key(order[i - 1]) ? ids[order[i - 1]] : order[i];
    return ids;
}

}  // namespace isotrack::detail
