// Meshes of the 3-state table compared as triangle sets: the same vertices (by
// grid edge, or cell for a centre, and the bits of position and normal) and
// the same triangles over them, whatever the order of either.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <tuple>
#include <vector>

#include "isotrack/mesh.h"

namespace isotrack::test {

using VertexKey = std::tuple<int, int, int, int, std::array<std::uint32_t, 6>>;

inline VertexKey vertexKey(const Mesh& mesh, std::uint32_t v) {
    std::array<std::uint32_t, 6> bits{};
    std::memcpy(bits.data(), mesh.vertices[v].position, 3 * sizeof(float));
    std::memcpy(bits.data() + 3, mesh.vertices[v].normal, 3 * sizeof(float));
    const GridEdge e = mesh.vertexEdges[v];
    return {e.x, e.y, e.z, e.axis, bits};
}

// The triangles as triples of the ranks of their vertices' keys among
// `sortedKeys`, each rotated so that its smallest comes first (the winding is
// kept), sorted; empty when a vertex's key is not there.
inline std::vector<std::array<std::size_t, 3>> rankedTriangles(const Mesh& mesh,
                                                               const std::vector<VertexKey>& sortedKeys) {
    std::vector<std::size_t> rank(mesh.vertices.size());
    for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) {
        const VertexKey key = vertexKey(mesh, v);
        const auto found = std::lower_bound(sortedKeys.begin(), sortedKeys.end(), key);
        if (found == sortedKeys.end() || *found != key) return {};
        rank[v] = std::size_t(found - sortedKeys.begin());
    }
    std::vector<std::array<std::size_t, 3>> out(mesh.triangleCount());
    for (std::size_t f = 0; f < out.size(); ++f) {
        auto& t = out[f];
        for (std::size_t k = 0; k < 3; ++k) t[k] = rank[mesh.indices[3 * f + k]];
        while (t[1] < t[0] || t[2] < t[0]) std::rotate(t.begin(), t.begin() + 1, t.end());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// The same vertex count, no two vertices with one key, and the same sorted triangles.
inline bool sameTriangles(const Mesh& a, const Mesh& b) {
    if (a.vertices.size() != b.vertices.size() || a.indices.size() != b.indices.size()) return false;
    std::vector<VertexKey> keys;
    for (std::uint32_t v = 0; v < b.vertices.size(); ++v) keys.push_back(vertexKey(b, v));
    std::sort(keys.begin(), keys.end());
    if (std::adjacent_find(keys.begin(), keys.end()) != keys.end()) return false;
    const auto triangles = rankedTriangles(a, keys);
    return triangles.size() == a.triangleCount() && triangles == rankedTriangles(b, keys);
}

}  // namespace isotrack::test
