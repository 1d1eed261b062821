#include <catch2/catch.hpp>

#include <random>
#include <set>

#include "core/mesh_checks.h"
#include "isotrack/errors.h"
#include "isotrack/extract.h"
#include "isotrack/fields.h"
#include "isotrack/marching_cubes.h"

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

TEST_CASE("track and all refuse the trilinear table with one line", "[core][trilinear]") {
    const Volume volume = makeField({"sphere", 16});
    for (Method method : {Method::Track, Method::All}) {
        ExtractRequest request;
        request.method = method;
        request.table = TableKind::Trilinear;
        request.seeds = {Vec3d{8, 8, 8}};
        CHECK_THROWS_AS(extract(volume, request), InputError);
    }
}
