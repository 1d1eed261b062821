// GpuMesh in a SurfaceArena: byte sizes, growth by appending (only new data
// uploaded, in place while the space after it is free, GPU-side moves
// otherwise), and freed ranges reused.
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

constexpr std::size_t kSlotBytes = sizeof(std::uint32_t);

Mesh sphereMesh(int n) {
    const Volume volume = makeField(parseFieldSpec("sphere:" + std::to_string(n)));
    return marchingCubes(volume, fieldDefaultIso("sphere"));
}

// What the arena sends for a mesh: vertices, one slot number per vertex, indices.
std::size_t sentBytes(const Mesh& mesh) { return mesh.drawByteSize() + mesh.vertices.size() * kSlotBytes; }

// The GPU ranges hold exactly the mesh's vertices and indices, and every vertex the slot's number.
void requireSameContents(const render::GpuMesh& gpu, const Mesh& mesh) {
    REQUIRE(gpu.vertexCount() == mesh.vertices.size());
    REQUIRE(gpu.indexCount() == mesh.indices.size());
    const std::vector<Vertex> vertices = gpu.readVertices();
    const std::vector<std::uint32_t> indices = gpu.readIndices();
    CHECK(std::memcmp(vertices.data(), mesh.vertices.data(), vertices.size() * sizeof(Vertex)) == 0);
    CHECK(std::equal(indices.begin(), indices.end(), mesh.indices.begin(), mesh.indices.end()));
    const std::vector<std::uint32_t> slots = gpu.readSlotNumbers();
    CHECK(std::count(slots.begin(), slots.end(), gpu.slot()) == static_cast<long>(slots.size()));
}

// Grows `gpu` with `whole`'s triangles a slice at a time, as a tracker would.
Mesh growInSlices(render::GpuMesh& gpu, const Mesh& whole, std::size_t slice) {
    Mesh growing;
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
        CHECK(gpu.uploadedBytes() == sentBytes(growing));  // nothing sent twice
    }
    return growing;
}

render::ArenaOptions smallPages() {
    render::ArenaOptions options;
    options.pageVertices = 4096;
    return options;
}

}  // namespace

TEST_CASE("a GpuMesh built from a mesh has exactly its size", "[gl][arena]") {
    test::useHeadlessGl();
    render::SurfaceArena arena;
    const Mesh mesh = sphereMesh(24);
    const render::GpuMesh gpu(arena, mesh);
    const render::GpuMeshBytes bytes = gpu.bytes();
    CHECK(bytes.vertexBytes == mesh.vertices.size() * sizeof(Vertex));
    CHECK(bytes.indexBytes == mesh.indices.size() * sizeof(std::uint32_t));
    CHECK(bytes.capacityBytes == sentBytes(mesh));
    CHECK(gpu.uploadedBytes() == sentBytes(mesh));
    requireSameContents(gpu, mesh);
}

TEST_CASE("a growing GpuMesh stays in place while the space after it is free", "[gl][arena]") {
    test::useHeadlessGl();
    render::SurfaceArena arena;
    const Mesh whole = sphereMesh(40);
    render::GpuMesh gpu(arena);
    CHECK(gpu.bytes().capacityBytes == 0);
    const Mesh grown = growInSlices(gpu, whole, 3 * 97);
    requireSameContents(gpu, grown);
    CHECK(grown.indices == whole.indices);
    CHECK(arena.stats().moves == 0);
    CHECK(gpu.bytes().capacityBytes <= 2 * sentBytes(grown) + 64 * 1024);  // about twice, ahead
    gpu.shrinkToFit();
    CHECK(gpu.bytes().capacityBytes == sentBytes(grown));
    requireSameContents(gpu, grown);
}

TEST_CASE("a growing GpuMesh boxed in by another moves GPU-side", "[gl][arena]") {
    test::useHeadlessGl();
    render::SurfaceArena arena(smallPages());
    const Mesh whole = sphereMesh(40), small = sphereMesh(8);
    render::GpuMesh gpu(arena);
    gpu.append(whole, render::MeshRange{0, 3, 0, 3});  // a first triangle, then a neighbour right after it
    const render::GpuMesh neighbour(arena, small);
    CHECK(neighbour.place().page == gpu.place().page);
    gpu.appendNew(whole);  // the rest of it: more than its reserve, and no room after it
    const render::ArenaStats stats = arena.stats();
    CHECK(stats.moves >= 1);
    CHECK(stats.movedBytes > 0);
    CHECK(gpu.uploadedBytes() == sentBytes(whole));  // moved, not sent again
    requireSameContents(gpu, whole);
    requireSameContents(neighbour, small);
}

TEST_CASE("freed ranges are reused and fragmentation is reported", "[gl][arena]") {
    test::useHeadlessGl();
    render::SurfaceArena arena(smallPages());
    const Mesh small = sphereMesh(8);
    std::vector<render::GpuMesh> meshes;
    for (int i = 0; i < 6; ++i) meshes.emplace_back(arena, small);
    const render::ArenaStats full = arena.stats();
    CHECK(full.pages == 1);
    CHECK(full.fragmentation == 0.0);
    meshes[1] = render::GpuMesh(arena);  // frees the second surface's ranges: a hole
    meshes[3] = render::GpuMesh(arena);
    const render::ArenaStats holes = arena.stats();
    CHECK(holes.freeBytes == full.freeBytes + 2 * sentBytes(small));
    CHECK(holes.fragmentation > 0.0);
    const render::GpuMesh again(arena, small);  // first fit: the first hole
    CHECK(again.place().firstVertex == small.vertices.size());
    CHECK(again.place().page == 0);
    requireSameContents(again, small);
}

TEST_CASE("appending a range that does not continue the mesh is refused", "[gl][arena]") {
    test::useHeadlessGl();
    render::SurfaceArena arena;
    const Mesh mesh = sphereMesh(16);
    render::GpuMesh gpu(arena, mesh);
    CHECK_THROWS_AS(gpu.append(mesh, render::MeshRange{0, 3, 0, 3}), std::invalid_argument);
    gpu.appendNew(mesh);  // nothing new: a no-op
    CHECK(gpu.uploadedBytes() == sentBytes(mesh));
}

TEST_CASE("a GpuMesh follows a SurfaceTracker step by step", "[gl][tracking][arena]") {
    test::useHeadlessGl();
    render::SurfaceArena arena;
    const Volume volume = makeField(parseFieldSpec("torus:48"));
    const double iso = fieldDefaultIso("torus");
    SurfaceTracker tracker(volume, iso);
    tracker.start(nearestCrossedEdge(volume, iso, {24.0, 24.0, 24.0}));
    render::GpuMesh gpu(arena);
    int steps = 0;
    while (!tracker.done()) {
        const SurfaceTracker::Step step = tracker.step(200);
        gpu.append(tracker.mesh(), step);
        ++steps;
    }
    CHECK(steps > 3);
    CHECK(gpu.uploadedBytes() == sentBytes(tracker.mesh()));
    requireSameContents(gpu, tracker.mesh());
}
