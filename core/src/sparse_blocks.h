#pragma once
// Per-surface storage for the tracker: blocks of 8x8x8 grid points, created on
// first touch and found through a hash map keyed by block. A surface touches a
// thin shell of blocks, so memory follows the surface, not the volume, while
// neighbouring cells and edges share cache lines, unlike a map keyed by cell.
//
// Each block keeps links to the 26 blocks around it, resolved through the hash
// map the first time they are needed: a cell's neighbours and the far ends of its
// edges are then one load away, however often the tracker crosses block faces.
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
    // The link to the block itself: links are numbered (dx + 1) + 3 (dy + 1) + 9 (dz + 1).
    static constexpr int kSelf = 13;

    struct Block {
        std::array<std::uint8_t, kPoints> config{};       // per cell; 0 until classified (0 is never queued)
        std::array<std::uint8_t, kPoints> visited{};      // per cell, one bit per piece
        std::array<std::uint32_t, 3 * kPoints> vertex;    // per grid point and axis, the vertex on that edge
        std::array<std::uint32_t, 27> link{};             // 1 + index of each adjacent block; 0 until looked up
        std::array<int, 3> origin{};                      // grid coordinates of local point (0, 0, 0)
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

    // The index of the block holding grid point (x, y, z), created empty on first use.
    std::uint32_t indexAt(int x, int y, int z) {
        const int bx = x >> kShift, by = y >> kShift, bz = z >> kShift;
        const std::uint64_t key = std::uint64_t(bx) + std::uint64_t(blocksX_) * (std::uint64_t(by) + std::uint64_t(blocksY_) * std::uint64_t(bz));
        bool inserted = false;
        const std::uint32_t index = index_.findOrInsert(key, static_cast<std::uint32_t>(pointers_.size()), inserted);
        if (inserted) {
            blocks_.emplace_back();
            blocks_.back().origin = {bx << kShift, by << kShift, bz << kShift};
            blocks_.back().link[kSelf] = index + 1;
            pointers_.push_back(&blocks_.back());
        }
        return index;
    }

    // References stay valid as blocks are added (a deque never moves them).
    Block& operator[](std::uint32_t index) { return *pointers_[index]; }

    // The index of the block at `link` from block `index` (see kSelf).
    std::uint32_t linked(std::uint32_t index, int link) {
        const std::uint32_t slot = pointers_[index]->link[std::size_t(link)];
        return slot != 0 ? slot - 1 : resolve(index, link);
    }

    std::size_t byteSize() const { return blocks_.size() * (sizeof(Block) + sizeof(Block*)) + index_.byteSize(); }

private:
    [[gnu::noinline]] std::uint32_t resolve(std::uint32_t index, int link) {
        const std::array<int, 3> o = pointers_[index]->origin;
        const std::uint32_t found = indexAt(o[0] + (link % 3 - 1) * kSide, o[1] + (link / 3 % 3 - 1) * kSide, o[2] + (link / 9 - 1) * kSide);
        pointers_[index]->link[std::size_t(link)] = found + 1;
        return found;
    }

    int blocksX_, blocksY_;
    FlatHashMap index_;
    std::deque<Block> blocks_;
    std::vector<Block*> pointers_;
};

}  // namespace isotrack::detail
