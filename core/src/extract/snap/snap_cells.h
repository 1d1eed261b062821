#pragma once
// The cells of the snap room's walks and march (snap_march.cpp,
// snap_together.cpp): the sample states, the table entry of a cell, its
// triangles emitted with their vertices made once, and where a walk from a
// seed edge starts.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "extract/common/edge_vertex.h"
#include "extract/snap/snap_march.h"
#include "extract/snap/snap_slots.h"
#include "extract/tracking/track_walker.h"
#include "isotrack/continuation.h"
#include "isotrack/cube.h"
#include "isotrack/errors.h"
#include "isotrack/mesh.h"
#include "isotrack/snap_table.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

// A grid edge through sample (x, y, z), chosen along an axis on which the sample
// is inside the volume, so that the edge lies on the volume's border exactly
// when the sample does (edgeOnVolumeBorder).
inline GridEdge edgeThroughSample(int x, int y, int z, const Dims& n) {
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

inline const CornerTable& corners() {
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

// A fanned loop's centre: the mean of its corners' positions, with their mean
// normal, the corners added in the table's order.
struct LoopCentre {
    double position[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
    int count = 0;

    void add(const Vertex& v) {
        for (int k = 0; k < 3; ++k) position[k] += v.position[k], normal[k] += v.normal[k];
        ++count;
    }
    Vertex vertex() const {
        Vertex v{};
        const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        for (int k = 0; k < 3; ++k) {
            v.position[k] = static_cast<float>(position[k] / count);
            v.normal[k] = length > 0.0 ? static_cast<float>(normal[k] / length) : 0.0f;
        }
        return v;
    }
};

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

    const CornerTable& cornerTable() const { return corners_; }

    // The vertex of table corner `corner` (an edge's or a sample's) of cell
    // (x, y, z): where it lies, and the grid edge it is recorded on.
    GridEdge cornerVertex(int corner, int x, int y, int z, Vertex& v) const {
        const auto& place = corners_.place[std::size_t(corner)];
        const int p[3] = {x + place[0], y + place[1], z + place[2]};
        return placeVertex(p, place[3], v);
    }

private:
    // The vertex on the edge along `axis` from sample `p`, or (axis 3) on the sample.
    GridEdge placeVertex(const int p[3], int axis, Vertex& v) const {
        if (axis < 3) {
            grid_.edgeVertex(p[0], p[1], p[2], axis, v);
            return GridEdge{p[0], p[1], p[2], axis};
        }
        sampleVertex(p, v);
        return edgeThroughSample(p[0], p[1], p[2], volume_.dims());
    }

    template <class Slots>
    std::uint32_t vertex(int corner, int x, int y, int z, Mesh& mesh, Slots& slots) const {
        const auto& place = corners_.place[std::size_t(corner)];
        const int p[3] = {x + place[0], y + place[1], z + place[2]};
        const int axis = place[3];  // a sample's slot, 3, follows its three edges'
        std::uint32_t& slot = slots.slot(p[0], p[1], p[2], axis);
        if (slot != kNoVertex) return slot;
        slot = std::uint32_t(mesh.vertices.size());
        Vertex v{};
        mesh.vertexEdges.push_back(placeVertex(p, axis, v));
        mesh.vertices.push_back(v);
        return std::uint32_t(mesh.vertices.size() - 1);
    }

    // The vertex at the mean of a centred loop's corners, with their mean normal.
    template <class Slots>
    std::uint32_t centre(const SnapCase& cased, int loop, int x, int y, int z, Mesh& mesh, Slots& slots) const {
        if (const std::uint32_t id = slots.slot(x, y, z, 4 + loop); id != kNoVertex) return id;
        LoopCentre sum;
        for (const std::int8_t corner : cased.centres[std::size_t(loop)]) {
            if (corner < 0) break;
            sum.add(mesh.vertices[vertex(corner, x, y, z, mesh, slots)]);
        }
        const auto id = std::uint32_t(mesh.vertices.size());
        mesh.vertices.push_back(sum.vertex());
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

// cube::edgeAcrossFace for every edge and face, computed once.
inline const std::array<std::array<std::int8_t, cube::kFaceCount>, cube::kEdgeCount>& edgesAcrossFaces() {
    static const auto table = [] {
        std::array<std::array<std::int8_t, cube::kFaceCount>, cube::kEdgeCount> across{};
        for (int e = 0; e < cube::kEdgeCount; ++e)
            for (int f = 0; f < cube::kFaceCount; ++f)
                across[std::size_t(e)][std::size_t(f)] = std::int8_t(cube::edgeAcrossFace(e, f));
        return across;
    }();
    return table;
}

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

}  // namespace isotrack::detail
