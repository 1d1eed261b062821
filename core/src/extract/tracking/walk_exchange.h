#pragma once
// The mailboxes of the threads that walk one surface together (walkTogether).
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
// the cells of its own tiles; a piece that continues into another thread's
// tile is sent to that thread, which queues it as its own.
//
// Each thread has a mailbox of its own: a lock, an inbox and a condition
// variable. A sender collects its messages per recipient and hands each batch
// over under the recipient's lock alone, waking that recipient only if it
// sleeps, so that threads meet only when one hands pieces to another (one lock
// for every inbox, and every thread woken on every hand-over, made 8 and 16
// threads slower than 4).
//
// The walk is over when no thread is active: a thread is active while it walks
// or has mail it has not taken. A thread going idle leaves the count of active
// threads; a sender handing pieces to an idle thread counts it back in while it
// is itself still active, so the count reaches zero only once every thread is
// idle and every inbox empty.
class Exchange {
public:
    struct Message {
        Block* block;
        std::size_t sample;  // the cell's first corner
        std::uint16_t cell;
        std::uint8_t edge;  // the entry edge
    };

    explicit Exchange(int threads) : boxes_(std::size_t(threads)), active_(threads) {
        for (Mailbox& box : boxes_) box.outbox.resize(std::size_t(threads));
    }

    // Collected by the sender, handed over at its next poll or wait.
    void send(int from, int to, const Message& message) {
        Mailbox& box = boxes_[std::size_t(from)];
        box.outbox[std::size_t(to)].push_back(message);
        box.unsent = true;
    }

    // From a walking thread every so often: hands over what it sent and takes
    // what was sent to it; false once the walk is abandoned.
    bool poll(int me, std::vector<Message>& received) {
        if (stopped_.load(std::memory_order_relaxed)) return false;
        Mailbox& box = boxes_[std::size_t(me)];
        if (box.unsent) handOver(me);
        if (box.mail.load(std::memory_order_acquire)) {
            const std::lock_guard<std::mutex> lock(box.mutex);
            take(box, received);
        }
        return true;
    }

    // From a thread with nothing left to walk: waits for pieces sent to it
    // (true) or for every thread to be done (false). It looks for mail a few
    // times, then sleeps until mail comes or the walk ends.
    bool wait(int me, std::vector<Message>& received) {
        Mailbox& box = boxes_[std::size_t(me)];
        if (box.unsent) handOver(me);
        {
            const std::lock_guard<std::mutex> lock(box.mutex);
            if (take(box, received)) return true;
            box.idle = true;
        }
        if (active_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
            finished_.store(true, std::memory_order_release);
            for (Mailbox& other : boxes_) {
                const std::lock_guard<std::mutex> lock(other.mutex);
                other.woken.notify_one();
            }
            return false;
        }
        for (int look = 0; look < kLooks; ++look) {
            if (box.mail.load(std::memory_order_acquire) || over()) break;
            std::this_thread::yield();
        }
        std::unique_lock<std::mutex> lock(box.mutex);
        box.sleeping = true;
        box.woken.wait(lock, [&] { return !box.idle || over(); });
        box.sleeping = false;
        if (box.idle) return false;  // over, with no mail
        return take(box, received) && !stopped_.load(std::memory_order_relaxed);
    }

    // Abandons the walk (a thread failed): every thread stops at its next poll or wait.
    void stop() {
        stopped_.store(true, std::memory_order_release);
        for (Mailbox& box : boxes_) {
            const std::lock_guard<std::mutex> lock(box.mutex);
            box.woken.notify_one();
        }
    }

private:
    struct alignas(64) Mailbox {
        // Used by its owner alone.
        std::vector<std::vector<Message>> outbox;  // per recipient
        bool unsent = false;                       // something waits in outbox
        // Its owner's and its senders', under mutex.
        alignas(64) std::mutex mutex;
        std::condition_variable woken;
        std::vector<Message> inbox;
        bool idle = false;              // the owner left the active count and no sender counted it back in
        bool sleeping = false;          // the owner waits on `woken`
        std::atomic<bool> mail{false};  // inbox holds something: read without the lock
    };

    bool over() const { return finished_.load(std::memory_order_acquire) || stopped_.load(std::memory_order_acquire); }

    void handOver(int me) {
        Mailbox& box = boxes_[std::size_t(me)];
        for (std::size_t to = 0; to < boxes_.size(); ++to) {
            std::vector<Message>& batch = box.outbox[to];
            if (batch.empty()) continue;
            Mailbox& recipient = boxes_[to];
            bool wake = false;
            {
                const std::lock_guard<std::mutex> lock(recipient.mutex);
                recipient.inbox.insert(recipient.inbox.end(), batch.begin(), batch.end());
                recipient.mail.store(true, std::memory_order_release);
                if (recipient.idle) {
                    recipient.idle = false;
                    active_.fetch_add(1, std::memory_order_acq_rel);
                }
                wake = recipient.sleeping;
            }
            if (wake) recipient.woken.notify_one();
            batch.clear();
        }
        box.unsent = false;
    }

    // Under box.mutex.
    static bool take(Mailbox& box, std::vector<Message>& received) {
        box.mail.store(false, std::memory_order_relaxed);
        if (box.inbox.empty()) return false;
        received.clear();
        received.swap(box.inbox);
        return true;
    }

    static constexpr int kLooks = 64;  // yields before an idle thread sleeps

    std::vector<Mailbox> boxes_;  // per thread
    alignas(64) std::atomic<int> active_;
    std::atomic<bool> finished_{false}, stopped_{false};
};

}  // namespace isotrack::detail
