#pragma once
// The queue of cell pieces a tracking walk has yet to walk, in the walk's own
// order (by sparse block) or breadth-first (for growth shown as it happens).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "extract/common/sparse_blocks.h"
#include "isotrack/continuation.h"

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
    std::size_t size() const { return tail_ - head_; }
    // The item `k` places after the next one popped (k < size()).
    const T& ahead(std::size_t k) const { return data_[(head_ + k) & (size_ - 1)]; }
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
//  - By block (a whole surface at once): each block with pieces waiting has a
//    set of them, one bit per (cell, piece), and the blocks wait their turn
//    first in, first out. A block's turn walks its pieces, lowest cell first,
//    until none is left, the pieces they lead to in the same block included, so
//    the block's vertex ids, flags and samples are walked while they are in
//    cache (half the first-level cache misses of breadth-first on the CT
//    skull), and in the order of its rows; the pieces they lead to in other
//    blocks wait in those blocks' sets. A bit set and its word of nonempty
//    words cost a few bit operations per push and pop, where a linked list of
//    pieces per block cost a node taken from and given back to a free list.
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
        return (currentSet_ == nullptr || currentSet_->words == 0) && blocks_.empty();
    }

    // Inlined where it is called: a push per exit is too frequent for a call.
    [[gnu::always_inline]] void push(const Entry& entry) {
        if (order_ == WalkOrder::BreadthFirst) {
            pieces_.push(entry);
            return;
        }
        Block* block = entry.block;
        if (block->pending == kNone) takeSet(block);
        PieceSet& set = *sets_[block->pending];
        const unsigned bit = unsigned(entry.cell) * kMaxPieces + entry.piece;
        set.bits[bit / 64] |= std::uint64_t(1) << (bit % 64);
        set.words |= std::uint64_t(1) << (bit / 64);
    }

    // The next piece; false when none is left. Inlined likewise; a block's
    // turn begins and ends out of line.
    [[gnu::always_inline]] bool pop(Entry& entry) {
        if (order_ == WalkOrder::BreadthFirst) {
            if (pieces_.empty()) return false;
            entry = pieces_.pop();
            return true;
        }
        if ((currentSet_ == nullptr || currentSet_->words == 0) && !nextBlock()) return false;
        PieceSet& set = *currentSet_;
        const unsigned word = unsigned(__builtin_ctzll(set.words));
        std::uint64_t bits = set.bits[word];
        const unsigned bit = 64 * word + unsigned(__builtin_ctzll(bits));
        bits &= bits - 1;
        set.bits[word] = bits;
        set.words &= ~(std::uint64_t(bits == 0) << word);  // no branch: whether a word empties is a coin toss
        const unsigned cell = bit / kMaxPieces;
        entry = {current_, static_cast<std::uint16_t>(cell), current_->config[cell],
                 static_cast<std::uint8_t>(bit % kMaxPieces)};
        return true;
    }

    // Every piece waiting, taken out of the queue, which is left empty.
    std::vector<Entry> drain() {
        std::vector<Entry> entries;
        for (Entry entry; pop(entry);) entries.push_back(entry);
        return entries;
    }

    std::size_t byteSize() const {
        return sets_.capacity() * sizeof(sets_[0]) + sets_.size() * sizeof(PieceSet) +
               spare_.capacity() * sizeof(std::uint32_t) + blocks_.capacity() * sizeof(Block*) +
               pieces_.capacity() * sizeof(Entry);
    }

private:
    static constexpr std::uint32_t kNone = SparseBlocks::kNoPending;
    // A piece's bit is cell * kMaxPieces + piece.
    static constexpr int kWords = SparseBlocks::kPoints * kMaxPieces / 64;
    static_assert(kWords <= 64, "a set's nonempty words fit one word");

    // The pieces waiting in one block.
    struct PieceSet {
        std::uint64_t words = 0;  // bit w set when bits[w] has a piece
        std::array<std::uint64_t, kWords> bits{};
    };

    // Gives `block` an empty set, one a block whose turn ended gave back or a
    // new one, and puts the block in line.
    [[gnu::noinline]] void takeSet(Block* block) {
        if (spare_.empty()) {
            block->pending = static_cast<std::uint32_t>(sets_.size());
            sets_.push_back(std::make_unique<PieceSet>());
        } else {
            block->pending = spare_.back();
            spare_.pop_back();
        }
        blocks_.push(block);
    }

    // Ends the current block's turn, its set empty, and begins the next
    // block's; false when no block is left.
    [[gnu::noinline]] bool nextBlock() {
        if (current_ != nullptr) {
            spare_.push_back(current_->pending);
            current_->pending = kNone;
            current_ = nullptr;
            currentSet_ = nullptr;
        }
        if (blocks_.empty()) return false;
        current_ = blocks_.pop();
        currentSet_ = sets_[current_->pending].get();
        return true;
    }

    std::vector<std::unique_ptr<PieceSet>> sets_;  // by a waiting block's `pending`; a set never moves
    std::vector<std::uint32_t> spare_;             // sets of no block, all empty
    Ring<Block*> blocks_;                          // blocks with pieces waiting, but for current_
    Block* current_ = nullptr;                     // the block being walked
    PieceSet* currentSet_ = nullptr;               // and its set
    WalkOrder order_;
    Ring<Entry> pieces_;  // breadth-first
};

}  // namespace isotrack::detail
