#pragma once
// The mailboxes of the threads that walk one surface together (walkTogether).
#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "extract/common/sparse_blocks.h"

namespace isotrack::detail {

// The messages between threads walking one surface together. Each thread walks
// the cells of its own regions; a piece that continues into another thread's
// region is sent to that thread, which queues it as its own.
class Exchange {
public:
    struct Message {
        Block* block;
        std::size_t sample;  // the cell's first corner
        std::uint16_t cell;
        std::uint8_t edge;  // the entry edge
    };

    explicit Exchange(int threads)
        : threads_(threads), outbox_(std::size_t(threads)), inbox_(std::size_t(threads)), mail_(std::size_t(threads)) {
        for (Outbox& box : outbox_) box.to.resize(std::size_t(threads));
    }

    // Collected by the sender, handed over at its next poll or wait.
    void send(int from, int to, const Message& message) {
        outbox_[std::size_t(from)].to[std::size_t(to)].push_back(message);
    }

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
            if (idle_ == threads_ &&
                std::all_of(inbox_.begin(), inbox_.end(), [](const auto& box) { return box.empty(); })) {
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
        woken_.wait(lock, [&] {
            return finished_.load(std::memory_order_relaxed) || stopped_.load(std::memory_order_relaxed) ||
                   !inbox_[std::size_t(me)].empty();
        });
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

}  // namespace isotrack::detail
