// Piecewise continuation: tracking one connected isosurface from a seed edge.
//
// After Ghataora, "The development of Piecewise Continuation on Marching Cubes"
// (Leeds, 2013), and the surface tracking of Shekhar et al. (1996).
//
// A queue holds (cell, entry edge) pairs. For each pair:
//  1. classify: the cell's configuration from its 8 samples (sample >= iso);
//  2. find the piece: the continuation table names the piece of the cell's
//     surface that holds the entry edge; a (cell, piece) seen before is skipped;
//  3. emit: the piece's triangles, each corner a grid edge whose vertex id is kept
//     in the sparse block of the edge's origin and computed only the first time;
//  4. continue: for each face the piece crosses, the cell across that face is
//     queued with the shared edge.
// Visited pieces, configurations and vertex ids live in sparse 8x8x8 blocks
// created as the surface reaches them (sparse_blocks.h), so the cost follows the
// surface, not the volume. extractAllSurfaces labels the exhaustive pass instead.
//
// On several threads, each thread walks the cells of its own tiles (a
// checkerboard), with plain loads and stores: a piece continuing into another
// thread's tile is sent to that thread (Exchange), and only vertices on edges
// between tiles, which cells of several threads share, are claimed with a
// compare-and-swap (track_together.cpp). The threads' parts are joined into one
// mesh at the end.
#include "extract/tracking/track_walker.h"
#include "extract/common/part_ids.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "extract/common/edge_vertex.h"
#include "extract/tracking/walk_exchange.h"
#include "isotrack/continuation.h"
#include "isotrack/cube.h"
#include "isotrack/errors.h"
#include "support/huge_pages.h"

namespace isotrack::detail {
namespace {

// Writes at the end of a mesh buffer through a pointer: the buffer is sized ahead
// in large steps (Buffer leaves new elements uninitialised) and trimmed to what
// was written when the appender goes, instead of a size check and a resize call
// per element.
template <class T>
class Appender {
public:
    explicit Appender(Buffer<T>& buffer) : buffer_(buffer), size_(buffer.size()) {}
    ~Appender() { buffer_.resize(size_); }
    Appender(const Appender&) = delete;
    Appender& operator=(const Appender&) = delete;

    // Room for `count` more elements, which the caller fills.
    T* extend(std::size_t count) {
        if (size_ + count > buffer_.size()) grow(count);
        T* at = buffer_.data() + size_;
        size_ += count;
        return at;
    }
    std::size_t size() const { return size_; }
    // Gives back the last `count` elements.
    void retract(std::size_t count) { size_ -= count; }

private:
    // Sizes the buffer to its capacity, first moving to one twice as large when
    // full (never more often: each step of a growing surface starts from a buffer
    // trimmed to its contents). The new buffer's pages may be backed by huge pages:
    // a large surface's mesh is tens of megabytes, written once, and faulting it in
    // 4 KiB pages costs more than computing it.
    [[gnu::noinline]] void grow(std::size_t count) {
        if (size_ + count > buffer_.capacity()) {
            const std::size_t capacity = std::max({2 * buffer_.capacity(), size_ + count, std::size_t(1024)});
            Buffer<T> larger;
            larger.reserve(capacity);
            detail::adviseHugePages(larger.data(), capacity * sizeof(T));
            larger.assign(buffer_.begin(), buffer_.begin() + std::ptrdiff_t(size_));
            buffer_.swap(larger);
        }
        buffer_.resize(buffer_.capacity());
    }

    Buffer<T>& buffer_;
    std::size_t size_;
};

// The continuation table as the tracker walks it, each piece in 64 bytes.
// Per piece: its edges, its triangles' corners (cube edges), and its exits as
// (face, entry edge in the cell across) pairs in the table's face order. Per
// face: the link to the sparse block across it, and the cells of a block whose
// neighbour across it lies in the next block (local index & mask == side).
struct WalkTable {
    struct Walk {
        std::uint16_t edgeMask = 0;
        std::uint8_t cornerCount = 0, exitCount = 0;
        std::array<std::uint8_t, 3 * kMaxCaseTriangles> corners{};
        std::array<std::uint8_t, 24> exits{};  // face << 4 | entry edge
    };
    std::array<std::array<Walk, kMaxPieces>, 256> walks{};
    // The corners every piece's triangles fit in (five triangles, the most a
    // piece of either table has), and those of up to three triangles, which the
    // walk copies for every piece, a fixed count (about 18 instructions a piece
    // fewer than copying 15; on the CT skull the test for more is mispredicted
    // for about one piece in fourteen).
    static constexpr int kPieceCorners = 15;
    static constexpr int kCommonCorners = 9;
    std::array<std::array<std::int8_t, 12>, 256> pieceOfEdge{};
    std::array<int, 6> link{}, cellStep{}, faceMask{}, faceSide{};
    std::array<std::array<int, 3>, 12> edgeOrigin{};
    std::array<int, 12> edgeAxis{};
    std::array<int, 12> edgeLocal{};  // offset of the edge's origin in a sparse block's local index
    std::array<int, 12> edgeSlot{};   // offset of the edge's vertex id from its cell's first corner's ids in a block
    // For a cell on its block's upper faces, by its corner class (bit k set when
    // its local coordinate k is the block's last) and edge: the link to the
    // block holding the edge's vertex id, and the id's offset there from 3 cell.
    std::array<std::array<int, 12>, 8> slotLink{}, slotOffset{};

    explicit WalkTable(TableKind kind) {
        using detail::SparseBlocks;
        for (int f = 0; f < cube::kFaceCount; ++f) {
            const int axis = cube::faceAxis(f), step = cube::faceSide(f) ? 1 : -1;
            std::array<int, 3> offset{0, 0, 0};
            offset[axis] = step;
            link[f] = SparseBlocks::kSelf + offset[0] + 3 * offset[1] + 9 * offset[2];
            cellStep[f] = step * SparseBlocks::kLocalStep[std::size_t(axis)];
            faceMask[f] = (SparseBlocks::kSide - 1) << (SparseBlocks::kShift * axis);
            faceSide[f] = cube::faceSide(f) ? faceMask[f] : 0;
        }
        const auto& table = continuationTable(kind);
        for (int c = 0; c < 256; ++c) {
            pieceOfEdge[c] = table[c].pieceOfEdge;
            for (int p = 0; p < table[c].pieceCount; ++p) {
                const Piece& piece = table[c].pieces[p];
                Walk& walk = walks[c][p];
                walk.edgeMask = piece.edgeMask;
                for (int t = piece.firstTriangle; t < piece.firstTriangle + piece.triangleCount; ++t) {
                    for (std::int8_t edge : table[c].triangles[t])
                        walk.corners[walk.cornerCount++] = static_cast<std::uint8_t>(edge);
                }
                if (walk.cornerCount > kPieceCorners)
                    throw std::logic_error("continuation table: a piece of more than five triangles");
                // The spare corners repeat the first, a vertex the piece has (see walk).
                for (int k = walk.cornerCount; k < kPieceCorners; ++k) walk.corners[std::size_t(k)] = walk.corners[0];
                for (int f = 0; f < cube::kFaceCount; ++f) {
                    for (std::int8_t exit : piece.exits[f]) {
                        if (exit < 0) break;
                        walk.exits[walk.exitCount++] =
                            static_cast<std::uint8_t>(f << 4 | cube::edgeAcrossFace(exit, f));
                    }
                }
            }
        }
        for (int e = 0; e < cube::kEdgeCount; ++e) {
            edgeOrigin[e] = cube::edgeOrigin(e);
            edgeAxis[e] = cube::edgeAxis(e);
            edgeLocal[e] = detail::SparseBlocks::local(edgeOrigin[e][0], edgeOrigin[e][1], edgeOrigin[e][2]);
            edgeSlot[e] = 3 * edgeLocal[e] + edgeAxis[e];
            for (int c = 0; c < 8; ++c) {
                int wrap[3];
                for (int k = 0; k < 3; ++k) wrap[k] = (c >> k & 1) & edgeOrigin[e][std::size_t(k)];
                slotLink[std::size_t(c)][std::size_t(e)] = SparseBlocks::kSelf + wrap[0] + 3 * wrap[1] + 9 * wrap[2];
                slotOffset[std::size_t(c)][std::size_t(e)] =
                    edgeSlot[e] - 3 * SparseBlocks::kSide *
                                      (wrap[0] * SparseBlocks::kLocalStep[0] + wrap[1] * SparseBlocks::kLocalStep[1] +
                                       wrap[2] * SparseBlocks::kLocalStep[2]);
            }
        }
    }
};

const WalkTable& walkTable(TableKind kind) {
    if (kind == TableKind::Trilinear) throw InputError(kTrilinearNoContinuationTable);
    static const WalkTable consistent(TableKind::Consistent);
    static const WalkTable classic(TableKind::Classic);
    return kind == TableKind::Classic ? classic : consistent;
}

template <class T>
class TypedTrackWorker final : public TrackWorker {
    static constexpr int kShift = SparseBlocks::kShift;
    static constexpr int kLast = SparseBlocks::kSide - 1;

public:
    TypedTrackWorker(const Volume& volume, const T* samples, double iso, TableKind table)
        : grid_(volume, samples, iso), walk_(walkTable(table)) {
        const std::size_t stride[3] = {1, grid_.strideY(), grid_.strideZ()};
        const int last[3] = {grid_.nx() - 2, grid_.ny() - 2, grid_.nz() - 2};
        for (int f = 0; f < cube::kFaceCount; ++f) {
            const int axis = cube::faceAxis(f);
            sampleStep_[f] = cube::faceSide(f) ? stride[axis] : 0 - stride[axis];
            border_[f] = cube::faceSide(f) ? last[axis] : 0;
        }
    }

    std::uint8_t config(int x, int y, int z) const override { return configAt(grid_.index(x, y, z)); }

    bool crossed(const GridEdge& e) const override {
        const std::size_t i = grid_.index(e.x, e.y, e.z);
        const std::size_t stride[3] = {1, grid_.strideY(), grid_.strideZ()};
        return grid_.above(i) != grid_.above(i + stride[e.axis]);
    }

    void enqueue(SparseBlocks& blocks, std::uint8_t* denseVisited, Walker& walker, int x, int y, int z,
                 int edge) const override {
        enqueueIn(walker, denseVisited, blocks.at(x, y, z, walker.thread), SparseBlocks::local(x, y, z),
                  grid_.index(x, y, z), edge);
    }

    std::size_t advance(SparseBlocks& blocks, std::uint8_t* denseVisited, Walker& walker,
                        std::size_t cellBudget) const override {
        return walk<false>(blocks, denseVisited, walker, cellBudget, nullptr);
    }

    void walkShared(SparseBlocks& blocks, Walker& walker, Exchange& exchange) const override {
        std::vector<Exchange::Message> received;
        do {
            enqueueReceived(walker, received);
            walk<true>(blocks, nullptr, walker, std::numeric_limits<std::size_t>::max(), &exchange);
        } while (walker.queue.empty() && exchange.wait(walker.thread, received));
    }

private:
    struct MeshAppender {
        explicit MeshAppender(Mesh& mesh)
            : vertices(mesh.vertices), indices(mesh.indices), vertexEdges(mesh.vertexEdges) {}
        Appender<Vertex> vertices;
        Appender<std::uint32_t> indices;
        Appender<PackedGridEdge> vertexEdges;
    };

    // Walks the walker's queue for up to `cellBudget` cell pieces. Shared: other
    // threads walk the other tiles; pieces continuing there are sent to them,
    // vertices on edges between tiles are claimed atomically, and triangles
    // with another thread's corners are measured once the walk is over.
    template <bool Shared>
    std::size_t walk(SparseBlocks& blocks, std::uint8_t* denseVisited, Walker& w, std::size_t cellBudget,
                     Exchange* exchange) const {
        MeshAppender out(w.mesh);
        const std::size_t firstIndex = out.indices.size(), firstVertex = out.vertices.size();
        std::size_t visited = 0;
        std::vector<Exchange::Message> received;
        while (visited < cellBudget) {
            if constexpr (Shared) {
                if ((visited & 63) == 0) {
                    if (!exchange->poll(w.thread, received)) break;
                    enqueueReceived(w, received);
                }
            }
            Entry entry;
            if (!w.queue.pop(entry)) break;
            ++visited;
            const WalkTable::Walk& walk = walk_.walks[entry.config][entry.piece];
            Block* block = entry.block;
            const int cell = entry.cell;
            const int local[3] = {cell & kLast, cell >> kShift & kLast, cell >> 2 * kShift};
            const int at[3] = {block->origin[0] + local[0], block->origin[1] + local[1], block->origin[2] + local[2]};
            // The cell's block holds its corners too unless it sits on the block's upper faces.
            const bool cornersInBlock = local[0] < kLast && local[1] < kLast && local[2] < kLast;
            std::array<std::uint32_t, 12> vertexOf;
            std::uint32_t* const cellSlots = block->vertex.data() + 3 * cell;  // the ids at the cell's first corner
            // The four rows of slots (y and y + 1, z and z + 1) that hold the cell's edges.
            if (cornersInBlock) SparseBlocks::vertexRows<Shared>(block, std::uint64_t(0x303) << (cell >> kShift));
            const int corners = (local[0] == kLast) | (local[1] == kLast) << 1 | (local[2] == kLast) << 2;
            for (unsigned mask = walk.edgeMask; mask != 0; mask &= mask - 1) {
                const int edge = __builtin_ctz(mask);
                std::uint32_t& slot = cornersInBlock
                                          ? cellSlots[walk_.edgeSlot[edge]]
                                          : *vertexSlot<Shared>(blocks, block, cell, corners, edge, w.thread);
                std::uint32_t id = Shared ? __atomic_load_n(&slot, __ATOMIC_RELAXED) : slot;
                if (id == SparseBlocks::kNoVertex) id = newVertex<Shared>(w, out, slot, at, edge);
                vertexOf[edge] = id;
            }
            // Every piece copies the same count of corners and gives back the spare
            // ones: no loop whose length changes from piece to piece, and so no
            // mispredicted branch at its end. The rare pieces of four or five
            // triangles copy the rest too.
            std::uint32_t* indices = out.indices.extend(WalkTable::kPieceCorners);
            for (int k = 0; k < WalkTable::kCommonCorners; ++k) indices[k] = vertexOf[walk.corners[std::size_t(k)]];
            if (walk.cornerCount > WalkTable::kCommonCorners) {
                for (int k = WalkTable::kCommonCorners; k < WalkTable::kPieceCorners; ++k)
                    indices[k] = vertexOf[walk.corners[std::size_t(k)]];
            }
            out.indices.retract(std::size_t(WalkTable::kPieceCorners - walk.cornerCount));
            const std::size_t sample = grid_.index(at[0], at[1], at[2]);
            for (int k = 0; k < walk.exitCount; ++k) {
                const int f = walk.exits[std::size_t(k)] >> 4, edge = walk.exits[std::size_t(k)] & 15;
                if (at[cube::faceAxis(f)] == border_[f]) {
                    // The surface is cut open by the volume's border here: the
                    // piece has a vertex on an edge in the border's plane.
                    w.measure.touchesBorder = true;
                    continue;
                }
                if ((cell & walk_.faceMask[f]) == walk_.faceSide[f]) {
                    Block* next = blocks.linked(block, walk_.link[f], w.thread);
                    if (Shared && next->owner != w.thread) {
                        exchange->send(
                            w.thread, next->owner,
                            {next, sample + sampleStep_[f], static_cast<std::uint16_t>(cell ^ walk_.faceMask[f]),
                             static_cast<std::uint8_t>(edge)});
                    } else {
                        enqueueIn(w, denseVisited, next, cell ^ walk_.faceMask[f], sample + sampleStep_[f], edge);
                    }
                } else {
                    enqueueIn(w, denseVisited, block, cell + walk_.cellStep[f], sample + sampleStep_[f], edge);
                }
            }
        }
        measureAppended<Shared>(w, out, firstIndex, firstVertex);
        w.cellsVisited += visited;
        return visited;
    }

    // Adds to the walker's measure the triangles and vertices a walk appended
    // from `firstIndex` and `firstVertex`, once it is over: four triangles at a
    // time in vector registers, in the order they were made (so the sums are
    // those of measuring each as it was made), and the bounds likewise. Shared,
    // a triangle with another thread's corners is measured once the walk is over.
    template <bool Shared>
    static void measureAppended(Walker& w, const MeshAppender& out, std::size_t firstIndex, std::size_t firstVertex) {
        const Vertex* vertices = w.mesh.vertices.data();
        const std::uint32_t* indices = w.mesh.indices.data();
        const std::size_t end = out.indices.size();
        double doubledArea = 0.0, sixfoldVolume = 0.0;
        std::size_t k = firstIndex;
        if constexpr (Shared) {
            const std::uint32_t tagMask = ~w.indexMask;
            for (; k < end; k += 3) {
                const std::uint32_t a = indices[k], b = indices[k + 1], c = indices[k + 2];
                if ((((a ^ w.idBase) | (b ^ w.idBase) | (c ^ w.idBase)) & tagMask) == 0) {
                    detail::TriangleMeasure::addTo(doubledArea, sixfoldVolume, vertices[a & w.indexMask],
                                                   vertices[b & w.indexMask], vertices[c & w.indexMask]);
                } else {
                    w.unmeasured.push_back(k);
                }
            }
        } else {
            for (; k + 12 <= end; k += 12)
                detail::TriangleMeasure::addFourTo(doubledArea, sixfoldVolume, vertices, indices + k);
            for (; k < end; k += 3)
                detail::TriangleMeasure::addTo(doubledArea, sixfoldVolume, vertices[indices[k]],
                                               vertices[indices[k + 1]], vertices[indices[k + 2]]);
        }
        w.measure.triangles.merge({doubledArea, sixfoldVolume});
        w.measure.addBounds(vertices + firstVertex, out.vertices.size() - firstVertex);
    }

    // The configuration of the cell whose first corner is `sample`.
    std::uint8_t configAt(std::size_t i) const { return grid_.cellConfig(i); }

    // Queues the piece holding `edge` of the cell at local index `cell` of `block`,
    // whose first corner is `sample`; only the thread walking the cell's tile does.
    void enqueueIn(Walker& w, std::uint8_t* denseVisited, Block* block, int cell, std::size_t sample, int edge) const {
        if (block->config[std::size_t(cell)] == 0) block->config[std::size_t(cell)] = configAt(sample);
        const std::uint8_t c = block->config[std::size_t(cell)];
        const int piece = walk_.pieceOfEdge[c][std::size_t(edge)];
        if (piece < 0) return;
        std::uint8_t& marks = denseVisited ? denseVisited[sample] : block->visited[std::size_t(cell)];
        const auto bit = static_cast<std::uint8_t>(1u << piece);
        if (marks & bit) return;
        marks = static_cast<std::uint8_t>(marks | bit);
        w.queue.push({block, static_cast<std::uint16_t>(cell), c, static_cast<std::uint8_t>(piece)});
    }

    // Queues the pieces other threads sent to this walker, and empties `received`.
    void enqueueReceived(Walker& w, std::vector<Exchange::Message>& received) const {
        for (const auto& m : received) enqueueIn(w, nullptr, m.block, m.cell, m.sample, m.edge);
        received.clear();
    }

    // The vertex slot of an edge of the cell at local index `cell`, on the
    // block's upper faces as `corners` says, whose origin may lie in a block
    // further up.
    template <bool Shared>
    std::uint32_t* vertexSlot(SparseBlocks& blocks, Block* block, int cell, int corners, int edge, int thread) const {
        Block* holder = blocks.linked(block, walk_.slotLink[std::size_t(corners)][std::size_t(edge)], thread);
        const int slot = 3 * cell + walk_.slotOffset[std::size_t(corners)][std::size_t(edge)];
        SparseBlocks::vertexRows<Shared>(holder, std::uint64_t(1) << (slot / SparseBlocks::kRowSlots));
        return holder->vertex.data() + slot;
    }

    // edgeVertex, through its interior form when both ends of the edge have their six neighbours in the volume.
    void vertexAlong(const GridEdge& e, Vertex& v) const {
        if (grid_.edgeInterior(e.axis, e.x, e.y, e.z)) {
            grid_.interiorEdgeVertex(e.axis, grid_.index(e.x, e.y, e.z), e.x, e.y, e.z, v);
        } else {
            grid_.edgeVertex(e.x, e.y, e.z, e.axis, v);
        }
    }

    // Computes the vertex of the cell's edge and records its id in `slot`. Shared,
    // on an edge between tiles (its cells may belong to several threads): when
    // another thread recorded one first, the vertex is given back and its id used.
    template <bool Shared>
    std::uint32_t newVertex(Walker& w, MeshAppender& out, std::uint32_t& slot, const int at[3], int edge) const {
        const std::uint32_t id = partVertexId(w.idBase, w.indexMask, out.vertices.size());
        const auto& o = walk_.edgeOrigin[edge];
        const GridEdge e{at[0] + o[0], at[1] + o[1], at[2] + o[2], walk_.edgeAxis[edge]};
        Vertex& v = *out.vertices.extend(1);
        vertexAlong(e, v);
        const int p[3] = {e.x, e.y, e.z};
        const int m = w.tileMask;
        if (Shared && ((e.axis != 0 && (p[0] & m) == 0) || (e.axis != 1 && (p[1] & m) == 0) ||
                       (e.axis != 2 && (p[2] & m) == 0))) {
            std::uint32_t first = SparseBlocks::kNoVertex;
            if (!__atomic_compare_exchange_n(&slot, &first, id, false, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {
                out.vertices.retract(1);
                return first;
            }
        } else {
            slot = id;
        }
        *out.vertexEdges.extend(1) = e;  // bounds: measureAppended; touchesBorder: the exits in walk
        return id;
    }

    detail::SampleGrid<T> grid_;
    const WalkTable& walk_;
    std::array<std::size_t, 6> sampleStep_{};  // to the first corner of the cell across each face
    std::array<int, 6> border_{};              // the cells' coordinate on the volume's border, per face
};

}  // namespace

std::unique_ptr<TrackWorker> makeWorker(const Volume& volume, double iso, TableKind table) {
    return visitSamples(volume, [&](const auto* samples) -> std::unique_ptr<TrackWorker> {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(samples)>>;
        return std::make_unique<TypedTrackWorker<T>>(volume, samples, iso, table);
    });
}

bool edgeInside(const Volume& volume, const GridEdge& e) {
    const Dims& n = volume.dims();
    const int p[3] = {e.x, e.y, e.z};
    if (e.axis < 0 || e.axis > 2) return false;
    for (int k = 0; k < 3; ++k) {
        if (p[k] < 0 || p[k] >= n[k] || (k == e.axis && p[k] + 1 >= n[k])) return false;
    }
    return true;
}

// Queues the cells around a seed edge, each entered through that edge.
void queueSeed(const Volume& volume, const GridEdge& seed, const TrackWorker& worker, SparseBlocks& blocks,
               Walker& walker) {
    const Dims& n = volume.dims();
    const int b = (seed.axis + 1) % 3, c = (seed.axis + 2) % 3;
    for (int db = 0; db < 2; ++db) {
        for (int dc = 0; dc < 2; ++dc) {
            int cell[3] = {seed.x, seed.y, seed.z};
            cell[b] -= db;
            cell[c] -= dc;
            if (cell[b] < 0 || cell[c] < 0 || cell[b] > n[b] - 2 || cell[c] > n[c] - 2) continue;
            std::array<int, 3> local{0, 0, 0};
            local[b] = db;
            local[c] = dc;
            worker.enqueue(blocks, nullptr, walker, cell[0], cell[1], cell[2], cube::edgeAt(local, seed.axis));
        }
    }
}

void checkSeed(const Volume& volume, double iso, const TrackWorker& worker, const GridEdge& seed) {
    if (!edgeInside(volume, seed)) throw InputError("seed edge " + edgeText(seed) + " is outside the volume");
    if (!worker.crossed(seed)) throw InputError("seed edge " + edgeText(seed) + " does not cross iso " + isoText(iso));
}

// The finished surface, its mesh taken from the walk's state.
Surface finishedSurface(Walker& walker, TableKind table) {
    Surface surface;
    surface.mesh = std::move(walker.mesh);
    surface.stats = detail::surfaceStats(surface.mesh, walker.measure, table == TableKind::Consistent);
    surface.stats.cellsVisited = walker.cellsVisited;
    return surface;
}

std::string isoText(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

std::string edgeText(const GridEdge& e) {
    return "(" + std::to_string(e.x) + "," + std::to_string(e.y) + "," + std::to_string(e.z) + ") axis " +
           "xyz"[e.axis];
}

}  // namespace isotrack::detail
