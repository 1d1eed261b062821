// Extraction with the 3-state table (SnapMC; isotrack/snap_table.h).
//
// Passes: (1) give every sample its side of the isovalue and whether it is at
// it: equal to it, or snapped because a crossing on one of its six grid edges
// lies within kSnapDistance of it (snapStates, snap_states.cpp: the decision
// reads the samples as they are, so it does not cascade, and is undone where
// it would shrink a surface to nothing or lay two sheets on one segment).
// (2) Per cell, the sides and at flags of its eight samples pick the table
// entry; marchSnap emits every cell, slab by slab, a walk the cells of one
// surface, entered through the consistent table's continuation over the
// 2-state configuration (the sides), so a walk visits the cells and pieces
// the consistent table's walk visits. (3) Each crossed grid edge whose ends
// are off the isovalue, and each sample at the isovalue, gets one vertex,
// computed once: the edge's as every extractor places it
// (SampleGrid::edgeVertex), the sample's on its grid point with the normal of
// its central-difference gradient; a loop the table fans around its centre
// gets a vertex inside its cell (vertexEdges: the cell, kCellInterior).
// (4) Pairs of triangles over the same three vertices, drawn by two cells on
// their shared face where a sheet of samples at the isovalue has samples
// below on both sides, are removed (removeFins' rule, applied by
// removeFinsAmong to the triangles with their three corners on one face of
// their cell: no other can have a twin), with the vertices only they used.
#include "extract/snap/snap_march.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>

#include "extract/common/sparse_blocks.h"
#include "extract/snap/snap_cells.h"
#include "extract/tracking/track_walker.h"
#include "isotrack/continuation.h"
#include "isotrack/cube.h"
#include "isotrack/errors.h"
#include "isotrack/tracking.h"
#include "mesh/weld.h"

namespace isotrack::detail {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Pairs of triangles over the same three vertices go (removeFinsAmong, over
// the triangles the cells drew on their faces), then the vertices they alone used.
void removeReversedPairs(Mesh& mesh, const std::vector<std::uint32_t>& onFaces) {
    mesh.indices.resize(removeFinsAmong(mesh.indices.data(), mesh.indices.size(), onFaces));
    dropUnusedVertices(mesh);
}

// What finishedSnap needs of a walk beyond TrilinearWalk: the triangles its
// cells drew on their faces (SnapCells::emit), taken with its mesh.
class SnapWalkBase : public TrilinearWalk {
public:
    std::vector<std::uint32_t> takeTrianglesOnFaces() { return std::move(onFaces_); }

protected:
    std::vector<std::uint32_t> onFaces_;
};

template <class T>
class SnapWalk final : public SnapWalkBase {
public:
    // `visited` (one bit per piece, per cell, at SnapCells::visitIndex) may be shared by walks.
    SnapWalk(std::shared_ptr<const SnapCells<T>> cells, std::vector<std::uint8_t>* visited)
        : cells_(std::move(cells)), visited_(visited), slots_(cells_->volume().dims()) {
        if (!visited_) {
            own_.assign(cells_->visitMarks(), 0);
            visited_ = &own_;
        }
    }

    void enqueue(int x, int y, int z, int piece) { enqueue(x, y, z, piece, cells_->config(x, y, z)); }

    // With the cell's entry index (SnapCells::config), read with the states its
    // 2-state configuration came from.
    void enqueue(int x, int y, int z, int piece, int config) {
        std::uint8_t& bits = (*visited_)[cells_->visitIndex(x, y, z)];
        if (bits >> piece & 1u) return;
        bits = static_cast<std::uint8_t>(bits | 1u << piece);
        queue_.push_back({x, y, z, piece, config});
    }

    std::size_t advance(std::size_t pieceBudget) override {
        const auto& continuation = continuationTable(TableKind::Consistent);
        const auto& across = edgesAcrossFaces();
        std::size_t emitted = 0;
        for (; emitted < pieceBudget && head_ < queue_.size(); ++emitted) {
            // The entries a few pieces ahead, fetched early: the table is far bigger than the caches.
            if (head_ + kFetchAhead < queue_.size()) {
                const char* ahead = reinterpret_cast<const char*>(&cells_->entry(queue_[head_ + kFetchAhead][4]));
                __builtin_prefetch(ahead);
                __builtin_prefetch(ahead + 64);
            }
            const auto [x, y, z, piece, index] = queue_[head_++];
            cells_->emit(index, piece, x, y, z, mesh_, slots_, onFaces_);
            const Piece& exits = continuation[index & 0xff].pieces[std::size_t(piece)];
            for (int f = 0; f < cube::kFaceCount; ++f) {
                if (exits.exits[std::size_t(f)][0] < 0) continue;
                int n[3] = {x, y, z};
                n[cube::faceAxis(f)] += cube::faceSide(f) ? 1 : -1;
                if (!cells_->cellInside(n[0], n[1], n[2])) continue;
                const int config = cells_->config(n[0], n[1], n[2]);
                const std::uint8_t above = std::uint8_t(config & 0xff);
                for (const std::int8_t edge : exits.exits[std::size_t(f)]) {
                    if (edge < 0) break;
                    const int entry = across[std::size_t(edge)][std::size_t(f)];
                    const int next = continuation[above].pieceOfEdge[std::size_t(entry)];
                    if (next < 0) throw std::logic_error("snap walk: an exit edge is not crossed across the face");
                    enqueue(n[0], n[1], n[2], next, config);
                }
            }
        }
        visitedPieces_ += emitted;
        if (head_ == queue_.size()) {
            queue_.clear();
            head_ = 0;
        }
        return emitted;
    }

    bool done() const override { return head_ == queue_.size(); }
    Mesh& mesh() override { return mesh_; }
    const Mesh& mesh() const override { return mesh_; }
    std::size_t piecesVisited() const override { return visitedPieces_; }
    std::size_t workingBytes() const override {
        return own_.size() + queue_.capacity() * sizeof(queue_[0]) + slots_.bytes();
    }

private:
    std::shared_ptr<const SnapCells<T>> cells_;
    std::vector<std::uint8_t> own_;
    std::vector<std::uint8_t>* visited_;
    static constexpr std::size_t kFetchAhead = 8;
    std::vector<std::array<int, 5>> queue_;  // cell, piece, entry index
    std::size_t head_ = 0, visitedPieces_ = 0;
    Mesh mesh_;
    BlockSlots slots_;
};

template <class T>
std::vector<Surface> allSnapTyped(const Volume& volume, const T* samples, double iso, int threads) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<Surface> surfaces;
    const Dims& n = volume.dims();
    if (n[0] < 2 || n[1] < 2 || n[2] < 2) return surfaces;
    const auto cells = std::make_shared<const SnapCells<T>>(volume, samples, iso, threads);
    const auto& continuation = continuationTable(TableKind::Consistent);
    std::vector<std::uint8_t> visited(cells->visitMarks(), 0);
    for (int z = 0; z + 1 < n[2]; ++z) {
        for (int y = 0; y + 1 < n[1]; ++y) {
            for (int x = 0; x + 1 < n[0]; ++x) {
                const std::uint8_t above = cells->aboveMask(x, y, z);
                for (int p = 0; p < continuation[above].pieceCount; ++p) {
                    if (visited[cells->visitIndex(x, y, z)] >> p & 1u) continue;
                    SnapWalk<T> walk(cells, &visited);
                    walk.enqueue(x, y, z, p);
                    walk.advance(std::numeric_limits<std::size_t>::max());
                    Surface surface = finishedSnap(walk, volume);
                    if (surface.mesh.triangleCount() > 0) surfaces.push_back(std::move(surface));
                }
            }
        }
    }
    std::stable_sort(surfaces.begin(), surfaces.end(),
                     [](const Surface& a, const Surface& b) { return a.stats.triangles > b.stats.triangles; });
    const double seconds = secondsSince(start);
    for (Surface& surface : surfaces) surface.stats.seconds = seconds;
    return surfaces;
}

}  // namespace

std::size_t removeFinsAmong(std::uint32_t* indices, std::size_t indexCount,
                            const std::vector<std::uint32_t>& suspects) {
    // Keys of the suspects: their sorted vertices and their place, sorted.
    std::vector<std::pair<std::array<std::uint32_t, 3>, std::uint32_t>> sets(suspects.size());
    for (std::size_t s = 0; s < suspects.size(); ++s) {
        const std::uint32_t* t = indices + 3 * std::size_t(suspects[s]);
        std::array<std::uint32_t, 3> key{t[0], t[1], t[2]};
        std::sort(key.begin(), key.end());
        sets[s] = {key, suspects[s]};
    }
    std::sort(sets.begin(), sets.end());
    // removeFins' rule: equal keys go in pairs, the first two, then the next two.
    std::vector<std::uint32_t> dropped;
    for (std::size_t i = 0; i + 1 < sets.size();) {
        if (sets[i].first == sets[i + 1].first) {
            dropped.push_back(sets[i].second);
            dropped.push_back(sets[i + 1].second);
            i += 2;
        } else {
            ++i;
        }
    }
    if (dropped.empty()) return indexCount;
    std::sort(dropped.begin(), dropped.end());
    std::size_t kept = 3 * std::size_t(dropped.front()), next = 0;
    for (std::size_t t = dropped.front(); t < indexCount / 3; ++t) {
        if (next < dropped.size() && dropped[next] == t) {
            ++next;
            continue;
        }
        for (int k = 0; k < 3; ++k) indices[kept++] = indices[3 * t + std::size_t(k)];
    }
    return kept;
}

Mesh marchSnap(const Volume& volume, double iso, int threads) {
    return visitSamples(volume, [&](const auto* samples) {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(samples)>>;
        Mesh mesh;
        const Dims& n = volume.dims();
        if (n[0] < 2 || n[1] < 2 || n[2] < 2) return mesh;
        const SnapCells<T> cells(volume, samples, iso, threads);
        SliceSlots slots(n);
        std::vector<std::uint32_t> onFaces;
        for (int z = 0; z + 1 < n[2]; ++z) {
            slots.startSlab(z);
            for (int y = 0; y + 1 < n[1]; ++y) {
                for (int x = 0; x + 1 < n[0]; ++x) {
                    // A cell with all its samples on one side has no triangles:
                    // the table refines the 2-state one (tested in snap_test).
                    const std::uint8_t above = cells.aboveMask(x, y, z);
                    if (above == 0 || above == 0xff) continue;
                    cells.emit(cells.config(x, y, z), -1, x, y, z, mesh, slots, onFaces);
                }
            }
        }
        removeReversedPairs(mesh, onFaces);
        return mesh;
    });
}

std::unique_ptr<TrilinearWalk> startSnap(const Volume& volume, double iso, const GridEdge& seed, int threads) {
    return visitSamples(volume, [&](const auto* samples) -> std::unique_ptr<TrilinearWalk> {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(samples)>>;
        const auto cells = std::make_shared<const SnapCells<T>>(volume, samples, iso, threads);
        const auto [x, y, z, piece] = seedPiece(*cells, iso, seed);
        auto walk = std::make_unique<SnapWalk<T>>(cells, nullptr);
        walk->enqueue(x, y, z, piece);
        return walk;
    });
}

Surface finishedSnap(TrilinearWalk& walk, const Volume& volume, int threads) {
    Surface surface;
    surface.mesh = std::move(walk.mesh());
    // Every walk startSnap and allSnap make is a SnapWalk.
    auto& snapWalk = dynamic_cast<SnapWalkBase&>(walk);
    removeReversedPairs(surface.mesh, snapWalk.takeTrianglesOnFaces());
    surface.stats = measureSurfaceOn(surface.mesh, volume, false, threads);
    surface.stats.cellsVisited = walk.piecesVisited();
    return surface;
}

Surface trackSnap(const Volume& volume, double iso, const GridEdge& seed, int threads) {
    const auto start = std::chrono::steady_clock::now();
    // As the other tables' tracks: more threads than the volume's tiles can share out would only wait.
    const int walkers = std::min({threads, kMaxTrackThreads, SparseBlocks::usefulThreads(volume.dims())});
    Surface surface;
    if (walkers > 1) {
        surface = trackSnapTogether(volume, iso, seed, walkers);
    } else {
        const auto walk = startSnap(volume, iso, seed, threads);
        walk->advance(std::numeric_limits<std::size_t>::max());
        surface = finishedSnap(*walk, volume, threads);
    }
    surface.stats.seconds = secondsSince(start);
    return surface;
}

std::vector<Surface> allSnap(const Volume& volume, double iso, int threads) {
    return visitSamples(volume, [&](const auto* samples) { return allSnapTyped(volume, samples, iso, threads); });
}

}  // namespace isotrack::detail