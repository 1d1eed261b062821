#pragma once
// Ranges of one linear address space (elements of a GPU buffer): first fit,
// freed ranges coalesced with their free neighbours. No GL; SurfaceArena keeps
// one per buffer of each page.
//
// A range may also grow where it lies, when the space right after it is free
// (tryGrow), and give back its tail (shrink): a growing surface then stays put.
#include <cstddef>
#include <map>
#include <optional>

namespace isotrack::render {

class RangeAllocator {
public:
    explicit RangeAllocator(std::size_t capacity = 0);

    // The lowest offset with `size` free elements, taken; nullopt when no free
    // range is large enough. A size of 0 is an error (std::invalid_argument).
    std::optional<std::size_t> allocate(std::size_t size);
    // Gives back [offset, offset + size), which must have been allocated
    // (std::invalid_argument if it overlaps free space or leaves the capacity).
    void release(std::size_t offset, std::size_t size);
    // Grows the allocated [offset, offset + size) to `newSize` in place when the
    // elements after it are free; false (and nothing changed) otherwise.
    bool tryGrow(std::size_t offset, std::size_t size, std::size_t newSize);
    // Gives back the tail of [offset, offset + size) beyond `newSize`.
    void shrink(std::size_t offset, std::size_t size, std::size_t newSize);

    std::size_t capacity() const { return capacity_; }
    std::size_t freeSize() const { return free_; }
    std::size_t usedSize() const { return capacity_ - free_; }
    std::size_t largestFree() const;
    // The free elements starting right at `offset` (0 if it is not free).
    std::size_t freeAt(std::size_t offset) const;
    std::size_t freeRangeCount() const { return ranges_.size(); }
    // 1 - largest free range / all free space: 0 when the free space is one
    // range (or there is none), towards 1 as it splits into many small ones.
    double fragmentation() const;

private:
    std::map<std::size_t, std::size_t> ranges_;  // free ranges: offset -> size
    std::size_t capacity_ = 0, free_ = 0;
};

}  // namespace isotrack::render
