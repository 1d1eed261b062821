// nearestCrossedEdge against a brute-force reference: every crossed edge of
// the volume, the nearest midpoint (world units) winning, ties to the edge a
// search in growing shells around the point's voxel meets first (the smaller
// Chebyshev ring from that voxel, then z, y, x, axis). Points on and off
// surfaces, at grid points (where a sphere's edges tie), outside the volume,
// with anisotropic spacing and an origin.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <tuple>

#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/tracking.h"

using namespace isotrack;

namespace {

GridEdge referenceNearest(const Volume& volume, double iso, const Vec3d& point) {
    const Dims& n = volume.dims();
    const Vec3d &s = volume.spacing(), &o = volume.origin();
    std::array<double, 3> p{};
    std::array<int, 3> centre{};
    for (int k = 0; k < 3; ++k) {
        p[std::size_t(k)] = (point[k] - o[k]) / s[k];
        centre[std::size_t(k)] = int(std::lround(std::clamp(p[std::size_t(k)], 0.0, double(n[k] - 1))));
    }
    using Key = std::tuple<double, int, int, int, int, int>;  // distance, ring, z, y, x, axis
    Key best{std::numeric_limits<double>::infinity(), 0, 0, 0, 0, 0};
    for (int z = 0; z < n[2]; ++z) {
        for (int y = 0; y < n[1]; ++y) {
            for (int x = 0; x < n[0]; ++x) {
                const bool above = volume.value(x, y, z) >= iso;
                const std::array<int, 3> q{x, y, z};
                for (int axis = 0; axis < 3; ++axis) {
                    std::array<int, 3> t = q;
                    ++t[std::size_t(axis)];
                    if (t[std::size_t(axis)] >= n[axis] || (volume.value(t[0], t[1], t[2]) >= iso) == above) continue;
                    double d2 = 0.0;
                    int ring = 0;
                    for (int k = 0; k < 3; ++k) {
                        const double mid = q[std::size_t(k)] + (k == axis ? 0.5 : 0.0);
                        d2 += (mid - p[std::size_t(k)]) * (mid - p[std::size_t(k)]) * s[k] * s[k];
                        ring = std::max(ring, std::abs(q[std::size_t(k)] - centre[std::size_t(k)]));
                    }
                    best = std::min(best, Key{std::sqrt(d2), ring, z, y, x, axis});
                }
            }
        }
    }
    REQUIRE(std::isfinite(std::get<0>(best)));
    return GridEdge{std::get<4>(best), std::get<3>(best), std::get<2>(best), std::get<5>(best)};
}

void checkPoints(const Volume& volume, double iso, int randomPoints) {
    const Dims& n = volume.dims();
    const Vec3d &s = volume.spacing(), &o = volume.origin();
    std::vector<Vec3d> points;
    // Grid points (ties between edges around them) and the volume's corners and beyond.
    for (const std::array<double, 3>& f : std::vector<std::array<double, 3>>{
             {0.5, 0.5, 0.5}, {0, 0, 0}, {1, 1, 1}, {0.25, 0.75, 0.5}, {-0.5, 0.5, 1.5}, {2, -1, 0.5}}) {
        Vec3d point{};
        for (int k = 0; k < 3; ++k) point[k] = o[k] + std::round(f[std::size_t(k)] * (n[k] - 1)) * s[k];
        points.push_back(point);
    }
    std::mt19937 random(17);
    std::uniform_real_distribution<double> unit(-0.3, 1.3);
    for (int i = 0; i < randomPoints; ++i) {
        Vec3d point{};
        for (int k = 0; k < 3; ++k) point[k] = o[k] + unit(random) * (n[k] - 1) * s[k];
        points.push_back(point);
    }
    for (const Vec3d& point : points) {
        INFO("point " << point[0] << ", " << point[1] << ", " << point[2]);
        const GridEdge found = nearestCrossedEdge(volume, iso, point);
        const GridEdge expected = referenceNearest(volume, iso, point);
        CHECK(std::array<int, 4>{found.x, found.y, found.z, found.axis} ==
              std::array<int, 4>{expected.x, expected.y, expected.z, expected.axis});
    }
}

}  // namespace

TEST_CASE("the nearest crossed edge is the brute-force nearest, ties as shells meet them", "[tracking][seeds]") {
    SECTION("a sphere, centred on a grid point: every edge of a ring ties") {
        checkPoints(makeField({"sphere", 33}), 0.0, 40);
    }
    SECTION("noise: many small surfaces") { checkPoints(makeField({"noise", 24}), 0.5, 60); }
    SECTION("one small blob far from most points, anisotropic spacing and an origin") {
        Volume volume = makeField({"blobs", 40});
        volume.setSpacing({0.7, 1.3, 2.1});
        volume.setOrigin({-5.0, 3.0, 11.0});
        checkPoints(volume, 0.93, 40);
    }
}

TEST_CASE("a volume no edge crosses has no nearest crossed edge", "[tracking][seeds]") {
    const Volume volume = makeField({"sphere", 16});
    CHECK_THROWS_AS(nearestCrossedEdge(volume, 1e9, {3.0, 4.0, 5.0}), InputError);
}
