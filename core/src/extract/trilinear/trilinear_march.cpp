// Exhaustive marching cubes with the trilinear table, over chunks of slabs run
// in parallel.
//
// Per row of cells: trim the row to the cells between the first and the last
// change of classification along its four rows of samples (beyond them, every
// cell's eight samples agree). Per cell: classify the eight samples (the
// configuration), skip cells the surface misses, then let classifyTrilinear pick the subcase from the samples
// (asymptotic decider on the ambiguous faces, the interior test where a tunnel
// is possible). Each crossed cube edge maps to its grid edge, whose vertex id
// lives in a per-slice cache, so a crossed grid edge gets its vertex computed
// once, by the first cell that needs it; a subcase's interior vertex is made by
// its cell, at the mean of the vertices of the loop fanned around it.
// A chunk owns the x- and y-edges of its first slice but not of the slice after
// its last slab: it writes placeholders for those, resolved from the next
// chunk's first slice when the chunks are joined into one mesh.
#include "extract/trilinear/trilinear_march.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "extract/common/edge_vertex.h"
#include "isotrack/cube.h"
#include "isotrack/trilinear.h"
#include "support/parallel.h"

namespace isotrack::detail {
namespace {

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint32_t kPlaceholder = 0x80000000u;  // an x- or y-edge on the next chunk's first slice

struct TrilinearChunk {
    int zBegin = 0, zEnd = 0;
    bool last = false;
    Mesh mesh;                                 // vertex ids local to the chunk, placeholders flagged
    std::vector<std::uint32_t> firstSliceIds;  // x- then y-edge ids of slice zBegin
};

struct CellGeometry {
    std::array<std::size_t, 8> corner{};  // sample offsets of the cube's corners
    std::array<std::uint16_t, 256> crossed{};
    std::array<int, 12> axis{};
    std::array<std::array<int, 3>, 12> origin{};
};

CellGeometry cellGeometry(std::size_t strideY, std::size_t strideZ) {
    CellGeometry g;
    for (int v = 0; v < 8; ++v) {
        const auto& o = cube::kVertexOffset[std::size_t(v)];
        g.corner[std::size_t(v)] = std::size_t(o[0]) + strideY * std::size_t(o[1]) + strideZ * std::size_t(o[2]);
    }
    for (int e = 0; e < cube::kEdgeCount; ++e) {
        g.axis[std::size_t(e)] = cube::edgeAxis(e);
        g.origin[std::size_t(e)] = cube::edgeOrigin(e);
    }
    for (int c = 0; c < 256; ++c) {
        unsigned mask = 0;
        for (int e = 0; e < cube::kEdgeCount; ++e) {
            if ((c >> cube::kEdgeVertices[std::size_t(e)][0] & 1) != (c >> cube::kEdgeVertices[std::size_t(e)][1] & 1))
                mask |= 1u << e;
        }
        g.crossed[std::size_t(c)] = static_cast<std::uint16_t>(mask);
    }
    return g;
}

template <class T>
class TrilinearMarcher {
public:
    TrilinearMarcher(const SampleGrid<T>& grid, const CellGeometry& geometry)
        : grid_(grid),
          geometry_(geometry),
          nx_(grid.nx()),
          ny_(grid.ny()),
          sliceSize_(std::size_t(grid.nx()) * std::size_t(grid.ny())) {
        for (auto& planar : planar_) planar.assign(2 * sliceSize_, kNoVertex);
        vertical_.assign(sliceSize_, kNoVertex);
    }

    void run(TrilinearChunk& chunk) {
        chunk_ = &chunk;
        std::fill(planar_[0].begin(), planar_[0].end(), kNoVertex);
        rowSpans(chunk.zBegin, spans_[0]);
        for (int z = chunk.zBegin; z < chunk.zEnd; ++z) {
            bottom_ = (z - chunk.zBegin) & 1;
            std::fill(planar_[bottom_ ^ 1].begin(), planar_[bottom_ ^ 1].end(), kNoVertex);
            std::fill(vertical_.begin(), vertical_.end(), kNoVertex);
            seamSlab_ = !chunk.last && z + 1 == chunk.zEnd;
            rowSpans(z + 1, spans_[std::size_t(bottom_ ^ 1)]);
            for (int y = 0; y + 1 < ny_; ++y) {
                const auto [begin, end] = cellSpan(y);
                for (int x = begin; x < end; ++x) marchCell(x, y, z);
            }
            if (z == chunk.zBegin) chunk.firstSliceIds = planar_[bottom_];
        }
    }

private:
    // A row of samples: its first and last sample's classification, the first
    // sample classified unlike the first (nx if none) and the last unlike the last (-1 if none).
    struct RowSpan {
        bool head = false, tail = false;
        int first = 0, last = -1;
    };

    void rowSpans(int z, std::vector<RowSpan>& out) const {
        out.resize(std::size_t(ny_));
        for (int y = 0; y < ny_; ++y) {
            const std::size_t i = grid_.index(0, y, z);
            RowSpan& row = out[std::size_t(y)];
            row.head = grid_.above(i);
            row.tail = grid_.above(i + std::size_t(nx_ - 1));
            row.first = 1;
            while (row.first < nx_ && grid_.above(i + std::size_t(row.first)) == row.head) ++row.first;
            row.last = row.first == nx_ ? -1 : nx_ - 2;
            while (row.last >= 0 && grid_.above(i + std::size_t(row.last)) == row.tail) --row.last;
        }
    }

    // The cells [begin, end) of row (y, z) that may hold surface: before the
    // first change along its four rows of samples and after the last one, a
    // cell's eight samples agree when the rows' heads (tails) agree.
    std::pair<int, int> cellSpan(int y) const {
        const RowSpan* rows[4] = {
            &spans_[std::size_t(bottom_)][std::size_t(y)], &spans_[std::size_t(bottom_)][std::size_t(y + 1)],
            &spans_[std::size_t(bottom_ ^ 1)][std::size_t(y)], &spans_[std::size_t(bottom_ ^ 1)][std::size_t(y + 1)]};
        bool heads = true, tails = true;
        int first = nx_, last = -1;
        for (const RowSpan* row : rows) {
            heads = heads && row->head == rows[0]->head;
            tails = tails && row->tail == rows[0]->tail;
            first = std::min(first, row->first);
            last = std::max(last, row->last);
        }
        const int begin = heads ? std::max(0, first - 1) : 0;
        const int end = tails ? std::min(nx_ - 1, last + 1) : nx_ - 1;
        return {begin, end};
    }

    void marchCell(int x, int y, int z) {
        const std::size_t i = grid_.index(x, y, z);
        const std::uint8_t config = grid_.cellConfig(i);
        if (config == 0 || config == 255) return;
        double values[8];
        for (int v = 0; v < 8; ++v) values[v] = grid_.at(i + geometry_.corner[std::size_t(v)]) - grid_.iso();
        const TrilinearCase& subcase = classifyTrilinear(values, config);
        std::array<std::uint32_t, kInteriorVertex + kMaxInteriorVertices> ids;
        for (unsigned mask = geometry_.crossed[config]; mask != 0; mask &= mask - 1) {
            const int e = __builtin_ctz(mask);
            ids[std::size_t(e)] = vertexOnEdge(x, y, z, e);
        }
        for (int k = 0; k < subcase.interiorCount; ++k)
            ids[std::size_t(kInteriorVertex + k)] = interiorVertex(x, y, z, subcase.interior[std::size_t(k)], ids);
        Buffer<std::uint32_t>& indices = chunk_->mesh.indices;
        for (int t = 0; t < subcase.triangleCount; ++t) {
            for (int k = 0; k < 3; ++k)
                indices.push_back(ids[std::size_t(subcase.triangles[std::size_t(t)][std::size_t(k)])]);
        }
    }

    std::uint32_t vertexOnEdge(int x, int y, int z, int edge) {
        const int axis = geometry_.axis[std::size_t(edge)];
        const auto& o = geometry_.origin[std::size_t(edge)];
        const std::size_t at = std::size_t(x + o[0]) + std::size_t(nx_) * std::size_t(y + o[1]);
        std::uint32_t* slot;
        if (axis == 2) {
            slot = &vertical_[at];
        } else {
            const bool upper = o[2] != 0;
            if (seamSlab_ && upper)
                return kPlaceholder | static_cast<std::uint32_t>(std::size_t(axis) * sliceSize_ + at);
            slot = &planar_[std::size_t(bottom_ ^ int(upper))][std::size_t(axis) * sliceSize_ + at];
        }
        if (*slot != kNoVertex) return *slot;
        Mesh& mesh = chunk_->mesh;
        *slot = static_cast<std::uint32_t>(mesh.vertices.size());
        mesh.vertices.emplace_back();
        grid_.edgeVertex(x + o[0], y + o[1], z + o[2], axis, mesh.vertices.back());
        mesh.vertexEdges.push_back(GridEdge{x + o[0], y + o[1], z + o[2], axis});
        return *slot;
    }

    // The vertex of a crossed cube edge, made by now or, for a placeholder, the next chunk's (computed here again).
    Vertex edgeVertexOf(int x, int y, int z, int edge, std::uint32_t id) const {
        if (!(id & kPlaceholder)) return chunk_->mesh.vertices[id];
        Vertex v;
        const auto& o = geometry_.origin[std::size_t(edge)];
        grid_.edgeVertex(x + o[0], y + o[1], z + o[2], geometry_.axis[std::size_t(edge)], v);
        return v;
    }

    std::uint32_t interiorVertex(int x, int y, int z, const InteriorVertex& where,
                                 const std::array<std::uint32_t, kInteriorVertex + kMaxInteriorVertices>& ids) {
        double position[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
        int count = 0;
        for (unsigned mask = where.around; mask != 0; mask &= mask - 1) {
            const int e = __builtin_ctz(mask);
            const Vertex v = edgeVertexOf(x, y, z, e, ids[std::size_t(e)]);
            for (int k = 0; k < 3; ++k) position[k] += v.position[k], normal[k] += v.normal[k];
            ++count;
        }
        for (int k = 0; k < 3; ++k) position[k] /= count;
        if (where.anchor >= 0) {
            const Vertex anchor = edgeVertexOf(x, y, z, where.anchor, ids[std::size_t(where.anchor)]);
            for (int k = 0; k < 3; ++k) position[k] = 0.5 * (position[k] + anchor.position[k]);
        }
        Mesh& mesh = chunk_->mesh;
        const auto id = static_cast<std::uint32_t>(mesh.vertices.size());
        Vertex& out = mesh.vertices.emplace_back();
        const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        for (int k = 0; k < 3; ++k) {
            out.position[k] = static_cast<float>(position[k]);
            out.normal[k] = length > 0.0 ? static_cast<float>(normal[k] / length) : 0.0f;
        }
        mesh.vertexEdges.push_back(GridEdge{x, y, z, kCellInterior});
        return id;
    }

    const SampleGrid<T>& grid_;
    const CellGeometry& geometry_;
    const int nx_, ny_;
    const std::size_t sliceSize_;
    TrilinearChunk* chunk_ = nullptr;
    int bottom_ = 0;
    bool seamSlab_ = false;
    std::array<std::vector<std::uint32_t>, 2> planar_;  // x then y edges of a slice, ping-pong
    std::vector<std::uint32_t> vertical_;               // z edges of the current slab
    std::array<std::vector<RowSpan>, 2> spans_;         // rows of samples of a slice, ping-pong as planar_
};

// The chunks' meshes as one, placeholders resolved from the next chunk's first slice.
Mesh join(std::vector<TrilinearChunk>& chunks) {
    std::vector<std::size_t> base(chunks.size() + 1, 0);
    std::size_t indexCount = 0;
    for (std::size_t c = 0; c < chunks.size(); ++c) {
        base[c + 1] = base[c] + chunks[c].mesh.vertices.size();
        indexCount += chunks[c].mesh.indices.size();
    }
    if (base.back() >= kPlaceholder) throw std::length_error("marching cubes: more than 2^31 vertices");
    Mesh mesh;
    mesh.vertices.reserve(base.back());
    mesh.vertexEdges.reserve(base.back());
    mesh.indices.reserve(indexCount);
    for (std::size_t c = 0; c < chunks.size(); ++c) {
        const Mesh& part = chunks[c].mesh;
        mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
        mesh.vertexEdges.insert(mesh.vertexEdges.end(), part.vertexEdges.begin(), part.vertexEdges.end());
        for (const std::uint32_t id : part.indices) {
            if (id & kPlaceholder) {
                mesh.indices.push_back(
                    static_cast<std::uint32_t>(base[c + 1] + chunks[c + 1].firstSliceIds[id & ~kPlaceholder]));
            } else {
                mesh.indices.push_back(static_cast<std::uint32_t>(base[c] + id));
            }
        }
        chunks[c].mesh = Mesh{};
    }
    return mesh;
}

}  // namespace

Mesh marchTrilinear(const Volume& volume, double iso, int threads) {
    const Dims& n = volume.dims();
    if (n[0] < 2 || n[1] < 2 || n[2] < 2) return {};
    trilinearTable();  // generated once, before the threads need it
    const int slabs = n[2] - 1;
    threads = std::max(1, threads);
    const int chunkCount = threads == 1 ? 1 : std::min(slabs, threads * 4);
    std::vector<TrilinearChunk> chunks(static_cast<std::size_t>(chunkCount));
    for (int c = 0; c < chunkCount; ++c) {
        chunks[std::size_t(c)].zBegin = int(std::int64_t(slabs) * c / chunkCount);
        chunks[std::size_t(c)].zEnd = int(std::int64_t(slabs) * (c + 1) / chunkCount);
        chunks[std::size_t(c)].last = c + 1 == chunkCount;
    }
    visitSamples(volume, [&](const auto* samples) {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(samples)>>;
        const SampleGrid<T> grid(volume, samples, iso);
        const CellGeometry geometry = cellGeometry(grid.strideY(), grid.strideZ());
        parallelForWithState(
            chunkCount, threads, [&] { return TrilinearMarcher<T>(grid, geometry); },
            [&](TrilinearMarcher<T>& marcher, int c) { marcher.run(chunks[std::size_t(c)]); });
    });
    return join(chunks);
}

}  // namespace isotrack::detail
