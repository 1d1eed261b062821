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
#include <cmath>
#include <limits>
#include <numeric>

#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"
#include "surface_measure.h"

namespace isotrack {
namespace {

class UnionFind {
public:
    explicit UnionFind(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }

    std::uint32_t find(std::uint32_t v) {
        while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
        return v;
    }

    // Joins the sets of a triangle's corners, linking larger roots under smaller
    // ones, so a root is its component's first vertex.
    void uniteTriangle(const std::uint32_t* v) {
        std::uint32_t a = find(v[0]);
        const std::uint32_t b = find(v[1]);
        if (a != b) a = link(a, b);
        const std::uint32_t c = find(v[2]);
        if (a != c) link(a, c);
    }

private:
    std::uint32_t link(std::uint32_t a, std::uint32_t b) {
        if (a < b) return parent_[b] = a;
        return parent_[a] = b;
    }

public:

private:
    std::vector<std::uint32_t> parent_;
};

}  // namespace

std::vector<Surface> extractAllSurfaces(const Volume& volume, double iso, TableKind table, int threads) {
    std::vector<std::uint8_t> pieceStarts;
    const Mesh mesh = marchingCubes(volume, iso, table, threads, &pieceStarts);
    const std::size_t vertexCount = mesh.vertices.size(), triangleCount = mesh.triangleCount();
    const Dims& dims = volume.dims();

    UnionFind sets(vertexCount);
    for (std::size_t t = 0; t < triangleCount; ++t) sets.uniteTriangle(&mesh.indices[3 * t]);
    // Components numbered in order of their first vertex; each vertex's index in its component.
    std::vector<std::uint32_t> component(vertexCount), localIndex(vertexCount);
    std::vector<std::size_t> vertices;
    for (std::uint32_t v = 0; v < vertexCount; ++v) {
        const std::uint32_t root = sets.find(v);
        if (root == v) {
            component[v] = static_cast<std::uint32_t>(vertices.size());
            vertices.push_back(0);
        } else {
            component[v] = component[root];
        }
        localIndex[v] = static_cast<std::uint32_t>(vertices[component[v]]++);
    }
    const std::size_t count = vertices.size();
    std::vector<std::size_t> triangles(count, 0), pieces(count, 0);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t c = component[mesh.indices[3 * t]];
        ++triangles[c];
        pieces[c] += pieceStarts[t / 8] >> (t % 8) & 1u;
    }

    // One pass over vertices and one over triangles split the mesh and measure
    // each surface on the way (bounds, border, area, enclosed volume).
    std::vector<Surface> surfaces(count);
    for (std::size_t c = 0; c < count; ++c) {
        surfaces[c].mesh.vertices.reserve(vertices[c]);
        surfaces[c].mesh.vertexEdges.reserve(vertices[c]);
        surfaces[c].mesh.indices.reserve(3 * triangles[c]);
        for (int k = 0; k < 3; ++k) {
            surfaces[c].stats.boundsMin[k] = std::numeric_limits<double>::infinity();
            surfaces[c].stats.boundsMax[k] = -std::numeric_limits<double>::infinity();
        }
    }
    for (std::uint32_t v = 0; v < vertexCount; ++v) {
        Surface& s = surfaces[component[v]];
        const Vertex& vertex = mesh.vertices[v];
        s.mesh.vertices.push_back(vertex);
        s.mesh.vertexEdges.push_back(mesh.vertexEdges[v]);
        for (int k = 0; k < 3; ++k) {
            s.stats.boundsMin[k] = std::min(s.stats.boundsMin[k], double(vertex.position[k]));
            s.stats.boundsMax[k] = std::max(s.stats.boundsMax[k], double(vertex.position[k]));
        }
        if (!s.stats.touchesBorder) s.stats.touchesBorder = detail::edgeOnVolumeBorder(mesh.vertexEdges[v], dims);
    }
    std::vector<detail::TriangleMeasure> measures(count);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        const std::uint32_t c = component[v[0]];
        Surface& s = surfaces[c];
        s.mesh.indices.insert(s.mesh.indices.end(), {localIndex[v[0]], localIndex[v[1]], localIndex[v[2]]});
        measures[c].add(mesh.vertices[v[0]].position, mesh.vertices[v[1]].position, mesh.vertices[v[2]].position);
    }
    for (std::size_t c = 0; c < count; ++c) {
        SurfaceStats& stats = surfaces[c].stats;
        stats.triangles = triangles[c];
        stats.vertices = vertices[c];
        stats.bytes = surfaces[c].mesh.byteSize();
        stats.cellsVisited = pieces[c];
        // The consistent table leaves no holes: a surface is closed unless the border cuts it.
        stats.area = measures[c].area;
        stats.closed = table == TableKind::Consistent ? !stats.touchesBorder : detail::meshIsClosed(surfaces[c].mesh);
        if (stats.closed) stats.enclosedVolume = std::abs(measures[c].signedVolume);
    }

    // Largest first; equal sizes by their first grid edge in memory order, as trackAllSurfaces.
    auto firstEdge = [&](std::size_t c) {
        std::uint64_t first = std::numeric_limits<std::uint64_t>::max();
        for (const GridEdge e : surfaces[c].mesh.vertexEdges) first = std::min(first, detail::edgeOrder(e, dims));
        return first;
    };
    std::vector<std::size_t> order(count);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return triangles[a] > triangles[b]; });
    for (std::size_t i = 0; i < count;) {
        std::size_t j = i + 1;
        while (j < count && triangles[order[j]] == triangles[order[i]]) ++j;
        if (j - i > 1) {
            std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
            for (std::size_t k = i; k < j; ++k) keyed.push_back({firstEdge(order[k]), order[k]});
            std::sort(keyed.begin(), keyed.end());
            for (std::size_t k = i; k < j; ++k) order[k] = keyed[k - i].second;
        }
        i = j;
    }
    std::vector<Surface> sorted;
    sorted.reserve(count);
    for (std::size_t c : order) sorted.push_back(std::move(surfaces[c]));
    return sorted;
}

}  // namespace isotrack
