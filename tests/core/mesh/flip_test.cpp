#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "mesh/flip.h"

using namespace isotrack;

namespace {

Mesh meshOf(const std::vector<std::array<float, 3>>& points, const std::vector<std::uint32_t>& indices) {
    Mesh mesh;
    for (const auto& p : points) {
        Vertex v{};
        std::copy(p.begin(), p.end(), v.position);
        mesh.vertices.push_back(v);
    }
    mesh.indices.assign(indices.begin(), indices.end());
    return mesh;
}

// The vector area (half the sum of the triangles' cross products): a flat
// patch's is its area times its normal, whatever its triangulation.
std::array<double, 3> vectorArea(const Mesh& mesh) {
    std::array<double, 3> sum{};
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const float* a = mesh.vertices[mesh.indices[3 * t]].position;
        const float* b = mesh.vertices[mesh.indices[3 * t + 1]].position;
        const float* c = mesh.vertices[mesh.indices[3 * t + 2]].position;
        const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
        const double w[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
        sum[0] += 0.5 * (u[1] * w[2] - u[2] * w[1]);
        sum[1] += 0.5 * (u[2] * w[0] - u[0] * w[2]);
        sum[2] += 0.5 * (u[0] * w[1] - u[1] * w[0]);
    }
    return sum;
}

// Directed edges with no reverse: the patch's border, in a fixed order.
std::vector<std::pair<std::uint32_t, std::uint32_t>> border(const Mesh& mesh) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    for (std::size_t c = 0; c < mesh.indices.size(); ++c)
        ++uses[{mesh.indices[c], mesh.indices[c % 3 == 2 ? c - 2 : c + 1]}];
    std::vector<std::pair<std::uint32_t, std::uint32_t>> open;
    for (const auto& [edge, count] : uses)
        if (!uses.count({edge.second, edge.first})) open.push_back(edge);
    return open;
}

}  // namespace

TEST_CASE("a zero-area triangle is flipped away without moving the surface", "[core][mesh]") {
    // a, b, and c between them on the x axis; d above, e below: (a, b, c) has
    // no area, (b, a, d) lies across its longest side.
    const Mesh before =
        meshOf({{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, -1, 0}}, {0, 1, 2, 1, 0, 3, 2, 1, 4, 0, 2, 4});
    Mesh after = before;
    detail::flipZeroAreaTriangles(after);
    REQUIRE(after.triangleCount() == before.triangleCount());
    for (std::size_t t = 0; t < after.triangleCount(); ++t) {
        const float* a = after.vertices[after.indices[3 * t]].position;
        const float* b = after.vertices[after.indices[3 * t + 1]].position;
        const float* c = after.vertices[after.indices[3 * t + 2]].position;
        CHECK_FALSE(detail::zeroArea(a, b, c));
    }
    const auto areaBefore = vectorArea(before), areaAfter = vectorArea(after);
    for (int k = 0; k < 3; ++k) CHECK(areaAfter[k] == Approx(areaBefore[k]).margin(1e-12));
    CHECK(border(after) == border(before));
}

TEST_CASE("a zero-area triangle on the border stays", "[core][mesh]") {
    // Nothing lies across (a, b, c)'s longest side: no flip is possible.
    const Mesh before = meshOf({{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {1, -1, 0}}, {0, 1, 2, 2, 1, 3, 0, 2, 3});
    Mesh after = before;
    detail::flipZeroAreaTriangles(after);
    CHECK(std::vector<std::uint32_t>(after.indices.begin(), after.indices.end()) ==
          std::vector<std::uint32_t>(before.indices.begin(), before.indices.end()));
}
