// Tracking with the 3-state table on several threads: on surfaces of more
// pieces than the first thread walks alone, so that several threads walk,
// 2, 3, 5 and 8 threads give the one-thread surface's triangles over the
// same vertices, closed as it is, of its area and enclosed volume.
#include <catch2/catch.hpp>

#include <cstddef>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "core/extract/snap/random_integers.h"
#include "core/extract/snap/same_triangles.h"
#include "extract/common/sparse_blocks.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/tracking.h"

using namespace isotrack;

namespace {

// Of the crossed grid edges nearest four points on the volume's diagonal, the
// one on the surface of most pieces (a seed for a surface many threads walk).
GridEdge largeSurfaceSeed(const Volume& v, double iso) {
    GridEdge best{};
    std::size_t most = 0;
    for (int step = 1; step <= 4; ++step) {
        Vec3d point{};
        for (std::size_t k = 0; k < 3; ++k) point[k] = v.origin()[k] + step / 5.0 * (v.dims()[k] - 1) * v.spacing()[k];
        const GridEdge seed = nearestCrossedEdge(v, iso, point);
        const std::size_t pieces = trackSurface(v, iso, seed, TableKind::Snap, 1).stats.cellsVisited;
        if (pieces > most) most = pieces, best = seed;
    }
    return best;
}

void requireSameOnThreads(const Volume& v, double iso, const GridEdge& seed) {
    const Surface one = trackSurface(v, iso, seed, TableKind::Snap, 1);
    // More pieces than a walk on several threads walks alone first.
    REQUIRE(one.stats.cellsVisited > 8192);
    for (const int threads : {2, 3, 5, 8}) {
        INFO(threads << " threads");
        const Surface many = trackSurface(v, iso, seed, TableKind::Snap, threads);
        CHECK(many.stats.triangles == one.stats.triangles);
        CHECK(many.stats.vertices == one.stats.vertices);
        CHECK(many.stats.cellsVisited == one.stats.cellsVisited);
        CHECK(many.stats.closed == one.stats.closed);
        CHECK(many.stats.touchesBorder == one.stats.touchesBorder);
        CHECK(many.stats.area == Approx(one.stats.area).epsilon(1e-9));
        REQUIRE(many.stats.enclosedVolume.has_value() == one.stats.enclosedVolume.has_value());
        if (one.stats.enclosedVolume)
            CHECK(*many.stats.enclosedVolume == Approx(*one.stats.enclosedVolume).epsilon(1e-9));
        CHECK(test::sameTriangles(many.mesh, one.mesh));
    }
}

}  // namespace

TEST_CASE("snap: 2, 3, 5 and 8 threads track the one-thread surface", "[core][snap][threads][tracking]") {
    SECTION("noise:64") {
        const Volume v = makeField({"noise", 64});
        const double iso = fieldDefaultIso("noise");
        requireSameOnThreads(v, iso, largeSurfaceSeed(v, iso));
    }
    SECTION("random integers, many samples at the isovalue or snapped to it") {
        std::mt19937 rng(43);
        const Volume v = test::randomIntegers({200, 40, 32}, rng, 3);
        REQUIRE(detail::SparseBlocks::usefulThreads(v.dims()) == 8);  // 8 threads all walk
        for (const double iso : {0.0, 0.5}) {
            INFO("iso " << iso);
            requireSameOnThreads(v, iso, largeSurfaceSeed(v, iso));
        }
    }
}

TEST_CASE("snap CT skull: 2, 3, 5 and 8 threads track the one-thread surface", "[core][snap][threads][ct]") {
    const std::string path = std::string(ISOTRACK_SOURCE_DIR) + "/assets/ct/cranium.nrrd";
    if (!std::ifstream(path)) {
        WARN("skipped: " << path << " is missing (scripts/get_ct.sh makes it)");
        return;
    }
    const Volume v = loadVolume(path);
    // The skull from the benchmark's seed point at its isovalue's isovalue, and at an integer one: samples exactly at
    // it.
    for (const double iso : {400.5, 400.0}) {
        INFO("iso " << iso);
        requireSameOnThreads(v, iso, nearestCrossedEdge(v, iso, {122, 122, 160}));
    }
}
