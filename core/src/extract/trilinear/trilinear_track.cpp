// One surface and every surface with the trilinear table.
//
// Tracking is piecewise continuation over the trilinear subcases: a queue of
// (cell, entry edge) pairs from the seed edge, walked breadth-first. For each
// pair the cell is classified (configuration, decided faces, tunnel:
// classifyTrilinear), the piece of its subcase holding the entry edge is looked
// up (each subcase's pieces and their exits are worked out once, SubcasePieces),
// the piece is emitted unless seen before, and the cell across every face the
// piece reaches is queued, entered through the segment the piece draws on that
// face: the asymptotic decider reads only the face's samples, so the cell across
// draws the same segment in one of its pieces. Visited pieces and the vertex ids
// of grid edges live in sparse 8x8x8 blocks, as the consistent tracker keeps
// them (sparse_blocks.h); a piece's interior vertices belong to it alone and are
// made with it. The walk goes a budget of pieces at a time, for SurfaceTracker.
//
// On several threads the walk is shared out as the consistent tracker's is
// (track_together.cpp): each thread walks the cells of its own tiles, sends a
// cell in another thread's tile to that thread's mailbox (Exchange), and claims
// the vertices on edges between tiles with a compare-and-swap
// (trilinear_together.cpp joins the threads' parts), and the finished surface
// is measured on them too (measureSurfaceInRuns, meshIsClosed).
//
// Every surface is the exhaustive pass's mesh split into its connected parts
// (a union-find over the vertices of each triangle), largest first.
#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <cmath>

#include "extract/common/edge_vertex.h"
#include "extract/common/part_ids.h"
#include "extract/common/sparse_blocks.h"
#include "extract/measure/surface_measure.h"
#include "extract/trilinear/trilinear_march.h"
#include "extract/trilinear/trilinear_walker.h"
#include "isotrack/cube.h"
#include "isotrack/errors.h"
#include "isotrack/tracking.h"
#include "isotrack/trilinear.h"

namespace isotrack::detail {
namespace {

constexpr int kCorners = kInteriorVertex + kMaxInteriorVertices;

// A subcase's triangles grouped into pieces (triangles sharing a corner), and
// each piece's exits: the faces where it draws a segment, with the edge that
// enters the cell across, in the order the walk queues them.
struct SubcasePieces {
    std::array<std::int8_t, kCorners> piece{};  // per corner its piece, -1 if unused
    std::uint8_t allPieces = 0;                 // a bit per piece
    std::array<std::uint8_t, 9> firstExit{};    // piece p's exits are exits[firstExit[p] .. firstExit[p + 1])
    std::array<std::uint8_t, 24> exits{};       // face << 4 | entry edge in the cell across
};

// Per corner, its piece among the subcase's triangles; -1 if unused.
std::array<std::int8_t, kCorners> piecesOf(const TrilinearCase& subcase) {
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
    std::array<std::int8_t, kCorners> piece{};
    piece.fill(-1);
    std::array<int, kCorners> number{};
    number.fill(-1);
    int count = 0;
    for (int c = 0; c < kCorners; ++c) {
        if (!used[std::size_t(c)]) continue;
        int& n = number[std::size_t(root(c))];
        if (n < 0) n = count++;
        piece[std::size_t(c)] = static_cast<std::int8_t>(n);
    }
    return piece;
}

// The exits of one piece: its triangles' sides used once that join two cube
// edges lie on a face, in the order of the sides' first use.
void addExits(const TrilinearCase& subcase, int mine, SubcasePieces& out, int& exitCount) {
    std::array<std::uint8_t, kCorners * kCorners> uses{};  // per side (a, b), a < b
    std::array<std::uint16_t, 3 * kMaxTrilinearTriangles> sides{};
    int sideCount = 0;
    for (int t = 0; t < subcase.triangleCount; ++t) {
        const auto& tri = subcase.triangles[std::size_t(t)];
        if (out.piece[std::size_t(tri[0])] != mine) continue;
        for (int k = 0; k < 3; ++k) {
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
            if (exitCount == int(out.exits.size())) throw std::logic_error("trilinear table: a subcase of many exits");
            out.exits[std::size_t(exitCount++)] = static_cast<std::uint8_t>(f << 4 | cube::edgeAcrossFace(a, f));
        }
    }
}

// SubcasePieces of every subcase of the trilinear table, by its index in cases().
const std::vector<SubcasePieces>& subcasePieces() {
    static const std::vector<SubcasePieces> all = [] {
        const auto& cases = trilinearTable().cases();
        std::vector<SubcasePieces> pieces(cases.size());
        for (std::size_t i = 0; i < cases.size(); ++i) {
            SubcasePieces& out = pieces[i];
            out.piece = piecesOf(cases[i]);
            const int count = 1 + *std::max_element(out.piece.begin(), out.piece.end());
            if (count > 8) throw std::logic_error("trilinear table: a subcase of more than eight pieces");
            out.allPieces = static_cast<std::uint8_t>((1u << count) - 1);
            int exitCount = 0;
            for (int p = 0; p < 8; ++p) {
                out.firstExit[std::size_t(p)] = static_cast<std::uint8_t>(exitCount);
                if (p < count) addExits(cases[i], p, out, exitCount);
            }
            out.firstExit[8] = static_cast<std::uint8_t>(exitCount);
        }
        return pieces;
    }();
    return all;
}

template <class T>
class TypedTrilinearWalker final : public TrilinearWalker {
    static constexpr int kShift = SparseBlocks::kShift;
    static constexpr int kLast = SparseBlocks::kSide - 1;

public:
    TypedTrilinearWalker(const Volume& volume, const T* samples, double iso)
        : grid_(volume, samples, iso),
          n_(volume.dims()),
          cases_(trilinearTable().cases().data()),
          pieces_(subcasePieces()) {}

    void queueSeed(SparseBlocks& blocks, TrilinearPart& part, const GridEdge& seed) const override {
        // A cell holding the seed edge: its origin moves back along the other axes where it can.
        std::array<int, 3> cell{seed.x, seed.y, seed.z}, offset{0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            if (k != seed.axis && cell[std::size_t(k)] == n_[k] - 1) --cell[std::size_t(k)], offset[std::size_t(k)] = 1;
        }
        part.queue.push({blocks.at(cell[0], cell[1], cell[2], part.thread),
                         static_cast<std::uint16_t>(SparseBlocks::local(cell[0], cell[1], cell[2])),
                         static_cast<std::uint8_t>(cube::edgeAt(offset, seed.axis))});
    }

    std::size_t advance(SparseBlocks& blocks, TrilinearPart& part, std::size_t pieceBudget) const override {
        return walk(blocks, part, pieceBudget, nullptr);
    }

    void walkShared(SparseBlocks& blocks, TrilinearPart& part, Exchange& exchange) const override {
        std::vector<Exchange::Message> received;
        do {
            enqueueReceived(part, received);
            walk(blocks, part, std::numeric_limits<std::size_t>::max(), &exchange);
        } while (part.queue.empty() && exchange.wait(part.thread, received));
    }

private:
    // Walks the part's queue until `pieceBudget` pieces are emitted or none is
    // left. With `exchange`, other threads walk the other tiles: cells there
    // are sent to them, and what they sent is taken every 64 cells.
    std::size_t walk(SparseBlocks& blocks, TrilinearPart& part, std::size_t pieceBudget, Exchange* exchange) const {
        std::size_t walked = 0, taken = 0;
        std::vector<Exchange::Message> received;
        while (walked < pieceBudget) {
            if (exchange != nullptr && (taken & 63) == 0) {
                if (!exchange->poll(part.thread, received)) break;
                enqueueReceived(part, received);
            }
            if (part.queue.empty()) break;
            ++taken;
            walked += visit(blocks, part, part.queue.pop(), exchange) ? 1 : 0;
        }
        part.piecesVisited += walked;
        return walked;
    }

    static void enqueueReceived(TrilinearPart& part, std::vector<Exchange::Message>& received) {
        for (const auto& m : received) part.queue.push({m.block, m.cell, m.edge});
        received.clear();
    }

    // Emits the piece of the entry's cell holding its edge unless it was
    // emitted before, and queues the cells it continues into (sending those of
    // other threads' tiles, with `exchange`); whether it was emitted.
    bool visit(SparseBlocks& blocks, TrilinearPart& part, const TrilinearEntry& entry, Exchange* exchange) const {
        Block* const block = entry.block;
        const int cell = entry.cell;
        const std::array<int, 3> local{cell & kLast, cell >> kShift & kLast, cell >> 2 * kShift};
        const std::array<int, 3> c{block->origin[0] + local[0], block->origin[1] + local[1],
                                   block->origin[2] + local[2]};
        std::uint8_t& visited = block->visited[std::size_t(cell)];
        // The block's config byte keeps a bit per piece of the cell once it is
        // classified: a cell whose pieces were all emitted is not classified again.
        std::uint8_t& pieceBits = block->config[std::size_t(cell)];
        if (pieceBits != 0 && visited == pieceBits) return false;
        const std::size_t i = grid_.index(c[0], c[1], c[2]);
        const std::uint8_t config = grid_.cellConfig(i);
        double values[8];
        for (int v = 0; v < 8; ++v) {
            const auto& o = cube::kVertexOffset[std::size_t(v)];
            values[v] = grid_.at(grid_.index(c[0] + o[0], c[1] + o[1], c[2] + o[2])) - grid_.iso();
        }
        const TrilinearCase& subcase = classifyTrilinear(values, config);
        const SubcasePieces& pieces = pieces_[std::size_t(&subcase - cases_)];
        pieceBits = pieces.allPieces;
        const int mine = pieces.piece[std::size_t(entry.edge)];
        if (mine < 0 || (visited & (1u << mine)) != 0) return false;
        visited = static_cast<std::uint8_t>(visited | 1u << mine);
        std::array<std::uint32_t, kCorners> ids{};
        std::array<bool, kCorners> made{};
        auto id = [&](int corner) {
            if (!made[std::size_t(corner)]) {
                ids[std::size_t(corner)] = corner < kInteriorVertex ? edgeVertex(blocks, part, block, local, c, corner)
                                                                    : interiorVertex(blocks, part, block, local, c,
                                                                                     subcase, corner, ids, made);
                made[std::size_t(corner)] = true;
            }
            return ids[std::size_t(corner)];
        };
        for (int t = 0; t < subcase.triangleCount; ++t) {
            const auto& tri = subcase.triangles[std::size_t(t)];
            if (pieces.piece[std::size_t(tri[0])] != mine) continue;
            for (int k = 0; k < 3; ++k) part.mesh.indices.push_back(id(tri[std::size_t(k)]));
        }
        for (int e = pieces.firstExit[std::size_t(mine)]; e < pieces.firstExit[std::size_t(mine) + 1]; ++e) {
            const int f = pieces.exits[std::size_t(e)] >> 4, axis = cube::faceAxis(f),
                      step = cube::faceSide(f) ? 1 : -1;
            const int next = c[std::size_t(axis)] + step;
            if (next < 0 || next > n_[axis] - 2) continue;
            // The cell across, in this block or the one across the block's face.
            std::array<int, 3> across = local;
            across[std::size_t(axis)] += step;
            Block* nextBlock = block;
            if (across[std::size_t(axis)] < 0 || across[std::size_t(axis)] > kLast) {
                across[std::size_t(axis)] &= kLast;
                nextBlock = blocks.linked(block, SparseBlocks::kSelf + step * linkStep(axis), part.thread);
            }
            const auto nextCell = static_cast<std::uint16_t>(SparseBlocks::local(across[0], across[1], across[2]));
            const auto edge = static_cast<std::uint8_t>(pieces.exits[std::size_t(e)] & 15);
            if (exchange != nullptr && nextBlock->owner != part.thread) {
                exchange->send(part.thread, nextBlock->owner, {nextBlock, 0, nextCell, edge});
            } else {
                part.queue.push({nextBlock, nextCell, edge});
            }
        }
        return true;
    }

    // The step in link number (SparseBlocks::kSelf) for a unit step along `axis`.
    static int linkStep(int axis) { return axis == 0 ? 1 : axis == 1 ? 3 : 9; }

    // The id of the vertex on cube edge `edge` of cell `c` (at `local` in
    // `block`), made the first time. Shared, on an edge between tiles (whose
    // cells may belong to several threads): when another thread recorded one
    // first, the vertex is given back and its id used.
    std::uint32_t edgeVertex(SparseBlocks& blocks, TrilinearPart& part, Block* block, const std::array<int, 3>& local,
                             const std::array<int, 3>& c, int edge) const {
        const auto& o = cube::edgeOrigin(edge);
        const int axis = cube::edgeAxis(edge);
        const int p[3] = {local[0] + o[0], local[1] + o[1], local[2] + o[2]};
        Block* holder = blocks.linked(
            block, SparseBlocks::kSelf + (p[0] >> kShift) + 3 * (p[1] >> kShift) + 9 * (p[2] >> kShift), part.thread);
        std::uint32_t& slot = holder->vertex[std::size_t(3 * SparseBlocks::local(p[0], p[1], p[2]) + axis)];
        const GridEdge e{c[0] + o[0], c[1] + o[1], c[2] + o[2], axis};
        const int m = part.tileMask;
        const bool seam = part.shared && ((axis != 0 && (e.x & m) == 0) || (axis != 1 && (e.y & m) == 0) ||
                                          (axis != 2 && (e.z & m) == 0));
        const std::uint32_t found = seam ? __atomic_load_n(&slot, __ATOMIC_RELAXED) : slot;
        if (found != SparseBlocks::kNoVertex) return found;
        const auto id = newId(part);
        grid_.edgeVertex(e.x, e.y, e.z, e.axis, part.mesh.vertices.emplace_back());
        if (seam) {
            std::uint32_t first = SparseBlocks::kNoVertex;
            if (!__atomic_compare_exchange_n(&slot, &first, id, false, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {
                part.mesh.vertices.pop_back();
                return first;
            }
        } else {
            slot = id;
        }
        part.mesh.vertexEdges.push_back(e);
        return id;
    }

    // The id the part's next vertex will have.
    static std::uint32_t newId(const TrilinearPart& part) {
        return partVertexId(part.idBase, part.indexMask, part.mesh.vertices.size());
    }

    // A vertex inside the cell: the mean of the vertices on the cube edges
    // `around` it, moved halfway to its anchor's. The edges' vertices are made
    // (or found) first, and their positions computed again here: one of them
    // may be another thread's.
    template <class Ids, class Made>
    std::uint32_t interiorVertex(SparseBlocks& blocks, TrilinearPart& part, Block* block,
                                 const std::array<int, 3>& local, const std::array<int, 3>& c,
                                 const TrilinearCase& subcase, int corner, Ids& ids, Made& made) const {
        const InteriorVertex& where = subcase.interior[std::size_t(corner - kInteriorVertex)];
        double position[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
        int count = 0;
        auto vertexOf = [&](int edge) {
            if (!made[std::size_t(edge)])
                ids[std::size_t(edge)] = edgeVertex(blocks, part, block, local, c, edge),
                made[std::size_t(edge)] = true;
            const auto& o = cube::edgeOrigin(edge);
            Vertex v;
            grid_.edgeVertex(c[0] + o[0], c[1] + o[1], c[2] + o[2], cube::edgeAxis(edge), v);
            return v;
        };
        for (unsigned mask = where.around; mask != 0; mask &= mask - 1) {
            const Vertex v = vertexOf(__builtin_ctz(mask));
            for (int k = 0; k < 3; ++k) position[k] += v.position[k], normal[k] += v.normal[k];
            ++count;
        }
        for (int k = 0; k < 3; ++k) position[k] /= count;
        if (where.anchor >= 0) {
            const Vertex anchor = vertexOf(where.anchor);
            for (int k = 0; k < 3; ++k) position[k] = 0.5 * (position[k] + anchor.position[k]);
        }
        const auto id = newId(part);
        Vertex& out = part.mesh.vertices.emplace_back();
        const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
        for (int k = 0; k < 3; ++k) {
            out.position[k] = static_cast<float>(position[k]);
            out.normal[k] = length > 0.0 ? static_cast<float>(normal[k] / length) : 0.0f;
        }
        part.mesh.vertexEdges.push_back(GridEdge{c[0], c[1], c[2], kCellInterior});
        return id;
    }

    SampleGrid<T> grid_;
    const Dims n_;
    const TrilinearCase* cases_;
    const std::vector<SubcasePieces>& pieces_;
};

// The walk on one thread, a budget of pieces at a time (trackTrilinear on one
// thread, and SurfaceTracker's growth).
class OneThreadWalk final : public TrilinearWalk {
public:
    OneThreadWalk(const Volume& volume, double iso, const GridEdge& seed)
        : blocks_(volume.dims()), walker_(makeTrilinearWalker(volume, iso)) {
        walker_->queueSeed(blocks_, part_, seed);
    }

    std::size_t advance(std::size_t pieceBudget) override { return walker_->advance(blocks_, part_, pieceBudget); }
    bool done() const override { return part_.queue.empty(); }
    Mesh& mesh() override { return part_.mesh; }
    const Mesh& mesh() const override { return part_.mesh; }
    std::size_t piecesVisited() const override { return part_.piecesVisited; }
    std::size_t workingBytes() const override {
        return blocks_.byteSize() + part_.queue.capacity() * sizeof(TrilinearEntry);
    }

private:
    SparseBlocks blocks_;
    std::unique_ptr<TrilinearWalker> walker_;
    TrilinearPart part_;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

void checkTrilinearSeed(const Volume& volume, double iso, const GridEdge& seed) {
    const Dims& n = volume.dims();
    const int p[3] = {seed.x, seed.y, seed.z};
    bool inside = seed.axis >= 0 && seed.axis < 3;
    for (int k = 0; k < 3 && inside; ++k) inside = p[k] >= 0 && p[k] + (k == seed.axis) < n[k] && n[k] >= 2;
    if (!inside) throw InputError("track: the seed edge is outside the volume");
    const int end[3] = {seed.x + (seed.axis == 0), seed.y + (seed.axis == 1), seed.z + (seed.axis == 2)};
    const bool a = volume.value(seed.x, seed.y, seed.z) >= iso, b = volume.value(end[0], end[1], end[2]) >= iso;
    if (a == b) throw InputError("track: the seed edge is not crossed by the surface at this isovalue");
}

std::unique_ptr<TrilinearWalker> makeTrilinearWalker(const Volume& volume, double iso) {
    return visitSamples(volume, [&](const auto* samples) -> std::unique_ptr<TrilinearWalker> {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(samples)>>;
        return std::make_unique<TypedTrilinearWalker<T>>(volume, samples, iso);
    });
}

std::unique_ptr<TrilinearWalk> startTrilinear(const Volume& volume, double iso, const GridEdge& seed) {
    checkTrilinearSeed(volume, iso, seed);
    return std::make_unique<OneThreadWalk>(volume, iso, seed);
}

Surface finishedTrilinear(TrilinearWalk& walk, const Volume& volume, int threads) {
    Surface surface;
    surface.mesh = std::move(walk.mesh());
    surface.stats = measureSurfaceOn(surface.mesh, volume, false, threads);
    surface.stats.cellsVisited = walk.piecesVisited();
    return surface;
}

Surface trackTrilinear(const Volume& volume, double iso, const GridEdge& seed, int threads) {
    const auto start = std::chrono::steady_clock::now();
    // As the consistent table's track: more threads than the volume's tiles can share out would only wait.
    threads = std::min({threads, kMaxTrackThreads, SparseBlocks::usefulThreads(volume.dims())});
    Surface surface;
    if (threads > 1) {
        checkTrilinearSeed(volume, iso, seed);
        const auto walker = makeTrilinearWalker(volume, iso);
        std::vector<std::size_t> pieces;
        surface.mesh = walkTrilinearTogether(volume, *walker, seed, threads, pieces);
        surface.stats = measureSurfaceInRuns(surface.mesh, volume, threads);
        surface.stats.cellsVisited = std::accumulate(pieces.begin(), pieces.end(), std::size_t(0));
    } else {
        const auto walk = startTrilinear(volume, iso, seed);
        walk->advance(std::numeric_limits<std::size_t>::max());
        surface = finishedTrilinear(*walk, volume);
    }
    surface.stats.seconds = secondsSince(start);
    return surface;
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
    std::vector<std::size_t> surfaceOfRoot(mesh.vertices.size(), ~std::size_t(0));  // per root vertex
    std::vector<Surface> surfaces;
    std::vector<std::uint32_t> local(mesh.vertices.size(), ~0u);
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
        std::size_t& surface = surfaceOfRoot[root(mesh.indices[i])];
        if (surface == ~std::size_t(0)) surface = surfaces.size(), surfaces.emplace_back();
        Mesh& part = surfaces[surface].mesh;
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
