#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <random>
#include <set>
#include <tuple>

#include "core/mesh_checks.h"
#include "isotrack/errors.h"
#include "isotrack/extract.h"
#include "isotrack/fields.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"

using namespace isotrack;
using isotrack::testing::topology;

namespace {

std::size_t interiorVertices(const Mesh& mesh) {
    std::size_t count = 0;
    for (const GridEdge e : mesh.vertexEdges) count += e.axis == kCellInterior;
    return count;
}

// No holes, no edge of more than two triangles, one winding, and one vertex per
// crossed grid edge besides the cells' interior vertices.
void requireWatertight(const Mesh& mesh, const Volume& volume, double iso) {
    const auto t = topology(mesh, volume.dims());
    CHECK(t.interiorBoundaryEdges == 0);
    CHECK(t.nonManifoldEdges == 0);
    CHECK(t.repeatedDirectedEdges == 0);
    CHECK(mesh.vertices.size() - interiorVertices(mesh) == countCrossedEdges(volume, iso));
    // Each crossed grid edge has one vertex (a cell may have several interior ones).
    std::set<std::uint64_t> keys;
    for (const GridEdge e : mesh.vertexEdges) {
        if (e.axis != kCellInterior) keys.insert(isotrack::testing::edgeKey(e, volume.dims()));
    }
    CHECK(keys.size() == mesh.vertices.size() - interiorVertices(mesh));
}

Volume randomVolume(int n, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    Volume volume({n, n, n}, ScalarType::Float32);
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) volume.setValue(x, y, z, value(random));
    return volume;
}

}  // namespace

TEST_CASE("the trilinear table is watertight and manifold on random volumes", "[core][mc][trilinear]") {
    for (unsigned seed = 1; seed <= 4; ++seed) {
        INFO("seed " << seed);
        const Volume volume = randomVolume(24, seed);  // 12167 random cubes each
        for (int threads : {1, 3}) {
            const Mesh mesh = marchingCubes(volume, 0.0, TableKind::Trilinear, threads);
            requireWatertight(mesh, volume, 0.0);
        }
    }
}

TEST_CASE("the trilinear table is watertight on 64^3 noise at many isovalues", "[core][mc][trilinear]") {
    const Volume volume = makeField({"noise", 64});
    for (double iso : {0.1, 0.3, 0.45, 0.5, 0.55, 0.7, 0.9}) {
        INFO("iso " << iso);
        requireWatertight(marchingCubes(volume, iso, TableKind::Trilinear, 2), volume, iso);
    }
}

TEST_CASE("the trilinear table makes the same mesh on any number of threads", "[core][mc][trilinear]") {
    const Volume volume = makeField({"gyroid", 37});
    const Mesh one = marchingCubes(volume, 0.0, TableKind::Trilinear, 1);
    const Mesh three = marchingCubes(volume, 0.0, TableKind::Trilinear, 3);
    CHECK(isotrack::testing::triangleSet(one, volume.dims()) == isotrack::testing::triangleSet(three, volume.dims()));
    const auto t = topology(one, volume.dims());
    CHECK(t.interiorBoundaryEdges == 0);
}

TEST_CASE("a sphere with the trilinear table is the consistent table's sphere", "[core][mc][trilinear]") {
    // No ambiguous cube: both tables draw the same pieces.
    const Volume volume = makeField({"sphere", 48});
    const Mesh mesh = marchingCubes(volume, 0.0, TableKind::Trilinear);
    const auto t = topology(mesh, volume.dims());
    CHECK(t.boundaryEdges == 0);
    CHECK(t.nonManifoldEdges == 0);
    CHECK(t.euler() == 2);
    CHECK(mesh.triangleCount() == marchingCubes(volume, 0.0, TableKind::Consistent).triangleCount());
}

TEST_CASE("the trilinear pass finds surface at the very ends of rows and alone in a row", "[core][mc][trilinear]") {
    // Rows are trimmed to their first and last change of sign: here the only
    // changes are next to a row's first or last sample, or one sample inside a
    // row, in some rows only; no cube is ambiguous, so the consistent table's
    // mesh is the reference.
    const int n = 13;
    Volume volume({n, n - 2, n - 4}, ScalarType::Float32);
    for (int z = 0; z < n - 4; ++z)
        for (int y = 0; y < n - 2; ++y)
            for (int x = 0; x < n; ++x) {
                const bool end = (x == 0 && y < 4) || (x == n - 1 && z > 5);
                const bool lone = x == 6 && y == 5 && z == 4;
                volume.setValue(x, y, z, end || lone ? 1.0 : 0.0);
            }
    for (int threads : {1, 3}) {
        const Mesh mesh = marchingCubes(volume, 0.5, TableKind::Trilinear, threads);
        const Mesh reference = marchingCubes(volume, 0.5, TableKind::Consistent, threads);
        CHECK(mesh.triangleCount() == reference.triangleCount());
        CHECK(mesh.vertices.size() == countCrossedEdges(volume, 0.5));
    }
}

namespace {

// A vertex as a comparable key: its grid edge, or for an interior vertex its cell and position.
using VertexKey = std::tuple<std::uint64_t, float, float, float>;
using TriangleKey = std::array<VertexKey, 3>;

std::multiset<TriangleKey> triangleKeys(const Mesh& mesh, const Dims& dims) {
    std::multiset<TriangleKey> out;
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f) {
        TriangleKey t;
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = mesh.indices[3 * f + std::size_t(k)];
            const GridEdge e = mesh.vertexEdges[v];
            if (e.axis == kCellInterior) {
                const float* p = mesh.vertices[v].position;
                t[std::size_t(k)] = {isotrack::testing::edgeKey(GridEdge{e.x, e.y, e.z, 0}, dims) * 4 + 3, p[0], p[1],
                                     p[2]};
            } else {
                t[std::size_t(k)] = {isotrack::testing::edgeKey(e, dims) / 3 * 4 + std::uint64_t(e.axis), 0.0f, 0.0f,
                                     0.0f};
            }
        }
        while (t[0] > t[1] || t[0] > t[2]) std::rotate(t.begin(), t.begin() + 1, t.end());
        out.insert(t);
    }
    return out;
}

void requireTrackedAreAllsSurfaces(const Volume& volume, double iso, std::size_t leastSurfaces, bool noisy) {
    const Mesh exhaustive = marchingCubes(volume, iso, TableKind::Trilinear, 2);
    const std::vector<Surface> all = extractAllSurfaces(volume, iso, TableKind::Trilinear, 2);
    REQUIRE(all.size() >= leastSurfaces);
    if (noisy) CHECK(interiorVertices(exhaustive) > 0);  // noisy volumes exercise the interior vertices
    std::multiset<TriangleKey> united;
    std::vector<std::multiset<TriangleKey>> each;
    for (const Surface& surface : all) {
        each.push_back(triangleKeys(surface.mesh, volume.dims()));
        united.insert(each.back().begin(), each.back().end());
        CHECK(surface.stats.triangles == surface.mesh.triangleCount());
    }
    CHECK(united == triangleKeys(exhaustive, volume.dims()));  // every surface together: the exhaustive mesh
    for (std::size_t k = 1; k < all.size(); ++k) CHECK(all[k - 1].stats.triangles >= all[k].stats.triangles);
    // From a crossed edge of every surface (its first vertex on an edge), tracking gives that surface exactly.
    for (std::size_t s = 0; s < all.size(); ++s) {
        const Mesh& mesh = all[s].mesh;
        std::size_t v = 0;
        while (GridEdge(mesh.vertexEdges[v]).axis == kCellInterior) ++v;
        const Surface tracked = trackSurface(volume, iso, mesh.vertexEdges[v], TableKind::Trilinear);
        INFO("surface " << s << " of " << all.size());
        REQUIRE(triangleKeys(tracked.mesh, volume.dims()) == each[s]);
        CHECK(tracked.stats.triangles == all[s].stats.triangles);
    }
}

}  // namespace

TEST_CASE("with the trilinear table, tracking from any surface gives exactly that surface of all",
          "[core][tracking][trilinear]") {
    SECTION("random") { requireTrackedAreAllsSurfaces(randomVolume(16, 5), 0.0, 20, true); }
    SECTION("noise") { requireTrackedAreAllsSurfaces(makeField({"noise", 20}), 0.5, 5, true); }
    SECTION("gyroid") { requireTrackedAreAllsSurfaces(makeField({"gyroid", 24}), 0.0, 1, false); }
    SECTION("blobs") { requireTrackedAreAllsSurfaces(makeField({"blobs", 32}), fieldDefaultIso("blobs"), 10, false); }
}

TEST_CASE("the extraction entry point tracks and splits with the trilinear table", "[core][trilinear]") {
    const Volume volume = makeField({"blobs", 32});
    ExtractRequest request;
    request.table = TableKind::Trilinear;
    request.iso = fieldDefaultIso("blobs");
    request.method = Method::All;
    const std::vector<Surface> all = extract(volume, request);
    CHECK(all.size() > 10);
    request.method = Method::Track;
    request.seeds = {Vec3d{-100, -100, -100}};
    const std::vector<Surface> tracked = extract(volume, request);
    REQUIRE(tracked.size() == 1);
    CHECK(tracked[0].stats.triangles > 0);
}
