#pragma once
// The queue of cell pieces a tracking walk has yet to walk, in the walk's own
// order (by sparse block) or breadth-first (for growth shown as it happens).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "extract/common/sparse_blocks.h"

namespace isotrack::detail {

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
        return nodes_.capacity() * sizeof(Node) + blocks_.capacity() * sizeof(Block*) +
               pieces_.capacity() * sizeof(Entry);
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
    Ring<Block*> blocks_;       // blocks with pieces waiting, but for current_
    Block* current_ = nullptr;  // the block being walked
    WalkOrder order_;
    Ring<Entry> pieces_;  // breadth-first
};

}  // namespace isotrack::detail
