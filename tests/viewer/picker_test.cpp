// Picking without a surface: marching a ray through the volume to its first
// crossing of the isovalue.
#include <catch2/catch.hpp>
#include <cmath>

#include "isotrack/fields.h"
#include "isotrack/tracking.h"
#include "viewer/picker.h"

using namespace isotrack;

TEST_CASE("a ray through a sphere field stops on the sphere", "[viewer][pick]") {
    const Volume volume = makeField(parseFieldSpec("sphere:48"));
    const double iso = fieldDefaultIso("sphere");
    const Vec3d centre = sphereFieldCenter(48);
    const double radius = sphereFieldRadius(48);
    // From outside the box along -x, through the centre.
    const glm::vec3 origin(200.0f, float(centre[1]), float(centre[2]));
    const auto hit = viewer::firstIsoCrossing(volume, iso, origin, glm::vec3(-1.0f, 0.0f, 0.0f));
    REQUIRE(hit);
    CHECK((*hit)[0] == Approx(centre[0] + radius).margin(0.05));
    CHECK((*hit)[1] == Approx(centre[1]));
    // The crossed edge nearest the hit is one of the sphere's.
    const GridEdge seed = nearestCrossedEdge(volume, iso, *hit);
    CHECK(edgeIsCrossed(volume, iso, seed));
    CHECK(std::abs(seed.x - (centre[0] + radius)) < 1.5);
}

TEST_CASE("a ray that misses the volume or never crosses finds nothing", "[viewer][pick]") {
    const Volume volume = makeField(parseFieldSpec("sphere:32"));
    const double iso = fieldDefaultIso("sphere");
    CHECK_FALSE(viewer::firstIsoCrossing(volume, iso, glm::vec3(100.0f, 100.0f, 100.0f), glm::vec3(1.0f, 0.0f, 0.0f)));
    // Along the box's edge, outside the sphere all the way.
    CHECK_FALSE(viewer::firstIsoCrossing(volume, iso, glm::vec3(-5.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f)));
}
