// Exhaustive marching cubes (Lorensen & Cline 1987) over slabs of cells.
//
// Passes, per slab between sample slices z and z+1:
//  1. classify: one above/below flag per sample of the new slice (slice z is kept
//     from the previous slab), with the single rule sample > iso;
//  2. triangulate: each cell's 8 flags index the triangle table; each triangle
//     corner is a cube edge, mapped to a grid edge whose vertex id lives in a
//     per-slice cache, so a crossed grid edge gets its vertex computed once, by
//     the first cell that needs it, and every later cell reuses the id.
// The x- and y-edge caches of slice z+1 become those of slice z for the next
// slab, so memory is a few ints per sample of one slice, not of the volume.
#include "isotrack/marching_cubes.h"

#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "edge_vertex.h"
#include "isotrack/cube.h"

namespace isotrack {
namespace {

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

template <class T>
class SlabMarcher {
public:
    SlabMarcher(const detail::SampleGrid<T>& grid, const TriangleTable& table, Mesh& mesh)
        : grid_(grid), table_(table), mesh_(mesh), sliceSize_(std::size_t(grid.nx()) * std::size_t(grid.ny())) {
        for (auto& flags : flags_) flags.assign(sliceSize_, 0);
        for (auto& cache : planarCache_) cache.assign(2 * sliceSize_, kNoVertex);
        verticalCache_.assign(sliceSize_, kNoVertex);
        for (int e = 0; e < cube::kEdgeCount; ++e) {
            const auto& o = cube::edgeOrigin(e);
            edgeSlot_[e] = std::size_t(o[0]) + std::size_t(grid.nx()) * std::size_t(o[1]);
        }
    }

    void run() {
        if (grid_.nx() < 2 || grid_.ny() < 2 || grid_.nz() < 2) return;
        classifySlice(0, flags_[0]);
        for (int z = 0; z + 1 < grid_.nz(); ++z) {
            classifySlice(z + 1, flags_[1]);
            marchSlab(z);
            std::swap(flags_[0], flags_[1]);
            // Slice z+1's planar edges become slice z's for the next slab.
            for (auto& cache : planarCache_) {
                std::copy(cache.begin() + std::ptrdiff_t(sliceSize_), cache.end(), cache.begin());
                std::fill(cache.begin() + std::ptrdiff_t(sliceSize_), cache.end(), kNoVertex);
            }
            std::fill(verticalCache_.begin(), verticalCache_.end(), kNoVertex);
        }
    }

private:
    void classifySlice(int z, std::vector<std::uint8_t>& flags) const {
        const std::size_t base = grid_.index(0, 0, z);
        for (std::size_t i = 0; i < sliceSize_; ++i) flags[i] = grid_.above(base + i);
    }

    void marchSlab(int z) {
        const int nx = grid_.nx();
        const auto& lo = flags_[0];
        const auto& hi = flags_[1];
        for (int y = 0; y + 1 < grid_.ny(); ++y) {
            const std::size_t row = std::size_t(nx) * std::size_t(y);
            for (int x = 0; x + 1 < nx; ++x) {
                const std::size_t i = row + std::size_t(x);
                const std::size_t j = i + std::size_t(nx);
                const unsigned config = lo[i] | lo[i + 1] << 1 | lo[j + 1] << 2 | lo[j] << 3 | hi[i] << 4 |
                                        hi[i + 1] << 5 | hi[j + 1] << 6 | hi[j] << 7;
                if (config == 0 || config == 255) continue;
                const CaseTriangles& triangles = table_[static_cast<std::uint8_t>(config)];
                for (int t = 0; t < triangles.count; ++t) {
                    for (int corner = 0; corner < 3; ++corner) {
                        mesh_.indices.push_back(vertexOnEdge(x, y, z, i, triangles.triangles[t][corner]));
                    }
                }
            }
        }
    }

    std::uint32_t vertexOnEdge(int x, int y, int z, std::size_t cell, int edge) {
        const auto& o = cube::edgeOrigin(edge);
        const int axis = cube::edgeAxis(edge);
        std::uint32_t& slot = axis == 2 ? verticalCache_[cell + edgeSlot_[edge]]
                                        : planarCache_[axis][std::size_t(o[2]) * sliceSize_ + cell + edgeSlot_[edge]];
        if (slot == kNoVertex) {
            slot = static_cast<std::uint32_t>(mesh_.vertices.size());
            mesh_.vertices.push_back(grid_.edgeVertex(x + o[0], y + o[1], z + o[2], axis));
            mesh_.vertexEdges.push_back(GridEdge{x + o[0], y + o[1], z + o[2], axis});
        }
        return slot;
    }

    const detail::SampleGrid<T>& grid_;
    const TriangleTable& table_;
    Mesh& mesh_;
    std::size_t sliceSize_;
    std::array<std::vector<std::uint8_t>, 2> flags_;
    std::array<std::vector<std::uint32_t>, 2> planarCache_;  // x and y edges of slices z and z+1
    std::vector<std::uint32_t> verticalCache_;               // z edges between them
    std::array<std::size_t, 12> edgeSlot_{};
};

}  // namespace

Mesh marchingCubes(const Volume& volume, double iso, TableKind table) {
    Mesh mesh;
    visitSamples(volume, [&](const auto* samples) {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(samples)>>;
        const detail::SampleGrid<T> grid(volume, samples, iso);
        SlabMarcher<T>(grid, triangleTable(table), mesh).run();
    });
    return mesh;
}

std::size_t countCrossedEdges(const Volume& volume, double iso) {
    return visitSamples(volume, [&](const auto* samples) {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(samples)>>;
        const detail::SampleGrid<T> grid(volume, samples, iso);
        std::size_t crossed = 0;
        for (int z = 0; z < grid.nz(); ++z)
            for (int y = 0; y < grid.ny(); ++y)
                for (int x = 0; x < grid.nx(); ++x) {
                    const std::size_t i = grid.index(x, y, z);
                    const bool a = grid.above(i);
                    if (x + 1 < grid.nx()) crossed += a != grid.above(i + 1);
                    if (y + 1 < grid.ny()) crossed += a != grid.above(i + grid.strideY());
                    if (z + 1 < grid.nz()) crossed += a != grid.above(i + grid.strideZ());
                }
        return crossed;
    });
}

}  // namespace isotrack
