// Tracking with the trilinear table on several threads: every thread count
// from 1 to 16 gives the one-thread surface, and the threads share the walk.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "core/mesh_checks.h"
#include "extract/common/sparse_blocks.h"
#include "extract/trilinear/trilinear_walker.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/tracking.h"

using namespace isotrack;
using detail::SparseBlocks;
using isotrack::testing::edgeKey;

namespace {

// A vertex as its grid edge (or cell, for a vertex inside one) and the bits of
// its position and normal: the trilinear table may put more than one vertex
// inside a cell, told apart by where they lie.
using VertexKey = std::tuple<std::uint64_t, std::array<std::uint32_t, 6>>;

VertexKey vertexKey(const Mesh& mesh, std::uint32_t v, const Dims& dims) {
    std::array<std::uint32_t, 6> bits{};
    std::memcpy(bits.data(), mesh.vertices[v].position, 3 * sizeof(float));
    std::memcpy(bits.data() + 3, mesh.vertices[v].normal, 3 * sizeof(float));
    return {edgeKey(mesh.vertexEdges[v], dims), bits};
}

// Each vertex's rank among the one-thread surface's vertices, by key.
using Ranks = std::map<VertexKey, std::uint32_t>;

Ranks vertexRanks(const Mesh& mesh, const Dims& dims) {
    Ranks ranks;
    for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) ranks.emplace(vertexKey(mesh, v, dims), 0);
    std::uint32_t rank = 0;
    for (auto& entry : ranks) entry.second = rank++;
    return ranks;
}

// The mesh's triangles as triples of vertex ranks, rotated so the smallest
// comes first (the winding is kept), sorted; empty when a vertex has no rank
// or two vertices have one.
std::vector<std::array<std::uint32_t, 3>> rankedTriangles(const Mesh& mesh, const Dims& dims, const Ranks& ranks) {
    std::vector<std::uint32_t> rankOf(mesh.vertices.size());
    std::vector<bool> taken(ranks.size(), false);
    for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) {
        const auto found = ranks.find(vertexKey(mesh, v, dims));
        if (found == ranks.end() || taken[found->second]) return {};
        taken[found->second] = true;
        rankOf[v] = found->second;
    }
    std::vector<std::array<std::uint32_t, 3>> out(mesh.triangleCount());
    for (std::size_t f = 0; f < out.size(); ++f) {
        auto& t = out[f];
        for (std::size_t k = 0; k < 3; ++k) t[k] = rankOf[mesh.indices[3 * f + k]];
        while (t[0] > t[1] || t[0] > t[2]) std::rotate(t.begin(), t.begin() + 1, t.end());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Every thread count from 1 to 16 gives the one-thread surface: the same
// vertices (one per crossed edge, by grid edge, position and normal), the same
// triangles (the order follows the walk) and the same figures.
struct OneThread {
    std::size_t pieces = 0;  // (cell, piece) pairs walked
    std::size_t inside = 0;  // vertices inside cells
};

OneThread requireSameOnEveryThreadCount(const Volume& volume, double iso, const GridEdge& seed) {
    const Surface one = trackSurface(volume, iso, seed, TableKind::Trilinear);
    const Ranks ranks = vertexRanks(one.mesh, volume.dims());
    REQUIRE(ranks.size() == one.mesh.vertices.size());  // welded
    const auto triangles = rankedTriangles(one.mesh, volume.dims(), ranks);
    REQUIRE(triangles.size() == one.mesh.triangleCount());
    for (int threads = 2; threads <= 16; ++threads) {
        INFO(threads << " threads");
        const Surface many = trackSurface(volume, iso, seed, TableKind::Trilinear, threads);
        CHECK(many.stats.triangles == one.stats.triangles);
        CHECK(many.stats.vertices == one.stats.vertices);
        CHECK(many.stats.cellsVisited == one.stats.cellsVisited);
        CHECK(many.stats.closed == one.stats.closed);
        CHECK(many.stats.touchesBorder == one.stats.touchesBorder);
        CHECK(many.stats.area == Approx(one.stats.area).epsilon(1e-12));
        CHECK(many.stats.enclosedVolume.has_value() == one.stats.enclosedVolume.has_value());
        if (one.stats.enclosedVolume && many.stats.enclosedVolume)
            CHECK(*many.stats.enclosedVolume == Approx(*one.stats.enclosedVolume).epsilon(1e-12));
        for (int k = 0; k < 3; ++k) {
            CHECK(many.stats.boundsMin[k] == one.stats.boundsMin[k]);
            CHECK(many.stats.boundsMax[k] == one.stats.boundsMax[k]);
        }
        CHECK(many.mesh.vertices.size() == one.mesh.vertices.size());
        CHECK(rankedTriangles(many.mesh, volume.dims(), ranks) == triangles);  // the same vertices too
    }
    OneThread out{one.stats.cellsVisited, 0};
    for (std::size_t v = 0; v < one.mesh.vertexEdges.size(); ++v)
        out.inside += GridEdge(one.mesh.vertexEdges[v]).axis == kCellInterior ? 1 : 0;
    return out;
}

// The largest surface's first vertex on a grid edge, a seed for it.
GridEdge largestSurfaceSeed(const Volume& volume, double iso) {
    const std::vector<Surface> surfaces = extractAllSurfaces(volume, iso, TableKind::Trilinear);
    const Mesh& mesh = surfaces.front().mesh;
    for (std::size_t v = 0; v < mesh.vertexEdges.size(); ++v) {
        const GridEdge e = mesh.vertexEdges[v];
        if (e.axis != kCellInterior) return e;
    }
    FAIL("the largest surface has no vertex on a grid edge");
    return {};
}

}  // namespace

TEST_CASE("trilinear: 1 to 16 threads track the same surface", "[core][tracking][trilinear]") {
    SECTION("a sphere across many tiles (at most 13 threads used)") {
        const Volume volume = makeField({"sphere", 150});
        REQUIRE(SparseBlocks::usefulThreads(volume.dims()) == 13);
        const Vec3d c = sphereFieldCenter(150);
        const GridEdge seed = nearestCrossedEdge(volume, 0.0, {c[0], c[1] + sphereFieldRadius(150), c[2]});
        // More pieces than a walk on several threads walks alone first.
        CHECK(requireSameOnEveryThreadCount(volume, 0.0, seed).pieces > 8192);
    }
    SECTION("a small sphere: more threads than the volume has tiles for are not started") {
        const Volume volume = makeField({"sphere", 64});
        REQUIRE(SparseBlocks::usefulThreads(volume.dims()) == 5);
        const Vec3d c = sphereFieldCenter(64);
        const GridEdge seed = nearestCrossedEdge(volume, 0.0, {c[0] + sphereFieldRadius(64), c[1], c[2]});
        CHECK(requireSameOnEveryThreadCount(volume, 0.0, seed).pieces > 8192);
    }
    SECTION("a sphere walked whole before the other threads would start") {
        const Volume volume = makeField({"sphere", 40});
        const Vec3d c = sphereFieldCenter(40);
        const GridEdge seed = nearestCrossedEdge(volume, 0.0, {c[0], c[1], c[2] + sphereFieldRadius(40)});
        REQUIRE(SparseBlocks::usefulThreads(volume.dims()) == 3);
        CHECK(requireSameOnEveryThreadCount(volume, 0.0, seed).pieces <= 8192);
    }
    SECTION("the gyroid: one sheet through the whole volume (at most 7 threads used)") {
        const Volume volume = makeField({"gyroid", 80});
        REQUIRE(SparseBlocks::usefulThreads(volume.dims()) == 7);
        const double iso = fieldDefaultIso("gyroid");
        CHECK(requireSameOnEveryThreadCount(volume, iso, largestSurfaceSeed(volume, iso)).pieces > 8192);
    }
    SECTION("noise: the largest of many surfaces, with vertices inside cells (at most 3 threads used)") {
        const Volume volume = makeField({"noise", 40});
        REQUIRE(SparseBlocks::usefulThreads(volume.dims()) == 3);
        const double iso = fieldDefaultIso("noise");
        const OneThread one = requireSameOnEveryThreadCount(volume, iso, largestSurfaceSeed(volume, iso));
        CHECK(one.pieces > 8192);
        CHECK(one.inside > 0);
    }
}

TEST_CASE("trilinear: the threads share the walk", "[core][tracking][trilinear]") {
    // Each thread emits pieces of its own tiles, and together every piece once.
    const Volume volume = makeField({"sphere", 150});
    const Vec3d c = sphereFieldCenter(150);
    const GridEdge seed = nearestCrossedEdge(volume, 0.0, {c[0], c[1] + sphereFieldRadius(150), c[2]});
    const Surface one = trackSurface(volume, 0.0, seed, TableKind::Trilinear);
    const auto walker = detail::makeTrilinearWalker(volume, 0.0);
    for (int threads = 2; threads <= 13; ++threads) {
        INFO(threads << " threads");
        std::vector<std::size_t> pieces;
        const Mesh mesh = detail::walkTrilinearTogether(volume, *walker, seed, threads, pieces);
        REQUIRE(int(pieces.size()) == threads);
        std::size_t total = 0;
        for (const std::size_t p : pieces) {
            CHECK(p > 0);
            total += p;
        }
        CHECK(total == one.stats.cellsVisited);
        CHECK(mesh.triangleCount() == one.mesh.triangleCount());
    }
}

TEST_CASE("trilinear CT skull: 1 to 16 threads track the same surface", "[core][tracking][trilinear][ct]") {
    const std::string path = std::string(ISOTRACK_SOURCE_DIR) + "/assets/ct/cranium.nrrd";
    if (!std::ifstream(path)) {
        WARN("skipped: " << path << " is missing (scripts/get_ct.sh makes it)");
        return;
    }
    const Volume volume = loadVolume(path);
    // The largest surface at 400.5 is the skull (the benchmark's).
    CHECK(requireSameOnEveryThreadCount(volume, 400.5, largestSurfaceSeed(volume, 400.5)).pieces > 8192);
}
