#pragma once
// Running work on a few threads.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "worker_pool.h"

namespace isotrack::detail {

// The first exception of several threads, kept to be rethrown on the calling one.
class FirstFailure {
public:
    // From a catch block.
    void record() {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (!failure_) failure_ = std::current_exception();
    }
    void rethrowIfAny() const {
        if (failure_) std::rethrow_exception(failure_);
    }

private:
    std::mutex mutex_;
    std::exception_ptr failure_;
};

// Runs fn(state, i) for i in [0, count) on `threads` threads (the calling one
// and kept ones, see WorkerPool), handing out indices in order, so that each
// thread's come to it in increasing order. Every thread that takes part makes a
// state of its own with make() before its first index. The first exception any
// iteration throws stops the hand-out and is rethrown on the calling thread
// once every thread has stopped.
template <class Make, class Fn>
void parallelForWithState(int count, int threads, Make&& make, Fn&& fn) {
    if (count <= 0) return;
    if (threads <= 1 || count <= 1) {
        auto state = make();
        for (int i = 0; i < count; ++i) fn(state, i);
        return;
    }
    std::atomic<int> next{0};
    FirstFailure failure;
    auto work = [&] {
        try {
            int i = next++;
            if (i >= count) return;
            auto state = make();
            for (; i < count; i = next++) fn(state, i);
        } catch (...) {
            next = count;
            failure.record();
        }
    };
    const int helpers = std::min(threads, count) - 1;
    using Work = decltype(work);
    if (!WorkerPool::shared().run(helpers, {[](void* w) { (*static_cast<Work*>(w))(); }, &work})) {
        // The pool is busy (another thread's step, or this one nested in a step): threads of its own.
        std::vector<std::thread> pool;
        try {
            for (int t = 0; t < helpers; ++t) pool.emplace_back(work);
        } catch (const std::system_error&) {
            // No more threads to be had: the ones started, and this one, do the work.
        }
        work();
        for (auto& thread : pool) thread.join();
    }
    failure.rethrowIfAny();
}

// Runs fn(i) for i in [0, count) on `threads` threads, as parallelForWithState.
template <class Fn>
void parallelFor(int count, int threads, Fn&& fn) {
    parallelForWithState(
        count, threads, [] { return 0; }, [&](int, int i) { fn(i); });
}

// Runs fn(i) for every i in [0, count) at once, each on a thread of its own
// (kept ones where the pool is free), for parts that wait on one another. When a part
// throws, or a thread cannot be started, abandon() lets the running parts stop;
// the first failure is rethrown once every thread has.
template <class Fn, class Abandon>
void runTogether(int count, Fn&& fn, Abandon&& abandon) {
    FirstFailure failure;
    auto part = [&](int i) {
        try {
            fn(i);
        } catch (...) {
            failure.record();
            abandon();
        }
    };
    // Kept threads each run one part, all at once; starting 15 threads took
    // longer than a tracked skull's share of work per thread.
    std::atomic<int> next{0};
    auto job = [&] { part(next++); };
    using Job = decltype(job);
    if (count > 1 && WorkerPool::shared().run(count - 1, {[](void* j) { (*static_cast<Job*>(j))(); }, &job})) {
        failure.rethrowIfAny();
        return;
    }
    std::vector<std::thread> pool;
    try {
        for (int i = 1; i < count; ++i) pool.emplace_back(part, i);
    } catch (...) {
        abandon();
        for (auto& thread : pool) thread.join();
        throw;
    }
    part(0);
    for (auto& thread : pool) thread.join();
    failure.rethrowIfAny();
}

}  // namespace isotrack::detail
