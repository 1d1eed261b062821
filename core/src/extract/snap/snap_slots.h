#pragma once
// Vertex slots of the snap room's extractors (snap_march.cpp): where a grid
// edge's or a sample's vertex id is kept once made, so that every cell that
// uses it finds it.
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <limits>
#include <memory>
#include <unordered_map>
#include <vector>

#include "isotrack/volume.h"

namespace isotrack::detail {

constexpr std::uint32_t kNoVertex = std::numeric_limits<std::uint32_t>::max();

// Vertex ids of a walk, which goes anywhere: four slots per sample (its edges
// along x, y and z, then the sample itself) in blocks of 4x4x4 samples made
// when a walk first reaches them, so lookups neither hash nor allocate per
// vertex; the rare centres of fanned loops (slot 4..7 of a cell) in a map.
class BlockSlots {
public:
    explicit BlockSlots(const Dims& n)
        : blocks_{(n[0] + kSide - 1) / kSide, (n[1] + kSide - 1) / kSide, (n[2] + kSide - 1) / kSide},
          table_(std::size_t(blocks_[0]) * std::size_t(blocks_[1]) * std::size_t(blocks_[2]), nullptr) {}

    std::uint32_t& slot(int x, int y, int z, int kind) {
        if (kind >= 4) {
            const std::uint64_t cell =
                std::uint64_t(x) +
                std::uint64_t(kMaxSide) * (std::uint64_t(y) + std::uint64_t(kMaxSide) * std::uint64_t(z));
            return centres_.try_emplace(cell * 4 + std::uint64_t(kind - 4), kNoVertex).first->second;
        }
        const std::size_t block =
            std::size_t(x / kSide) +
            std::size_t(blocks_[0]) * (std::size_t(y / kSide) + std::size_t(blocks_[1]) * std::size_t(z / kSide));
        std::uint32_t*& slots = table_[block];
        if (!slots) slots = newBlock();
        return slots[std::size_t(((z % kSide * kSide + y % kSide) * kSide + x % kSide) * 4 + kind)];
    }

    std::size_t bytes() const {
        return table_.size() * sizeof(table_[0]) + chunks_.size() * kChunkSlots * sizeof(std::uint32_t) +
               centres_.size() * (sizeof(std::uint64_t) + sizeof(std::uint32_t) + 2 * sizeof(void*));
    }

private:
    static constexpr int kSide = 4;
    static constexpr std::size_t kBlockSlots = 4 * kSide * kSide * kSide;
    static constexpr std::size_t kChunkSlots = 64 * kBlockSlots;
    static constexpr std::uint64_t kMaxSide = std::uint64_t(1) << 21;

    std::uint32_t* newBlock() {
        if (chunks_.empty() || used_ == kChunkSlots) {
            chunks_.push_back(std::make_unique<std::uint32_t[]>(kChunkSlots));
            used_ = 0;
        }
        std::uint32_t* block = chunks_.back().get() + used_;
        std::fill(block, block + kBlockSlots, kNoVertex);
        used_ += kBlockSlots;
        return block;
    }

    std::array<int, 3> blocks_;
    std::vector<std::uint32_t*> table_;
    std::vector<std::unique_ptr<std::uint32_t[]>> chunks_;
    std::size_t used_ = 0;
    std::unordered_map<std::uint64_t, std::uint32_t> centres_;
};

// BlockSlots' edge and sample slots for a walk on several threads
// (snap_together.cpp): a block is made by the first thread to reach it, from
// that thread's chunks, and published with a compare-and-swap (a thread that
// loses keeps its block for its next). The slots in a block are the walk's to
// read and write: those cells of several threads share are claimed with a
// compare-and-swap there. The centres, rare, are kept elsewhere.
class SharedBlockSlots {
public:
    SharedBlockSlots(const Dims& n, int threads)
        : blocks_{(n[0] + kSide - 1) / kSide, (n[1] + kSide - 1) / kSide, (n[2] + kSide - 1) / kSide},
          // Value-initialised: every pointer null.
          table_(std::size_t(blocks_[0]) * std::size_t(blocks_[1]) * std::size_t(blocks_[2])),
          arenas_(std::size_t(threads)) {}

    // Slot `kind` (an axis, or 3 for the sample) of sample (x, y, z), reached from thread `thread`.
    std::uint32_t* slot(int x, int y, int z, int kind, int thread) {
        const std::size_t block =
            std::size_t(x / kSide) +
            std::size_t(blocks_[0]) * (std::size_t(y / kSide) + std::size_t(blocks_[1]) * std::size_t(z / kSide));
        std::uint32_t* slots = table_[block].load(std::memory_order_acquire);
        if (slots == nullptr) slots = publish(table_[block], arenas_[std::size_t(thread)]);
        return slots + std::size_t(((z % kSide * kSide + y % kSide) * kSide + x % kSide) * 4 + kind);
    }

private:
    static constexpr int kSide = 4;
    static constexpr std::size_t kBlockSlots = 4 * kSide * kSide * kSide;
    static constexpr std::size_t kChunkSlots = 64 * kBlockSlots;

    struct alignas(64) Arena {
        std::vector<std::unique_ptr<std::uint32_t[]>> chunks;
        std::size_t used = kChunkSlots;
        std::uint32_t* spare = nullptr;  // made, but another thread published its block first
    };

    [[gnu::noinline]] static std::uint32_t* publish(std::atomic<std::uint32_t*>& entry, Arena& arena) {
        std::uint32_t* made = arena.spare;
        arena.spare = nullptr;
        if (made == nullptr) {
            if (arena.used == kChunkSlots) {
                arena.chunks.push_back(std::make_unique<std::uint32_t[]>(kChunkSlots));
                arena.used = 0;
            }
            made = arena.chunks.back().get() + arena.used;
            arena.used += kBlockSlots;
            std::fill(made, made + kBlockSlots, kNoVertex);
        }
        std::uint32_t* expected = nullptr;
        if (entry.compare_exchange_strong(expected, made, std::memory_order_acq_rel, std::memory_order_acquire))
            return made;
        arena.spare = made;
        return expected;
    }

    std::array<int, 3> blocks_;
    std::vector<std::atomic<std::uint32_t*>> table_;
    std::vector<Arena> arenas_;
};

// The same for marchSnap, which goes slab by slab: the slots of two slices of
// samples, the slice of the slab's top reused from the slab two below, and of
// the cell being emitted's centres.
class SliceSlots {
public:
    SliceSlots(const Dims& n)
        : nx_(std::size_t(n[0])), slice_(std::size_t(n[0]) * std::size_t(n[1])), slots_(8 * slice_, kNoVertex) {}

    // Before emitting the cells between slices z and z + 1.
    void startSlab(int z) {
        const std::size_t top = std::size_t((z + 1) & 1) * 4 * slice_;
        std::fill(slots_.begin() + std::ptrdiff_t(top), slots_.begin() + std::ptrdiff_t(top + 4 * slice_), kNoVertex);
    }

    std::uint32_t& slot(int x, int y, int z, int kind) {
        if (kind >= 4) {
            const std::array<int, 3> cell{x, y, z};
            if (cell != centreCell_) {
                centreCell_ = cell;
                centres_.fill(kNoVertex);
            }
            return centres_[std::size_t(kind - 4)];
        }
        const std::size_t parity = std::size_t(z) & 1;
        return slots_[(parity * 4 + std::size_t(kind)) * slice_ + std::size_t(x) + nx_ * std::size_t(y)];
    }

private:
    std::size_t nx_;
    std::size_t slice_;
    std::vector<std::uint32_t> slots_;
    std::array<int, 3> centreCell_{-1, -1, -1};
    std::array<std::uint32_t, 4> centres_{};
};

}  // namespace isotrack::detail
