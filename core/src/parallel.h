#pragma once
// Running a loop's iterations on a few threads.
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace isotrack::detail {

// Runs fn(i) for i in [0, count) on `threads` threads, handing out indices in order.
template <class Fn>
void parallelFor(int count, int threads, Fn&& fn) {
    if (threads <= 1 || count <= 1) {
        for (int i = 0; i < count; ++i) fn(i);
        return;
    }
    std::atomic<int> next{0};
    auto work = [&] {
        for (int i = next++; i < count; i = next++) fn(i);
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min(threads, count); ++t) pool.emplace_back(work);
    work();
    for (auto& thread : pool) thread.join();
}

}  // namespace isotrack::detail
