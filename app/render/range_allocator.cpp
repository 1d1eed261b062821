#include "render/range_allocator.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

namespace isotrack::render {
namespace {

std::string rangeText(std::size_t offset, std::size_t size) {
    return "[" + std::to_string(offset) + ", " + std::to_string(offset + size) + ")";
}

}  // namespace

RangeAllocator::RangeAllocator(std::size_t capacity) : capacity_(capacity), free_(capacity) {
    if (capacity > 0) ranges_.emplace(0, capacity);
}

std::optional<std::size_t> RangeAllocator::allocate(std::size_t size) {
    if (size == 0) throw std::invalid_argument("RangeAllocator::allocate: a range of 0 elements");
    for (auto it = ranges_.begin(); it != ranges_.end(); ++it) {
        if (it->second < size) continue;
        const std::size_t offset = it->first, left = it->second - size;
        ranges_.erase(it);
        if (left > 0) ranges_.emplace(offset + size, left);
        free_ -= size;
        return offset;
    }
    return std::nullopt;
}

void RangeAllocator::release(std::size_t offset, std::size_t size) {
    if (size == 0) return;
    auto next = ranges_.lower_bound(offset);
    const bool overlapsNext = next != ranges_.end() && next->first < offset + size;
    const bool overlapsPrevious = next != ranges_.begin() && std::prev(next)->first + std::prev(next)->second > offset;
    if (offset + size > capacity_ || offset + size < offset || overlapsNext || overlapsPrevious) {
        throw std::invalid_argument("RangeAllocator::release: " + rangeText(offset, size) +
                                    " was not allocated (capacity " + std::to_string(capacity_) + ")");
    }
    free_ += size;
    std::size_t start = offset, length = size;
    if (next != ranges_.end() && next->first == offset + size) {  // joins the free range after it
        length += next->second;
        next = ranges_.erase(next);
    }
    if (next != ranges_.begin()) {
        auto previous = std::prev(next);
        if (previous->first + previous->second == offset) {  // and the one before
            previous->second += length;
            return;
        }
    }
    ranges_.emplace(start, length);
}

bool RangeAllocator::tryGrow(std::size_t offset, std::size_t size, std::size_t newSize) {
    if (newSize <= size) return true;
    const auto after = ranges_.find(offset + size);
    const std::size_t extra = newSize - size;
    if (after == ranges_.end() || after->second < extra) return false;
    const std::size_t left = after->second - extra;
    ranges_.erase(after);
    if (left > 0) ranges_.emplace(offset + newSize, left);
    free_ -= extra;
    return true;
}

void RangeAllocator::shrink(std::size_t offset, std::size_t size, std::size_t newSize) {
    if (newSize < size) release(offset + newSize, size - newSize);
}

std::size_t RangeAllocator::freeAt(std::size_t offset) const {
    const auto range = ranges_.find(offset);
    return range == ranges_.end() ? 0 : range->second;
}

std::size_t RangeAllocator::largestFree() const {
    std::size_t largest = 0;
    for (const auto& range : ranges_) largest = std::max(largest, range.second);
    return largest;
}

double RangeAllocator::fragmentation() const {
    if (free_ == 0) return 0.0;
    return 1.0 - static_cast<double>(largestFree()) / static_cast<double>(free_);
}

}  // namespace isotrack::render
