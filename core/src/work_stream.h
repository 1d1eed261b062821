#pragma once
// A one-way stream of 64-bit words from one thread to another, for work the
// first hands to the second as it goes (the tracker's vertices and triangles).
// Words are written into segments that never move, published in batches, and
// read in order; the reader frees each segment it has finished.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

namespace isotrack::detail {

class WorkStream {
public:
    static constexpr int kShift = 16;
    static constexpr std::size_t kSegment = std::size_t(1) << kShift;  // words
    static constexpr std::size_t kSlots = std::size_t(1) << 16;        // up to 2^32 words

    WorkStream() : slots_(kSlots) {}
    ~WorkStream() {
        for (auto& slot : slots_) delete[] slot.load(std::memory_order_relaxed);
    }
    WorkStream(const WorkStream&) = delete;
    WorkStream& operator=(const WorkStream&) = delete;

    // Writer: appends a word, made visible to the reader by the next publish().
    void push(std::uint64_t word) {
        const std::size_t at = size_ & (kSegment - 1);
        if (at == 0) startSegment();
        segment_[at] = word;
        ++size_;
    }
    void publish() { published_.store(size_, std::memory_order_release); }
    // Writer: no more words; also when the writer fails, so that the reader stops.
    void finish() {
        publish();
        finished_.store(true, std::memory_order_release);
    }

    // Reader: calls fn(word) for every word in order until the writer has finished
    // and every word is read.
    template <class Fn>
    void drain(Fn&& fn) {
        std::size_t read = 0;
        for (;;) {
            const bool finished = finished_.load(std::memory_order_acquire);
            const std::size_t available = published_.load(std::memory_order_acquire);
            if (read == available) {
                if (finished) return;
                // Waiting: sleep rather than spin, so as not to take cycles from the
                // writer (two threads may share one core).
                std::this_thread::sleep_for(std::chrono::microseconds(20));
                continue;
            }
            while (read < available) {
                const std::size_t slot = read >> kShift;
                const std::uint64_t* segment = slots_[slot].load(std::memory_order_acquire);
                const std::size_t end = std::min(available, (slot + 1) << kShift);
                for (; read < end; ++read) fn(segment[read & (kSegment - 1)]);
                if ((read & (kSegment - 1)) == 0) delete[] slots_[slot].exchange(nullptr, std::memory_order_acq_rel);
            }
        }
    }

private:
    void startSegment() {
        const std::size_t slot = size_ >> kShift;
        if (slot >= kSlots) throw std::length_error("tracking: more than 2^32 words of work in flight");
        segment_ = new std::uint64_t[kSegment];
        slots_[slot].store(segment_, std::memory_order_release);
    }

    std::vector<std::atomic<std::uint64_t*>> slots_;
    std::uint64_t* segment_ = nullptr;  // the writer's current segment
    std::size_t size_ = 0;              // words written
    std::atomic<std::size_t> published_{0};
    std::atomic<bool> finished_{false};
};

}  // namespace isotrack::detail
