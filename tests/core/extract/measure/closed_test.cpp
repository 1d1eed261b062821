// meshIsClosed on one thread and on several against a reference of its own
// (every directed side counted in a map, closed when each appears once and so
// does its reverse), and measureSurfaceInRuns against measureSurface.
#include <catch2/catch.hpp>

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "extract/measure/surface_measure.h"
#include "isotrack/fields.h"
#include "isotrack/tracking.h"

using namespace isotrack;

namespace {

bool closedByCount(const Mesh& mesh) {
    if (mesh.indices.empty()) return false;
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> sides;
    for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
        const std::size_t next = i % 3 == 2 ? i - 2 : i + 1;
        ++sides[{mesh.indices[i], mesh.indices[next]}];
    }
    for (const auto& [side, count] : sides) {
        const auto reverse = sides.find({side.second, side.first});
        if (count != 1 || reverse == sides.end() || reverse->second != 1) return false;
    }
    return true;
}

// The same answer as the reference on 1 to 8 threads; returns it.
bool requireSameOnEveryThreadCount(const Mesh& mesh) {
    const bool expected = closedByCount(mesh);
    for (int threads = 1; threads <= 8; ++threads) {
        INFO(threads << " threads");
        REQUIRE(detail::meshIsClosed(mesh, threads) == expected);
    }
    return expected;
}

Mesh fromTriangles(std::size_t vertexCount, const std::vector<std::uint32_t>& indices) {
    Mesh mesh;
    mesh.vertices.resize(vertexCount);
    mesh.vertexEdges.resize(vertexCount);
    mesh.indices.assign(indices.begin(), indices.end());
    return mesh;
}

const std::vector<std::uint32_t> kTetrahedron = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};

}  // namespace

TEST_CASE("closing check: small meshes, more threads than vertices", "[core][measure]") {
    CHECK(requireSameOnEveryThreadCount(fromTriangles(4, kTetrahedron)));
    CHECK_FALSE(requireSameOnEveryThreadCount(Mesh{}));
    std::vector<std::uint32_t> holed(kTetrahedron.begin(), kTetrahedron.end() - 3);
    CHECK_FALSE(requireSameOnEveryThreadCount(fromTriangles(4, holed)));
    std::vector<std::uint32_t> flipped = kTetrahedron;
    std::swap(flipped[10], flipped[11]);
    CHECK_FALSE(requireSameOnEveryThreadCount(fromTriangles(4, flipped)));
    // A triangle twice, both windings: every side has its reverse, but three triangles share an edge.
    std::vector<std::uint32_t> fin = kTetrahedron;
    fin.insert(fin.end(), {0, 1, 3, 0, 3, 1});
    CHECK_FALSE(requireSameOnEveryThreadCount(fromTriangles(4, fin)));
    // Two tetrahedra sharing vertex 0 (pinched, but every side once with its reverse).
    std::vector<std::uint32_t> pinched = kTetrahedron;
    for (std::uint32_t i : kTetrahedron) pinched.push_back(i == 0 ? 0 : i + 3);
    CHECK(requireSameOnEveryThreadCount(fromTriangles(7, pinched)));
}

TEST_CASE("closing check: tracked surfaces, closed, cut by the border and holed", "[core][measure][trilinear]") {
    const Volume sphere = makeField({"sphere", 48});
    const Vec3d c = sphereFieldCenter(48);
    const GridEdge seed = nearestCrossedEdge(sphere, 0.0, {c[0] + sphereFieldRadius(48), c[1], c[2]});
    const Mesh ball = trackSurface(sphere, 0.0, seed, TableKind::Trilinear).mesh;
    CHECK(requireSameOnEveryThreadCount(ball));
    // One triangle taken out, in each eighth of the mesh: some thread's range has the hole.
    for (int eighth = 0; eighth < 8; ++eighth) {
        Mesh holed = ball;
        const std::size_t t = holed.triangleCount() * std::size_t(eighth) / 8 + 5;
        holed.indices.erase(holed.indices.begin() + std::ptrdiff_t(3 * t),
                            holed.indices.begin() + std::ptrdiff_t(3 * t + 3));
        CHECK_FALSE(requireSameOnEveryThreadCount(holed));
    }
    const Volume gyroid = makeField({"gyroid", 40});
    const std::vector<Surface> open = extractAllSurfaces(gyroid, fieldDefaultIso("gyroid"), TableKind::Trilinear);
    REQUIRE_FALSE(open.empty());
    CHECK_FALSE(requireSameOnEveryThreadCount(open.front().mesh));
}

TEST_CASE("measure in runs: measureSurface's figures on 1 to 8 threads", "[core][measure][trilinear]") {
    const Volume sphere = makeField({"sphere", 48});
    const Vec3d c = sphereFieldCenter(48);
    const GridEdge seed = nearestCrossedEdge(sphere, 0.0, {c[0] + sphereFieldRadius(48), c[1], c[2]});
    const Volume gyroid = makeField({"gyroid", 40});
    const Mesh ball = trackSurface(sphere, 0.0, seed, TableKind::Trilinear).mesh;
    const Mesh open = extractAllSurfaces(gyroid, fieldDefaultIso("gyroid"), TableKind::Trilinear).front().mesh;
    for (const auto& [mesh, volume] : {std::pair<const Mesh*, const Volume*>{&ball, &sphere}, {&open, &gyroid}}) {
        const SurfaceStats one = measureSurface(*mesh, *volume);
        for (int threads = 1; threads <= 8; ++threads) {
            INFO(threads << " threads, " << mesh->triangleCount() << " triangles");
            const SurfaceStats runs = detail::measureSurfaceInRuns(*mesh, *volume, threads);
            CHECK(runs.closed == one.closed);
            CHECK(runs.touchesBorder == one.touchesBorder);
            CHECK(runs.triangles == one.triangles);
            CHECK(runs.vertices == one.vertices);
            for (int k = 0; k < 3; ++k) {
                CHECK(runs.boundsMin[k] == one.boundsMin[k]);
                CHECK(runs.boundsMax[k] == one.boundsMax[k]);
            }
            CHECK(runs.area == Approx(one.area).epsilon(1e-12));
            REQUIRE(runs.enclosedVolume.has_value() == one.enclosedVolume.has_value());
            if (one.enclosedVolume) CHECK(*runs.enclosedVolume == Approx(*one.enclosedVolume).epsilon(1e-12));
        }
    }
    CHECK(measureSurface(ball, sphere).closed);
    CHECK_FALSE(measureSurface(open, gyroid).closed);
}
