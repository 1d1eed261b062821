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

#include "extract/common/edge_vertex.h"
#include "extract/snap/snap_slots.h"
#include "extract/tracking/track_walker.h"
#include "isotrack/continuation.h"
#include "isotrack/cube.h"
#include "isotrack/errors.h"
#include "mesh/weld.h"

namespace isotrack::detail {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A grid edge through sample (x, y, z), chosen along an axis on which the sample
// is inside the volume, so that the edge lies on the volume's border exactly
// when the sample does (edgeOnVolumeBorder).
GridEdge edgeThroughSample(int x, int y, int z, const Dims& n) {
    const int p[3] = {x, y, z};
    int axis = 0;
    for (int k = 2; k >= 0; --k) {
        if (p[k] > 0 && p[k] < n[k] - 1) axis = k;
    }
    int q[3] = {x, y, z};
    if (q[axis] + 1 >= n[axis]) --q[axis];
    return GridEdge{q[0], q[1], q[2], axis};
}

// For each table corner: the sample its vertex is keyed at (an edge's origin,
// or the sample itself, as an offset in the cell) and its slot there (the
// edge's axis; 3 for the sample); and the cube faces (a bit per face) it lies
// on: an edge's crossing on the two faces that hold the edge, a sample on its
// three, a centre on none. Computed once.
struct CornerTable {
    std::array<std::array<int, 4>, kSnapCornerCentre> place{};
    std::array<std::uint8_t, kSnapCornerCentre + kMaxSnapCentres> faces{};
};

const CornerTable& corners() {
    static const auto table = [] {
        CornerTable out;
        for (int corner = 0; corner < kSnapCornerCentre; ++corner) {
            const bool edge = corner < kSnapCornerVertex;
            const auto& o =
                edge ? cube::edgeOrigin(corner) : cube::kVertexOffset[std::size_t(corner - kSnapCornerVertex)];
            out.place[std::size_t(corner)] = {o[0], o[1], o[2], edge ? cube::edgeAxis(corner) : 3};
            for (int f = 0; f < cube::kFaceCount; ++f) {
                const int axis = cube::faceAxis(f);
                if ((!edge || cube::edgeAxis(corner) != axis) && o[std::size_t(axis)] == cube::faceSide(f))
                    out.faces[std::size_t(corner)] = std::uint8_t(out.faces[std::size_t(corner)] | 1u << f);
            }
        }
        return out;
    }();
    return table;
}

template <class T>
class SnapCells {
public:
    SnapCells(const Volume& volume, const T* samples, double iso, int threads)
        : volume_(volume),
          grid_(volume, samples, iso),
          states_(snapStates(volume, iso, threads)),
          table_(snapTable()),
          corners_(corners()) {
        for (int v = 0; v < cube::kVertexCount; ++v) {
            const auto& o = cube::kVertexOffset[std::size_t(v)];
            vertexOffset_[std::size_t(v)] = grid_.index(o[0], o[1], o[2]);
        }
        for (int k = 0; k < 3; ++k) visitBlocks_[std::size_t(k)] = (std::size_t(volume.dims()[std::size_t(k)]) + 3) / 4;
    }

    // Where the walks mark cell (x, y, z) visited: cells in blocks of 4x4x4,
    // a cache line of marks each, so that a walk's front, which moves along
    // every axis, reads few lines (in sample order, a step along z is a
    // slice of samples away).
    std::size_t visitIndex(int x, int y, int z) const {
        const std::size_t block =
            std::size_t(x >> 2) + visitBlocks_[0] * (std::size_t(y >> 2) + visitBlocks_[1] * std::size_t(z >> 2));
        return block * 64 + std::size_t((z & 3) << 4 | (y & 3) << 2 | (x & 3));
    }
    std::size_t visitMarks() const { return visitBlocks_[0] * visitBlocks_[1] * visitBlocks_[2] * 64; }

    const Volume& volume() const { return volume_; }
    SampleState state(int x, int y, int z) const { return states_[grid_.index(x, y, z)]; }
    bool cellInside(int x, int y, int z) const {
        return x >= 0 && y >= 0 && z >= 0 && x + 1 < grid_.nx() && y + 1 < grid_.ny() && z + 1 < grid_.nz();
    }

    // The snap table's entry for cell (x, y, z) (snapCaseIndex).
    int config(int x, int y, int z) const {
        const SampleState* first = states_.data() + grid_.index(x, y, z);
        unsigned above = 0, at = 0;
        for (int v = 0; v < cube::kVertexCount; ++v) {
            const SampleState s = first[vertexOffset_[std::size_t(v)]];
            above |= unsigned(isAbove(s)) << v;
            at |= unsigned(isAt(s)) << v;
        }
        return snapCaseIndex(std::uint8_t(above), std::uint8_t(at));
    }
    const SnapCase& entry(int index) const { return table_[std::size_t(index)]; }

    // The 2-state configuration of cell (x, y, z): its snap table entry's
    // aboveMask, without reading the table (snapCaseIndex keeps it in the low byte).
    std::uint8_t aboveMask(int x, int y, int z) const {
        unsigned above = 0;
        for (int v = 0; v < cube::kVertexCount; ++v) {
            const auto& o = cube::kVertexOffset[std::size_t(v)];
            above |= unsigned(isAbove(state(x + o[0], y + o[1], z + o[2]))) << v;
        }
        return std::uint8_t(above);
    }

    // Appends the triangles of `piece` (all pieces when negative) of cell (x,
    // y, z); lists in `onFaces` those with their three corners on one face of
    // the cell, the only ones a neighbouring cell can draw too (a fin's).
    template <class Slots>
    void emit(int index, int piece, int x, int y, int z, Mesh& mesh, Slots& slots,
              std::vector<std::uint32_t>& onFaces) const {
        const SnapCase& cased = table_[std::size_t(index)];
        const auto& faces = corners_.faces;
        // The cell's corners' vertices as its triangles first use them: each is
        // looked up in `slots` once, however many triangles share it.
        std::array<std::uint32_t, kSnapCornerCentre> ids;
        ids.fill(kNoVertex);
        for (int t = 0; t < cased.count; ++t) {
            if (piece >= 0 && cased.piece[std::size_t(t)] != piece) continue;
            const auto& triangle = cased.triangles[std::size_t(t)];
            if (faces[std::size_t(triangle[0])] & faces[std::size_t(triangle[1])] & faces[std::size_t(triangle[2])])
                onFaces.push_back(std::uint32_t(mesh.indices.size() / 3));
            for (const std::int8_t corner : triangle) {
                if (corner >= kSnapCornerCentre) {
                    mesh.indices.push_back(centre(cased, corner - kSnapCornerCentre, x, y, z, mesh, slots));
                    continue;
                }
                std::uint32_t& id = ids[std::size_t(corner)];
                if (id == kNoVertex) id = vertex(corner, x, y, z, mesh, slots);
                mesh.indices.push_back(id);
            }
        }
    }

private:
    template <class Slots>
    std::uint32_t vertex(int corner, int x, int y, int z, Mesh& mesh, Slots& slots) const {
        const auto& place = corners_.place[std::size_t(corner)];
        const int p[3] = {x + place[0], y + place[1], z + place[2]};
        const int axis = place[3];  // a sample's slot, 3, follows its three edges'
        std::uint32_t& slot = slots.slot(p[0], p[1], p[2], axis);
        if (slot != kNoVertex) return slot;
        slot = std::uint32_t(mesh.vertices.size());
        Vertex v{};
        if (axis < 3) {
            grid_.edgeVertex(p[0], p[1], p[2], axis, v);
            mesh.vertexEdges.push_back(GridEdge{p[0], p[1], p[2], axis});
        } else {
            sampleVertex(p, v);
            mesh.vertexEdges.push_back(edgeThroughSample(p[0], p[1], p[2], volume_.dims()));
        }
        mesh.vertices.push_back(v);
        return std::uint32_t(mesh.vertices.size() - 1);
    }

    // The vertex at the mean of a centred loop's corners, with their mean normal.
    template <class Slots>
    std::uint32_t centre(const SnapCase& cased, int loop, int x, int y, int z, Mesh& mesh, Slots& slots) const {
        if (const std::uint32_t id = slots.slot(x, y, z, 4 + loop); id != kNoVertex) return id;
        double position[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
        int count = 0;
        for (const std::int8_t corner : cased.centres[std::size_t(loop)]) {
            if (corner < 0) break;
            const Vertex& v = mesh.vertices[vertex(corner, x, y, z, mesh, slots)];
            for (int k = 0; k < 3; ++k) position[k] += v.position[k], normal[k] += v.normal[k];
            ++count;
        }
        Vertex v{};
        const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        for (int k = 0; k < 3; ++k) {
            v.position[k] = static_cast<float>(position[k] / count);
            v.normal[k] = length > 0.0 ? static_cast<float>(normal[k] / length) : 0.0f;
        }
        const auto id = std::uint32_t(mesh.vertices.size());
        mesh.vertices.push_back(v);
        mesh.vertexEdges.push_back(GridEdge{x, y, z, kCellInterior});
        slots.slot(x, y, z, 4 + loop) = id;
        return id;
    }

    void sampleVertex(const int p[3], Vertex& v) const {
        double g[3];
        grid_.gradient(p[0], p[1], p[2], g);
        const double length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        for (int k = 0; k < 3; ++k) {
            v.position[k] =
                static_cast<float>(volume_.origin()[std::size_t(k)] + p[k] * volume_.spacing()[std::size_t(k)]);
            v.normal[k] = length > 0.0 && std::isfinite(length) ? static_cast<float>(-g[k] / length) : 0.0f;
        }
        if (!(length > 0.0 && std::isfinite(length))) v.normal[2] = 1.0f;
    }

    const Volume& volume_;
    SampleGrid<T> grid_;
    std::vector<SampleState> states_;
    const std::vector<SnapCase>& table_;
    const CornerTable& corners_;
    std::array<std::size_t, cube::kVertexCount> vertexOffset_{};
    std::array<std::size_t, 3> visitBlocks_{};  // of each cube vertex's sample from the cell's first
};

// Pairs of triangles over the same three vertices go (removeFinsAmong, over
// the triangles the cells drew on their faces), then the vertices they alone used.
void removeReversedPairs(Mesh& mesh, const std::vector<std::uint32_t>& onFaces) {
    mesh.indices.resize(removeFinsAmong(mesh.indices.data(), mesh.indices.size(), onFaces));
    dropUnusedVertices(mesh);
}

// cube::edgeAcrossFace for every edge and face, computed once.
const std::array<std::array<std::int8_t, cube::kFaceCount>, cube::kEdgeCount>& edgesAcrossFaces() {
    static const auto table = [] {
        std::array<std::array<std::int8_t, cube::kFaceCount>, cube::kEdgeCount> across{};
        for (int e = 0; e < cube::kEdgeCount; ++e)
            for (int f = 0; f < cube::kFaceCount; ++f)
                across[std::size_t(e)][std::size_t(f)] = std::int8_t(cube::edgeAcrossFace(e, f));
        return across;
    }();
    return table;
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

// The (cell, piece) a walk from `seed` starts at: a cell around the seed edge.
// Samples keep their side, so the 2-state configuration crosses it.
template <class T>
std::array<int, 4> seedPiece(const SnapCells<T>& cells, double iso, const GridEdge& seed) {
    const Volume& volume = cells.volume();
    if (!edgeInside(volume, seed)) throw InputError("seed edge " + edgeText(seed) + " is outside the volume");
    int q[3] = {seed.x, seed.y, seed.z};
    ++q[seed.axis];
    if ((volume.value(seed.x, seed.y, seed.z) >= iso) == (volume.value(q[0], q[1], q[2]) >= iso))
        throw InputError("seed edge " + edgeText(seed) + " does not cross iso " + isoText(iso));
    const int u = (seed.axis + 1) % 3, w = (seed.axis + 2) % 3;
    for (int du = 0; du < 2; ++du) {
        for (int dw = 0; dw < 2; ++dw) {
            int c[3] = {seed.x, seed.y, seed.z};
            c[u] -= du;
            c[w] -= dw;
            if (!cells.cellInside(c[0], c[1], c[2])) continue;
            std::array<int, 3> origin{};
            origin[std::size_t(u)] = du;
            origin[std::size_t(w)] = dw;
            const std::uint8_t above = cells.aboveMask(c[0], c[1], c[2]);
            const int piece = continuationTable(TableKind::Consistent)[above]
                                  .pieceOfEdge[std::size_t(cube::edgeAt(origin, seed.axis))];
            if (piece >= 0) return {c[0], c[1], c[2], piece};
        }
    }
    throw std::logic_error("snap walk: a crossed seed edge with no cell that crosses it");
}

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
    const auto walk = startSnap(volume, iso, seed, threads);
    walk->advance(std::numeric_limits<std::size_t>::max());
    Surface surface = finishedSnap(*walk, volume, threads);
    surface.stats.seconds = secondsSince(start);
    return surface;
}

std::vector<Surface> allSnap(const Volume& volume, double iso, int threads) {
    return visitSamples(volume, [&](const auto* samples) { return allSnapTyped(volume, samples, iso, threads); });
}

}  // namespace isotrack::detail
