// A contour tree build reports its phases in order, ends Done at fraction 1,
// gives the same tree as without a watcher, and stops with Cancelled when asked.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "isotrack/contour_tree.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"

using namespace isotrack;

namespace {

Volume field(const char* spec) { return makeField(parseFieldSpec(spec)); }

}  // namespace

TEST_CASE("a watched build goes through its phases to Done and builds the same tree", "[core][contour-tree]") {
    const Volume volume = field("noise:48");
    const ContourTree plain = computeContourTree(volume, 2);
    ContourTreeProgress progress;
    std::atomic<bool> finished{false};
    std::vector<double> seen;
    std::vector<ContourTreeProgress::Phase> phases;
    std::thread watcher([&] {
        while (!finished.load()) {
            seen.push_back(progress.fraction());
            phases.push_back(progress.phase.load());
            std::this_thread::sleep_for(std::chrono::microseconds(50));
        }
    });
    const auto started = std::chrono::steady_clock::now();
    const ContourTree watched = computeContourTree(volume, 2, &progress);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    finished = true;
    watcher.join();
    // Each phase timed, together within the build's own time.
    CHECK(std::all_of(progress.seconds.begin(), progress.seconds.end(), [](double s) { return s > 0.0; }));
    CHECK(progress.seconds[0] + progress.seconds[1] + progress.seconds[2] + progress.seconds[3] <= wall);
    CHECK(progress.phase.load() == ContourTreeProgress::Phase::Done);
    CHECK(progress.fraction() == 1.0);
    CHECK(std::is_sorted(phases.begin(), phases.end()));
    CHECK(std::all_of(seen.begin(), seen.end(), [](double f) { return f >= 0.0 && f <= 1.0; }));
    CHECK(watched.arcs.size() == plain.arcs.size());
    CHECK(watched.samples == plain.samples);
    CHECK(std::string(contourTreePhaseName(ContourTreeProgress::Phase::Sweeping)) ==
          "sweeping the join and split trees");
}

TEST_CASE("a build asked to stop throws Cancelled", "[core][contour-tree]") {
    const Volume volume = field("gyroid:96");
    std::atomic<bool> cancel{true};
    ContourTreeProgress progress;
    progress.cancel = &cancel;
    CHECK_THROWS_AS(computeContourTree(volume, 2, &progress), Cancelled);
    CHECK(progress.phase.load() == ContourTreeProgress::Phase::Sorting);  // it stopped at the first check
    // Raised while the sweeps run (on two threads): the build stops within a stride.
    cancel = false;
    ContourTreeProgress later;
    later.cancel = &cancel;
    std::thread stopper([&] {
        while (later.phase.load() != ContourTreeProgress::Phase::Sweeping) std::this_thread::yield();
        cancel = true;
    });
    CHECK_THROWS_AS(computeContourTree(volume, 2, &later), Cancelled);
    stopper.join();
    CHECK(later.phase.load() != ContourTreeProgress::Phase::Done);
}

TEST_CASE("a build stopped in any phase on several threads throws Cancelled, and the next is whole",
          "[core][contour-tree][threads]") {
    using Phase = ContourTreeProgress::Phase;
    const Volume volume = field("gyroid:128");  // phases long enough for the stopper to come in time
    const ContourTree plain = computeContourTree(volume, 1);
    for (const int threads : {2, 4}) {
        for (const Phase phase : {Phase::Sweeping, Phase::Merging, Phase::Arcs}) {
            INFO(threads << " threads, stopped while " << contourTreePhaseName(phase));
            std::atomic<bool> cancel{false}, over{false};
            ContourTreeProgress progress;
            progress.cancel = &cancel;
            bool inTime = false;  // the stopper saw the phase itself, not a later one
            std::thread stopper([&] {
                Phase now = progress.phase.load();
                for (; now < phase && !over.load(); now = progress.phase.load()) std::this_thread::yield();
                inTime = now == phase;
                cancel = true;
            });
            bool cancelled = false;
            try {
                computeContourTree(volume, threads, &progress);
            } catch (const Cancelled&) {
                cancelled = true;
            }
            over = true;
            stopper.join();
            if (inTime) {
                CHECK(cancelled);
                CHECK(progress.phase.load() >= phase);  // not before it was asked
            } else {
                WARN("the stopper came after " << contourTreePhaseName(phase) << " at " << threads
                                               << " threads; not checked");
            }
        }
        // The kept threads that ran the cancelled parts build the next tree whole.
        const ContourTree again = computeContourTree(volume, threads);
        CHECK(again.arcs.size() == plain.arcs.size());
        CHECK(again.samples == plain.samples);
        CHECK(again.nodeArcs == plain.nodeArcs);
    }
}
