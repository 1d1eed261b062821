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
// On several threads, each thread walks the cells of its own 64^3 regions (a
// checkerboard), with plain loads and stores: a piece continuing into another
// thread's region is sent to that thread (Exchange), and only vertices on edges
// between regions, which cells of several threads share, are claimed with a
// compare-and-swap. The threads' parts are joined into one mesh at the end.
#include "isotrack/tracking.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <string>
#include <stdexcept>
#include <thread>

#include "edge_vertex.h"
#include "support/flat_hash.h"
#include "support/huge_pages.h"
#include "support/parallel.h"
#include "sparse_blocks.h"
#include "surface_measure.h"
#include "isotrack/continuation.h"
#include "isotrack/cube.h"
#include "isotrack/errors.h"

namespace isotrack {
namespace {

using Clock = std::chrono::steady_clock;
using detail::SparseBlocks;
using Block = SparseBlocks::Block;

// A cell piece waiting to be walked; it was marked when queued, so each piece is
// queued once.
struct Entry {
    Block* block;
    std::uint16_t cell;  // local index in the block
    std::uint8_t config;
    std::uint8_t piece;
};

// First in, first out, in a ring that doubles when full; nothing is ever moved
// to compact it.
template <class T>
class Ring {
public:
    Ring() = default;
    Ring(Ring&& other) noexcept { swap(other); }
    Ring& operator=(Ring&& other) noexcept {
        swap(other);
        return *this;
    }

    bool empty() const { return head_ == tail_; }
    void push(const T& item) {
        if (tail_ - head_ == size_) grow();
        data_[tail_++ & (size_ - 1)] = item;
    }
    T pop() { return data_[head_++ & (size_ - 1)]; }
    std::size_t capacity() const { return size_; }

private:
    void swap(Ring& other) noexcept {
        ring_.swap(other.ring_);
        std::swap(data_, other.data_);
        std::swap(size_, other.size_);
        std::swap(head_, other.head_);
        std::swap(tail_, other.tail_);
    }
    [[gnu::noinline]] void grow() {
        std::vector<T> larger(std::max<std::size_t>(2 * size_, 256));
        for (std::size_t i = head_; i != tail_; ++i) larger[i - head_] = data_[i & (size_ - 1)];
        tail_ -= head_;
        head_ = 0;
        ring_.swap(larger);
        data_ = ring_.data();
        size_ = ring_.size();
    }

    std::vector<T> ring_;  // a power-of-two size
    T* data_ = nullptr;    // ring_'s, and its size: kept at hand for push and pop
    std::size_t size_ = 0;
    std::size_t head_ = 0, tail_ = 0;
};

enum class WalkOrder { ByBlock, BreadthFirst };

// The pieces waiting to be walked, in one of two orders.
//  - By block (a whole surface at once): each block with pieces waiting holds a
//    list of them, and the blocks wait their turn first in, first out. A block's
//    turn walks its pieces until none is left, the pieces they lead to in the
//    same block included, so the block's vertex ids, flags and samples are
//    walked while they are in cache (half the first-level cache misses of
//    breadth-first on the CT skull); the pieces they lead to in other blocks
//    wait in those blocks' lists.
//  - Breadth-first (growth shown as it happens): one ring of pieces, first in,
//    first out, so the surface grows from the seed as a smooth front.
// (The order is a member tested per push and pop, not a template parameter of
// the walk: two instantiations of the walk lost the inlining of its helpers and
// cost more instructions than the test, 259M against 255M on the CT skull.)
class PieceQueue {
public:
    explicit PieceQueue(WalkOrder order = WalkOrder::ByBlock) : order_(order) {}

    bool empty() const {
        if (order_ == WalkOrder::BreadthFirst) return pieces_.empty();
        return (current_ == nullptr || current_->pending == kNone) && blocks_.empty();
    }

    // Inlined where it is called: a push per exit is too frequent for a call.
    [[gnu::always_inline]] void push(const Entry& entry) {
        if (order_ == WalkOrder::BreadthFirst) {
            pieces_.push(entry);
            return;
        }
        std::uint32_t n = free_;
        if (n != kNone) {
            free_ = nodes_[n].next;
        } else {
            n = static_cast<std::uint32_t>(nodes_.size());
            nodes_.emplace_back();
        }
        Block* block = entry.block;
        nodes_[n] = {entry.cell, entry.config, entry.piece, block->pending};
        block->pending = n;
        if (!block->queued) {
            block->queued = true;
            blocks_.push(block);
        }
    }

    // The next piece; false when none is left.
    bool pop(Entry& entry) {
        if (order_ == WalkOrder::BreadthFirst) {
            if (pieces_.empty()) return false;
            entry = pieces_.pop();
            return true;
        }
        for (;;) {
            if (current_ != nullptr) {
                const std::uint32_t n = current_->pending;
                if (n != kNone) {
                    Node& node = nodes_[n];
                    entry = {current_, node.cell, node.config, node.piece};
                    current_->pending = node.next;
                    node.next = free_;
                    free_ = n;
                    return true;
                }
                current_->queued = false;
                current_ = nullptr;
            }
            if (blocks_.empty()) return false;
            current_ = blocks_.pop();
        }
    }

    // Every piece waiting, taken out of the queue, which is left empty.
    std::vector<Entry> drain() {
        std::vector<Entry> entries;
        for (Entry entry; pop(entry);) entries.push_back(entry);
        return entries;
    }

    std::size_t byteSize() const {
        return nodes_.capacity() * sizeof(Node) + blocks_.capacity() * sizeof(Block*) + pieces_.capacity() * sizeof(Entry);
    }

private:
    static constexpr std::uint32_t kNone = SparseBlocks::kNoPending;
    struct Node {
        std::uint16_t cell;
        std::uint8_t config, piece;
        std::uint32_t next;  // the next piece waiting in the same block
    };

    std::vector<Node> nodes_;  // waiting pieces and, linked from free_, spare nodes
    std::uint32_t free_ = kNone;
    Ring<Block*> blocks_;      // blocks with pieces waiting, but for current_
    Block* current_ = nullptr; // the block being walked
    WalkOrder order_;
    Ring<Entry> pieces_;       // breadth-first
};

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
    // piece of either table has): the walk copies this many, a fixed count.
    static constexpr int kPieceCorners = 15;
    std::array<std::array<std::int8_t, 12>, 256> pieceOfEdge{};
    std::array<int, 6> link{}, cellStep{}, faceMask{}, faceSide{};
    std::array<std::array<int, 3>, 12> edgeOrigin{};
    std::array<int, 12> edgeAxis{};
    std::array<int, 12> edgeLocal{};  // offset of the edge's origin in a sparse block's local index
    std::array<int, 12> edgeSlot{};   // offset of the edge's vertex id from its cell's first corner's ids in a block

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
                    for (std::int8_t edge : table[c].triangles[t]) walk.corners[walk.cornerCount++] = static_cast<std::uint8_t>(edge);
                }
                if (walk.cornerCount > kPieceCorners) throw std::logic_error("continuation table: a piece of more than five triangles");
                // The spare corners repeat the first, a vertex the piece has (see walk).
                for (int k = walk.cornerCount; k < kPieceCorners; ++k) walk.corners[std::size_t(k)] = walk.corners[0];
                for (int f = 0; f < cube::kFaceCount; ++f) {
                    for (std::int8_t exit : piece.exits[f]) {
                        if (exit < 0) break;
                        walk.exits[walk.exitCount++] = static_cast<std::uint8_t>(f << 4 | cube::edgeAcrossFace(exit, f));
                    }
                }
            }
        }
        for (int e = 0; e < cube::kEdgeCount; ++e) {
            edgeOrigin[e] = cube::edgeOrigin(e);
            edgeAxis[e] = cube::edgeAxis(e);
            edgeLocal[e] = detail::SparseBlocks::local(edgeOrigin[e][0], edgeOrigin[e][1], edgeOrigin[e][2]);
            edgeSlot[e] = 3 * edgeLocal[e] + edgeAxis[e];
        }
    }
};

const WalkTable& walkTable(TableKind kind) {
    static const WalkTable consistent(TableKind::Consistent);
    static const WalkTable classic(TableKind::Classic);
    return kind == TableKind::Classic ? classic : consistent;
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

// One thread's share of a walk: its queue, and the vertices and triangles it
// emits with their measure. A vertex id is the vertex's index in the walker's
// mesh, with the walker's thread in the id's top bits when several walk. Each
// walker has cache lines of its own: its queue and measure change every cell.
struct alignas(128) Walker {
    Mesh mesh;
    detail::SurfaceMeasure measure;
    PieceQueue queue;
    std::size_t cellsVisited = 0;
    int thread = 0;  // the regions it walks, and its arena in the sparse blocks
    std::uint32_t idBase = 0;                 // thread << the width of an index
    std::uint32_t indexMask = ~std::uint32_t(0);  // the index bits of an id
    std::vector<std::size_t> unmeasured;      // triangles (first index) with another thread's corners
};

// A surface walked by one thread, whatever the sample type.
struct TrackState {
    explicit TrackState(const Dims& dims, WalkOrder order = WalkOrder::ByBlock) : blocks(dims) { walker.queue = PieceQueue(order); }
    SparseBlocks blocks;
    std::uint8_t* denseVisited = nullptr;  // one bit per piece per cell, for trackAllSurfaces
    Walker walker;
};

// The messages between threads walking one surface together. Each thread walks
// the cells of its own regions; a piece that continues into another thread's
// region is sent to that thread, which queues it as its own.
class Exchange {
public:
    struct Message {
        Block* block;
        std::size_t sample;  // the cell's first corner
        std::uint16_t cell;
        std::uint8_t edge;   // the entry edge
    };

    explicit Exchange(int threads)
        : threads_(threads), outbox_(std::size_t(threads)), inbox_(std::size_t(threads)), mail_(std::size_t(threads)) {
        for (Outbox& box : outbox_) box.to.resize(std::size_t(threads));
    }

    // Collected by the sender, handed over at its next poll or wait.
    void send(int from, int to, const Message& message) { outbox_[std::size_t(from)].to[std::size_t(to)].push_back(message); }

    // From a walking thread every so often: hands over what it sent and takes
    // what was sent to it; false once the walk is abandoned.
    bool poll(int me, std::vector<Message>& received) {
        if (stopped_.load(std::memory_order_relaxed)) return false;
        bool sent = false;
        for (const auto& box : outbox_[std::size_t(me)].to) sent = sent || !box.empty();
        if (sent || mail_[std::size_t(me)].flag.load(std::memory_order_relaxed)) {
            const std::lock_guard<std::mutex> lock(mutex_);
            handOver(me);
            takeLocked(me, received);
        }
        return true;
    }

    // From a thread with nothing left to walk: waits for pieces sent to it
    // (true) or for every thread to be done (false). It looks for mail a few
    // times, then sleeps until mail comes or the walk ends.
    bool wait(int me, std::vector<Message>& received) {
        {
            const std::lock_guard<std::mutex> lock(mutex_);
            handOver(me);
            if (takeLocked(me, received)) return true;
            ++idle_;
            if (idle_ == threads_ && std::all_of(inbox_.begin(), inbox_.end(), [](const auto& box) { return box.empty(); })) {
                finished_.store(true, std::memory_order_release);
                woken_.notify_all();
                return false;
            }
        }
        for (int look = 0; look < kLooks; ++look) {
            if (finished_.load(std::memory_order_acquire) || stopped_.load(std::memory_order_acquire)) return false;
            if (mail_[std::size_t(me)].flag.load(std::memory_order_relaxed)) break;
            std::this_thread::yield();
        }
        std::unique_lock<std::mutex> lock(mutex_);
        woken_.wait(lock, [&] { return finished_.load(std::memory_order_relaxed) || stopped_.load(std::memory_order_relaxed) || !inbox_[std::size_t(me)].empty(); });
        if (!takeLocked(me, received)) return false;
        --idle_;
        return true;
    }

    // Abandons the walk (a thread failed): every thread stops at its next poll or wait.
    void stop() {
        const std::lock_guard<std::mutex> lock(mutex_);
        stopped_.store(true, std::memory_order_release);
        woken_.notify_all();
    }

private:
    void handOver(int me) {
        for (int to = 0; to < threads_; ++to) {
            auto& box = outbox_[std::size_t(me)].to[std::size_t(to)];
            if (box.empty()) continue;
            inbox_[std::size_t(to)].insert(inbox_[std::size_t(to)].end(), box.begin(), box.end());
            box.clear();
            mail_[std::size_t(to)].flag.store(true, std::memory_order_relaxed);
            woken_.notify_all();
        }
    }

    bool takeLocked(int me, std::vector<Message>& received) {
        mail_[std::size_t(me)].flag.store(false, std::memory_order_relaxed);
        if (inbox_[std::size_t(me)].empty()) return false;
        received.swap(inbox_[std::size_t(me)]);
        return true;
    }

    struct alignas(64) Flag {
        std::atomic<bool> flag{false};
    };
    struct alignas(64) Outbox {
        std::vector<std::vector<Message>> to;  // used by its sender only
    };

    static constexpr int kLooks = 64;  // yields before an idle thread sleeps

    const int threads_;
    std::vector<Outbox> outbox_;  // per sender
    std::mutex mutex_;            // guards inbox_ and idle_, and the waits on woken_
    std::condition_variable woken_;
    std::vector<std::vector<Message>> inbox_;
    int idle_ = 0;
    std::vector<Flag> mail_;  // something may be in the thread's inbox
    std::atomic<bool> finished_{false}, stopped_{false};
};

class TrackWorker {
public:
    virtual ~TrackWorker() = default;
    // Queues on `walker` the piece of cell (x, y, z) holding cube edge `edge`, unless it was queued before.
    virtual void enqueue(SparseBlocks& blocks, std::uint8_t* denseVisited, Walker& walker, int x, int y, int z, int edge) const = 0;
    // Walks on one thread for up to `cellBudget` cell pieces; returns how many it walked.
    virtual std::size_t advance(SparseBlocks& blocks, std::uint8_t* denseVisited, Walker& walker, std::size_t cellBudget) const = 0;
    // Walks the walker's regions as one of several threads sharing `blocks`, until no piece is left.
    virtual void walkShared(SparseBlocks& blocks, Walker& walker, Exchange& exchange) const = 0;
    virtual std::uint8_t config(int x, int y, int z) const = 0;
    virtual bool crossed(const GridEdge& edge) const = 0;
};

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

    void enqueue(SparseBlocks& blocks, std::uint8_t* denseVisited, Walker& walker, int x, int y, int z, int edge) const override {
        enqueueIn(walker, denseVisited, blocks.at(x, y, z, walker.thread), SparseBlocks::local(x, y, z), grid_.index(x, y, z), edge);
    }

    std::size_t advance(SparseBlocks& blocks, std::uint8_t* denseVisited, Walker& walker, std::size_t cellBudget) const override {
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
        explicit MeshAppender(Mesh& mesh) : vertices(mesh.vertices), indices(mesh.indices), vertexEdges(mesh.vertexEdges) {}
        Appender<Vertex> vertices;
        Appender<std::uint32_t> indices;
        Appender<PackedGridEdge> vertexEdges;
    };

    // Walks the walker's queue for up to `cellBudget` cell pieces. Shared: other
    // threads walk the other regions; pieces continuing there are sent to them,
    // vertices on edges between regions are claimed atomically, and triangles
    // with another thread's corners are measured once the walk is over.
    template <bool Shared>
    std::size_t walk(SparseBlocks& blocks, std::uint8_t* denseVisited, Walker& w, std::size_t cellBudget, Exchange* exchange) const {
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
            for (unsigned mask = walk.edgeMask; mask != 0; mask &= mask - 1) {
                const int edge = __builtin_ctz(mask);
                std::uint32_t& slot = cornersInBlock ? cellSlots[walk_.edgeSlot[edge]]
                                                     : vertexSlot(blocks, block, local, edge, w.thread);
                std::uint32_t id = Shared ? __atomic_load_n(&slot, __ATOMIC_RELAXED) : slot;
                if (id == SparseBlocks::kNoVertex) id = newVertex<Shared>(w, out, slot, at, edge);
                vertexOf[edge] = id;
            }
            // Every piece copies the same count of corners and gives back the spare
            // ones: no loop whose length changes from piece to piece, and so no
            // mispredicted branch at its end.
            std::uint32_t* indices = out.indices.extend(WalkTable::kPieceCorners);
            for (int k = 0; k < WalkTable::kPieceCorners; ++k) indices[k] = vertexOf[walk.corners[std::size_t(k)]];
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
                        exchange->send(w.thread, next->owner, {next, sample + sampleStep_[f], static_cast<std::uint16_t>(cell ^ walk_.faceMask[f]), static_cast<std::uint8_t>(edge)});
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
                    detail::TriangleMeasure::addTo(doubledArea, sixfoldVolume, vertices[a & w.indexMask], vertices[b & w.indexMask], vertices[c & w.indexMask]);
                } else {
                    w.unmeasured.push_back(k);
                }
            }
        } else {
            for (; k + 12 <= end; k += 12) detail::TriangleMeasure::addFourTo(doubledArea, sixfoldVolume, vertices, indices + k);
            for (; k < end; k += 3) detail::TriangleMeasure::addTo(doubledArea, sixfoldVolume, vertices[indices[k]], vertices[indices[k + 1]], vertices[indices[k + 2]]);
        }
        w.measure.triangles.merge({doubledArea, sixfoldVolume});
        w.measure.addBounds(vertices + firstVertex, out.vertices.size() - firstVertex);
    }

    // The configuration of the cell whose first corner is `sample`.
    std::uint8_t configAt(std::size_t i) const { return grid_.cellConfig(i); }

    // Queues the piece holding `edge` of the cell at local index `cell` of `block`,
    // whose first corner is `sample`; only the thread walking the cell's region does.
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

    // The vertex slot of a cell's edge when the edge's origin may lie in a block further up.
    std::uint32_t& vertexSlot(SparseBlocks& blocks, Block* block, const int local[3], int edge, int thread) const {
        const auto& o = walk_.edgeOrigin[edge];
        const int p[3] = {local[0] + o[0], local[1] + o[1], local[2] + o[2]};
        const int link = SparseBlocks::kSelf + (p[0] >> kShift) + 3 * (p[1] >> kShift) + 9 * (p[2] >> kShift);
        Block* holder = blocks.linked(block, link, thread);
        return holder->vertex[std::size_t(3 * SparseBlocks::local(p[0], p[1], p[2]) + walk_.edgeAxis[edge])];
    }

    // edgeVertex, through its interior form when both ends of the edge have their six neighbours in the volume.
    template <int Axis>
    void vertexAlong(int x, int y, int z, Vertex& v) const {
        if (grid_.template edgeInterior<Axis>(x, y, z)) {
            grid_.template interiorEdgeVertex<Axis>(grid_.index(x, y, z), x, y, z, v);
        } else {
            grid_.edgeVertex(x, y, z, Axis, v);
        }
    }

    // Computes the vertex of the cell's edge and records its id in `slot`. Shared,
    // on an edge between regions (its cells may belong to several threads): when
    // another thread recorded one first, the vertex is given back and its id used.
    template <bool Shared>
    std::uint32_t newVertex(Walker& w, MeshAppender& out, std::uint32_t& slot, const int at[3], int edge) const {
        const std::size_t index = out.vertices.size();
        if (index >= w.indexMask) throw InputError("surface too large: more than " + std::to_string(w.indexMask) + " vertices per thread");
        const auto id = static_cast<std::uint32_t>(w.idBase | index);
        const auto& o = walk_.edgeOrigin[edge];
        const GridEdge e{at[0] + o[0], at[1] + o[1], at[2] + o[2], walk_.edgeAxis[edge]};
        Vertex& v = *out.vertices.extend(1);
        switch (e.axis) {
            case 0: vertexAlong<0>(e.x, e.y, e.z, v); break;
            case 1: vertexAlong<1>(e.x, e.y, e.z, v); break;
            default: vertexAlong<2>(e.x, e.y, e.z, v); break;
        }
        const int p[3] = {e.x, e.y, e.z};
        constexpr int m = SparseBlocks::kRegionMask;
        if (Shared && ((e.axis != 0 && (p[0] & m) == 0) || (e.axis != 1 && (p[1] & m) == 0) || (e.axis != 2 && (p[2] & m) == 0))) {
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
void queueSeed(const Volume& volume, const GridEdge& seed, const TrackWorker& worker, SparseBlocks& blocks, Walker& walker) {
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
    : impl_(std::make_unique<Impl>(Impl{&volume, iso, table, makeWorker(volume, iso, table), TrackState(volume.dims(), WalkOrder::BreadthFirst)})) {}
SurfaceTracker::~SurfaceTracker() = default;
SurfaceTracker::SurfaceTracker(SurfaceTracker&&) noexcept = default;
SurfaceTracker& SurfaceTracker::operator=(SurfaceTracker&&) noexcept = default;

namespace {

// The finished surface, its mesh taken from the walk's state.
Surface finishedSurface(Walker& walker, TableKind table) {
    Surface surface;
    surface.mesh = std::move(walker.mesh);
    surface.stats = detail::surfaceStats(surface.mesh, walker.measure, table == TableKind::Consistent);
    surface.stats.cellsVisited = walker.cellsVisited;
    return surface;
}

void checkSeed(const Volume& volume, double iso, const TrackWorker& worker, const GridEdge& seed) {
    if (!edgeInside(volume, seed)) throw InputError("seed edge " + edgeText(seed) + " is outside the volume");
    if (!worker.crossed(seed)) throw InputError("seed edge " + edgeText(seed) + " does not cross iso " + numberText(iso));
}

}  // namespace

void SurfaceTracker::start(const GridEdge& seed) {
    checkSeed(*impl_->volume, impl_->iso, *impl_->worker, seed);
    impl_->state = TrackState(impl_->volume->dims(), WalkOrder::BreadthFirst);
    queueSeed(*impl_->volume, seed, *impl_->worker, impl_->state.blocks, impl_->state.walker);
}

SurfaceTracker::Step SurfaceTracker::step(std::size_t cellBudget) {
    TrackState& s = impl_->state;
    const Mesh& mesh = s.walker.mesh;
    Step step{mesh.vertices.size(), 0, mesh.indices.size(), 0, 0};
    step.cellsVisited = impl_->worker->advance(s.blocks, s.denseVisited, s.walker, cellBudget);
    step.vertexCount = mesh.vertices.size() - step.firstVertex;
    step.indexCount = mesh.indices.size() - step.firstIndex;
    return step;
}

SurfaceTracker::Step SurfaceTracker::stepFor(std::chrono::nanoseconds budget) {
    const auto deadline = Clock::now() + budget;
    const Mesh& mesh = impl_->state.walker.mesh;
    Step total{mesh.vertices.size(), 0, mesh.indices.size(), 0, 0};
    do {
        total.cellsVisited += step(512).cellsVisited;
    } while (!done() && Clock::now() < deadline);
    total.vertexCount = mesh.vertices.size() - total.firstVertex;
    total.indexCount = mesh.indices.size() - total.firstIndex;
    return total;
}

bool SurfaceTracker::done() const { return impl_->state.walker.queue.empty(); }
const Mesh& SurfaceTracker::mesh() const { return impl_->state.walker.mesh; }
std::size_t SurfaceTracker::cellsVisited() const { return impl_->state.walker.cellsVisited; }
std::size_t SurfaceTracker::workingBytes() const {
    return impl_->state.blocks.byteSize() + impl_->state.walker.queue.byteSize();
}
SurfaceStats SurfaceTracker::stats() const {
    const Walker& walker = impl_->state.walker;
    SurfaceStats stats = detail::measuredStats(walker.mesh, walker.measure);
    stats.cellsVisited = walker.cellsVisited;
    return stats;
}
Surface SurfaceTracker::takeSurface() { return finishedSurface(impl_->state.walker, impl_->table); }

// ---- whole surfaces -------------------------------------------------------

namespace {

// Walks the surface from the queued seed to the end.
Surface walkWhole(const TrackWorker& worker, TrackState& state, TableKind table, Clock::time_point start) {
    while (!state.walker.queue.empty()) worker.advance(state.blocks, state.denseVisited, state.walker, std::numeric_limits<std::size_t>::max());
    Surface surface = finishedSurface(state.walker, table);
    surface.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return surface;
}

// Sizes `buffer` to `size` and returns null where its capacity allows; otherwise
// sizes `fresh` instead (its pages possibly huge) and returns it, for the caller
// to fill with the buffer's contents too.
template <class T>
Buffer<T>* sizeWhole(Buffer<T>& buffer, std::size_t size, Buffer<T>& fresh) {
    if (size <= buffer.capacity()) {
        buffer.resize(size);
        return nullptr;
    }
    detail::resizeOnHugePages(fresh, size);
    return &fresh;
}

// Cell pieces a walk on several threads first walks on one (about a millisecond).
constexpr std::size_t kCellsAlone = 8192;

// Walks the surface from `seed` on `threads` threads, each walking its own
// regions, then gathers their parts into one mesh.
Surface walkTogether(const Volume& volume, const TrackWorker& worker, const GridEdge& seed, TableKind table, int threads,
                     Clock::time_point start) {
    SparseBlocks blocks(volume.dims(), threads);
    std::vector<Walker> walkers(static_cast<std::size_t>(threads));
    int tagBits = 0;
    while ((1 << tagBits) < threads) ++tagBits;
    const int idShift = 32 - tagBits;
    for (int t = 0; t < threads; ++t) {
        walkers[std::size_t(t)].thread = t;
        walkers[std::size_t(t)].idBase = static_cast<std::uint32_t>(std::uint64_t(t) << idShift);
        walkers[std::size_t(t)].indexMask = static_cast<std::uint32_t>((std::uint64_t(1) << idShift) - 1);
    }
    // The first cells are walked on this thread alone: a small surface is done
    // before more threads would pay for starting. What is left is handed to the
    // walkers of the queued pieces' regions.
    queueSeed(volume, seed, worker, blocks, walkers[0]);
    worker.advance(blocks, nullptr, walkers[0], kCellsAlone);
    if (walkers[0].queue.empty()) {
        Surface surface = finishedSurface(walkers[0], table);
        surface.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        return surface;
    }
    for (const Entry& entry : walkers[0].queue.drain()) walkers[std::size_t(entry.block->owner)].queue.push(entry);
    Exchange exchange(threads);
    detail::runTogether(threads, [&](int t) { worker.walkShared(blocks, walkers[std::size_t(t)], exchange); }, [&] { exchange.stop(); });

    // The parts, in thread order, in the first walker's buffers; vertex ids become indices.
    std::vector<std::size_t> firstVertex(std::size_t(threads) + 1, 0), firstIndex(std::size_t(threads) + 1, 0);
    for (std::size_t t = 0; t < walkers.size(); ++t) {
        firstVertex[t + 1] = firstVertex[t] + walkers[t].mesh.vertices.size();
        firstIndex[t + 1] = firstIndex[t] + walkers[t].mesh.indices.size();
    }
    // The whole mesh goes in the first walker's buffers where they have room; a
    // buffer without is replaced by a new one (its pages possibly huge), which
    // takes the first walker's part too, copied in parallel with the others'.
    Mesh& mesh = walkers[0].mesh;
    Mesh grown;
    Buffer<Vertex>* const movedVertices = sizeWhole(mesh.vertices, firstVertex.back(), grown.vertices);
    Buffer<PackedGridEdge>* const movedEdges = sizeWhole(mesh.vertexEdges, firstVertex.back(), grown.vertexEdges);
    Buffer<std::uint32_t>* const movedIndices = sizeWhole(mesh.indices, firstIndex.back(), grown.indices);
    Vertex* const vertices = movedVertices ? movedVertices->data() : mesh.vertices.data();
    PackedGridEdge* const edges = movedEdges ? movedEdges->data() : mesh.vertexEdges.data();
    std::uint32_t* const indices = movedIndices ? movedIndices->data() : mesh.indices.data();
    const std::uint32_t indexMask = walkers[0].indexMask;
    auto finalIndex = [&](std::uint32_t id) { return static_cast<std::uint32_t>(firstVertex[id >> idShift] + (id & indexMask)); };
    // Each part in `threads` slices, so that every thread has a share of the copying.
    // The first walker's ids are final but for the corners it took from other
    // walkers (its unmeasured triangles), set once every part is in place.
    const int slices = threads;
    detail::parallelFor(threads * slices, threads, [&](int task) {
        const std::size_t t = std::size_t(task / slices), slice = std::size_t(task % slices);
        const Mesh& part = walkers[t].mesh;
        const std::size_t vertexCount = firstVertex[t + 1] - firstVertex[t], indexCount = firstIndex[t + 1] - firstIndex[t];
        const std::size_t vBegin = vertexCount * slice / std::size_t(slices), vEnd = vertexCount * (slice + 1) / std::size_t(slices);
        const std::size_t iBegin = indexCount * slice / std::size_t(slices), iEnd = indexCount * (slice + 1) / std::size_t(slices);
        if (t > 0 || movedVertices) std::copy(part.vertices.data() + vBegin, part.vertices.data() + vEnd, vertices + firstVertex[t] + vBegin);
        if (t > 0 || movedEdges) std::copy(part.vertexEdges.data() + vBegin, part.vertexEdges.data() + vEnd, edges + firstVertex[t] + vBegin);
        if (t > 0) {
            for (std::size_t i = iBegin; i < iEnd; ++i) indices[firstIndex[t] + i] = finalIndex(part.indices[i]);
        } else if (movedIndices) {
            std::copy(part.indices.data() + iBegin, part.indices.data() + iEnd, indices + iBegin);
        }
    });
    if (movedVertices) mesh.vertices.swap(*movedVertices);
    if (movedEdges) mesh.vertexEdges.swap(*movedEdges);
    if (movedIndices) mesh.indices.swap(*movedIndices);
    for (const std::size_t first : walkers[0].unmeasured) {
        for (std::size_t k = first; k < first + 3; ++k) mesh.indices[k] = finalIndex(mesh.indices[k]);
    }

    // The first walker takes the others' figures, and measures the triangles
    // between regions now that every corner is in place.
    Walker& whole = walkers[0];
    for (std::size_t t = 0; t < walkers.size(); ++t) {
        if (t > 0) {
            whole.measure.merge(walkers[t].measure);
            whole.cellsVisited += walkers[t].cellsVisited;
        }
        for (const std::size_t first : walkers[t].unmeasured) {
            const std::size_t k = firstIndex[t] + first;
            whole.measure.addTriangle(mesh.vertices.data(), mesh.indices[k], mesh.indices[k + 1], mesh.indices[k + 2]);
        }
    }
    Surface surface = finishedSurface(whole, table);
    surface.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return surface;
}

}  // namespace

Surface trackSurface(const Volume& volume, double iso, const GridEdge& seed, TableKind table, int threads) {
    const auto start = Clock::now();
    threads = std::min(threads, kMaxTrackThreads);
    const auto worker = makeWorker(volume, iso, table);
    checkSeed(volume, iso, *worker, seed);
    if (threads > 1) return walkTogether(volume, *worker, seed, table, threads, start);
    TrackState state(volume.dims());
    queueSeed(volume, seed, *worker, state.blocks, state.walker);
    return walkWhole(*worker, state, table, start);
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
                    worker->enqueue(state.blocks, state.denseVisited, state.walker, x, y, z, entryEdge);
                    surfaces.push_back(walkWhole(*worker, state, table, start));
                }
            }
        }
    }
    // Discovery order is the order of each surface's first cell; break ties by first grid edge.
    std::vector<std::pair<std::uint64_t, std::size_t>> keys;
    for (std::size_t i = 0; i < surfaces.size(); ++i) keys.push_back({detail::firstEdgeOrder(surfaces[i].mesh, n), i});
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
    detail::SurfaceMeasure measure;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) measure.addVertex(mesh.vertices[v], mesh.vertexEdges[v], volume.dims());
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        measure.addTriangle(mesh.vertices.data(), mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]);
    }
    return detail::surfaceStats(mesh, measure, closedUnlessOnBorder);
}

}  // namespace isotrack
