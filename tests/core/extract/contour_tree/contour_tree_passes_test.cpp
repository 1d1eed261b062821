// The contour tree's threaded passes (contour_tree_build.h: the sort, the class
// pass, the arcs) run their parts on core's kept threads: a part that throws,
// here Cancelled from a build asked to stop before the pass, hands its exception
// to the calling thread, on any number of threads, and the next build is whole.
#include <catch2/catch.hpp>

#include <atomic>
#include <cstdint>
#include <utility>
#include <vector>

#include "extract/contour_tree/contour_tree_build.h"
#include "isotrack/contour_tree.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"

using namespace isotrack;

namespace {

// A progress whose cancel is raised already: the pass's parts meet it at their first check.
struct Stopped {
    std::atomic<bool> cancel{true};
    ContourTreeProgress progress;
    Stopped() { progress.cancel = &cancel; }
    detail::BuildProgress build() { return detail::BuildProgress(&progress); }
};

// The field as float64, for the sort's path of 8-byte samples.
Volume asDoubles(const Volume& volume) {
    Volume out(volume.dims(), ScalarType::Float64);
    const Dims& d = volume.dims();
    for (int z = 0; z < d[2]; ++z)
        for (int y = 0; y < d[1]; ++y)
            for (int x = 0; x < d[0]; ++x) out.setValue(x, y, z, volume.value(x, y, z));
    return out;
}

std::vector<std::uint32_t> orderOf(const detail::SortedSamples& sorted) {
    const detail::Slice<std::uint32_t> order = sorted.order();
    return {order.begin(), order.end()};
}

}  // namespace

TEST_CASE("contour tree passes rethrow a part's Cancelled on the calling thread", "[core][contour-tree][threads]") {
    // 64^3 samples: above the 2^16 below which the sort and the arcs use one part.
    const Volume volume = makeField({"gyroid", 64});
    const detail::BuildProgress unwatched(nullptr);
    const std::vector<std::uint32_t> order = orderOf(detail::sortSamples(volume, 1, unwatched));
    const detail::Buffer<std::uint8_t> classes = detail::classifySamples(volume, 1, unwatched);
    const ContourTree tree = computeContourTree(volume, 1);
    for (const int threads : {1, 2, 4}) {
        INFO(threads << " threads");
        {  // the sort
            Stopped stopped;
            CHECK_THROWS_AS(detail::sortSamples(volume, threads, stopped.build()), Cancelled);
            CHECK_THROWS_AS(detail::sortSamples(asDoubles(volume), threads, stopped.build()), Cancelled);
            CHECK(orderOf(detail::sortSamples(volume, threads, unwatched)) == order);
        }
        {  // the class pass
            Stopped stopped;
            CHECK_THROWS_AS(detail::classifySamples(volume, threads, stopped.build()), Cancelled);
            CHECK(detail::classifySamples(volume, threads, unwatched) == classes);
        }
        {  // the arcs
            Stopped stopped;
            detail::AugmentedTree augmented = detail::augmentedContourTree(volume, threads);
            CHECK_THROWS_AS(detail::compressContourTree(volume, std::move(augmented), threads, stopped.build()),
                            Cancelled);
            const ContourTree again =
                detail::compressContourTree(volume, detail::augmentedContourTree(volume, threads), threads, unwatched);
            CHECK(again.arcs.size() == tree.arcs.size());
            CHECK(again.samples == tree.samples);
            CHECK(again.nodeArcs == tree.nodeArcs);
        }
    }
}

TEST_CASE("the sort counts its passes as the Sorting phase's progress", "[core][contour-tree][threads]") {
    // gyroid:64 as float32 (the pairs' sort: 3 passes of 11 bits, the counting
    // read and the moves) and as float64 (one-thread sort, 4 passes of 16 bits).
    const Volume floats = makeField({"gyroid", 64});
    const Volume doubles = asDoubles(floats);
    for (const Volume* input : {&floats, &doubles}) {
        for (const int threads : {1, 2, 4}) {
            INFO((input == &doubles ? "float64, " : "float32, ") << threads << " threads");
            ContourTreeProgress progress;
            const detail::BuildProgress build(&progress);
            build.start(ContourTreeProgress::Phase::Sorting, 0);
            detail::sortSamples(*input, threads, build);
            const std::uint64_t n = input->sampleCount();
            CHECK(progress.total.load() >= 2 * n);  // a read and at least one move
            CHECK(progress.total.load() % n == 0);
            CHECK(progress.done.load() == progress.total.load());
            CHECK(progress.fraction() == Approx(0.15));  // the end of the sort's share
        }
    }
}
