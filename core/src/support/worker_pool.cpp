// Kept threads for parallel steps (worker_pool.h).
//
// A step is published in one atomic word, its number and its helper count: a
// helper reads the job only in a step it takes part in, and the step does not
// end (nor can the next one replace the job) before every such helper has
// finished. Between steps, helpers spin for a while on that word, since the next
// step of an extraction usually follows within microseconds, then sleep on a
// condition variable.
#include "worker_pool.h"

#include <algorithm>
#include <chrono>
#include <system_error>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace isotrack::detail {
namespace {

constexpr auto kSpin = std::chrono::microseconds(200);
constexpr unsigned kHelperBits = 16;
constexpr std::uint64_t kHelperMask = (std::uint64_t(1) << kHelperBits) - 1;

void relax() {
#if defined(__SSE2__)
    _mm_pause();
#else
    std::this_thread::yield();
#endif
}

// Spins until ready() or kSpin has passed; true when ready.
template <class Ready>
bool spinUntil(Ready&& ready) {
    const auto until = std::chrono::steady_clock::now() + kSpin;
    for (;;) {
        for (int i = 0; i < 256; ++i) {
            if (ready()) return true;
            relax();
        }
        if (std::chrono::steady_clock::now() >= until) return ready();
    }
}

}  // namespace

WorkerPool& WorkerPool::shared() {
    static WorkerPool pool;
    return pool;
}

WorkerPool::~WorkerPool() {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (std::thread& thread : threads_) thread.join();
}

bool WorkerPool::grow(int helpers) {
    try {
        while (int(threads_.size()) < helpers) {
            const int index = int(threads_.size());
            threads_.emplace_back([this, index] { work(index); });
        }
    } catch (const std::system_error&) {
        // Keep the threads there are.
    }
    return !threads_.empty();
}

bool WorkerPool::run(int helpers, Job job) {
    const std::unique_lock<std::mutex> claimed(claim_, std::try_to_lock);
    if (!claimed.owns_lock() || helpers <= 0 || std::uint64_t(helpers) > kHelperMask || !grow(helpers)) return false;
    helpers = std::min(helpers, int(threads_.size()));
    job_ = job;
    running_.store(helpers, std::memory_order_relaxed);
    {
        const std::lock_guard<std::mutex> lock(mutex_);  // a helper going to sleep sees the step or is woken
        const std::uint64_t next = (step_.load(std::memory_order_relaxed) >> kHelperBits) + 1;
        step_.store(next << kHelperBits | std::uint64_t(helpers), std::memory_order_release);
    }
    wake_.notify_all();
    job.run(job.context);
    auto finished = [&] { return running_.load(std::memory_order_acquire) == 0; };
    if (!spinUntil(finished)) {
        std::unique_lock<std::mutex> lock(mutex_);
        done_.wait(lock, finished);
    }
    return true;
}

void WorkerPool::work(int index) {
    std::uint64_t seen = 0;
    for (;;) {
        auto published = [&] { return step_.load(std::memory_order_acquire) != seen; };
        if (!spinUntil(published)) {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || published(); });
            if (stop_) return;
        }
        seen = step_.load(std::memory_order_acquire);
        if (std::uint64_t(index) >= (seen & kHelperMask)) continue;  // not taking part
        job_.run(job_.context);
        if (running_.fetch_sub(1, std::memory_order_acq_rel) == 1) {
            const std::lock_guard<std::mutex> lock(mutex_);  // the caller is asleep or will see zero
            done_.notify_all();
        }
    }
}

}  // namespace isotrack::detail
