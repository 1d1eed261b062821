#pragma once
// Running a loop's iterations on a few threads.
#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace isotrack::detail {

// Runs fn(i) for i in [0, count) on `threads` threads, handing out indices in
// order. The first exception any iteration throws stops the hand-out and is
// rethrown on the calling thread once every thread has stopped.
template <class Fn>
void parallelFor(int count, int threads, Fn&& fn) {
    if (threads <= 1 || count <= 1) {
        for (int i = 0; i < count; ++i) fn(i);
        return;
    }
    std::atomic<int> next{0};
    std::exception_ptr failure;
    std::mutex failureMutex;
    auto work = [&] {
        try {
            for (int i = next++; i < count; i = next++) fn(i);
        } catch (...) {
            next = count;
            const std::lock_guard<std::mutex> lock(failureMutex);
            if (!failure) failure = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    try {
        for (int t = 1; t < std::min(threads, count); ++t) pool.emplace_back(work);
    } catch (const std::system_error&) {
        // No more threads to be had: the ones started, and this one, do the work.
    }
    work();
    for (auto& thread : pool) thread.join();
    if (failure) std::rethrow_exception(failure);
}

}  // namespace isotrack::detail
