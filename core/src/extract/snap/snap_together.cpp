// Tracking one surface with the 3-state table on several threads, as the
// trilinear table's walk does (trilinear_together.cpp): each thread walks the
// cells of its own tiles (SparseBlocks::ownerShift), sends a (cell, piece) in
// another thread's tile to that thread (Exchange), which marks and queues it
// as its own, and claims the vertices that cells of several tiles share with a
// compare-and-swap: those on grid edges between tiles, and on samples at the
// isovalue on a tile's faces. A fanned loop's centre, inside one cell, is
// made once under a lock (centres are rare). The threads' parts are joined
// into one mesh in parallel (joinWalkParts), the triangles the cells drew on
// their faces listed in the joined order, and the fins among them removed
// (removeFinsAmong) as on one thread.
//
// The walk visits the (cell, piece) pairs that continue from the seed's, on
// any number of threads, and each piece draws the same triangles over the same
// vertices: the triangle set is one thread's, their order and the vertices'
// are the threads' (a surface done within the first kPiecesAlone pieces is
// one thread's mesh, byte for byte).
#include <cstddef>
#include <cstdint>
#include <limits>
#include <mutex>
#include <numeric>
#include <string>
#include <unordered_map>
#include <vector>

#include "extract/common/part_ids.h"
#include "extract/common/sparse_blocks.h"
#include "extract/measure/surface_measure.h"
#include "extract/snap/snap_cells.h"
#include "extract/tracking/piece_queue.h"
#include "extract/tracking/walk_exchange.h"
#include "extract/trilinear/trilinear_walker.h"
#include "mesh/weld.h"
#include "support/parallel.h"

namespace isotrack::detail {
namespace {

// A (cell, piece) to walk, marked visited when queued; `config` is the cell's
// snap table entry (snapCaseIndex, below 2^16).
struct SnapEntry {
    int x, y, z;
    std::uint16_t config;
    std::uint8_t piece;
};

// One thread's share of the walk: its queue, breadth-first, the vertices and
// triangles it emits and those of its triangles drawn on a cell face. A vertex
// id is the vertex's index in the part's mesh with the part's thread in the
// id's top bits.
struct alignas(128) SnapPart {
    Mesh mesh;
    std::vector<std::uint32_t> onFaces;
    Ring<SnapEntry> queue;
    std::size_t piecesVisited = 0;
    int thread = 0;
    std::uint32_t idBase = 0;
    std::uint32_t indexMask = ~std::uint32_t(0);
    int tileMask = 0;  // a tile's side less one
};

// A cell's coordinates in an Exchange message's `sample`, 21 bits each.
std::size_t packCell(int x, int y, int z) { return std::size_t(x) | std::size_t(y) << 21 | std::size_t(z) << 42; }

template <class T>
class SnapTogether {
public:
    SnapTogether(const SnapCells<T>& cells, int threads)
        : cells_(cells),
          tiles_(cells.volume().dims(), threads),
          slots_(cells.volume().dims(), threads),
          visited_(cells.visitMarks(), 0) {}

    int tileMask() const { return tiles_.tileMask(); }
    int owner(const SnapEntry& entry) const { return tiles_.ownerAt(entry.x, entry.y, entry.z); }

    // Marks and queues the piece unless it was queued before; with `exchange`,
    // a cell of another thread's tile is sent to that thread instead.
    void enqueue(SnapPart& part, const SnapEntry& entry, Exchange* exchange) {
        if (exchange != nullptr) {
            const int to = owner(entry);
            if (to != part.thread) {
                exchange->send(part.thread, to,
                               {nullptr, packCell(entry.x, entry.y, entry.z), entry.config, entry.piece});
                return;
            }
        }
        std::uint8_t& bits = visited_[cells_.visitIndex(entry.x, entry.y, entry.z)];
        if (bits >> entry.piece & 1u) return;
        bits = static_cast<std::uint8_t>(bits | 1u << entry.piece);
        part.queue.push(entry);
    }

    // Walks the part's queue until `pieceBudget` pieces are emitted or none is
    // left. With `exchange`, the other threads walk their tiles: what they sent
    // is taken every 64 pieces.
    std::size_t walk(SnapPart& part, std::size_t pieceBudget, Exchange* exchange) {
        std::size_t walked = 0;
        std::vector<Exchange::Message> received;
        for (; walked < pieceBudget; ++walked) {
            if (exchange != nullptr && (walked & 63) == 0) {
                if (!exchange->poll(part.thread, received)) break;
                enqueueReceived(part, received);
            }
            if (part.queue.empty()) break;
            // The entry a few pieces ahead, fetched early, as SnapWalk does.
            if (part.queue.size() > kFetchAhead) {
                const char* next = reinterpret_cast<const char*>(&cells_.entry(part.queue.ahead(kFetchAhead).config));
                __builtin_prefetch(next);
                __builtin_prefetch(next + 64);
            }
            visit(part, part.queue.pop(), exchange);
        }
        part.piecesVisited += walked;
        return walked;
    }

    // Walks the part's tiles as one of several threads, until no piece is left.
    void walkShared(SnapPart& part, Exchange& exchange) {
        std::vector<Exchange::Message> received;
        do {
            enqueueReceived(part, received);
            walk(part, std::numeric_limits<std::size_t>::max(), &exchange);
        } while (part.queue.empty() && exchange.wait(part.thread, received));
    }

private:
    static constexpr std::size_t kFetchAhead = 8;

    void enqueueReceived(SnapPart& part, std::vector<Exchange::Message>& received) {
        constexpr std::size_t mask = (std::size_t(1) << 21) - 1;
        for (const auto& m : received) {
            enqueue(part, {int(m.sample & mask), int(m.sample >> 21 & mask), int(m.sample >> 42), m.cell, m.edge},
                    nullptr);
        }
        received.clear();
    }

    // Emits the entry's piece and queues (or sends) the pieces it continues
    // into across the cell's faces, as SnapWalk::advance.
    void visit(SnapPart& part, const SnapEntry& entry, Exchange* exchange) {
        const auto& continuation = continuationTable(TableKind::Consistent);
        const auto& across = edgesAcrossFaces();
        const int x = entry.x, y = entry.y, z = entry.z, piece = entry.piece;
        emit(part, entry.config, piece, x, y, z);
        const Piece& exits = continuation[entry.config & 0xff].pieces[std::size_t(piece)];
        for (int f = 0; f < cube::kFaceCount; ++f) {
            if (exits.exits[std::size_t(f)][0] < 0) continue;
            int n[3] = {x, y, z};
            n[cube::faceAxis(f)] += cube::faceSide(f) ? 1 : -1;
            if (!cells_.cellInside(n[0], n[1], n[2])) continue;
            const int config = cells_.config(n[0], n[1], n[2]);
            const std::uint8_t above = std::uint8_t(config & 0xff);
            for (const std::int8_t edge : exits.exits[std::size_t(f)]) {
                if (edge < 0) break;
                const int entryEdge = across[std::size_t(edge)][std::size_t(f)];
                const int next = continuation[above].pieceOfEdge[std::size_t(entryEdge)];
                if (next < 0) throw std::logic_error("snap walk: an exit edge is not crossed across the face");
                enqueue(part, {n[0], n[1], n[2], std::uint16_t(config), std::uint8_t(next)}, exchange);
            }
        }
    }

    // SnapCells::emit for a part: the same triangles, with vertex ids that may
    // be another part's.
    void emit(SnapPart& part, int index, int piece, int x, int y, int z) {
        const SnapCase& cased = cells_.entry(index);
        const auto& faces = cells_.cornerTable().faces;
        std::array<std::uint32_t, kSnapCornerCentre> ids;
        ids.fill(kNoVertex);
        for (int t = 0; t < cased.count; ++t) {
            if (cased.piece[std::size_t(t)] != piece) continue;
            const auto& triangle = cased.triangles[std::size_t(t)];
            if (faces[std::size_t(triangle[0])] & faces[std::size_t(triangle[1])] & faces[std::size_t(triangle[2])])
                part.onFaces.push_back(std::uint32_t(part.mesh.indices.size() / 3));
            for (const std::int8_t corner : triangle) {
                if (corner >= kSnapCornerCentre) {
                    part.mesh.indices.push_back(centre(part, cased, corner - kSnapCornerCentre, x, y, z));
                    continue;
                }
                std::uint32_t& id = ids[std::size_t(corner)];
                if (id == kNoVertex) id = vertex(part, corner, x, y, z);
                part.mesh.indices.push_back(id);
            }
        }
    }

    // The id of table corner `corner`'s vertex in cell (x, y, z), made the
    // first time. A slot that cells of other tiles use too (its sample on a
    // tile's lower face, along an axis other than its edge's) is claimed with
    // a compare-and-swap: when another thread recorded a vertex first, this
    // one is given back and that one's id used.
    std::uint32_t vertex(SnapPart& part, int corner, int x, int y, int z) {
        const auto& place = cells_.cornerTable().place[std::size_t(corner)];
        const int p[3] = {x + place[0], y + place[1], z + place[2]};
        const int axis = place[3];
        std::uint32_t* slot = slots_.slot(p[0], p[1], p[2], axis, part.thread);
        const int m = part.tileMask;
        bool seam = false;
        for (int k = 0; k < 3; ++k) seam = seam || (k != axis && (p[k] & m) == 0);
        const std::uint32_t found = seam ? __atomic_load_n(slot, __ATOMIC_RELAXED) : *slot;
        if (found != kNoVertex) return found;
        const std::uint32_t id = newId(part);
        Vertex v{};
        const GridEdge edge = cells_.cornerVertex(corner, x, y, z, v);
        if (seam) {
            std::uint32_t first = kNoVertex;
            if (!__atomic_compare_exchange_n(slot, &first, id, false, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) return first;
        } else {
            *slot = id;
        }
        part.mesh.vertices.push_back(v);
        part.mesh.vertexEdges.push_back(edge);
        return id;
    }

    // The vertex at the mean of a fanned loop's corners, with their mean
    // normal, as SnapCells makes it; the corners' vertices are made (or found)
    // first, their positions computed again here: one may be another part's.
    std::uint32_t centre(SnapPart& part, const SnapCase& cased, int loop, int x, int y, int z) {
        const std::uint64_t key =
            (std::uint64_t(x) | std::uint64_t(y) << 21 | std::uint64_t(z) << 42) * 4 + std::uint64_t(loop);
        const std::lock_guard<std::mutex> lock(centresLock_);
        if (const auto it = centres_.find(key); it != centres_.end()) return it->second;
        LoopCentre sum;
        for (const std::int8_t corner : cased.centres[std::size_t(loop)]) {
            if (corner < 0) break;
            vertex(part, corner, x, y, z);
            Vertex v{};
            cells_.cornerVertex(corner, x, y, z, v);
            sum.add(v);
        }
        const std::uint32_t id = newId(part);
        part.mesh.vertices.push_back(sum.vertex());
        part.mesh.vertexEdges.push_back(GridEdge{x, y, z, kCellInterior});
        centres_.emplace(key, id);
        return id;
    }

    // The id the part's next vertex will have.
    static std::uint32_t newId(const SnapPart& part) {
        return partVertexId(part.idBase, part.indexMask, part.mesh.vertices.size());
    }

    const SnapCells<T>& cells_;
    SparseBlocks tiles_;  // for the tiles' owners alone
    SharedBlockSlots slots_;
    // One bit per piece, per cell, at SnapCells::visitIndex: read and written
    // by the thread owning the cell's tile alone (the first thread's too
    // before the others start).
    std::vector<std::uint8_t> visited_;
    std::mutex centresLock_;
    std::unordered_map<std::uint64_t, std::uint32_t> centres_;  // per cell and loop
};

// The parts in one mesh, the fins among the triangles drawn on cell faces removed.
Mesh joinedWithoutFins(const std::vector<SnapPart>& parts, int idShift, int threads) {
    Mesh mesh = joinWalkParts(parts, idShift, threads);
    std::vector<std::uint32_t> onFaces;
    std::uint32_t firstTriangle = 0;
    for (const SnapPart& part : parts) {
        for (const std::uint32_t t : part.onFaces) onFaces.push_back(firstTriangle + t);
        firstTriangle += std::uint32_t(part.mesh.indices.size() / 3);
    }
    mesh.indices.resize(removeFinsAmong(mesh.indices.data(), mesh.indices.size(), onFaces));
    dropUnusedVertices(mesh);
    return mesh;
}

template <class T>
Surface trackTogetherTyped(const Volume& volume, const T* samples, double iso, const GridEdge& seed, int threads) {
    const SnapCells<T> cells(volume, samples, iso, threads);
    const auto [x, y, z, piece] = seedPiece(cells, iso, seed);
    SnapTogether<T> walk(cells, threads);
    std::vector<SnapPart> parts(static_cast<std::size_t>(threads));
    const PartIds ids(threads);
    const int idShift = ids.shift;
    for (int t = 0; t < threads; ++t) {
        SnapPart& part = parts[std::size_t(t)];
        part.thread = t;
        part.idBase = ids.base(t);
        part.indexMask = ids.indexMask();
        part.tileMask = walk.tileMask();
    }
    // The first pieces are walked on this thread alone; what is left is handed
    // to the parts of the queued cells' tiles (marked already, by this thread).
    walk.enqueue(parts[0], {x, y, z, std::uint16_t(cells.config(x, y, z)), std::uint8_t(piece)}, nullptr);
    walk.walk(parts[0], kPiecesAlone, nullptr);
    const bool alone = parts[0].queue.empty();
    if (!alone) {
        std::vector<SnapEntry> left;
        while (!parts[0].queue.empty()) left.push_back(parts[0].queue.pop());
        for (const SnapEntry& entry : left) parts[std::size_t(walk.owner(entry))].queue.push(entry);
        Exchange exchange(threads);
        runTogether(
            threads, [&](int t) { walk.walkShared(parts[std::size_t(t)], exchange); }, [&] { exchange.stop(); });
    }
    Surface surface;
    surface.mesh = joinedWithoutFins(parts, idShift, threads);
    // A surface walked alone is one thread's, measured as on one thread.
    surface.stats = alone ? measureSurfaceOn(surface.mesh, volume, false, threads)
                          : measureSurfaceInRuns(surface.mesh, volume, threads);
    std::size_t pieces = 0;
    for (const SnapPart& part : parts) pieces += part.piecesVisited;
    surface.stats.cellsVisited = pieces;
    return surface;
}

}  // namespace

Surface trackSnapTogether(const Volume& volume, double iso, const GridEdge& seed, int threads) {
    return visitSamples(volume,
                        [&](const auto* samples) { return trackTogetherTyped(volume, samples, iso, seed, threads); });
}

}  // namespace isotrack::detail
