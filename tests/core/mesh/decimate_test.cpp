#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <set>

#include "core/mesh/mesh_distance.h"
#include "core/mesh/mesh_test_support.h"
#include "isotrack/errors.h"
#include "isotrack/mesh_processing.h"

using namespace isotrack;
using isotrack::test::ballVolume;
using isotrack::test::exhaustive;

TEST_CASE("decimating a sphere to a tenth keeps it closed and within a voxel", "[core][mesh]") {
    Surface surface = exhaustive(makeField({"sphere", 64}), 0.0);
    REQUIRE(surface.stats.closed);
    const Mesh original = surface.mesh;
    MeshProcessing decimate;
    decimate.decimateRatio = 0.1;
    processSurface(surface, decimate);
    CHECK(surface.mesh.triangleCount() <= std::size_t(0.11 * double(original.triangleCount())));
    CHECK(surface.mesh.triangleCount() >= std::size_t(0.05 * double(original.triangleCount())));
    CHECK(surface.stats.closed);
    CHECK(surface.stats.vertices == surface.mesh.vertices.size());
    CHECK(test::hausdorff(original, surface.mesh) < 1.0);
}

TEST_CASE("decimating a torus keeps its genus and closure", "[core][mesh]") {
    Surface surface = exhaustive(makeField({"torus", 64}), 0.0);
    REQUIRE(surface.stats.closed);
    measureTopology(surface);
    REQUIRE(*surface.stats.genus == 1);
    const Mesh original = surface.mesh;
    MeshProcessing decimate;
    decimate.decimateRatio = 0.1;
    processSurface(surface, decimate);
    CHECK(surface.stats.closed);
    CHECK(*surface.stats.genus == 1);
    CHECK(test::hausdorff(original, surface.mesh) < 1.0);
}

TEST_CASE("decimation keeps a cut surface's border where it was", "[core][mesh]") {
    Surface surface = exhaustive(ballVolume({30, 30, 30}, {3.3, 15.2, 14.6}, 11.0), 0.0);
    REQUIRE_FALSE(surface.stats.closed);
    std::set<std::array<float, 3>> border;
    for (const Vertex& v : surface.mesh.vertices)
        if (v.position[0] == 0.0f) border.insert({v.position[0], v.position[1], v.position[2]});
    const MeshQuality before = measureQuality(surface.mesh);
    decimateMesh(surface.mesh, 0.2);
    std::set<std::array<float, 3>> after;
    for (const Vertex& v : surface.mesh.vertices)
        if (v.position[0] == 0.0f) after.insert({v.position[0], v.position[1], v.position[2]});
    CHECK(after == border);
    CHECK(measureQuality(surface.mesh).boundaryEdges == before.boundaryEdges);
}

TEST_CASE("an error bound alone stops the decimation early", "[core][mesh]") {
    Surface surface = exhaustive(makeField({"sphere", 48}), 0.0);
    const Mesh original = surface.mesh;
    MeshProcessing tight;
    tight.decimateError = 0.05;
    processSurface(surface, tight);
    CHECK(surface.mesh.triangleCount() < original.triangleCount());
    CHECK(surface.mesh.triangleCount() > original.triangleCount() / 10);
    CHECK(test::hausdorff(original, surface.mesh) < 0.5);
    Mesh mesh;
    CHECK_THROWS_AS(decimateMesh(mesh, 1.5), InputError);
    CHECK_THROWS_AS(decimateMesh(mesh, 0.0), InputError);
    CHECK_THROWS_AS(decimateMesh(mesh, 0.5, -1.0), InputError);
}
