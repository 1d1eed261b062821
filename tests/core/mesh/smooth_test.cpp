#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "core/mesh/mesh_test_support.h"
#include "isotrack/errors.h"
#include "isotrack/mesh_processing.h"

using namespace isotrack;
using isotrack::test::ballVolume;
using isotrack::test::exhaustive;
using isotrack::test::meanDihedralAngle;

TEST_CASE("windowed-sinc smoothing keeps a sphere's volume and flattens its terraces", "[core][mesh]") {
    const int n = 48;
    const Volume sphere = makeField({"sphere", n});
    Surface surface = exhaustive(sphere, 0.0);
    REQUIRE(surface.stats.closed);
    const double before = *surface.stats.enclosedVolume;
    const double angleBefore = meanDihedralAngle(surface.mesh);
    const Mesh original = surface.mesh;

    MeshProcessing smooth;
    smooth.smoothIterations = 20;
    processSurface(surface, smooth);
    REQUIRE(surface.stats.closed);
    CHECK(*surface.stats.enclosedVolume == Approx(before).epsilon(0.01));
    const double r = sphereFieldRadius(n);
    CHECK(*surface.stats.enclosedVolume == Approx(4.0 / 3.0 * 3.14159265358979 * r * r * r).epsilon(0.01));
    CHECK(meanDihedralAngle(surface.mesh) < 1.25 * angleBefore);  // already smooth: little to gain

    // Every vertex stays near the sphere; normals are unit and point outwards
    // (from above the isovalue, the inside, towards below).
    const Vec3d c = sphereFieldCenter(n);
    for (const Vertex& v : surface.mesh.vertices) {
        const double d[3] = {v.position[0] - c[0], v.position[1] - c[1], v.position[2] - c[2]};
        const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        REQUIRE(length == Approx(r).margin(0.25));
        const double nl = std::sqrt(v.normal[0] * v.normal[0] + v.normal[1] * v.normal[1] + v.normal[2] * v.normal[2]);
        REQUIRE(nl == Approx(1.0).margin(1e-5));
        REQUIRE((d[0] * v.normal[0] + d[1] * v.normal[1] + d[2] * v.normal[2]) / length > 0.9);
    }
    // The same orientation as the extractor's gradient normals.
    double agreement = 0.0;
    for (std::size_t i = 0; i < original.vertices.size(); ++i)
        for (int a = 0; a < 3; ++a) agreement += original.vertices[i].normal[a] * surface.mesh.vertices[i].normal[a];
    CHECK(agreement / double(original.vertices.size()) > 0.95);
}

TEST_CASE("smoothing flattens the terraces of a segmented ball", "[core][mesh]") {
    // Samples rounded to whole numbers and iso 0.5: every vertex at an edge's
    // midpoint, a staircase as a binary mask gives.
    const double r = 12.0;
    const Vec3d c{15.3, 15.6, 15.2};
    Volume mask({32, 32, 32}, ScalarType::Int16);
    for (int z = 0; z < 32; ++z)
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 32; ++x) mask.setValue(x, y, z, std::hypot(x - c[0], y - c[1], z - c[2]) <= r ? 1 : 0);
    Surface surface = exhaustive(mask, 0.5);
    REQUIRE(surface.stats.closed);
    const double before = *surface.stats.enclosedVolume, angleBefore = meanDihedralAngle(surface.mesh);
    MeshProcessing smooth;
    smooth.smoothIterations = 20;
    processSurface(surface, smooth);
    REQUIRE(surface.stats.closed);
    CHECK(*surface.stats.enclosedVolume == Approx(before).epsilon(0.01));
    CHECK(meanDihedralAngle(surface.mesh) < 0.5 * angleBefore);
}

TEST_CASE("smoothing holds the border of a cut surface fixed", "[core][mesh]") {
    const Volume ball = ballVolume({20, 20, 20}, {3.3, 10.2, 9.6}, 7.0);
    Surface surface = exhaustive(ball, 0.0);
    REQUIRE_FALSE(surface.stats.closed);
    const Mesh before = surface.mesh;
    smoothMesh(surface.mesh, 20);
    std::size_t fixed = 0, moved = 0;
    for (std::size_t v = 0; v < before.vertices.size(); ++v) {
        const bool onBorderPlane = before.vertices[v].position[0] == 0.0f;  // the cut at x = 0
        bool same = true;
        for (int a = 0; a < 3; ++a)
            same = same && before.vertices[v].position[a] == surface.mesh.vertices[v].position[a];
        if (onBorderPlane) {
            REQUIRE(same);
            ++fixed;
        } else {
            moved += !same;
        }
    }
    CHECK(fixed > 20);
    CHECK(moved > before.vertices.size() / 2);
}

TEST_CASE("smoothing refuses iterations and pass bands it cannot use", "[core][mesh]") {
    Mesh mesh;
    CHECK_THROWS_AS(smoothMesh(mesh, 0), InputError);
    CHECK_THROWS_AS(smoothMesh(mesh, 10, 0.0), InputError);
    CHECK_THROWS_AS(smoothMesh(mesh, 10, 2.0), InputError);
    MeshProcessing bad;
    bad.smoothIterations = -1;
    CHECK_THROWS_AS(checkMeshProcessing(bad), InputError);
}
