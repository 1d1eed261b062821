// Identity across isovalues by the contour tree's arcs (matchSurfacesByArc), on
// a volume with two peaks joined at a saddle: 9 (three samples above the
// saddle) and 7 (one), the saddle at 3. Between 3 and 7 there are two surfaces,
// below 3 one, above 7 only the tall peak's.
#include <algorithm>
#include <catch2/catch.hpp>

#include "isotrack/follow.h"

using namespace isotrack;

namespace {

Volume twoPeaks() {
    Volume volume({9, 3, 3}, ScalarType::UInt8);
    const std::uint8_t row[9] = {0, 5, 9, 5, 3, 7, 2, 1, 0};
    for (int x = 0; x < 9; ++x) volume.data<std::uint8_t>()[volume.index(x, 1, 1)] = row[x];
    return volume;
}

// The arcs crossing v, the tall peak's first (by their upper node's value).
std::vector<std::optional<std::size_t>> arcsAt(const ContourTree& tree, double v) {
    std::vector<std::size_t> arcs = tree.arcsAt(v);
    std::sort(arcs.begin(), arcs.end(), [&](std::size_t a, std::size_t b) {
        return tree.nodes[tree.arcs[a].upper].value > tree.nodes[tree.arcs[b].upper].value;
    });
    return {arcs.begin(), arcs.end()};
}

}  // namespace

TEST_CASE("surfaces keep who they are by their contour-tree arcs", "[follow][tree]") {
    const Volume volume = twoPeaks();
    const ContourTree tree = computeContourTree(volume, 1);
    const auto two = arcsAt(tree, 5.0), one = arcsAt(tree, 2.0), tall = arcsAt(tree, 8.0);
    REQUIRE(two.size() == 2);
    REQUIRE(one.size() == 1);
    REQUIRE(tall.size() == 1);

    // No node between the isovalues: each surface is its own continuation.
    CHECK(matchSurfacesByArc(tree, 5.0, two, arcsAt(tree, 6.0)) == std::vector<int>{0, 1});
    CHECK(matchSurfacesByArc(tree, 5.0, {two[1], two[0]}, arcsAt(tree, 6.0)) == std::vector<int>{1, 0});
    // Down through the saddle they merge: the merged surface continues the branch sweeping the most samples.
    CHECK(matchSurfacesByArc(tree, 5.0, two, one) == std::vector<int>{0});
    CHECK(matchSurfacesByArc(tree, 5.0, {two[1], two[0]}, one) == std::vector<int>{1});
    // Up through it the surface splits: both parts continue it.
    CHECK(matchSurfacesByArc(tree, 2.0, one, two) == std::vector<int>{0, 0});
    // Down past the small peak a surface is born there: it continues nothing.
    CHECK(matchSurfacesByArc(tree, 8.0, tall, two) == std::vector<int>{0, -1});
    // Up past it that surface ends: nothing continues it.
    CHECK(matchSurfacesByArc(tree, 5.0, two, tall) == std::vector<int>{0});
    // A surface from another method has no arc: the caller matches by footprint.
    CHECK_FALSE(matchSurfacesByArc(tree, 5.0, {std::nullopt, two[1]}, two).has_value());
    CHECK_FALSE(matchSurfacesByArc(tree, 5.0, two, {two[0], std::nullopt}).has_value());
}
