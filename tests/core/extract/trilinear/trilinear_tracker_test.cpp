#include <catch2/catch.hpp>

#include <cstring>
#include <random>

#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/tracking.h"

using namespace isotrack;

namespace {

Volume randomVolume(int n, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    Volume volume({n, n, n}, ScalarType::Float32);
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) volume.setValue(x, y, z, value(random));
    return volume;
}

bool sameVertex(const Vertex& a, const Vertex& b) {
    return std::memcmp(a.position, b.position, sizeof a.position) == 0 &&
           std::memcmp(a.normal, b.normal, sizeof a.normal) == 0;
}

// Grows the surface from `seed` `budget` pieces at a time and requires the steps'
// ranges, laid end to end, to be trackSurface's mesh: the same vertices, grid
// edges and indices in the same order, with the same figures at the end.
void requireStepsMakeTheTrackedSurface(const Volume& volume, double iso, const GridEdge& seed, std::size_t budget) {
    const Surface whole = trackSurface(volume, iso, seed, TableKind::Trilinear);
    SurfaceTracker tracker(volume, iso, TableKind::Trilinear);
    tracker.start(seed);
    std::size_t vertices = 0, indices = 0, cells = 0, steps = 0;
    while (!tracker.done()) {
        const SurfaceTracker::Step step = tracker.step(budget);
        REQUIRE(step.firstVertex == vertices);
        REQUIRE(step.firstIndex == indices);
        CHECK(step.cellsVisited <= budget);
        CHECK(step.indexCount % 3 == 0);
        vertices += step.vertexCount;
        indices += step.indexCount;
        cells += step.cellsVisited;
        ++steps;
        // Every index of a step names a vertex uploaded by then.
        for (std::size_t i = step.firstIndex; i < indices; ++i) REQUIRE(tracker.mesh().indices[i] < vertices);
        const SurfaceStats sofar = tracker.stats();
        CHECK(sofar.triangles == indices / 3);
        CHECK(sofar.cellsVisited == cells);
    }
    if (whole.mesh.triangleCount() > 4 * budget) CHECK(steps > 1);
    const SurfaceStats grown = tracker.stats();
    const Mesh& mesh = tracker.mesh();
    REQUIRE(mesh.vertices.size() == whole.mesh.vertices.size());
    REQUIRE(mesh.indices.size() == whole.mesh.indices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        REQUIRE(sameVertex(mesh.vertices[v], whole.mesh.vertices[v]));
        REQUIRE(GridEdge(mesh.vertexEdges[v]) == GridEdge(whole.mesh.vertexEdges[v]));
    }
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) REQUIRE(mesh.indices[i] == whole.mesh.indices[i]);
    CHECK(grown.area == Approx(whole.stats.area).epsilon(1e-9));
    CHECK(grown.touchesBorder == whole.stats.touchesBorder);
    const Surface taken = tracker.takeSurface();
    CHECK(taken.stats.triangles == whole.stats.triangles);
    CHECK(taken.stats.cellsVisited == whole.stats.cellsVisited);
    CHECK(taken.stats.cellsVisited == cells);
    CHECK(taken.stats.closed == whole.stats.closed);
    CHECK(taken.stats.area == whole.stats.area);
}

}  // namespace

TEST_CASE("with the trilinear table, a surface grown in steps is the tracked surface", "[core][tracking][trilinear]") {
    SECTION("sphere, closed") {
        const Volume volume = makeField({"sphere", 40});
        const GridEdge seed = nearestCrossedEdge(volume, 0.0, {0.0, 20.0, 20.0});
        requireStepsMakeTheTrackedSurface(volume, 0.0, seed, 50);
    }
    SECTION("gyroid, cut by the border") {
        const Volume volume = makeField({"gyroid", 32});
        const GridEdge seed = nearestCrossedEdge(volume, 0.0, {16.0, 16.0, 16.0});
        requireStepsMakeTheTrackedSurface(volume, 0.0, seed, 300);
    }
    SECTION("random, with tunnels and interior vertices") {
        const Volume volume = randomVolume(16, 5);
        const Surface largest = extractAllSurfaces(volume, 0.0, TableKind::Trilinear).front();
        std::size_t v = 0;
        while (GridEdge(largest.mesh.vertexEdges[v]).axis == kCellInterior) ++v;
        requireStepsMakeTheTrackedSurface(volume, 0.0, largest.mesh.vertexEdges[v], 7);
        requireStepsMakeTheTrackedSurface(volume, 0.0, largest.mesh.vertexEdges[v], 1);
    }
}

TEST_CASE("with the trilinear table, the tracker refuses a seed edge the surface does not cross",
          "[core][tracking][trilinear]") {
    const Volume volume = makeField({"sphere", 16});
    SurfaceTracker tracker(volume, 0.0, TableKind::Trilinear);
    CHECK(tracker.done());
    CHECK(tracker.mesh().vertices.empty());
    CHECK_THROWS_AS(tracker.start(GridEdge{0, 0, 0, 0}), InputError);
    CHECK_THROWS_AS(tracker.start(GridEdge{15, 0, 0, 0}), InputError);
}
