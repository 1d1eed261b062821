#pragma once
// Per-surface storage for the tracker: blocks of 8x8x8 grid points, created on
// first touch and found through a hash map keyed by block. A surface touches a
// thin shell of blocks, so memory follows the surface, not the volume, while
// neighbouring cells and edges share cache lines, unlike a map keyed by cell.
#include <array>
#include <cstdint>
#include <deque>
#include <limits>
#include <vector>

#include "flat_hash.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

class SparseBlocks {
public:
    static constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

    static constexpr int kShift = 3;
    static constexpr int kSide = 1 << kShift;
    static constexpr int kPoints = kSide * kSide * kSide;

    struct Block {
        std::array<std::uint8_t, kPoints> config{};       // per cell; 0 until classified (0 is never queued)
        std::array<std::uint8_t, kPoints> visited{};      // per cell, one bit per piece
        std::array<std::uint32_t, 3 * kPoints> vertex;    // per grid point and axis, the vertex on that edge
        Block() { vertex.fill(kNoVertex); }
    };

    explicit SparseBlocks(const Dims& dims)
        : blocksX_((dims[0] + kSide - 1) / kSide), blocksY_((dims[1] + kSide - 1) / kSide) {}

    static int local(int x, int y, int z) {
        constexpr int m = kSide - 1;
        return (x & m) | (y & m) << kShift | (z & m) << (2 * kShift);
    }
    // The step in local index for a unit step along each axis.
    static constexpr std::array<int, 3> kLocalStep{1, kSide, kSide * kSide};

    // The block holding grid point (x, y, z), created empty on first use.
    // References stay valid as blocks are added (a deque never moves them).
    Block& at(int x, int y, int z) {
        const int bx = x >> kShift, by = y >> kShift, bz = z >> kShift;
        const std::uint64_t key = std::uint64_t(bx) + std::uint64_t(blocksX_) * (std::uint64_t(by) + std::uint64_t(blocksY_) * std::uint64_t(bz));
        // A small cache indexed by the low bits of the block coordinates: the
        // blocks around a cell land in different lines.
        CacheLine& line = cache_[std::size_t((bx & 3) | (by & 3) << 2 | (bz & 1) << 4)];
        if (line.key == key) return *line.block;
        bool inserted = false;
        const std::uint32_t slot = index_.findOrInsert(key, static_cast<std::uint32_t>(pointers_.size()), inserted);
        if (inserted) {
            blocks_.emplace_back();
            pointers_.push_back(&blocks_.back());
        }
        line = {key, pointers_[slot]};
        return *line.block;
    }

    std::size_t byteSize() const { return blocks_.size() * (sizeof(Block) + sizeof(Block*)) + index_.byteSize(); }

private:
    int blocksX_, blocksY_;
    FlatHashMap index_;
    std::deque<Block> blocks_;
    std::vector<Block*> pointers_;
    struct CacheLine {
        std::uint64_t key = std::numeric_limits<std::uint64_t>::max();
        Block* block = nullptr;
    };
    std::array<CacheLine, 32> cache_{};
};

}  // namespace isotrack::detail
