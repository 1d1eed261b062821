#include "cli/tree_progress.h"

#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <thread>

namespace isotrack::cli {

namespace {

void showProgress(const ContourTreeProgress& progress) {
    std::fprintf(stderr, "\risotrack: contour tree: %-34s %3d%%", contourTreePhaseName(progress.phase.load()),
                 int(progress.fraction() * 100.0));
    std::fflush(stderr);
}

}  // namespace

ContourTree buildContourTree(const Volume& volume, int threads, std::array<double, 4>* phaseSeconds) {
    ContourTreeProgress progress;
    if (!isatty(fileno(stderr))) {
        ContourTree tree = computeContourTree(volume, threads, &progress);
        if (phaseSeconds) *phaseSeconds = progress.seconds;
        return tree;
    }
    std::mutex mutex;
    std::condition_variable wake;
    bool finished = false;
    std::thread shower([&] {
        std::unique_lock<std::mutex> lock(mutex);
        do showProgress(progress);
        while (!wake.wait_for(lock, std::chrono::milliseconds(100), [&] { return finished; }));
        std::fprintf(stderr, "\r\033[K");  // the line is cleared for what follows
        std::fflush(stderr);
    });
    auto stop = [&] {
        {
            const std::lock_guard<std::mutex> lock(mutex);
            finished = true;
        }
        wake.notify_one();
        shower.join();
    };
    try {
        ContourTree tree = computeContourTree(volume, threads, &progress);
        stop();
        if (phaseSeconds) *phaseSeconds = progress.seconds;
        return tree;
    } catch (...) {
        stop();
        throw;
    }
}

}  // namespace isotrack::cli
