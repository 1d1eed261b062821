#pragma once
// Topological and geometric checks on meshes, shared by the extractor tests.
#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/volume.h"

namespace isotrack::testing {

struct Topology {
    std::size_t vertices = 0, edges = 0, faces = 0;
    std::size_t boundaryEdges = 0;          // used by one triangle
    std::size_t interiorBoundaryEdges = 0;  // used by one triangle, not on the volume's border
    std::size_t nonManifoldEdges = 0;       // used by more than two triangles
    std::size_t repeatedDirectedEdges = 0;  // a side wound the same way twice: inconsistent winding
    long euler() const { return long(vertices) - long(edges) + long(faces); }
};

inline bool edgeOnBorder(const GridEdge& e, const Dims& dims) {
    const int p[3] = {e.x, e.y, e.z};
    for (int k = 0; k < 3; ++k) {
        if (k != e.axis && (p[k] == 0 || p[k] == dims[k] - 1)) return true;
    }
    return false;
}

inline Topology topology(const Mesh& mesh, const Dims& dims) {
    Topology t;
    t.vertices = mesh.vertices.size();
    t.faces = mesh.triangleCount();
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> undirected;
    std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = mesh.indices[3 * f + std::size_t(k)];
            const std::uint32_t b = mesh.indices[3 * f + std::size_t((k + 1) % 3)];
            ++undirected[{std::min(a, b), std::max(a, b)}];
            if (!directed.insert({a, b}).second) ++t.repeatedDirectedEdges;
        }
    }
    t.edges = undirected.size();
    for (const auto& [edge, uses] : undirected) {
        if (uses > 2) ++t.nonManifoldEdges;
        if (uses == 1) {
            ++t.boundaryEdges;
            const bool border =
                edgeOnBorder(mesh.vertexEdges[edge.first], dims) && edgeOnBorder(mesh.vertexEdges[edge.second], dims);
            if (!border) ++t.interiorBoundaryEdges;
        }
    }
    return t;
}

inline std::uint64_t edgeKey(const GridEdge& e, const Dims& dims) {
    return (std::uint64_t(e.x) +
            std::uint64_t(dims[0]) * (std::uint64_t(e.y) + std::uint64_t(dims[1]) * std::uint64_t(e.z))) *
               3 +
           std::uint64_t(e.axis);
}

// Triangles as triples of grid edges, rotated so the smallest comes first (the
// winding is kept), so meshes from different extractors can be compared.
inline std::multiset<std::array<std::uint64_t, 3>> triangleSet(const Mesh& mesh, const Dims& dims) {
    std::multiset<std::array<std::uint64_t, 3>> out;
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f) {
        std::array<std::uint64_t, 3> t{};
        for (int k = 0; k < 3; ++k) t[k] = edgeKey(mesh.vertexEdges[mesh.indices[3 * f + std::size_t(k)]], dims);
        while (t[0] > t[1] || t[0] > t[2]) std::rotate(t.begin(), t.begin() + 1, t.end());
        out.insert(t);
    }
    return out;
}

inline std::set<std::uint64_t> vertexEdgeSet(const Mesh& mesh, const Dims& dims) {
    std::set<std::uint64_t> out;
    for (const GridEdge e : mesh.vertexEdges) out.insert(edgeKey(e, dims));
    return out;
}

inline std::size_t duplicatePositions(const Mesh& mesh) {
    std::set<std::tuple<float, float, float>> seen;
    std::size_t duplicates = 0;
    for (const Vertex& v : mesh.vertices) {
        if (!seen.insert({v.position[0], v.position[1], v.position[2]}).second) ++duplicates;
    }
    return duplicates;
}

}  // namespace isotrack::testing
