// Golden images of the renderer, drawn headless through OSMesa at 320x240.
// Metric, threshold and the update procedure: see gl_test_support.h.
#include <catch2/catch.hpp>

#include "gl_test_support.h"
#include "isotrack/fields.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"
#include "render/camera.h"

using namespace isotrack;

namespace {

Volume field(const std::string& spec) { return makeField(parseFieldSpec(spec)); }

std::vector<const Mesh*> pointersTo(const std::vector<Surface>& surfaces) {
    std::vector<const Mesh*> meshes;
    for (const Surface& surface : surfaces) meshes.push_back(&surface.mesh);
    return meshes;
}

}  // namespace

TEST_CASE("golden: a sphere, marching cubes", "[gl][golden]") {
    test::useHeadlessGl();
    const Volume volume = field("sphere:48");
    const Mesh mesh = marchingCubes(volume, fieldDefaultIso("sphere"));
    test::checkGolden("sphere", test::renderForGolden({&mesh}, volume));
}

TEST_CASE("golden: the blobs, every surface in its own colour", "[gl][golden][tracking]") {
    test::useHeadlessGl();
    const Volume volume = field("blobs:48");
    const std::vector<Surface> surfaces = extractAllSurfaces(volume, fieldDefaultIso("blobs"));
    REQUIRE(surfaces.size() > 1);
    test::checkGolden("blobs_all", test::renderForGolden(pointersTo(surfaces), volume));
}

TEST_CASE("golden: one tracked blob, the rest absent", "[gl][golden][tracking]") {
    test::useHeadlessGl();
    const Volume volume = field("blobs:64");
    const double iso = fieldDefaultIso("blobs");
    // Seeded nearest the centre, as `isotrack render --method track --seed 31.5,31.5,31.5` seeds.
    const Surface surface = trackSurface(volume, iso, nearestCrossedEdge(volume, iso, {31.5, 31.5, 31.5}));
    REQUIRE(surface.stats.closed);
    // Close enough for the blob to be large, far enough that its neighbours would
    // show if they were drawn. A stray surface may be small: allow only 0.1%.
    render::SnapshotOptions options;
    options.camera = render::parseCamera("-60,22,64,31.5,31.5,31.5");
    test::GoldenTolerance tolerance;
    tolerance.maxDifferentFraction = 0.001;
    test::checkGolden("blobs_track", test::renderForGolden({&surface.mesh}, volume, options), tolerance);
}

TEST_CASE("golden: wireframe over a coarse torus", "[gl][golden]") {
    test::useHeadlessGl();
    const Volume volume = field("torus:20");
    const Mesh mesh = marchingCubes(volume, fieldDefaultIso("torus"));
    render::SnapshotOptions options;
    options.wireframe = true;
    options.boundingBox = false;
    options.camera = render::parseCamera("-60,40,34,9.5,9.5,9.5");
    test::checkGolden("torus_wireframe", test::renderForGolden({&mesh}, volume, options));
}

TEST_CASE("golden: the selected surface is highlighted", "[gl][golden][tracking]") {
    test::useHeadlessGl();
    const Volume volume = field("blobs:48");
    const std::vector<Surface> surfaces = extractAllSurfaces(volume, fieldDefaultIso("blobs"));
    REQUIRE(surfaces.size() > 1);
    // Close up on the largest blob, with its neighbours around it.
    const SurfaceStats& selected = surfaces[0].stats;
    render::Camera camera;
    for (int axis = 0; axis < 3; ++axis) {
        camera.target[axis] = static_cast<float>((selected.boundsMin[axis] + selected.boundsMax[axis]) / 2);
    }
    camera.distance = static_cast<float>(5 * (selected.boundsMax[0] - selected.boundsMin[0]));
    render::SnapshotOptions options;
    options.selected = 0;
    options.camera = camera;
    test::checkGolden("blobs_selected", test::renderForGolden(pointersTo(surfaces), volume, options));
}

TEST_CASE("rendering the same scene twice gives the same pixels", "[gl]") {
    test::useHeadlessGl();
    const Volume volume = field("torus:24");
    const Mesh mesh = marchingCubes(volume, fieldDefaultIso("torus"));
    const render::Image first = test::renderForGolden({&mesh}, volume);
    const render::Image second = test::renderForGolden({&mesh}, volume);
    CHECK(first.rgba == second.rgba);
}
