#pragma once
// Per-surface storage for the tracker: blocks of 8x8x8 grid points, created on
// first touch. A surface touches a thin shell of blocks, so memory follows the
// surface, not the volume, while neighbouring cells and edges share cache lines,
// unlike a map keyed by cell.
//
// Blocks are found through a two-level directory: a table of regions of 8x8x8
// blocks (64^3 grid points), each region a table of its blocks, both filled as
// the surface reaches them. Each block also keeps links to the 26 blocks around
// it, looked up the first time they are needed, so a cell's neighbours and the
// far ends of its edges are one load away however often the tracker crosses
// block faces.
//
// Several threads may walk one surface. The volume is cut into cubic tiles of
// whole blocks, each walked by one of them (in a checkerboard of tiles, see
// ownerShift), the only thread that classifies, marks and queues the tile's
// cells; regions and blocks are published with a compare-and-swap, each thread
// allocating from its own arena.
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <deque>
#include <limits>
#include <vector>

#include "isotrack/volume.h"

namespace isotrack::detail {

class SparseBlocks {
public:
    static constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();
    static constexpr std::uint32_t kNoPending = std::numeric_limits<std::uint32_t>::max();

    static constexpr int kShift = 3;
    static constexpr int kSide = 1 << kShift;
    static constexpr int kPoints = kSide * kSide * kSide;
    // The link to the block itself: links are numbered (dx + 1) + 3 (dy + 1) + 9 (dz + 1).
    static constexpr int kSelf = 13;

    // How the vertex slots of a new block start: all kNoVertex (Eager), or
    // unwritten, a row of the block at a time made kNoVertex on first use
    // (Lazy, through vertexRows). A surface crosses few of a block's 1,536
    // edges (the CT skull about 100 in each of 2,500 blocks): filling every
    // slot wrote 6 KiB per block, most of it never read, and took 1.3 to 5% of
    // a one-thread track of the skull.
    enum class VertexSlots { Eager, Lazy };

    // A row of a block: the slots of its 8 points along x at one (y, z).
    static constexpr int kRowSlots = 3 * kSide;

    struct Block {
        std::array<std::uint8_t, kPoints> config{};     // per cell; 0 until classified (0 is never queued)
        std::array<std::uint8_t, kPoints> visited{};    // per cell, one bit per piece
        std::array<std::uint32_t, 3 * kPoints> vertex;  // per grid point and axis, the vertex on that edge
        std::atomic<std::uint64_t> rowsReady;           // Lazy: bit y + 8 z set once row (y, z) is kNoVertex or ids
        std::atomic<std::uint64_t> rowsClaimed;         // Lazy, on several threads: the rows a thread began to fill
        std::array<std::atomic<Block*>, 27> link;       // each adjacent block; null until looked up
        std::array<int, 3> origin{};                    // grid coordinates of local point (0, 0, 0)
        int owner = 0;                                  // the thread walking the block's cells
        std::uint32_t pending = kNoPending;             // the tracker's set of pieces waiting in the block, if any
        Block(const std::array<int, 3>& at, int thread, VertexSlots slots) : origin(at), owner(thread) {
            const std::uint64_t ready = slots == VertexSlots::Eager ? ~std::uint64_t(0) : 0;
            if (slots == VertexSlots::Eager) vertex.fill(kNoVertex);
            rowsReady.store(ready, std::memory_order_relaxed);
            rowsClaimed.store(ready, std::memory_order_relaxed);
            for (auto& l : link) l.store(nullptr, std::memory_order_relaxed);
            link[kSelf].store(this, std::memory_order_relaxed);
        }
    };

    // Makes the rows of `block` in the mask `rows` (bit y + 8 z) ready for use:
    // those not yet are filled with kNoVertex. Shared (several threads walk the
    // surface): a thread fills the rows it claims first and waits for those
    // another thread claimed; once ready, a row is read and written as before.
    template <bool Shared>
    static void vertexRows(Block* block, std::uint64_t rows) {
        if constexpr (!Shared) {
            const std::uint64_t ready = block->rowsReady.load(std::memory_order_relaxed);
            if ((ready & rows) != rows) fillRows(block, rows & ~ready, ready | rows);
        } else {
            const std::uint64_t ready = block->rowsReady.load(std::memory_order_acquire);
            if ((ready & rows) != rows) claimRows(block, rows, rows & ~ready);
        }
    }

    // The row bit of local point (x, y, z): rows are numbered y + 8 z.
    static constexpr int row(int localPoint) { return localPoint >> kShift; }

    // A region of 8x8x8 blocks.
    struct Region {
        std::array<std::atomic<Block*>, kPoints> block;
        Region() {
            for (auto& b : block) b.store(nullptr, std::memory_order_relaxed);
        }
    };

    // Where one thread's blocks and regions come from; only that thread uses it.
    class alignas(64) Arena {
    public:
        std::size_t byteSize() const { return blocks_.size() * sizeof(Block) + regions_.size() * sizeof(Region); }

    private:
        friend class SparseBlocks;
        std::deque<Block> blocks_;
        std::deque<Region> regions_;
        Block* spareBlock_ = nullptr;  // made, but another thread published its block first
        Region* spareRegion_ = nullptr;
    };

    SparseBlocks(const Dims& dims, int threads = 1, VertexSlots slots = VertexSlots::Eager)
        : slots_(slots),
          ownerShift_(ownerShift(dims, threads)),
          regionsX_((dims[0] + kRegionMask) >> kRegionShift),
          regionsY_((dims[1] + kRegionMask) >> kRegionShift),
          regions_(std::size_t(regionsX_) * std::size_t(regionsY_) *
                   std::size_t((dims[2] + kRegionMask) >> kRegionShift)),
          arenas_(std::size_t(std::max(threads, 1))),
          threads_(std::max(threads, 1)) {
        for (auto& r : regions_) r.store(nullptr, std::memory_order_relaxed);
    }

    static int local(int x, int y, int z) {
        constexpr int m = kSide - 1;
        return (x & m) | (y & m) << kShift | (z & m) << (2 * kShift);
    }
    // A region is 64^3 grid points: coordinates differing only in these low bits
    // lie in one region. (Regions of 32^3 or 16^3 walked the CT skull no faster
    // on two threads.)
    static constexpr int kRegionShift = 2 * kShift;
    static constexpr int kRegionMask = (1 << kRegionShift) - 1;
    // The thread walking the cells of the tile holding grid point (x, y, z): the
    // tiles' diagonal planes (x + y + z constant) are dealt out to the threads in
    // turn, so that neighbouring tiles belong to different threads.
    int ownerAt(int x, int y, int z) const {
        return ((x >> ownerShift_) + (y >> ownerShift_) + (z >> ownerShift_)) % threads_;
    }

    // The tile side (as a shift) for `threads` threads: the largest, from a
    // region (64^3) down to a block (8^3), that cuts the volume into at least
    // kPlanesPerThread diagonal planes per thread. Larger tiles send fewer
    // pieces between threads; more planes share the surface out more evenly.
    // On the CT skull (516k triangles), the busiest thread of 16 walked 4.9
    // times the mean with 64^3 tiles (8 planes: half the threads had none),
    // 1.24 times with 8^3 tiles, at 123k pieces sent against 13k.
    static int ownerShift(const Dims& dims, int threads) {
        for (int shift = kRegionShift; shift > kShift; --shift) {
            if (diagonalPlanes(dims, shift) >= kPlanesPerThread * std::int64_t(threads)) return shift;
        }
        return kShift;
    }

    // A tile's side less one (the coordinates of points on a tile's lower faces have 0 in these bits).
    int tileMask() const { return (1 << ownerShift_) - 1; }

    // The most threads that the volume's size gives work to: kPlanesPerThread
    // diagonal planes of blocks each, and at least one.
    static int usefulThreads(const Dims& dims) {
        return int(std::max<std::int64_t>(1, diagonalPlanes(dims, kShift) / kPlanesPerThread));
    }

    // The step in local index for a unit step along each axis.
    static constexpr std::array<int, 3> kLocalStep{1, kSide, kSide* kSide};

    // The block holding grid point (x, y, z), created empty on first use from
    // thread `thread`'s arena.
    Block* at(int x, int y, int z, int thread = 0) {
        const int bx = x >> kShift, by = y >> kShift, bz = z >> kShift;
        Arena& arena = arenas_[std::size_t(thread)];
        std::atomic<Region*>& regionSlot =
            regions_[std::size_t(x >> kRegionShift) +
                     std::size_t(regionsX_) *
                         (std::size_t(y >> kRegionShift) + std::size_t(regionsY_) * std::size_t(z >> kRegionShift))];
        Region* region = regionSlot.load(std::memory_order_acquire);
        if (region == nullptr)
            region = publish(regionSlot, arena.spareRegion_, [&] { return &arena.regions_.emplace_back(); });
        std::atomic<Block*>& blockSlot = region->block[std::size_t(local(bx, by, bz))];
        Block* block = blockSlot.load(std::memory_order_acquire);
        if (block == nullptr) {
            const std::array<int, 3> origin{bx << kShift, by << kShift, bz << kShift};
            const int owner = ownerAt(x, y, z);
            if (arena.spareBlock_ != nullptr) arena.spareBlock_->origin = origin, arena.spareBlock_->owner = owner;
            block = publish(blockSlot, arena.spareBlock_,
                            [&] { return &arena.blocks_.emplace_back(origin, owner, slots_); });
        }
        return block;
    }

    // The block at `link` from `block` (see kSelf).
    Block* linked(Block* block, int link, int thread = 0) {
        Block* found = block->link[std::size_t(link)].load(std::memory_order_acquire);
        return found != nullptr ? found : resolve(block, link, thread);
    }

    std::size_t byteSize() const {
        std::size_t bytes = regions_.size() * sizeof(regions_[0]);
        for (const Arena& arena : arenas_) bytes += arena.byteSize();
        return bytes;
    }

private:
    // Publishes a new object in `slot` unless another thread was first; the
    // loser keeps its object as `spare` for its next creation of the same kind.
    template <class T, class Make>
    static T* publish(std::atomic<T*>& slot, T*& spare, Make make) {
        T* made = spare != nullptr ? spare : make();
        spare = nullptr;
        T* expected = nullptr;
        if (slot.compare_exchange_strong(expected, made, std::memory_order_acq_rel, std::memory_order_acquire))
            return made;
        spare = made;
        return expected;
    }

    [[gnu::noinline]] static void fillRows(Block* block, std::uint64_t rows, std::uint64_t ready) {
        for (; rows != 0; rows &= rows - 1)
            std::fill_n(block->vertex.data() + kRowSlots * __builtin_ctzll(rows), kRowSlots, kNoVertex);
        block->rowsClaimed.store(ready, std::memory_order_relaxed);
        block->rowsReady.store(ready, std::memory_order_relaxed);
    }

    [[gnu::noinline]] static void claimRows(Block* block, std::uint64_t rows, std::uint64_t missing) {
        const std::uint64_t mine = missing & ~block->rowsClaimed.fetch_or(missing, std::memory_order_relaxed);
        for (std::uint64_t left = mine; left != 0; left &= left - 1)
            std::fill_n(block->vertex.data() + kRowSlots * __builtin_ctzll(left), kRowSlots, kNoVertex);
        if (mine != 0) block->rowsReady.fetch_or(mine, std::memory_order_release);
        // Rows another thread claimed are ready a few stores later.
        while ((block->rowsReady.load(std::memory_order_acquire) & rows) != rows) {
        }
    }

    [[gnu::noinline]] Block* resolve(Block* block, int link, int thread) {
        const std::array<int, 3> o = block->origin;
        Block* found =
            at(o[0] + (link % 3 - 1) * kSide, o[1] + (link / 3 % 3 - 1) * kSide, o[2] + (link / 9 - 1) * kSide, thread);
        block->link[std::size_t(link)].store(found, std::memory_order_release);
        return found;
    }

    static constexpr int kPlanesPerThread = 4;

    // How many diagonal planes of tiles of side 1 << shift cut the volume.
    static std::int64_t diagonalPlanes(const Dims& dims, int shift) {
        std::int64_t planes = 1;
        for (const auto n : dims) planes += ((std::int64_t(n) - 1) >> shift);
        return planes;
    }

    VertexSlots slots_;
    int ownerShift_;  // the side of a tile walked by one thread
    int regionsX_, regionsY_;
    std::vector<std::atomic<Region*>> regions_;
    std::vector<Arena> arenas_;
    int threads_;
};

}  // namespace isotrack::detail
