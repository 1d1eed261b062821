#pragma once
// Threads kept from one parallel step to the next.
//
// An extraction runs several short parallel steps in a row (the exhaustive
// pass's counting and writing, then numbering and splitting its surfaces), and a
// live isovalue change runs it again and again. Starting and joining threads for
// a step took about 60 us on a 2-core machine, eight times per extraction of
// every surface; kept threads, which spin briefly before they sleep, start a step
// in a few microseconds.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

namespace isotrack::detail {

class WorkerPool {
public:
    // What every thread taking part in a step runs; it must not throw.
    struct Job {
        void (*run)(void* context);
        void* context;
    };

    // The process's pool.
    static WorkerPool& shared();

    // Runs job on the calling thread and on `helpers` kept threads at once, and
    // returns when all have finished. Returns false, running nothing, when the
    // pool is busy (a step of another thread, or this call is nested in a step)
    // or no helper thread can be started: the caller then starts threads of its own.
    bool run(int helpers, Job job);

    ~WorkerPool();

private:
    WorkerPool() = default;
    void work(int index);
    bool grow(int helpers);

    std::mutex claim_;  // held by the thread whose step runs
    std::mutex mutex_;  // for sleeping and waking
    std::condition_variable wake_, done_;
    std::vector<std::thread> threads_;
    // The step's number and how many helpers take part, as step << 16 | helpers,
    // so that a helper learns both at once.
    std::atomic<std::uint64_t> step_{0};
    std::atomic<int> running_{0};  // helpers of the current step not finished yet
    Job job_{};
    bool stop_ = false;
};

}  // namespace isotrack::detail
