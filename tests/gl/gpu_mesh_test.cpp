// GpuMesh: byte sizes, growth by appending, and that only new data is uploaded.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>

#include "gl_test_support.h"
#include "isotrack/fields.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"
#include "render/gpu_mesh.h"

using namespace isotrack;

namespace {

Mesh sphereMesh(int n) {
    const Volume volume = makeField(parseFieldSpec("sphere:" + std::to_string(n)));
    return marchingCubes(volume, fieldDefaultIso("sphere"));
}

// The GPU buffers hold exactly the mesh's vertices and indices.
void requireSameContents(const render::GpuMesh& gpu, const Mesh& mesh) {
    REQUIRE(gpu.vertexCount() == mesh.vertices.size());
    REQUIRE(gpu.indexCount() == mesh.indices.size());
    std::vector<Vertex> vertices(mesh.vertices.size());
    Buffer<std::uint32_t> indices(mesh.indices.size());
    gpu.vertexBuffer().read(0, vertices.size() * sizeof(Vertex), vertices.data());
    gpu.indexBuffer().read(0, indices.size() * sizeof(std::uint32_t), indices.data());
    CHECK(std::memcmp(vertices.data(), mesh.vertices.data(), vertices.size() * sizeof(Vertex)) == 0);
    CHECK(indices == mesh.indices);
}

}  // namespace

TEST_CASE("a GpuMesh built from a mesh has exactly its size", "[gl]") {
    test::useHeadlessGl();
    const Mesh mesh = sphereMesh(24);
    const render::GpuMesh gpu(mesh);
    const render::GpuMeshBytes bytes = gpu.bytes();
    CHECK(bytes.vertexBytes == mesh.vertices.size() * sizeof(Vertex));
    CHECK(bytes.indexBytes == mesh.indices.size() * sizeof(std::uint32_t));
    CHECK(bytes.capacityBytes == mesh.drawByteSize());
    CHECK(gpu.uploadedBytes() == mesh.drawByteSize());
    requireSameContents(gpu, mesh);
}

TEST_CASE("appending uploads only the new ranges and doubles capacity", "[gl]") {
    test::useHeadlessGl();
    const Mesh whole = sphereMesh(40);
    // Grow a copy of the mesh a slice of triangles at a time, as a tracker would.
    Mesh growing;
    render::GpuMesh gpu;
    CHECK(gpu.bytes().capacityBytes == 0);
    std::size_t reallocations = 0, previousCapacity = 0;
    const std::size_t slice = 3 * 97;
    for (std::size_t first = 0; first < whole.indices.size(); first += slice) {
        const std::size_t last = std::min(first + slice, whole.indices.size());
        render::MeshRange range{growing.vertices.size(), 0, growing.indices.size(), last - first};
        growing.indices.insert(growing.indices.end(), whole.indices.begin() + long(first),
                               whole.indices.begin() + long(last));
        std::uint32_t highest = 0;
        for (std::size_t i = first; i < last; ++i) highest = std::max(highest, whole.indices[i]);
        if (highest + 1 > growing.vertices.size()) {
            range.vertexCount = highest + 1 - growing.vertices.size();
            growing.vertices.insert(growing.vertices.end(), whole.vertices.begin() + long(growing.vertices.size()),
                                    whole.vertices.begin() + long(highest) + 1);
        }
        gpu.append(growing, range);
        if (gpu.bytes().capacityBytes != previousCapacity) ++reallocations;
        previousCapacity = gpu.bytes().capacityBytes;
        CHECK(gpu.uploadedBytes() == growing.drawByteSize());
    }
    requireSameContents(gpu, growing);
    CHECK(growing.indices == whole.indices);
    // Doubling: a logarithmic number of reallocations, never more than twice the space needed
    // (beyond the minimum first allocation).
    CHECK(reallocations <= 2 * 12);
    CHECK(gpu.bytes().capacityBytes <= 2 * growing.drawByteSize() + 64 * 1024);
}

TEST_CASE("appending a range that does not continue the mesh is refused", "[gl]") {
    test::useHeadlessGl();
    const Mesh mesh = sphereMesh(16);
    render::GpuMesh gpu(mesh);
    CHECK_THROWS_AS(gpu.append(mesh, render::MeshRange{0, 3, 0, 3}), std::invalid_argument);
    gpu.appendNew(mesh);  // nothing new: a no-op
    CHECK(gpu.uploadedBytes() == mesh.drawByteSize());
}

TEST_CASE("a GpuMesh follows a SurfaceTracker step by step", "[gl][tracking]") {
    test::useHeadlessGl();
    const Volume volume = makeField(parseFieldSpec("torus:48"));
    const double iso = fieldDefaultIso("torus");
    SurfaceTracker tracker(volume, iso);
    tracker.start(nearestCrossedEdge(volume, iso, {24.0, 24.0, 24.0}));
    render::GpuMesh gpu;
    int steps = 0;
    while (!tracker.done()) {
        const SurfaceTracker::Step step = tracker.step(200);
        gpu.append(tracker.mesh(), step);
        ++steps;
    }
    CHECK(steps > 3);
    CHECK(gpu.uploadedBytes() == tracker.mesh().drawByteSize());
    requireSameContents(gpu, tracker.mesh());
}
