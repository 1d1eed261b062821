#include <catch2/catch.hpp>

#include <cmath>
#include <initializer_list>

#include "isotrack/mesh_processing.h"

using namespace isotrack;

namespace {

Mesh meshOf(std::initializer_list<std::array<float, 3>> points, std::initializer_list<std::uint32_t> indices) {
    Mesh mesh;
    for (const auto& p : points) mesh.vertices.push_back(Vertex{{p[0], p[1], p[2]}, {0, 0, 1}});
    for (std::uint32_t i : indices) mesh.indices.push_back(i);
    return mesh;
}

}  // namespace

TEST_CASE("a tetrahedron has no border, no pinch, no thin triangle", "[core][mesh]") {
    const Mesh tetra = meshOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3});
    const MeshQuality q = measureQuality(tetra);
    CHECK(q.degenerateTriangles == 0);
    CHECK(q.boundaryEdges == 0);
    CHECK(q.nonManifoldEdges == 0);
    CHECK(q.minAngleBelow20 == 0.0);
}

TEST_CASE("quality counts zero-area and thin triangles, and welds coincident vertices", "[core][mesh]") {
    // Triangle 0: smallest angle atan(0.1) = 5.7 degrees. Triangle 1: two
    // corners at one place (zero area). Vertex 4 repeats vertex 1's position.
    const Mesh mesh = meshOf({{0, 0, 0}, {1, 0, 0}, {0, 0.1f, 0}, {2, 2, 2}, {1, 0, 0}}, {0, 1, 2, 3, 1, 4});
    const MeshQuality q = measureQuality(mesh);
    CHECK(q.degenerateTriangles == 1);
    CHECK(q.minAngleBelow1 == 0.5);   // the degenerate one
    CHECK(q.minAngleBelow10 == 1.0);  // and the 5.7-degree one
    // Welding 4 into 1 collapses triangle 1: triangle 0's three edges are left.
    CHECK(q.boundaryEdges == 3);
    CHECK(q.nonManifoldEdges == 0);

    // Three triangles on one edge.
    const Mesh fan = meshOf({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {0, 1, 2, 1, 0, 3, 0, 1, 4});
    CHECK(measureQuality(fan).nonManifoldEdges == 1);
}
