#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>

#include "isotrack/chunks.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"

using namespace isotrack;

namespace {

// The samples [lo, lo + dims) of a volume, as a volume of their own.
Volume block(const Volume& volume, const Dims& lo, const Dims& dims) {
    Volume out(dims, ScalarType::Float32);
    for (int z = 0; z < dims[2]; ++z)
        for (int y = 0; y < dims[1]; ++y)
            for (int x = 0; x < dims[0]; ++x) out.setValue(x, y, z, volume.value(lo[0] + x, lo[1] + y, lo[2] + z));
    return out;
}

}  // namespace

TEST_CASE("global edge ids name edges in memory order and back", "[core][chunks]") {
    const Dims dims{7, 5, 3};
    std::uint64_t previous = 0;
    bool first = true;
    for (int z = 0; z < dims[2]; ++z)
        for (int y = 0; y < dims[1]; ++y)
            for (int x = 0; x < dims[0]; ++x)
                for (int axis = 0; axis < 3; ++axis) {
                    const GridEdge edge{x, y, z, axis};
                    const std::uint64_t id = globalEdgeId(edge, dims);
                    CHECK((first || id == previous + 1));
                    CHECK(edgeOfGlobalId(id, dims) == edge);
                    previous = id;
                    first = false;
                }
}

TEST_CASE("chunks' pieces name the whole volume's vertices, shared ones in two chunks or more", "[core][chunks]") {
    const Volume volume = makeField(parseFieldSpec("blobs:32"));
    const double iso = 0.5;
    const Dims n = volume.dims();
    const Mesh whole = marchingCubes(volume, iso);
    std::set<std::uint64_t> expected;
    for (const GridEdge e : whole.vertexEdges) expected.insert(globalEdgeId(e, n));

    // Chunks of 12 samples (the last of 8): each reads one more on its high side.
    std::map<std::uint64_t, int> chunksHolding;
    std::map<std::uint64_t, bool> sharedFlag;
    std::size_t triangles = 0;
    const int size = 12;
    for (int z = 0; z < n[2] - 1; z += size)
        for (int y = 0; y < n[1] - 1; y += size)
            for (int x = 0; x < n[0] - 1; x += size) {
                const Dims lo{x, y, z};
                const Dims dims{std::min(size + 1, n[0] - x), std::min(size + 1, n[1] - y),
                                std::min(size + 1, n[2] - z)};
                for (const Surface& piece : extractAllSurfaces(block(volume, lo, dims), iso)) {
                    triangles += piece.mesh.triangleCount();
                    const ChunkEdges edges = chunkEdges(piece.mesh, lo, dims, n);
                    for (std::size_t v = 0; v < edges.ids.size(); ++v) {
                        ++chunksHolding[edges.ids[v]];
                        sharedFlag[edges.ids[v]] = edges.shared[v] != 0;
                        const GridEdge e = edgeOfGlobalId(edges.ids[v], n);
                        const bool border = (e.axis != 0 && (e.x == 0 || e.x == n[0] - 1)) ||
                                            (e.axis != 1 && (e.y == 0 || e.y == n[1] - 1)) ||
                                            (e.axis != 2 && (e.z == 0 || e.z == n[2] - 1));
                        CHECK((edges.onBorder[v] != 0) == border);
                    }
                }
            }
    CHECK(triangles == whole.triangleCount());
    std::set<std::uint64_t> found;
    for (const auto& [id, count] : chunksHolding) {
        found.insert(id);
        // Shared edges are met in every chunk around them (2 or 4); others in one.
        CHECK((sharedFlag[id] ? count >= 2 : count == 1));
    }
    CHECK(found == expected);
}

TEST_CASE("a chunk outside its volume is refused, naming it", "[core][chunks]") {
    const Mesh empty;
    CHECK_THROWS_AS(chunkEdges(empty, {30, 0, 0}, {4, 4, 4}, {32, 32, 32}), InputError);
    CHECK_THROWS_WITH(chunkEdges(empty, {30, 0, 0}, {4, 4, 4}, {32, 32, 32}), Catch::Contains("(30, 0, 0)"));
}
