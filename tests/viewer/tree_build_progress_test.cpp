// The viewer's worker shows a contour tree build's phase and fraction, and a
// request for another volume cancels the build instead of waiting for it.
#include <catch2/catch.hpp>

#include <chrono>
#include <thread>

#include "viewer/extraction_worker.h"

using namespace isotrack;
using namespace isotrack::viewer;

namespace {

ExtractionRequest request(std::uint64_t generation, const char* field, Method method) {
    ExtractionRequest r;
    r.generation = generation;
    r.source = VolumeSource::field(field);
    r.method = method;
    return r;
}

}  // namespace

TEST_CASE("a contour tree build shows its progress and a new volume cancels it", "[viewer][worker]") {
    ExtractionWorker worker(2, defaultMemoryBudget());
    worker.submit(request(1, "gyroid:160", Method::Tree));
    // Wait until the build reports a phase of its own.
    WorkerProgress seen;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (std::chrono::steady_clock::now() < deadline) {
        seen = worker.progress();
        if (seen.what.rfind("building the contour tree: sweeping", 0) == 0) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    REQUIRE(seen.what.rfind("building the contour tree: sweeping", 0) == 0);
    CHECK(seen.fraction >= 0.1f);
    CHECK(seen.fraction < 1.0f);
    // Another volume: the build stops, and the next result is the new volume's.
    worker.submit(request(2, "blobs:32", Method::All));
    std::optional<ExtractionResult> result;
    while (!result && std::chrono::steady_clock::now() < deadline) {
        result = worker.poll();
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    REQUIRE(result);
    CHECK(result->generation == 2);
    CHECK(result->error.empty());
    CHECK(worker.cancelledCount() == 1);
}
