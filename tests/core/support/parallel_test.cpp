// The parallel steps the extractions run on: kept threads (WorkerPool) behind
// parallelFor, and the threads of its own a call starts when the pool is busy.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <stdexcept>
#include <thread>
#include <vector>

#include "support/parallel.h"

using namespace isotrack;

namespace {

// Runs parallelFor over `count` indices; true when each ran exactly once.
bool eachIndexOnce(int count, int threads) {
    std::vector<std::atomic<int>> runs(static_cast<std::size_t>(count));
    detail::parallelFor(count, threads, [&](int i) { runs[std::size_t(i)].fetch_add(1); });
    for (const std::atomic<int>& r : runs) {
        if (r.load() != 1) return false;
    }
    return true;
}

}  // namespace

TEST_CASE("parallelFor runs every index once, step after step", "[core][parallel]") {
    for (int threads : {1, 2, 3, 8}) {
        for (int step = 0; step < 200; ++step) {
            INFO("threads " << threads << ", step " << step);
            REQUIRE(eachIndexOnce(1 + step % 37, threads));
        }
    }
}

TEST_CASE("parallelForWithState gives each thread taking part its own state and increasing indices",
          "[core][parallel]") {
    struct State {
        int last = -1;
    };
    std::atomic<int> made{0}, outOfOrder{0};
    std::vector<std::atomic<int>> runs(500);
    detail::parallelForWithState(
        500, 4,
        [&] {
            ++made;
            return State{};
        },
        [&](State& state, int i) {
            if (i <= state.last) ++outOfOrder;
            state.last = i;
            runs[std::size_t(i)].fetch_add(1);
        });
    CHECK(outOfOrder.load() == 0);
    CHECK(made.load() >= 1);
    CHECK(made.load() <= 4);
    for (const std::atomic<int>& r : runs) CHECK(r.load() == 1);
}

TEST_CASE("parallelFor rethrows the first failure, and the next step runs", "[core][parallel]") {
    std::atomic<int> ran{0};
    auto failing = [&] {
        detail::parallelFor(64, 2, [&](int i) {
            ++ran;
            if (i == 5) throw std::runtime_error("index 5 failed");
        });
    };
    REQUIRE_THROWS_WITH(failing(), "index 5 failed");
    CHECK(ran.load() >= 1);
    CHECK(ran.load() <= 64);
    CHECK(eachIndexOnce(100, 2));
}

TEST_CASE("parallelFor nested in a step, or on two threads at once, runs every index once", "[core][parallel]") {
    SECTION("nested") {
        std::vector<std::atomic<int>> runs(16 * 16);
        detail::parallelFor(16, 2, [&](int outer) {
            detail::parallelFor(16, 2, [&](int inner) { runs[std::size_t(outer * 16 + inner)].fetch_add(1); });
        });
        for (const std::atomic<int>& r : runs) CHECK(r.load() == 1);
    }
    SECTION("two callers") {
        std::atomic<int> failures{0};
        auto caller = [&] {
            for (int step = 0; step < 300; ++step) {
                if (!eachIndexOnce(40, 2)) ++failures;
            }
        };
        std::thread other(caller);
        caller();
        other.join();
        CHECK(failures.load() == 0);
    }
}

TEST_CASE("runTogether runs every part at once, on kept threads or, nested, on its own", "[core][parallel]") {
    // Each part waits until all have started: it returns only if all run at once. It returns whether every
    // part ran exactly once; the assertions stay on the test's thread (Catch2's are not thread-safe).
    auto together = [](int count) {
        std::atomic<int> started{0};
        std::vector<std::atomic<int>> runs(static_cast<std::size_t>(count));
        detail::runTogether(
            count,
            [&](int i) {
                runs[std::size_t(i)].fetch_add(1);
                started.fetch_add(1);
                while (started.load() < count) std::this_thread::yield();
            },
            [] {});
        return std::all_of(runs.begin(), runs.end(), [](const std::atomic<int>& r) { return r.load() == 1; });
    };
    SECTION("alone") {
        for (int count : {1, 2, 16, 3}) CHECK(together(count));
    }
    SECTION("nested in a parallelFor step, the pool busy") {
        std::atomic<int> whole{0};
        detail::parallelFor(2, 2, [&](int) { whole.fetch_add(together(5) ? 1 : 0); });
        CHECK(whole.load() == 2);
    }
    SECTION("a part that throws is rethrown, and the others abandoned") {
        std::atomic<bool> abandoned{false};
        CHECK_THROWS_AS(detail::runTogether(
                            4,
                            [&](int i) {
                                if (i == 2) throw std::runtime_error("part 2");
                                while (!abandoned.load()) std::this_thread::yield();
                            },
                            [&] { abandoned.store(true); }),
                        std::runtime_error);
    }
}
