#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

#include "core/mesh_checks.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"

using namespace isotrack;
using isotrack::testing::topology;

namespace {

double meshArea(const Mesh& mesh) {
    double area = 0.0;
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f) {
        const float* a = mesh.vertices[mesh.indices[3 * f]].position;
        const float* b = mesh.vertices[mesh.indices[3 * f + 1]].position;
        const float* c = mesh.vertices[mesh.indices[3 * f + 2]].position;
        const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
        const double v[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    return area;
}

void requireWatertight(const Mesh& mesh, const Volume& volume, double iso) {
    const auto t = topology(mesh, volume.dims());
    CHECK(t.interiorBoundaryEdges == 0);
    CHECK(t.nonManifoldEdges == 0);
    CHECK(t.repeatedDirectedEdges == 0);
    CHECK(mesh.vertices.size() == countCrossedEdges(volume, iso));
}

}  // namespace

TEST_CASE("a sphere is one closed genus-0 surface with the analytic area", "[core][mc]") {
    const int n = 128;
    const Volume volume = makeField({"sphere", n});
    const Mesh mesh = marchingCubes(volume, 0.0);
    const auto t = topology(mesh, volume.dims());
    CHECK(t.boundaryEdges == 0);
    CHECK(t.nonManifoldEdges == 0);
    CHECK(t.repeatedDirectedEdges == 0);
    CHECK(t.euler() == 2);
    CHECK(isotrack::testing::duplicatePositions(mesh) == 0);
    const double r = sphereFieldRadius(n);
    CHECK(meshArea(mesh) == Approx(4.0 * M_PI * r * r).epsilon(0.01));

    // Normals are unit, point out of the ball (down the gradient), and the winding agrees.
    const Vec3d c = sphereFieldCenter(n);
    for (const Vertex& v : mesh.vertices) {
        double len = 0.0, outward = 0.0;
        for (int k = 0; k < 3; ++k) {
            len += double(v.normal[k]) * v.normal[k];
            outward += double(v.normal[k]) * (v.position[k] - c[k]) / r;
        }
        REQUIRE(std::sqrt(len) == Approx(1.0).epsilon(1e-5));
        REQUIRE(outward > 0.95);
    }
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f) {
        const Vertex& a = mesh.vertices[mesh.indices[3 * f]];
        const Vertex& b = mesh.vertices[mesh.indices[3 * f + 1]];
        const Vertex& cc = mesh.vertices[mesh.indices[3 * f + 2]];
        double u[3], v[3], dot = 0.0;
        for (int k = 0; k < 3; ++k) u[k] = b.position[k] - a.position[k], v[k] = cc.position[k] - a.position[k];
        const double nrm[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        for (int k = 0; k < 3; ++k) dot += nrm[k] * (a.normal[k] + b.normal[k] + cc.normal[k]);
        REQUIRE(dot >= 0.0);
    }
}

TEST_CASE("a torus is closed with Euler characteristic 0", "[core][mc]") {
    const Volume volume = makeField({"torus", 96});
    const Mesh mesh = marchingCubes(volume, 0.0);
    const auto t = topology(mesh, volume.dims());
    CHECK(t.boundaryEdges == 0);
    CHECK(t.nonManifoldEdges == 0);
    CHECK(t.euler() == 0);
    const auto radii = torusFieldRadii(96);
    CHECK(meshArea(mesh) == Approx(4.0 * M_PI * M_PI * radii[0] * radii[1]).epsilon(0.01));
}

TEST_CASE("each crossed grid edge yields exactly one vertex, on that edge", "[core][mc]") {
    // 37: rows whose length is not a multiple of 8; 1 and 3 threads: one chunk, several seams.
    for (const char* name : {"sphere", "gyroid", "marschner-lobb", "noise"}) {
        for (int size : {40, 37}) {
            for (int threads : {1, 3}) {
                const Volume volume = makeField(parseFieldSpec(std::string(name) + ":" + std::to_string(size)));
                const double iso = fieldDefaultIso(name);
                const Mesh mesh = marchingCubes(volume, iso, TableKind::Consistent, threads);
                INFO(name << " " << size << " on " << threads << " threads");
                CHECK(mesh.vertices.size() == countCrossedEdges(volume, iso));
                CHECK(isotrack::testing::vertexEdgeSet(mesh, volume.dims()).size() == mesh.vertices.size());
                for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
                    const GridEdge e = mesh.vertexEdges[i];
                    const int p[3] = {e.x, e.y, e.z};
                    for (int k = 0; k < 3; ++k) {
                        const float lo = float(p[k]), hi = float(p[k] + (k == e.axis));
                        REQUIRE(mesh.vertices[i].position[k] >= lo);
                        REQUIRE(mesh.vertices[i].position[k] <= hi);
                    }
                }
            }
        }
    }
}

TEST_CASE("rows longer than 2040 samples, crossed at every sample, count every crossed edge", "[core][mc]") {
    // Crossings are counted 8 flags to a word, 255 words at a time: rows of 2100 samples in
    // which every z-edge between the slices is crossed fill those sums to the brim, twice.
    const int nx = 2100;
    Volume volume({nx, 2, 3}, ScalarType::UInt8);
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < nx; ++x) {
                const bool above = (z == 1) != (x == 0);  // one change per row keeps every row's span open
                volume.setValue(x, y, z, above ? 1.0 : 0.0);
            }
    REQUIRE(countCrossedEdges(volume, 0.5) == std::size_t(4 * nx + 6));  // every z-edge, one x-edge per row
    for (int threads : {1, 2}) {
        INFO(threads << " threads");
        const Mesh mesh = marchingCubes(volume, 0.5, TableKind::Consistent, threads);
        CHECK(mesh.vertices.size() == countCrossedEdges(volume, 0.5));
        CHECK(isotrack::testing::vertexEdgeSet(mesh, volume.dims()).size() == mesh.vertices.size());
    }
}

TEST_CASE("the consistent table is watertight on white noise; the classic one is not", "[core][mc]") {
    const Volume volume = makeField({"noise", 48});
    requireWatertight(marchingCubes(volume, 0.5, TableKind::Consistent), volume, 0.5);
    const auto classic = topology(marchingCubes(volume, 0.5, TableKind::Classic), volume.dims());
    CHECK(classic.interiorBoundaryEdges > 0);
}

TEST_CASE("samples equal to the isovalue make neither holes nor duplicate faces", "[core][mc]") {
    // Integer samples 0..4 with iso 2: a fifth of all samples sit exactly on the isovalue.
    Volume volume({40, 40, 40}, ScalarType::UInt8);
    std::uint64_t state = 12345;
    for (int z = 0; z < 40; ++z)
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 40; ++x) {
                state = state * 6364136223846793005ull + 1442695040888963407ull;
                volume.setValue(x, y, z, double((state >> 33) % 5));
            }
    const Mesh mesh = marchingCubes(volume, 2.0);
    const auto t = topology(mesh, volume.dims());
    CHECK(t.interiorBoundaryEdges == 0);
    CHECK(t.nonManifoldEdges == 0);
    CHECK(t.repeatedDirectedEdges == 0);
    CHECK(mesh.vertices.size() == countCrossedEdges(volume, 2.0));
    std::set<std::array<std::uint32_t, 3>> faces;
    for (std::size_t f = 0; f < mesh.triangleCount(); ++f) {
        std::array<std::uint32_t, 3> tri{mesh.indices[3 * f], mesh.indices[3 * f + 1], mesh.indices[3 * f + 2]};
        std::sort(tri.begin(), tri.end());
        CHECK(faces.insert(tri).second);
    }
}

TEST_CASE("positions are in world units: spacing and origin are honoured", "[core][mc]") {
    Volume volume = makeField({"sphere", 32});
    const Mesh unit = marchingCubes(volume, 0.0);
    volume.setSpacing({0.5, 2.0, 1.5});
    volume.setOrigin({10.0, -4.0, 3.0});
    const Mesh scaled = marchingCubes(volume, 0.0);
    REQUIRE(scaled.vertices.size() == unit.vertices.size());
    for (std::size_t i = 0; i < unit.vertices.size(); ++i) {
        CHECK(scaled.vertices[i].position[0] == Approx(10.0 + 0.5 * unit.vertices[i].position[0]));
        CHECK(scaled.vertices[i].position[1] == Approx(-4.0 + 2.0 * unit.vertices[i].position[1]));
        CHECK(scaled.vertices[i].position[2] == Approx(3.0 + 1.5 * unit.vertices[i].position[2]));
    }
}

TEST_CASE("native sample types give the same surface as their float widening", "[core][mc]") {
    Volume narrow({24, 20, 16}, ScalarType::Int16);
    Volume wide({24, 20, 16}, ScalarType::Float32);
    for (int z = 0; z < 16; ++z)
        for (int y = 0; y < 20; ++y)
            for (int x = 0; x < 24; ++x) {
                const double v = std::round(1000.0 * std::sin(0.4 * x) * std::cos(0.3 * y) + 40.0 * z - 300.0);
                narrow.setValue(x, y, z, v);
                wide.setValue(x, y, z, v);
            }
    const Mesh a = marchingCubes(narrow, 100.5);
    const Mesh b = marchingCubes(wide, 100.5);
    CHECK(narrow.byteSize() == 2 * narrow.sampleCount());
    CHECK(isotrack::testing::triangleSet(a, narrow.dims()) == isotrack::testing::triangleSet(b, wide.dims()));
}

TEST_CASE("the CT skull is watertight away from the border with one vertex per crossed edge", "[core][mc][ct]") {
    const std::string path = std::string(ISOTRACK_SOURCE_DIR) + "/assets/ct/cranium.nrrd";
    if (!std::ifstream(path)) {
        WARN("skipped: " << path << " is missing (scripts/get_ct.sh makes it)");
        return;
    }
    const Volume volume = loadVolume(path);
    const Mesh mesh = marchingCubes(volume, 400.5);
    const auto t = topology(mesh, volume.dims());
    CHECK(mesh.triangleCount() == 657090);  // VTK's vtkMarchingCubes and vtkFlyingEdges3D agree on this count
    CHECK(t.interiorBoundaryEdges == 0);
    CHECK(t.nonManifoldEdges == 0);
    CHECK(t.repeatedDirectedEdges == 0);
    CHECK(mesh.vertices.size() == countCrossedEdges(volume, 400.5));
}

TEST_CASE("counting the samples at or above the isovalue agrees with classifying each one", "[core][mc]") {
    // 70 x 41 x 29 samples: more than one 65536-sample block, and parts of uneven length on 3 threads.
    const Dims dims{70, 41, 29};
    for (ScalarType type : {ScalarType::Int16, ScalarType::UInt8, ScalarType::Float32, ScalarType::Float64}) {
        INFO("type " << int(type));
        Volume volume(dims, type);
        std::uint32_t state = 12345;
        for (int z = 0; z < dims[2]; ++z)
            for (int y = 0; y < dims[1]; ++y)
                for (int x = 0; x < dims[0]; ++x) {
                    state = state * 1664525u + 1013904223u;
                    volume.setValue(x, y, z, double(state >> 24) - (type == ScalarType::UInt8 ? 0.0 : 100.0));
                }
        const bool floating = type == ScalarType::Float32 || type == ScalarType::Float64;
        if (floating) volume.setValue(3, 4, 5, std::nan(""));  // NaN is below every isovalue
        for (double iso : {-1000.0, -100.0, 0.0, 20.0, 20.5, 155.0, 1000.0}) {
            std::size_t expected = 0;
            for (int z = 0; z < dims[2]; ++z)
                for (int y = 0; y < dims[1]; ++y)
                    for (int x = 0; x < dims[0]; ++x) expected += volume.value(x, y, z) >= iso;
            for (int threads : {1, 2, 3}) {
                INFO("iso " << iso << ", " << threads << " threads");
                CHECK(countSamplesAbove(volume, iso, threads) == expected);
            }
        }
    }
}
