// Every surface at once: the exhaustive pass, then its connected components.
//
// extractAllSurfaces runs the (parallel) exhaustive pass, which emits each
// cell's triangles piece by piece and marks each piece's first triangle; a
// union-find over the vertices of every triangle then labels the connected
// surfaces, and one pass over vertices and one over triangles splits the mesh.
// It yields exactly the surfaces trackAllSurfaces finds by tracking one surface
// at a time (the tests hold them equal), at close to the cost of the exhaustive
// pass alone, and with no per-voxel memory.
#include <algorithm>
#include <chrono>
#include <numeric>

#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"

namespace isotrack {
namespace {

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }

    std::uint32_t find(std::uint32_t v) {
        while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
        return v;
    }

    // Links the larger root under the smaller, so a root is its component's first vertex.
    void unite(std::uint32_t a, std::uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return;
        if (a < b) parent_[b] = a;
        else parent_[a] = b;
    }

private:
    std::vector<std::uint32_t> parent_;
};

std::uint64_t edgeOrder(const GridEdge& e, const Dims& dims) {
    return ((std::uint64_t(e.z) * std::uint64_t(dims[1]) + std::uint64_t(e.y)) * std::uint64_t(dims[0]) + std::uint64_t(e.x)) * 3 +
           std::uint64_t(e.axis);
}

}  // namespace

std::vector<Surface> extractAllSurfaces(const Volume& volume, double iso, TableKind table, int threads) {
    std::vector<std::uint8_t> pieceStarts;
    const Mesh mesh = marchingCubes(volume, iso, table, threads, &pieceStarts);
    const std::size_t vertexCount = mesh.vertices.size(), triangleCount = mesh.triangleCount();

    UnionFind sets(vertexCount);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        sets.unite(v[0], v[1]);
        sets.unite(v[0], v[2]);
    }
    // Components numbered in order of their first vertex.
    std::vector<std::uint32_t> component(vertexCount), localIndex(vertexCount);
    std::vector<std::size_t> vertices, triangles, pieces;
    std::vector<std::uint64_t> firstEdge;
    for (std::uint32_t v = 0; v < vertexCount; ++v) {
        const std::uint32_t root = sets.find(v);
        if (root == v) {
            component[v] = static_cast<std::uint32_t>(vertices.size());
            vertices.push_back(0);
            firstEdge.push_back(edgeOrder(mesh.vertexEdges[v], volume.dims()));
        } else {
            component[v] = component[root];
        }
        const std::uint32_t c = component[v];
        localIndex[v] = static_cast<std::uint32_t>(vertices[c]++);
        firstEdge[c] = std::min(firstEdge[c], edgeOrder(mesh.vertexEdges[v], volume.dims()));
    }
    triangles.assign(vertices.size(), 0);
    pieces.assign(vertices.size(), 0);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t c = component[mesh.indices[3 * t]];
        ++triangles[c];
        pieces[c] += pieceStarts[t / 8] >> (t % 8) & 1u;
    }

    std::vector<Surface> surfaces(vertices.size());
    for (std::size_t c = 0; c < surfaces.size(); ++c) {
        surfaces[c].mesh.vertices.reserve(vertices[c]);
        surfaces[c].mesh.vertexEdges.reserve(vertices[c]);
        surfaces[c].mesh.indices.reserve(3 * triangles[c]);
    }
    for (std::uint32_t v = 0; v < vertexCount; ++v) {
        Mesh& m = surfaces[component[v]].mesh;
        m.vertices.push_back(mesh.vertices[v]);
        m.vertexEdges.push_back(mesh.vertexEdges[v]);
    }
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        Mesh& m = surfaces[component[v[0]]].mesh;
        m.indices.insert(m.indices.end(), {localIndex[v[0]], localIndex[v[1]], localIndex[v[2]]});
    }
    for (std::size_t c = 0; c < surfaces.size(); ++c) {
        // With the consistent table a surface is closed unless it reaches the border.
        surfaces[c].stats = measureSurface(surfaces[c].mesh, volume, table == TableKind::Consistent);
        surfaces[c].stats.cellsVisited = pieces[c];
    }
    std::vector<std::size_t> order(surfaces.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (triangles[a] != triangles[b]) return triangles[a] > triangles[b];
        return firstEdge[a] < firstEdge[b];
    });
    std::vector<Surface> sorted;
    sorted.reserve(surfaces.size());
    for (std::size_t c : order) sorted.push_back(std::move(surfaces[c]));
    return sorted;
}

}  // namespace isotrack
