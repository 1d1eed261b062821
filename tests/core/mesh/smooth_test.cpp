#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "core/mesh/mesh_distance.h"
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
    const Surface extracted = exhaustive(mask, 0.5);
    REQUIRE(extracted.stats.closed);
    const double before = *extracted.stats.enclosedVolume, angleBefore = meanDihedralAngle(extracted.mesh);
    // Unbounded, and within the front ends' default tolerance (half a voxel).
    for (const bool bounded : {false, true}) {
        Surface surface = extracted;
        MeshProcessing smooth;
        smooth.smoothIterations = 20;
        if (bounded) applyVolumeDefaults(smooth, mask);
        processSurface(surface, smooth);
        REQUIRE(surface.stats.closed);
        CHECK(*surface.stats.enclosedVolume == Approx(before).epsilon(0.01));
        CHECK(meanDihedralAngle(surface.mesh) < 0.5 * angleBefore);
    }
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

namespace {

// A binary mask of a ball, spacing 0.8 x 0.8 x 1.2: terraces, unevenly spaced.
Volume maskBall() {
    const double r = 10.0;
    const Vec3d c{14.6, 14.7, 9.7};
    Volume mask({30, 30, 20}, ScalarType::Int16, {0.8, 0.8, 1.2});
    for (int z = 0; z < 20; ++z)
        for (int y = 0; y < 30; ++y)
            for (int x = 0; x < 30; ++x)
                mask.setValue(x, y, z, std::hypot(0.8 * (x - c[0]), 0.8 * (y - c[1]), 1.2 * (z - c[2])) <= r ? 1 : 0);
    return mask;
}

double moved(const Vertex& a, const Vertex& b) {
    return std::hypot(a.position[0] - b.position[0], a.position[1] - b.position[1], a.position[2] - b.position[2]);
}

}  // namespace

TEST_CASE("a smoothing tolerance bounds each move and the Hausdorff distance", "[core][mesh]") {
    const Volume mask = maskBall();
    const Surface surface = exhaustive(mask, 0.5);
    REQUIRE(surface.stats.closed);
    const double tolerance = 0.15;
    Mesh free = surface.mesh, bounded = surface.mesh;
    smoothMesh(free, 20);
    smoothMesh(bounded, 20, 0.1, tolerance);
    std::size_t pulledBack = 0;
    for (std::size_t v = 0; v < surface.mesh.vertices.size(); ++v) {
        const Vertex& original = surface.mesh.vertices[v];
        REQUIRE(moved(original, bounded.vertices[v]) <= tolerance + 1e-6);
        if (moved(original, free.vertices[v]) <= tolerance * (1.0 - 1e-5)) {
            REQUIRE(moved(free.vertices[v], bounded.vertices[v]) == 0.0);  // within it: as without one
        } else {
            ++pulledBack;
            // Pulled back along its move, to the tolerance.
            REQUIRE(moved(original, bounded.vertices[v]) == Approx(tolerance).epsilon(1e-4));
            double along = 0.0;
            for (int a = 0; a < 3; ++a)
                along += (free.vertices[v].position[a] - original.position[a]) *
                         (bounded.vertices[v].position[a] - original.position[a]);
            REQUIRE(along / (moved(original, free.vertices[v]) * tolerance) == Approx(1.0).epsilon(1e-4));
        }
    }
    CHECK(pulledBack > surface.mesh.vertices.size() / 10);  // the bound is at work
    CHECK(test::hausdorff(free, surface.mesh) > 1.5 * tolerance);
    CHECK(test::hausdorff(bounded, surface.mesh) <= tolerance + 1e-5);
}

TEST_CASE("front ends' defaults: half the smallest spacing to smooth, 0.98 to decimate", "[core][mesh]") {
    const Volume mask = maskBall();
    MeshProcessing p;
    applyVolumeDefaults(p, mask);
    CHECK_FALSE(p.smoothTolerance);
    CHECK_FALSE(p.decimateError);
    p.smoothIterations = 20;
    p.decimateRatio = 0.5;
    applyVolumeDefaults(p, mask);
    CHECK(*p.smoothTolerance == Approx(0.4));
    CHECK(*p.decimateError == Approx(0.784));
    p.smoothTolerance = 2.0;
    applyVolumeDefaults(p, mask);
    CHECK(*p.smoothTolerance == 2.0);  // a given one stays

    // processSurface uses it: every vertex within it.
    Surface surface = exhaustive(mask, 0.5);
    const Mesh before = surface.mesh;
    MeshProcessing smooth;
    smooth.smoothIterations = 20;
    smooth.smoothTolerance = 0.1;
    processSurface(surface, smooth);
    for (std::size_t v = 0; v < before.vertices.size(); ++v)
        REQUIRE(moved(before.vertices[v], surface.mesh.vertices[v]) <= 0.1 + 1e-6);
    CHECK(surface.stats.closed);
}

TEST_CASE("smoothing refuses iterations, pass bands and tolerances it cannot use", "[core][mesh]") {
    Mesh mesh;
    CHECK_THROWS_AS(smoothMesh(mesh, 0), InputError);
    CHECK_THROWS_AS(smoothMesh(mesh, 10, 0.0), InputError);
    CHECK_THROWS_AS(smoothMesh(mesh, 10, 2.0), InputError);
    CHECK_THROWS_AS(smoothMesh(mesh, 10, 0.1, 0.0), InputError);
    CHECK_THROWS_AS(smoothMesh(mesh, 10, 0.1, -1.0), InputError);
    MeshProcessing bad;
    bad.smoothIterations = -1;
    CHECK_THROWS_AS(checkMeshProcessing(bad), InputError);
    MeshProcessing badTolerance;
    badTolerance.smoothIterations = 5;
    badTolerance.smoothTolerance = 0.0;
    CHECK_THROWS_AS(checkMeshProcessing(badTolerance), InputError);
}
