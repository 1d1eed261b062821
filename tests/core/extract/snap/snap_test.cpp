#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <set>
#include <tuple>

#include "core/extract/snap/random_integers.h"
#include "core/mesh_checks.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/mesh_processing.h"
#include "isotrack/snap_table.h"
#include "isotrack/surface.h"
#include "isotrack/tracking.h"

using namespace isotrack;
using isotrack::testing::topology;

namespace {

using Point = std::tuple<float, float, float>;

Point pointOf(const Vertex& v) { return {v.position[0], v.position[1], v.position[2]}; }

// Triangles as triples of vertex positions, rotated so the smallest comes first
// (winding kept): meshes from different extractors compare, whatever their
// vertex numbering.
std::multiset<std::array<Point, 3>> trianglesByPosition(const Mesh& mesh) {
    std::multiset<std::array<Point, 3>> out;
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f) {
        std::array<Point, 3> t{};
        for (int k = 0; k < 3; ++k) t[std::size_t(k)] = pointOf(mesh.vertices[mesh.indices[3 * f + std::size_t(k)]]);
        while (t[0] > t[1] || t[0] > t[2]) std::rotate(t.begin(), t.begin() + 1, t.end());
        out.insert(t);
    }
    return out;
}

using test::randomIntegers;

// Edges of more than two triangles, by vertex position, whose two ends are not
// both samples equal to the isovalue (where the surface touches itself).
std::size_t crowdedEdgesOffTheIsovalue(const Mesh& mesh, const Volume& volume, double iso) {
    std::map<std::pair<Point, Point>, int> uses;
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const Point a = pointOf(mesh.vertices[mesh.indices[3 * f + std::size_t(k)]]);
            const Point b = pointOf(mesh.vertices[mesh.indices[3 * f + std::size_t((k + 1) % 3)]]);
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    }
    auto onSampleAtIso = [&](const Point& p) {
        const float c[3] = {std::get<0>(p), std::get<1>(p), std::get<2>(p)};
        int g[3];
        for (int k = 0; k < 3; ++k) {
            g[k] = int(c[k]);
            if (float(g[k]) != c[k]) return false;  // unit spacing, origin 0
        }
        return volume.value(g[0], g[1], g[2]) == iso;
    };
    std::size_t crowded = 0;
    for (const auto& [edge, count] : uses)
        crowded += count > 2 && !(onSampleAtIso(edge.first) && onSampleAtIso(edge.second));
    return crowded;
}

}  // namespace

TEST_CASE("snap: on noise, closed and edge-manifold after welding, no zero-area triangles", "[core][snap][mc]") {
    std::mt19937 rng(11);
    for (int trial = 0; trial < 40; ++trial) {
        const Volume v = test::randomFloats({7, 6, 5}, rng);
        const Mesh mesh = marchingCubes(v, 0.1, TableKind::Snap);
        const auto t = topology(mesh, v.dims());
        CHECK(t.interiorBoundaryEdges == 0);
        CHECK(t.repeatedDirectedEdges == 0);
        CHECK(t.nonManifoldEdges == 0);
        CHECK(testing::duplicatePositions(mesh) == 0);  // a snapped sample is one vertex
        const MeshQuality q = measureQuality(mesh);
        CHECK(q.degenerateTriangles == 0);
        CHECK(q.nonManifoldEdges == 0);
    }
}

TEST_CASE("snap: many samples at the isovalue, closed; edges of four only where the volume touches itself",
          "[core][snap][mc]") {
    std::mt19937 rng(5);
    for (int trial = 0; trial < 300; ++trial) {
        const Volume v = randomIntegers({4, 4, 4}, rng, trial % 3 + 1);
        const Mesh mesh = marchingCubes(v, 0.0, TableKind::Snap);
        const auto t = topology(mesh, v.dims());
        INFO("trial " << trial);
        CHECK(t.interiorBoundaryEdges == 0);
        CHECK(testing::duplicatePositions(mesh) == 0);
        CHECK(measureQuality(mesh).degenerateTriangles == 0);
        CHECK(crowdedEdgesOffTheIsovalue(mesh, v, 0.0) == 0);
    }
}

TEST_CASE("snap: track and all give mc's triangles, one surface per consistent surface", "[core][snap][tracking]") {
    std::mt19937 rng(3);
    for (int trial = 0; trial < 30; ++trial) {
        const Volume v = trial % 2 ? test::randomFloats({9, 8, 7}, rng) : randomIntegers({9, 8, 7}, rng, 4);
        const double iso = trial % 2 ? 0.2 : 0.5;
        INFO("trial " << trial);
        const Mesh mesh = marchingCubes(v, iso, TableKind::Snap);
        const std::vector<Surface> all = extractAllSurfaces(v, iso, TableKind::Snap);
        const std::vector<Surface> tracked = trackAllSurfaces(v, iso, TableKind::Snap);
        std::multiset<std::array<Point, 3>> unionAll, unionTracked;
        for (const Surface& s : all) {
            const auto part = trianglesByPosition(s.mesh);
            unionAll.insert(part.begin(), part.end());
            CHECK(s.stats.triangles == s.mesh.triangleCount());
        }
        for (const Surface& s : tracked) {
            const auto part = trianglesByPosition(s.mesh);
            unionTracked.insert(part.begin(), part.end());
        }
        CHECK(unionAll == trianglesByPosition(mesh));
        CHECK(unionTracked == unionAll);
        // Samples keep their side, so surfaces are the consistent table's; snapping
        // keeps each of them (no isovalue here equals a sample).
        CHECK(all.size() == extractAllSurfaces(v, iso, TableKind::Consistent).size());
        // Tracking from a crossed edge of a surface gives that surface.
        for (const Surface& s : all) {
            const GridEdge seed = s.mesh.vertexEdges[0];
            if (seed.axis == kCellInterior) continue;
            int q[3] = {seed.x, seed.y, seed.z};
            ++q[seed.axis];
            if ((v.value(seed.x, seed.y, seed.z) >= iso) == (v.value(q[0], q[1], q[2]) >= iso)) continue;
            const Surface one = trackSurface(v, iso, seed, TableKind::Snap);
            CHECK(trianglesByPosition(one.mesh) == trianglesByPosition(s.mesh));
            SurfaceTracker tracker(v, iso, TableKind::Snap);
            tracker.start(seed);
            while (!tracker.done()) tracker.step(7);
            CHECK(trianglesByPosition(tracker.takeSurface().mesh) == trianglesByPosition(s.mesh));
            break;
        }
    }
}

TEST_CASE("snap: closed fields give closed surfaces of the consistent table's topology", "[core][snap]") {
    for (const char* name : {"sphere", "torus", "shells"}) {
        const Volume v = makeField(parseFieldSpec(std::string(name) + ":24"));
        const double iso = fieldDefaultIso(name);
        INFO(name);
        const std::vector<Surface> snapped = extractAllSurfaces(v, iso, TableKind::Snap);
        const std::vector<Surface> consistent = extractAllSurfaces(v, iso, TableKind::Consistent);
        REQUIRE(snapped.size() == consistent.size());
        std::size_t snappedTriangles = 0, consistentTriangles = 0;
        for (std::size_t i = 0; i < snapped.size(); ++i) {
            Surface s = snapped[i];
            CHECK(s.stats.closed);
            measureTopology(s);
            Surface c = consistent[i];
            measureTopology(c);
            CHECK(s.stats.euler == c.stats.euler);
            CHECK(s.stats.enclosedVolume.value() == Approx(c.stats.enclosedVolume.value()).epsilon(0.02));
            snappedTriangles += s.stats.triangles;
            consistentTriangles += c.stats.triangles;
            CHECK(measureQuality(s.mesh).minAngleBelow10 < measureQuality(c.mesh).minAngleBelow10 + 1e-12);
        }
        CHECK(snappedTriangles < consistentTriangles);
    }
}

TEST_CASE("snap: a sample equal to the isovalue is one vertex on its grid point", "[core][snap]") {
    Volume v({3, 3, 3}, ScalarType::Int16);
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 3; ++x) v.setValue(x, y, z, z == 0 ? 10 : z == 1 ? 5 : 0);
    // The middle plane equals the isovalue: the surface is that plane, two triangles per cell face.
    const Mesh mesh = marchingCubes(v, 5.0, TableKind::Snap);
    CHECK(mesh.vertices.size() == 9);
    CHECK(mesh.triangleCount() == 8);
    for (const Vertex& p : mesh.vertices) {
        CHECK(p.position[2] == 1.0f);
        CHECK(p.normal[2] == Approx(1.0f));  // from above the isovalue (z = 0) towards below
    }
    // A sheet of samples at the isovalue between samples below it on both sides encloses nothing.
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 3; ++x) v.setValue(x, y, 0, 0);
    CHECK(marchingCubes(v, 5.0, TableKind::Snap).triangleCount() == 0);
}

TEST_CASE("snap: tables by name", "[core][snap]") {
    CHECK(parseTableKind("snap") == TableKind::Snap);
    CHECK(std::string(tableKindName(TableKind::Snap)) == "snap");
    CHECK(std::count(kTableKinds.begin(), kTableKinds.end(), TableKind::Snap) == 1);
    CHECK_THROWS_AS(parseTableKind("snapmc"), InputError);
}

// marchSnap skips the cells whose samples are all on one side without reading
// the table; it may because no such entry has a triangle, whatever its at samples.
TEST_CASE("snap: entries with every sample on one side have no triangles", "[core][snap][tables]") {
    for (const unsigned above : {0u, 0xffu}) {
        for (unsigned at = 0; at < 256; ++at) {
            CHECK(int(snapTable()[std::size_t(snapCaseIndex(std::uint8_t(above), std::uint8_t(at)))].count) == 0);
        }
    }
}

namespace {

// A snap tracker's surface, grown `budget` pieces a step.
Surface grownSnap(const Volume& v, double iso, const GridEdge& seed, int threads, std::size_t budget) {
    SurfaceTracker tracker(v, iso, TableKind::Snap, threads);
    tracker.start(seed);
    while (!tracker.done()) tracker.step(budget);
    return tracker.takeSurface();
}

bool sameBytes(const Mesh& a, const Mesh& b) {
    return a.vertices.size() == b.vertices.size() && a.indices == b.indices &&
           std::equal(a.vertexEdges.begin(), a.vertexEdges.end(), b.vertexEdges.begin(), b.vertexEdges.end(),
                      [](GridEdge p, GridEdge q) { return p == q; }) &&
           std::equal(a.vertices.begin(), a.vertices.end(), b.vertices.begin(), [](const Vertex& p, const Vertex& q) {
               return std::equal(std::begin(p.position), std::end(p.position), std::begin(q.position)) &&
                      std::equal(std::begin(p.normal), std::end(p.normal), std::begin(q.normal));
           });
}

}  // namespace

TEST_CASE("snap: the tracker's states on several threads grow the same mesh", "[core][snap][tracking]") {
    std::mt19937 rng(11);
    struct Case {
        std::string name;
        Volume volume;
        double iso;
    };
    std::vector<Case> cases;
    for (const char* spec : {"sphere:40", "gyroid:32"}) {
        const FieldSpec field = parseFieldSpec(spec);
        cases.push_back({spec, makeField(field), fieldDefaultIso(field.name)});
    }
    cases.push_back({"integers at the isovalue", randomIntegers({30, 28, 26}, rng, 4), 0.0});
    for (const Case& c : cases) {
        INFO(c.name);
        const Surface largest = extractAllSurfaces(c.volume, c.iso, TableKind::Snap).front();
        // A crossed edge (a sample at the isovalue has a vertex on an edge from it, not crossed).
        const auto& edges = largest.mesh.vertexEdges;
        const auto crossed = std::find_if(edges.begin() + std::ptrdiff_t(edges.size() / 2), edges.end(),
                                          [&](const GridEdge& e) { return edgeIsCrossed(c.volume, c.iso, e); });
        REQUIRE(crossed != edges.end());
        const GridEdge seed = *crossed;
        const Surface one = grownSnap(c.volume, c.iso, seed, 1, 97);
        REQUIRE(one.mesh.triangleCount() == largest.mesh.triangleCount());
        for (int threads : {2, 3, 8}) {
            INFO(threads << " threads");
            const Surface several = grownSnap(c.volume, c.iso, seed, threads, 97);
            CHECK(sameBytes(several.mesh, one.mesh));
            CHECK(several.stats.closed == one.stats.closed);
            CHECK(several.stats.area == one.stats.area);
            CHECK(several.stats.cellsVisited == one.stats.cellsVisited);
        }
    }
}
