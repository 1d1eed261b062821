// Piecewise continuation: tracking one connected isosurface from a seed edge.
//
// After Ghataora, "The development of Piecewise Continuation on Marching Cubes"
// (Leeds, 2013), and the surface tracking of Shekhar et al. (1996).
//
// A queue holds (cell, entry edge) pairs. For each pair:
//  1. classify: the cell's configuration from its 8 samples (sample >= iso);
//  2. find the piece: the continuation table names the piece of the cell's
//     surface that holds the entry edge; a (cell, piece) seen before is skipped;
//  3. emit: the piece's triangles, each corner a grid edge whose vertex is looked
//     up in an edge-keyed map and computed only the first time;
//  4. continue: for each face the piece crosses, the cell across that face is
//     queued with the shared edge.
// Visited pieces and vertices live in hash maps sized by the surface, so the cost
// follows the surface, not the volume. extractAllSurfaces scans every cell
// instead, and marks pieces in one byte per cell.
#include "isotrack/tracking.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "edge_vertex.h"
#include "flat_hash.h"
#include "sparse_blocks.h"
#include "surface_measure.h"
#include "isotrack/continuation.h"
#include "isotrack/cube.h"
#include "isotrack/errors.h"

namespace isotrack {
namespace {

using Clock = std::chrono::steady_clock;

// With the consistent table a tracked surface has no holes: it is closed exactly
// when the volume's border does not cut it.
SurfaceStats measureTracked(const Mesh& mesh, const Volume& volume, TableKind table) {
    return measureSurface(mesh, volume, table == TableKind::Consistent);
}

// A cell piece waiting in the queue; it was marked when queued, so each piece is
// queued once.
struct Entry {
    int x, y, z;
    std::uint8_t config;
    std::uint8_t piece;
};

// Per-face step and the entry edge across each face, computed once.
struct FaceSteps {
    std::array<std::array<int, 3>, 6> step{};
    std::array<std::array<std::int8_t, 12>, 6> across{};
    std::array<std::array<int, 3>, 12> edgeOrigin{};
    std::array<int, 12> edgeAxis{};
    std::array<int, 12> edgeLocal{};  // offset of the edge's origin in a sparse block's local index
    FaceSteps() {
        for (int f = 0; f < cube::kFaceCount; ++f) {
            step[f][cube::faceAxis(f)] = cube::faceSide(f) ? 1 : -1;
            for (int e = 0; e < cube::kEdgeCount; ++e) {
                across[f][e] = static_cast<std::int8_t>(cube::edgeOnFace(e, f) ? cube::edgeAcrossFace(e, f) : -1);
            }
        }
        for (int e = 0; e < cube::kEdgeCount; ++e) {
            edgeOrigin[e] = cube::edgeOrigin(e);
            edgeAxis[e] = cube::edgeAxis(e);
            edgeLocal[e] = detail::SparseBlocks::local(edgeOrigin[e][0], edgeOrigin[e][1], edgeOrigin[e][2]);
        }
    }
};

const FaceSteps& faceSteps() {
    static const FaceSteps steps;
    return steps;
}

std::string numberText(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

std::string edgeText(const GridEdge& e) {
    return "(" + std::to_string(e.x) + "," + std::to_string(e.y) + "," + std::to_string(e.z) + ") axis " +
           "xyz"[e.axis];
}

// What a tracked surface accumulates, whatever the sample type.
struct TrackState {
    explicit TrackState(const Dims& dims) : blocks(dims) {}
    Mesh mesh;
    detail::SparseBlocks blocks;
    std::uint8_t* denseVisited = nullptr;  // one bit per piece per cell, for trackAllSurfaces
    std::vector<Entry> queue;
    std::size_t head = 0;
    std::size_t cellsVisited = 0;
    bool leftVolume = false;
};

class TrackWorker {
public:
    virtual ~TrackWorker() = default;
    // Queues the piece of cell (x, y, z) holding cube edge `edge`, unless it was queued before.
    virtual void enqueue(TrackState& state, int x, int y, int z, int edge) const = 0;
    virtual std::size_t advance(TrackState& state, std::size_t cellBudget) const = 0;
    virtual std::uint8_t config(int x, int y, int z) const = 0;
    virtual bool crossed(const GridEdge& edge) const = 0;
};

template <class T>
class TypedTrackWorker final : public TrackWorker {
public:
    TypedTrackWorker(const Volume& volume, const T* samples, double iso, TableKind table)
        : grid_(volume, samples, iso), table_(continuationTable(table)), steps_(faceSteps()) {}

    std::uint8_t config(int x, int y, int z) const override {
        const std::size_t i = grid_.index(x, y, z);
        const std::size_t sy = grid_.strideY(), sz = grid_.strideZ();
        const unsigned c = grid_.above(i) | grid_.above(i + 1) << 1 | grid_.above(i + 1 + sy) << 2 |
                           grid_.above(i + sy) << 3 | grid_.above(i + sz) << 4 | grid_.above(i + 1 + sz) << 5 |
                           grid_.above(i + 1 + sy + sz) << 6 | grid_.above(i + sy + sz) << 7;
        return static_cast<std::uint8_t>(c);
    }

    bool crossed(const GridEdge& e) const override {
        const std::size_t i = grid_.index(e.x, e.y, e.z);
        const std::size_t stride[3] = {1, grid_.strideY(), grid_.strideZ()};
        return grid_.above(i) != grid_.above(i + stride[e.axis]);
    }

    void enqueue(TrackState& state, int x, int y, int z, int edge) const override {
        enqueueIn(state, state.blocks.at(x, y, z), detail::SparseBlocks::local(x, y, z), x, y, z, edge);
    }

    // As enqueue, with the cell's block and local index already known.
    void enqueueIn(TrackState& state, detail::SparseBlocks::Block& block, int cell, int x, int y, int z, int edge) const {
        if (block.config[std::size_t(cell)] == 0) block.config[std::size_t(cell)] = config(x, y, z);
        const std::uint8_t c = block.config[std::size_t(cell)];
        const int piece = table_[c].pieceOfEdge[edge];
        if (piece < 0) return;
        std::uint8_t& marks = state.denseVisited ? state.denseVisited[grid_.index(x, y, z)] : block.visited[std::size_t(cell)];
        const auto bit = static_cast<std::uint8_t>(1u << piece);
        if (marks & bit) return;
        marks = static_cast<std::uint8_t>(marks | bit);
        state.queue.push_back({x, y, z, c, static_cast<std::uint8_t>(piece)});
    }

    std::size_t advance(TrackState& state, std::size_t cellBudget) const override {
        const int last[3] = {grid_.nx() - 2, grid_.ny() - 2, grid_.nz() - 2};
        std::size_t visited = 0;
        while (state.head < state.queue.size() && visited < cellBudget) {
            const Entry entry = state.queue[state.head++];
            ++visited;
            const CaseContinuation& cased = table_[entry.config];
            const Piece& piece = cased.pieces[entry.piece];
            // The cell's block holds its corners too unless it sits on the block's upper faces.
            constexpr int kLast = detail::SparseBlocks::kSide - 1;
            detail::SparseBlocks::Block& block = state.blocks.at(entry.x, entry.y, entry.z);
            const int cell = detail::SparseBlocks::local(entry.x, entry.y, entry.z);
            const int lx = entry.x & kLast, ly = entry.y & kLast, lz = entry.z & kLast;
            const bool cornersInBlock = lx < kLast && ly < kLast && lz < kLast;
            std::array<std::uint32_t, 12> vertexOf;
            for (unsigned mask = piece.edgeMask; mask != 0; mask &= mask - 1) {
                const int edge = __builtin_ctz(mask);
                std::uint32_t& id = cornersInBlock ? block.vertex[std::size_t(3 * (cell + steps_.edgeLocal[edge]) + steps_.edgeAxis[edge])]
                                                   : vertexSlot(state, entry, edge);
                if (id == detail::SparseBlocks::kNoVertex) id = newVertex(state, entry, edge);
                vertexOf[edge] = id;
            }
            const std::size_t at = state.mesh.indices.size();
            state.mesh.indices.resize(at + 3 * std::size_t(piece.triangleCount));
            std::uint32_t* out = state.mesh.indices.data() + at;
            for (int t = piece.firstTriangle; t < piece.firstTriangle + piece.triangleCount; ++t) {
                for (int corner = 0; corner < 3; ++corner) *out++ = vertexOf[cased.triangles[t][corner]];
            }
            const int local[3] = {lx, ly, lz};
            for (int f = 0; f < cube::kFaceCount; ++f) {
                if (piece.exits[f][0] < 0) continue;
                const int axis = cube::faceAxis(f);
                const int step = steps_.step[f][axis];
                const int to[3] = {entry.x + steps_.step[f][0], entry.y + steps_.step[f][1], entry.z + steps_.step[f][2]};
                if (to[axis] < 0 || to[axis] > last[axis]) {
                    state.leftVolume = true;  // the surface is cut open by the volume's border here
                    continue;
                }
                const int toLocal = local[axis] + step;
                const bool sameBlock = toLocal >= 0 && toLocal <= kLast;
                detail::SparseBlocks::Block& target = sameBlock ? block : state.blocks.at(to[0], to[1], to[2]);
                const int targetCell = sameBlock ? cell + step * detail::SparseBlocks::kLocalStep[std::size_t(axis)]
                                                 : detail::SparseBlocks::local(to[0], to[1], to[2]);
                for (std::int8_t exit : piece.exits[f]) {
                    if (exit < 0) break;
                    enqueueIn(state, target, targetCell, to[0], to[1], to[2], steps_.across[f][exit]);
                }
            }
        }
        if (state.head == state.queue.size()) {
            state.queue.clear();
            state.head = 0;
        } else if (state.head > 4096 && state.head * 2 > state.queue.size()) {
            state.queue.erase(state.queue.begin(), state.queue.begin() + std::ptrdiff_t(state.head));
            state.head = 0;
        }
        state.cellsVisited += visited;
        return visited;
    }

private:
    std::uint32_t& vertexSlot(TrackState& state, const Entry& entry, int edge) const {
        const auto& o = steps_.edgeOrigin[edge];
        const int x = entry.x + o[0], y = entry.y + o[1], z = entry.z + o[2];
        return state.blocks.at(x, y, z).vertex[std::size_t(3 * detail::SparseBlocks::local(x, y, z) + steps_.edgeAxis[edge])];
    }

    std::uint32_t newVertex(TrackState& state, const Entry& entry, int edge) const {
        const auto& o = steps_.edgeOrigin[edge];
        const int axis = steps_.edgeAxis[edge];
        const int x = entry.x + o[0], y = entry.y + o[1], z = entry.z + o[2];
        state.mesh.vertices.push_back(grid_.edgeVertex(x, y, z, axis));
        state.mesh.vertexEdges.push_back(GridEdge{x, y, z, axis});
        return static_cast<std::uint32_t>(state.mesh.vertices.size() - 1);
    }

    detail::SampleGrid<T> grid_;
    const std::array<CaseContinuation, 256>& table_;
    const FaceSteps& steps_;
};

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
void queueSeed(const Volume& volume, const GridEdge& seed, const TrackWorker& worker, TrackState& state) {
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
            worker.enqueue(state, cell[0], cell[1], cell[2], cube::edgeAt(local, seed.axis));
        }
    }
}

}  // namespace

bool edgeIsCrossed(const Volume& volume, double iso, const GridEdge& edge) {
    if (!edgeInside(volume, edge)) return false;
    return makeWorker(volume, iso, TableKind::Consistent)->crossed(edge);
}

GridEdge nearestCrossedEdge(const Volume& volume, double iso, const Vec3d& worldPoint) {
    const Dims& n = volume.dims();
    const Vec3d& s = volume.spacing();
    const Vec3d& o = volume.origin();
    const auto worker = makeWorker(volume, iso, TableKind::Consistent);
    int centre[3];
    double p[3];
    for (int k = 0; k < 3; ++k) {
        p[k] = (worldPoint[k] - o[k]) / s[k];
        const double clamped = std::clamp(std::isfinite(p[k]) ? p[k] : 0.0, 0.0, double(n[k] - 1));
        centre[k] = static_cast<int>(std::lround(clamped));
    }
    const double minSpacing = std::min({s[0], s[1], s[2]});
    double best = std::numeric_limits<double>::infinity();
    GridEdge bestEdge;
    const int maxRadius = std::max({n[0], n[1], n[2]});
    for (int r = 0; r <= maxRadius; ++r) {
        if (std::isfinite(best) && (r - 1) * minSpacing > best) break;
        const int lo[3] = {centre[0] - r, centre[1] - r, centre[2] - r};
        const int hi[3] = {centre[0] + r, centre[1] + r, centre[2] + r};
        for (int z = std::max(lo[2], 0); z <= std::min(hi[2], n[2] - 1); ++z) {
            for (int y = std::max(lo[1], 0); y <= std::min(hi[1], n[1] - 1); ++y) {
                const bool shellYZ = z == lo[2] || z == hi[2] || y == lo[1] || y == hi[1];
                for (int x = std::max(lo[0], 0); x <= std::min(hi[0], n[0] - 1);
                     x += (shellYZ || x == hi[0]) ? 1 : std::max(1, hi[0] - x)) {
                    for (int axis = 0; axis < 3; ++axis) {
                        const GridEdge e{x, y, z, axis};
                        if (!edgeInside(volume, e) || !worker->crossed(e)) continue;
                        double d2 = 0.0;
                        const int q[3] = {x, y, z};
                        for (int k = 0; k < 3; ++k) {
                            const double mid = q[k] + (k == axis ? 0.5 : 0.0);
                            d2 += (mid - p[k]) * (mid - p[k]) * s[k] * s[k];
                        }
                        if (std::sqrt(d2) < best) {
                            best = std::sqrt(d2);
                            bestEdge = e;
                        }
                    }
                }
            }
        }
    }
    if (!std::isfinite(best)) {
        throw InputError("no surface at iso " + numberText(iso) + ": no grid edge crosses it");
    }
    return bestEdge;
}

GridEdge edgeOfVertex(const Mesh& mesh, std::uint32_t vertex) {
    if (vertex >= mesh.vertexEdges.size()) throw InputError("picked vertex " + std::to_string(vertex) + " is not in the mesh");
    return mesh.vertexEdges[vertex];
}

GridEdge edgeOfTriangle(const Mesh& mesh, std::size_t triangle, const Vec3d& worldPoint) {
    if (triangle >= mesh.triangleCount()) throw InputError("picked triangle " + std::to_string(triangle) + " is not in the mesh");
    std::uint32_t nearest = mesh.indices[3 * triangle];
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = mesh.indices[3 * triangle + std::size_t(k)];
        double d2 = 0.0;
        for (int i = 0; i < 3; ++i) d2 += (mesh.vertices[v].position[i] - worldPoint[i]) * (mesh.vertices[v].position[i] - worldPoint[i]);
        if (d2 < best) best = d2, nearest = v;
    }
    return edgeOfVertex(mesh, nearest);
}

// ---- SurfaceTracker -------------------------------------------------------

struct SurfaceTracker::Impl {
    const Volume* volume;
    double iso;
    TableKind table;
    std::unique_ptr<TrackWorker> worker;
    TrackState state;
};

SurfaceTracker::SurfaceTracker(const Volume& volume, double iso, TableKind table)
    : impl_(std::make_unique<Impl>(Impl{&volume, iso, table, makeWorker(volume, iso, table), TrackState(volume.dims())})) {}
SurfaceTracker::~SurfaceTracker() = default;
SurfaceTracker::SurfaceTracker(SurfaceTracker&&) noexcept = default;
SurfaceTracker& SurfaceTracker::operator=(SurfaceTracker&&) noexcept = default;

void SurfaceTracker::start(const GridEdge& seed) {
    if (!edgeInside(*impl_->volume, seed)) throw InputError("seed edge " + edgeText(seed) + " is outside the volume");
    if (!impl_->worker->crossed(seed)) {
        throw InputError("seed edge " + edgeText(seed) + " does not cross iso " + numberText(impl_->iso));
    }
    impl_->state = TrackState(impl_->volume->dims());
    queueSeed(*impl_->volume, seed, *impl_->worker, impl_->state);
}

SurfaceTracker::Step SurfaceTracker::step(std::size_t cellBudget) {
    TrackState& s = impl_->state;
    Step step{s.mesh.vertices.size(), 0, s.mesh.indices.size(), 0, 0};
    step.cellsVisited = impl_->worker->advance(s, cellBudget);
    step.vertexCount = s.mesh.vertices.size() - step.firstVertex;
    step.indexCount = s.mesh.indices.size() - step.firstIndex;
    return step;
}

SurfaceTracker::Step SurfaceTracker::stepFor(std::chrono::nanoseconds budget) {
    const auto deadline = Clock::now() + budget;
    const TrackState& s = impl_->state;
    Step total{s.mesh.vertices.size(), 0, s.mesh.indices.size(), 0, 0};
    do {
        total.cellsVisited += step(512).cellsVisited;
    } while (!done() && Clock::now() < deadline);
    total.vertexCount = s.mesh.vertices.size() - total.firstVertex;
    total.indexCount = s.mesh.indices.size() - total.firstIndex;
    return total;
}

bool SurfaceTracker::done() const { return impl_->state.head >= impl_->state.queue.size(); }
const Mesh& SurfaceTracker::mesh() const { return impl_->state.mesh; }
std::size_t SurfaceTracker::cellsVisited() const { return impl_->state.cellsVisited; }
bool SurfaceTracker::leftVolume() const { return impl_->state.leftVolume; }
std::size_t SurfaceTracker::workingBytes() const {
    return impl_->state.blocks.byteSize() + impl_->state.queue.capacity() * sizeof(Entry);
}
Mesh SurfaceTracker::takeMesh() { return std::move(impl_->state.mesh); }

// ---- whole surfaces -------------------------------------------------------

Surface trackSurface(const Volume& volume, double iso, const GridEdge& seed, TableKind table) {
    const auto start = Clock::now();
    SurfaceTracker tracker(volume, iso, table);
    tracker.start(seed);
    while (!tracker.done()) tracker.step(std::numeric_limits<std::size_t>::max());
    Surface surface;
    const std::size_t cells = tracker.cellsVisited();
    surface.mesh = tracker.takeMesh();
    surface.stats = measureTracked(surface.mesh, volume, table);
    surface.stats.cellsVisited = cells;
    surface.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return surface;
}

std::vector<Surface> trackAllSurfaces(const Volume& volume, double iso, TableKind table) {
    std::vector<Surface> surfaces;
    const Dims& n = volume.dims();
    if (n[0] < 2 || n[1] < 2 || n[2] < 2) return surfaces;
    const auto worker = makeWorker(volume, iso, table);
    const auto& continuation = continuationTable(table);
    std::vector<std::uint8_t> visited(volume.sampleCount(), 0);
    for (int z = 0; z + 1 < n[2]; ++z) {
        for (int y = 0; y + 1 < n[1]; ++y) {
            for (int x = 0; x + 1 < n[0]; ++x) {
                const std::uint8_t config = worker->config(x, y, z);
                if (config == 0 || config == 255) continue;
                const CaseContinuation& cased = continuation[config];
                const std::size_t cell = volume.index(x, y, z);
                for (int p = 0; p < cased.pieceCount; ++p) {
                    if (visited[cell] >> p & 1u) continue;
                    const auto start = Clock::now();
                    TrackState state(n);
                    state.denseVisited = visited.data();
                    int entryEdge = 0;
                    while (!(cased.pieces[p].edgeMask >> entryEdge & 1u)) ++entryEdge;
                    worker->enqueue(state, x, y, z, entryEdge);
                    while (state.head < state.queue.size()) {
                        worker->advance(state, std::numeric_limits<std::size_t>::max());
                    }
                    Surface surface;
                    surface.mesh = std::move(state.mesh);
                    surface.stats = measureTracked(surface.mesh, volume, table);
                    surface.stats.cellsVisited = state.cellsVisited;
                    surface.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
                    surfaces.push_back(std::move(surface));
                }
            }
        }
    }
    // Discovery order is the order of each surface's first cell; break ties by first grid edge.
    auto firstEdge = [&](const Surface& s) {
        std::uint64_t first = std::numeric_limits<std::uint64_t>::max();
        for (const GridEdge e : s.mesh.vertexEdges) first = std::min(first, detail::edgeOrder(e, n));
        return first;
    };
    std::vector<std::pair<std::uint64_t, std::size_t>> keys;
    for (std::size_t i = 0; i < surfaces.size(); ++i) keys.push_back({firstEdge(surfaces[i]), i});
    std::sort(keys.begin(), keys.end(), [&](const auto& a, const auto& b) {
        const std::size_t ta = surfaces[a.second].mesh.triangleCount(), tb = surfaces[b.second].mesh.triangleCount();
        return ta != tb ? ta > tb : a.first < b.first;
    });
    std::vector<Surface> sorted;
    sorted.reserve(surfaces.size());
    for (const auto& key : keys) sorted.push_back(std::move(surfaces[key.second]));
    surfaces = std::move(sorted);
    return surfaces;
}

// ---- measurement ----------------------------------------------------------

SurfaceStats measureSurface(const Mesh& mesh, const Volume& volume, bool closedUnlessOnBorder) {
    SurfaceStats stats;
    stats.triangles = mesh.triangleCount();
    stats.vertices = mesh.vertices.size();
    stats.bytes = mesh.byteSize();
    if (!mesh.vertices.empty()) {
        for (int k = 0; k < 3; ++k) {
            stats.boundsMin[k] = std::numeric_limits<double>::infinity();
            stats.boundsMax[k] = -std::numeric_limits<double>::infinity();
        }
        for (const Vertex& v : mesh.vertices) {
            for (int k = 0; k < 3; ++k) {
                stats.boundsMin[k] = std::min(stats.boundsMin[k], double(v.position[k]));
                stats.boundsMax[k] = std::max(stats.boundsMax[k], double(v.position[k]));
            }
        }
    }
    detail::TriangleMeasure measure;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t* idx = &mesh.indices[3 * t];
        measure.add(mesh.vertices[idx[0]].position, mesh.vertices[idx[1]].position, mesh.vertices[idx[2]].position);
    }
    stats.area = measure.area;
    for (const GridEdge e : mesh.vertexEdges) {
        if (detail::edgeOnVolumeBorder(e, volume.dims())) {
            stats.touchesBorder = true;
            break;
        }
    }
    stats.closed = closedUnlessOnBorder ? !stats.touchesBorder && !mesh.indices.empty() : detail::meshIsClosed(mesh);
    if (stats.closed) stats.enclosedVolume = std::abs(measure.signedVolume);
    return stats;
}

}  // namespace isotrack
