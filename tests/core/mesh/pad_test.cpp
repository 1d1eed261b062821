#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/mesh/mesh_test_support.h"
#include "isotrack/errors.h"
#include "isotrack/mesh_processing.h"
#include "isotrack/tracking.h"

using namespace isotrack;
using isotrack::test::ballVolume;
using isotrack::test::exhaustive;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A padded copy made sample by sample, independently of padVolume.
Volume paddedByHand(const Volume& v, double pad) {
    const Dims& n = v.dims();
    Volume out({n[0] + 2, n[1] + 2, n[2] + 2}, v.type(), v.spacing(),
               {v.origin()[0] - v.spacing()[0], v.origin()[1] - v.spacing()[1], v.origin()[2] - v.spacing()[2]});
    for (int z = 0; z < n[2] + 2; ++z)
        for (int y = 0; y < n[1] + 2; ++y)
            for (int x = 0; x < n[0] + 2; ++x) {
                const bool inside = x >= 1 && y >= 1 && z >= 1 && x <= n[0] && y <= n[1] && z <= n[2];
                out.setValue(x, y, z, inside ? v.value(x - 1, y - 1, z - 1) : pad);
            }
    return out;
}

std::vector<std::array<float, 3>> sortedPositions(const Mesh& mesh) {
    std::vector<std::array<float, 3>> out;
    for (const Vertex& v : mesh.vertices) out.push_back({v.position[0], v.position[1], v.position[2]});
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST_CASE("the pad value is the smallest sample, else one below iso", "[core][mesh]") {
    const Volume ball = ballVolume({12, 12, 12}, {5.3, 5.6, 5.2}, 3.0);
    CHECK(capPadValue(ball, 0.0) == ball.range()[0]);
    Volume above({4, 4, 4}, ScalarType::Int16);
    for (int z = 0; z < 4; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x) above.setValue(x, y, z, 500);
    CHECK(capPadValue(above, 400.5) == 399.0);
    Volume bytes({4, 4, 4}, ScalarType::UInt8);
    CHECK_THROWS_AS(capPadValue(bytes, 0.0), InputError);
}

TEST_CASE("padVolume puts the samples one step in, the pad around, the origin one spacing out", "[core][mesh]") {
    Volume v({3, 4, 5}, ScalarType::Int16, {0.5, 2.0, 1.5}, {10, 20, 30});
    for (int z = 0; z < 5; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 3; ++x) v.setValue(x, y, z, x + 10 * y + 100 * z);
    const Volume padded = padVolume(v, -7);
    REQUIRE(padded.dims() == Dims{5, 6, 7});
    CHECK(padded.origin() == Vec3d{9.5, 18.0, 28.5});
    const Volume byHand = paddedByHand(v, -7);
    for (int z = 0; z < 7; ++z)
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 5; ++x) REQUIRE(padded.value(x, y, z) == byHand.value(x, y, z));
}

TEST_CASE("a ball cut by the border is closed by --cap, as from a padded copy", "[core][mesh]") {
    const double r = 8.0;
    const Vec3d centre{4.3, 12.4, 11.7};  // reaches 3.7 past x = 0
    const Volume ball = ballVolume({26, 26, 26}, centre, r);
    const Surface open = exhaustive(ball, 0.0);
    CHECK_FALSE(open.stats.closed);

    const Surface capped = exhaustive(ball, 0.0, true);
    REQUIRE(capped.stats.closed);
    const Surface reference = exhaustive(paddedByHand(ball, ball.range()[0]), 0.0);
    CHECK(capped.mesh.triangleCount() == reference.mesh.triangleCount());
    CHECK(sortedPositions(capped.mesh) == sortedPositions(reference.mesh));
    REQUIRE(reference.stats.enclosedVolume);
    CHECK(*capped.stats.enclosedVolume == Approx(*reference.stats.enclosedVolume).epsilon(1e-9));
    // The ball's part at x >= 0 (a cap of height r + 4.3), and a sliver past x = 0.
    const double h = r + centre[0];
    CHECK(*capped.stats.enclosedVolume == Approx(kPi * h * h * (3 * r - h) / 3).epsilon(0.03));
    CHECK(measureQuality(capped.mesh).boundaryEdges == 0);

    Surface topology = capped;
    measureTopology(topology);
    CHECK(*topology.stats.euler == 2);
    CHECK(*topology.stats.genus == 0);

    // track and all give the same closed surface.
    ExtractRequest track;
    track.method = Method::Track;
    track.cap = true;
    track.seeds = {{centre[0] + r, centre[1], centre[2]}};
    const Surface tracked = extract(ball, track).front();
    CHECK(tracked.stats.closed);
    CHECK(tracked.mesh.triangleCount() == capped.mesh.triangleCount());
    ExtractRequest all;
    all.method = Method::All;
    all.cap = true;
    const std::vector<Surface> every = extract(ball, all);
    REQUIRE(every.size() == 1);
    CHECK(every.front().stats.closed);
    CHECK(*every.front().stats.enclosedVolume == Approx(*capped.stats.enclosedVolume).epsilon(1e-6));
}
