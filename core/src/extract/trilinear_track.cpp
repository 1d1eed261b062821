// One surface and every surface with the trilinear table.
//
// Tracking is piecewise continuation over the trilinear subcases: a queue of
// (cell, entry edge) pairs from the seed edge. For each pair the cell is
// classified (configuration, decided faces, tunnel: classifyTrilinear), its
// subcase's triangles are grouped into pieces (triangles sharing a corner), the
// piece holding the entry edge is emitted unless seen before, and the cell
// across every face the piece reaches is queued, entered through the segment
// the piece draws on that face: the asymptotic decider reads only the face's
// samples, so the cell across draws the same segment in one of its pieces.
// Vertex ids live in a hash map keyed by grid edge; a piece's interior vertices
// belong to it alone and are made with it.
//
// Every surface is the exhaustive pass's mesh split into its connected parts
// (a union-find over the vertices of each triangle), largest first.
#include <algorithm>
#include <chrono>
#include <deque>
#include <numeric>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include <cmath>

#include "edge_vertex.h"
#include "isotrack/cube.h"
#include "isotrack/errors.h"
#include "isotrack/trilinear.h"
#include "trilinear_march.h"

namespace isotrack::detail {
namespace {

constexpr int kCorners = kInteriorVertex + kMaxInteriorVertices;

// A subcase's triangles grouped into pieces: per corner its piece, -1 if unused.
std::array<int, kCorners> piecesOf(const TrilinearCase& subcase) {
    std::array<int, kCorners> parent{};
    std::iota(parent.begin(), parent.end(), 0);
    auto root = [&](int v) {
        while (parent[std::size_t(v)] != v) v = parent[std::size_t(v)] = parent[std::size_t(parent[std::size_t(v)])];
        return v;
    };
    std::array<bool, kCorners> used{};
    for (int t = 0; t < subcase.triangleCount; ++t) {
        const auto& tri = subcase.triangles[std::size_t(t)];
        for (int k = 0; k < 3; ++k) {
            used[std::size_t(tri[std::size_t(k)])] = true;
            parent[std::size_t(root(tri[std::size_t(k)]))] = root(tri[std::size_t((k + 1) % 3)]);
        }
    }
    std::array<int, kCorners> piece{};
    piece.fill(-1);
    std::array<int, kCorners> number{};
    number.fill(-1);
    int count = 0;
    for (int c = 0; c < kCorners; ++c) {
        if (!used[std::size_t(c)]) continue;
        int& n = number[std::size_t(root(c))];
        if (n < 0) n = count++;
        piece[std::size_t(c)] = n;
    }
    return piece;
}

std::uint64_t edgeKey(const GridEdge& e, const Dims& n) {
    return ((std::uint64_t(e.z) * std::uint64_t(n[1]) + std::uint64_t(e.y)) * std::uint64_t(n[0]) +
            std::uint64_t(e.x)) *
               3 +
           std::uint64_t(e.axis);
}

template <class T>
class TrilinearTracker {
public:
    TrilinearTracker(const Volume& volume, const SampleGrid<T>& grid)
        : volume_(volume), grid_(grid), n_(volume.dims()) {}

    Surface track(const GridEdge& seed) {
        // A cell holding the seed edge: its origin moves back along the other axes where it can.
        std::array<int, 3> cell{seed.x, seed.y, seed.z}, offset{0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            if (k != seed.axis && cell[std::size_t(k)] == n_[k] - 1) --cell[std::size_t(k)], offset[std::size_t(k)] = 1;
        }
        queue_.push_back({cell, cube::edgeAt(offset, seed.axis)});
        while (!queue_.empty()) {
            const auto [at, entry] = queue_.front();
            queue_.pop_front();
            visit(at, entry);
        }
        Surface surface;
        surface.mesh = std::move(mesh_);
        return surface;
    }

    std::size_t piecesVisited() const { return visited_.size(); }

private:
    struct Entry {
        std::array<int, 3> cell;
        int edge;
    };

    void visit(const std::array<int, 3>& c, int entry) {
        const std::size_t i = grid_.index(c[0], c[1], c[2]);
        const std::uint8_t config = grid_.cellConfig(i);
        double values[8];
        for (int v = 0; v < 8; ++v) {
            const auto& o = cube::kVertexOffset[std::size_t(v)];
            values[v] = grid_.at(grid_.index(c[0] + o[0], c[1] + o[1], c[2] + o[2])) - grid_.iso();
        }
        const TrilinearCase& subcase = classifyTrilinear(values, config);
        const std::array<int, kCorners> piece = piecesOf(subcase);
        const int mine = piece[std::size_t(entry)];
        if (mine < 0) return;
        if (!visited_.insert(i * 8 + std::size_t(mine)).second) return;
        std::array<std::uint32_t, kCorners> ids{};
        std::array<bool, kCorners> made{};
        auto id = [&](int corner) {
            if (!made[std::size_t(corner)]) {
                ids[std::size_t(corner)] =
                    corner < kInteriorVertex ? edgeVertex(c, corner) : interiorVertex(c, subcase, corner, ids, made);
                made[std::size_t(corner)] = true;
            }
            return ids[std::size_t(corner)];
        };
        std::array<std::uint8_t, kCorners * kCorners> uses{};  // per side (a, b), a < b, of the piece's triangles
        std::array<std::uint16_t, 3 * kMaxTrilinearTriangles> sides{};
        int sideCount = 0;
        for (int t = 0; t < subcase.triangleCount; ++t) {
            const auto& tri = subcase.triangles[std::size_t(t)];
            if (piece[std::size_t(tri[0])] != mine) continue;
            for (int k = 0; k < 3; ++k) {
                mesh_.indices.push_back(id(tri[std::size_t(k)]));
                const int a = tri[std::size_t(k)], b = tri[std::size_t((k + 1) % 3)];
                const auto side = static_cast<std::uint16_t>(std::min(a, b) * kCorners + std::max(a, b));
                if (uses[side]++ == 0) sides[std::size_t(sideCount++)] = side;
            }
        }
        for (int s = 0; s < sideCount; ++s) {
            const int a = sides[std::size_t(s)] / kCorners, b = sides[std::size_t(s)] % kCorners;
            if (uses[sides[std::size_t(s)]] != 1 || b >= kInteriorVertex) continue;
            for (int f = 0; f < cube::kFaceCount; ++f) {
                if (!cube::edgeOnFace(a, f) || !cube::edgeOnFace(b, f)) continue;
                std::array<int, 3> next = c;
                next[std::size_t(cube::faceAxis(f))] += cube::faceSide(f) ? 1 : -1;
                const int axis = cube::faceAxis(f);
                if (next[std::size_t(axis)] < 0 || next[std::size_t(axis)] > n_[axis] - 2) continue;
                queue_.push_back({next, cube::edgeAcrossFace(a, f)});
            }
        }
    }

    std::uint32_t edgeVertex(const std::array<int, 3>& c, int edge) {
        const auto& o = cube::edgeOrigin(edge);
        const GridEdge e{c[0] + o[0], c[1] + o[1], c[2] + o[2], cube::edgeAxis(edge)};
        const auto [it, fresh] = vertexIds_.try_emplace(edgeKey(e, n_), std::uint32_t(mesh_.vertices.size()));
        if (fresh) {
            grid_.edgeVertex(e.x, e.y, e.z, e.axis, mesh_.vertices.emplace_back());
            mesh_.vertexEdges.push_back(e);
        }
        return it->second;
    }

    template <class Ids, class Made>
    std::uint32_t interiorVertex(const std::array<int, 3>& c, const TrilinearCase& subcase, int corner, Ids& ids,
                                 Made& made) {
        const InteriorVertex& where = subcase.interior[std::size_t(corner - kInteriorVertex)];
        double position[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
        int count = 0;
        auto vertexOf = [&](int edge) -> const Vertex& {
            if (!made[std::size_t(edge)]) ids[std::size_t(edge)] = edgeVertex(c, edge), made[std::size_t(edge)] = true;
            return mesh_.vertices[ids[std::size_t(edge)]];
        };
        for (unsigned mask = where.around; mask != 0; mask &= mask - 1) {
            const Vertex& v = vertexOf(__builtin_ctz(mask));
            for (int k = 0; k < 3; ++k) position[k] += v.position[k], normal[k] += v.normal[k];
            ++count;
        }
        for (int k = 0; k < 3; ++k) position[k] /= count;
        if (where.anchor >= 0) {
            const Vertex& anchor = vertexOf(where.anchor);
            for (int k = 0; k < 3; ++k) position[k] = 0.5 * (position[k] + anchor.position[k]);
        }
        const auto id = std::uint32_t(mesh_.vertices.size());
        Vertex& out = mesh_.vertices.emplace_back();
        const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        for (int k = 0; k < 3; ++k) {
            out.position[k] = static_cast<float>(position[k]);
            out.normal[k] = length > 0.0 ? static_cast<float>(normal[k] / length) : 0.0f;
        }
        mesh_.vertexEdges.push_back(GridEdge{c[0], c[1], c[2], kCellInterior});
        return id;
    }

    const Volume& volume_;
    const SampleGrid<T>& grid_;
    const Dims n_;
    Mesh mesh_;
    std::deque<Entry> queue_;
    std::unordered_map<std::uint64_t, std::uint32_t> vertexIds_;
    std::unordered_set<std::size_t> visited_;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Surface trackTrilinear(const Volume& volume, double iso, const GridEdge& seed) {
    const auto start = std::chrono::steady_clock::now();
    const Dims& n = volume.dims();
    const int p[3] = {seed.x, seed.y, seed.z};
    bool inside = seed.axis >= 0 && seed.axis < 3;
    for (int k = 0; k < 3 && inside; ++k) inside = p[k] >= 0 && p[k] + (k == seed.axis) < n[k] && n[k] >= 2;
    if (!inside) throw InputError("track: the seed edge is outside the volume");
    const int end[3] = {seed.x + (seed.axis == 0), seed.y + (seed.axis == 1), seed.z + (seed.axis == 2)};
    const bool a = volume.value(seed.x, seed.y, seed.z) >= iso, b = volume.value(end[0], end[1], end[2]) >= iso;
    if (a == b) throw InputError("track: the seed edge is not crossed by the surface at this isovalue");
    return visitSamples(volume, [&](const auto* samples) {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(samples)>>;
        const SampleGrid<T> grid(volume, samples, iso);
        TrilinearTracker<T> tracker(volume, grid);
        Surface surface = tracker.track(seed);
        surface.stats = measureSurface(surface.mesh, volume);
        surface.stats.cellsVisited = tracker.piecesVisited();
        surface.stats.seconds = secondsSince(start);
        return surface;
    });
}

std::vector<Surface> allTrilinear(const Volume& volume, double iso, int threads) {
    const auto start = std::chrono::steady_clock::now();
    const Mesh mesh = marchTrilinear(volume, iso, threads);
    std::vector<std::uint32_t> parent(mesh.vertices.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&](std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        parent[root(mesh.indices[i])] = root(mesh.indices[i + 1]);
        parent[root(mesh.indices[i + 1])] = root(mesh.indices[i + 2]);
    }
    std::unordered_map<std::uint32_t, std::size_t> surfaceOfRoot;
    std::vector<Surface> surfaces;
    std::vector<std::uint32_t> local(mesh.vertices.size(), ~0u);
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        const auto [it, fresh] = surfaceOfRoot.try_emplace(root(mesh.indices[i]), surfaces.size());
        if (fresh) surfaces.emplace_back();
        Mesh& part = surfaces[it->second].mesh;
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.indices[i + k];
            if (local[v] == ~0u) {
                local[v] = std::uint32_t(part.vertices.size());
                part.vertices.push_back(mesh.vertices[v]);
                part.vertexEdges.push_back(mesh.vertexEdges[v]);
            }
            part.indices.push_back(local[v]);
        }
    }
    for (Surface& surface : surfaces) surface.stats = measureSurface(surface.mesh, volume);
    std::stable_sort(surfaces.begin(), surfaces.end(),
                     [](const Surface& a, const Surface& b) { return a.stats.triangles > b.stats.triangles; });
    const double seconds = secondsSince(start);
    for (Surface& surface : surfaces) surface.stats.seconds = seconds;
    return surfaces;
}

}  // namespace isotrack::detail
