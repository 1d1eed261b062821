// Tracking on several threads: how the volume's tiles are shared out to the
// threads, and the surface walked on every thread count from 1 to 16.
#include <catch2/catch.hpp>

#include <fstream>
#include <set>
#include <string>

#include "core/mesh_checks.h"
#include "extract/common/sparse_blocks.h"
#include "isotrack/continuation.h"
#include "isotrack/extract.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/tracking.h"

using namespace isotrack;
using detail::SparseBlocks;
using isotrack::testing::triangleSet;
using isotrack::testing::vertexEdgeSet;

namespace {

// Every thread count from 1 to 16 gives the one-thread surface: the same
// triangles (as crossed-edge triples; the vertex order follows the walk) and
// the same figures.
void requireSameOnEveryThreadCount(const Volume& volume, double iso, const GridEdge& seed) {
    const Surface one = trackSurface(volume, iso, seed);
    REQUIRE(one.stats.cellsVisited > 8192);  // more than a walk on several threads walks alone first
    const auto triangles = triangleSet(one.mesh, volume.dims());
    for (int threads = 2; threads <= 16; ++threads) {
        INFO(threads << " threads");
        const Surface many = trackSurface(volume, iso, seed, TableKind::Consistent, threads);
        CHECK(many.stats.triangles == one.stats.triangles);
        CHECK(many.stats.vertices == one.stats.vertices);
        CHECK(many.stats.cellsVisited == one.stats.cellsVisited);
        CHECK(many.stats.closed == one.stats.closed);
        CHECK(many.stats.area == Approx(one.stats.area).epsilon(1e-12));
        CHECK(vertexEdgeSet(many.mesh, volume.dims()).size() == many.mesh.vertices.size());  // welded
        CHECK(triangleSet(many.mesh, volume.dims()) == triangles);
    }
}

}  // namespace

TEST_CASE("tiles: the largest that gives each thread four diagonal planes", "[core][tracking]") {
    // The CT skull's volume: 8 planes of 64^3 tiles, 18 of 32^3, 37 of 16^3, 76 of 8^3.
    const Dims ct{256, 256, 108};
    CHECK(SparseBlocks::ownerShift(ct, 1) == 6);
    CHECK(SparseBlocks::ownerShift(ct, 2) == 6);
    CHECK(SparseBlocks::ownerShift(ct, 4) == 5);
    CHECK(SparseBlocks::ownerShift(ct, 8) == 4);
    CHECK(SparseBlocks::ownerShift(ct, 16) == 3);
    CHECK(SparseBlocks::ownerShift(ct, 64) == 3);  // never below a block
    CHECK(SparseBlocks::usefulThreads(ct) == 19);
    CHECK(SparseBlocks::usefulThreads({8, 8, 8}) == 1);
    CHECK(SparseBlocks::usefulThreads({1024, 2, 2}) == 32);

    // Every thread owns tiles, and tiles meeting at a face belong to different threads.
    for (int threads = 1; threads <= 16; ++threads) {
        INFO(threads << " threads");
        const SparseBlocks blocks(ct, threads);
        const int side = 1 << SparseBlocks::ownerShift(ct, threads);
        std::set<int> owners;
        for (int z = 0; z < ct[2]; z += side)
            for (int y = 0; y < ct[1]; y += side)
                for (int x = 0; x < ct[0]; x += side) {
                    const int owner = blocks.ownerAt(x, y, z);
                    owners.insert(owner);
                    if (threads > 1 && x + side < ct[0]) CHECK(blocks.ownerAt(x + side, y, z) != owner);
                    if (threads > 1 && z + side < ct[2]) CHECK(blocks.ownerAt(x, y, z + side) != owner);
                    CHECK(blocks.ownerAt(x + side - 1, y + side - 1, z + side - 1) == owner);
                }
        CHECK(int(owners.size()) == threads);
    }
}

TEST_CASE("1 to 16 threads track the same surface", "[core][tracking]") {
    SECTION("a sphere across many tiles (at most 13 threads used)") {
        const Volume volume = makeField({"sphere", 150});
        REQUIRE(SparseBlocks::usefulThreads(volume.dims()) == 13);
        const Vec3d c = sphereFieldCenter(150);
        requireSameOnEveryThreadCount(volume, 0.0,
                                      nearestCrossedEdge(volume, 0.0, {c[0], c[1] + sphereFieldRadius(150), c[2]}));
    }
    SECTION("a small sphere: more threads than the volume has tiles for are not started") {
        const Volume volume = makeField({"sphere", 64});
        REQUIRE(SparseBlocks::usefulThreads(volume.dims()) == 5);
        const Vec3d c = sphereFieldCenter(64);
        requireSameOnEveryThreadCount(volume, 0.0,
                                      nearestCrossedEdge(volume, 0.0, {c[0] + sphereFieldRadius(64), c[1], c[2]}));
    }
}

TEST_CASE("CT skull: 1 to 16 threads track the same surface", "[core][tracking][ct]") {
    const std::string path = std::string(ISOTRACK_SOURCE_DIR) + "/assets/ct/cranium.nrrd";
    if (!std::ifstream(path)) {
        WARN("skipped: " << path << " is missing (scripts/get_ct.sh makes it)");
        return;
    }
    const Volume volume = loadVolume(path);
    // The largest surface at 400.5 is the skull (the benchmark's, 516k triangles).
    const GridEdge seed = extractAllSurfaces(volume, 400.5).front().mesh.vertexEdges[0];
    requireSameOnEveryThreadCount(volume, 400.5, seed);
}
