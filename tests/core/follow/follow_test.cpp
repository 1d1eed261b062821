// Following seeds and surfaces across isovalues (isotrack/follow.h).
#include <catch2/catch.hpp>

#include <cmath>

#include "isotrack/fields.h"
#include "isotrack/follow.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"

using namespace isotrack;

namespace {

double distance(const Vec3d& a, const Vec3d& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

bool crossed(const Volume& volume, double iso, const GridEdge& e) {
    const double a = volume.value(e.x, e.y, e.z);
    const double b = volume.value(e.x + (e.axis == 0), e.y + (e.axis == 1), e.z + (e.axis == 2));
    return (a >= iso) != (b >= iso);
}

SurfaceFootprint box(std::uint64_t firstBlock, std::size_t blocks, std::size_t triangles) {
    SurfaceFootprint f;
    for (std::size_t i = 0; i < blocks; ++i) f.blocks.push_back(firstBlock + i);
    f.triangles = triangles;
    f.boundsMin = {double(firstBlock), 0.0, 0.0};
    f.boundsMax = {double(firstBlock + blocks), 1.0, 1.0};
    return f;
}

}  // namespace

TEST_CASE("a seed on a sphere follows the surface as the isovalue moves, and is gone when it vanishes", "[follow]") {
    const int n = 48;
    const Volume volume = makeField({"sphere", n});  // r - distance from the centre, in voxels
    const double r = sphereFieldRadius(n);
    const Vec3d centre = sphereFieldCenter(n);
    const Vec3d point{centre[0] + r, centre[1], centre[2]};  // on the surface at isovalue 0
    for (double iso : {-4.0, -2.5, 0.0, 3.0, 7.5}) {         // the sphere stays inside the grid
        CAPTURE(iso);
        const std::optional<FollowedSeed> seed = followSeed(volume, iso, point);
        REQUIRE(seed);
        CHECK(crossed(volume, iso, seed->edge));
        // The sphere at this isovalue has radius r - iso; the seed is on it, near the old point's ray.
        CHECK(std::abs(distance(seed->point, centre) - (r - iso)) < 0.1);
        CHECK(distance(seed->point, Vec3d{centre[0] + r - iso, centre[1], centre[2]}) < 1.5);
        // And it is the sphere's surface: tracking from it gives the whole exhaustive mesh.
        if (iso == 3.0) {
            const Surface tracked = trackSurface(volume, iso, seed->edge);
            CHECK(tracked.mesh.triangleCount() == marchingCubes(volume, iso).triangleCount());
        }
    }
    CHECK_FALSE(followSeed(volume, r + 1.0, point));  // above the centre's value: no surface anywhere
}

TEST_CASE("a seed far from any surface finds none, but one near a surface that moved finds it", "[follow]") {
    const int n = 48;
    const Volume volume = makeField({"sphere", n});
    const Vec3d centre = sphereFieldCenter(n);
    const double r = sphereFieldRadius(n);
    // Outside, in the corner: the walk goes down the gradient towards the sphere.
    const Vec3d outside{centre[0] + r + 10.0, centre[1], centre[2]};
    const std::optional<FollowedSeed> seed = followSeed(volume, 0.0, outside);
    REQUIRE(seed);
    CHECK(std::abs(distance(seed->point, centre) - r) < 0.1);
    // A constant region has no gradient to walk and no crossing nearby.
    Volume flat({16, 16, 16}, ScalarType::Float32);
    CHECK_FALSE(followSeed(flat, 0.5, Vec3d{8, 8, 8}));
}

TEST_CASE("footprints match each blob to itself after a small isovalue step", "[follow]") {
    const Volume volume = makeField({"blobs", 64});
    const double iso = fieldDefaultIso("blobs");
    const std::vector<Surface> before = extractAllSurfaces(volume, iso);
    const std::vector<Surface> after = extractAllSurfaces(volume, iso + 0.02);
    REQUIRE(before.size() == after.size());
    std::vector<SurfaceFootprint> a, b;
    for (const Surface& s : before) a.push_back(footprintOf(s.mesh));
    for (const Surface& s : after) b.push_back(footprintOf(s.mesh));
    std::vector<const SurfaceFootprint*> pa, pb;
    for (const auto& f : a) pa.push_back(&f);
    for (const auto& f : b) pb.push_back(&f);
    const std::vector<int> match = matchSurfaces(pa, pb);
    REQUIRE(match.size() == after.size());
    for (std::size_t j = 0; j < after.size(); ++j) {
        CAPTURE(j);
        REQUIRE(match[j] >= 0);
        // The same blob: the new one's bounds hold the old one's centre.
        const SurfaceFootprint& old = a[std::size_t(match[j])];
        for (int k = 0; k < 3; ++k) {
            const double c = 0.5 * (old.boundsMin[k] + old.boundsMax[k]);
            CHECK(c >= b[j].boundsMin[k]);
            CHECK(c <= b[j].boundsMax[k]);
        }
    }
}

TEST_CASE("matching: a split continues one old surface twice, a merge takes the largest, strangers match nothing",
          "[follow]") {
    const SurfaceFootprint big = box(0, 100, 1000), small = box(200, 40, 300), far = box(5000, 10, 50);
    // Merged: a new surface covering both old ones continues the larger, though it shares fewer blocks with it.
    const SurfaceFootprint merged = box(60, 180, 1400);  // 40 of big's blocks and all 40 of small's
    SurfaceFootprint halfA = box(0, 50, 500), halfB = box(50, 50, 500);
    const std::vector<int> m = matchSurfaces({&big, &small}, {&merged, &halfA, &halfB, &far});
    CHECK(m[0] == 0);
    CHECK(m[1] == 0);
    CHECK(m[2] == 0);
    CHECK(m[3] == -1);
    // A surface sharing fewer than a quarter of the best share does not count as merged in.
    const SurfaceFootprint mostlySmall = box(195, 45, 400);  // 40 of small's blocks, 0 of big's
    CHECK(matchSurfaces({&big, &small}, {&mostlySmall}) == std::vector<int>{1});
}
