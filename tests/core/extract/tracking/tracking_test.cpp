#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>

#include "core/mesh_checks.h"
#include "isotrack/continuation.h"
#include "isotrack/cube.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"

using namespace isotrack;
using isotrack::testing::triangleSet;
using isotrack::testing::vertexEdgeSet;

namespace {

std::set<std::uint16_t> pieceMasks(const CaseContinuation& c) {
    std::set<std::uint16_t> masks;
    for (int p = 0; p < c.pieceCount; ++p) masks.insert(c.pieces[p].edgeMask);
    return masks;
}

std::uint16_t rotateMask(std::uint16_t mask, const cube::Rotation& r) {
    unsigned out = 0;
    for (int e = 0; e < 12; ++e) {
        if (mask >> e & 1u) out |= 1u << r.edge[e];
    }
    return static_cast<std::uint16_t>(out);
}

// The number of connected components of a mesh, joining triangles through shared vertices.
std::size_t connectedComponents(const Mesh& mesh) {
    std::vector<std::uint32_t> parent(mesh.vertices.size());
    for (std::uint32_t v = 0; v < parent.size(); ++v) parent[v] = v;
    auto find = [&](std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        parent[find(mesh.indices[i])] = find(mesh.indices[i + 1]);
        parent[find(mesh.indices[i + 1])] = find(mesh.indices[i + 2]);
    }
    std::set<std::uint32_t> roots;
    for (std::uint32_t v = 0; v < parent.size(); ++v) roots.insert(find(v));
    return roots.size();
}

// The figures of one surface made two ways: equal, area and volume up to the
// order of their sums.
void checkSameFigures(const SurfaceStats& a, const SurfaceStats& b, double epsilon = 1e-9) {
    CHECK(a.triangles == b.triangles);
    CHECK(a.vertices == b.vertices);
    CHECK(a.bytes == b.bytes);
    CHECK(a.cellsVisited == b.cellsVisited);
    CHECK(a.closed == b.closed);
    CHECK(a.touchesBorder == b.touchesBorder);
    CHECK(a.boundsMin == b.boundsMin);
    CHECK(a.boundsMax == b.boundsMax);
    CHECK(a.area == Approx(b.area).epsilon(epsilon));
    REQUIRE(a.enclosedVolume.has_value() == b.enclosedVolume.has_value());
    if (a.enclosedVolume) CHECK(*a.enclosedVolume == Approx(*b.enclosedVolume).epsilon(epsilon));
}

// Every surface of a field together must be the exhaustive mesh, split.
void requireSurfacesEqualExhaustive(const Volume& volume, double iso, TableKind table,
                                    const std::vector<Surface>& surfaces) {
    const Mesh whole = marchingCubes(volume, iso, table);
    std::multiset<std::array<std::uint64_t, 3>> united;
    std::set<std::uint64_t> seenEdges;
    std::size_t vertices = 0;
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        const auto tris = triangleSet(surfaces[i].mesh, volume.dims());
        united.insert(tris.begin(), tris.end());
        const auto edges = vertexEdgeSet(surfaces[i].mesh, volume.dims());
        CHECK(edges.size() == surfaces[i].mesh.vertices.size());            // one vertex per crossed edge
        for (std::uint64_t e : edges) REQUIRE(seenEdges.insert(e).second);  // no vertex shared by two surfaces
        vertices += surfaces[i].mesh.vertices.size();
        CHECK(connectedComponents(surfaces[i].mesh) == 1);
        if (i > 0) CHECK(surfaces[i - 1].mesh.triangleCount() >= surfaces[i].mesh.triangleCount());
    }
    CHECK(united == triangleSet(whole, volume.dims()));
    CHECK(vertices == whole.vertices.size());
}

// Tracking every surface, and labelling the exhaustive mesh on one to three
// threads (surfaces labelled across the seams of 1, 8 and 12 chunks, split in
// 1, 2 and 3 ranges), must give the same surfaces in the same order.
void requireAllEqualsExhaustive(const Volume& volume, double iso, TableKind table) {
    const auto tracked = trackAllSurfaces(volume, iso, table);
    requireSurfacesEqualExhaustive(volume, iso, table, tracked);
    for (int threads : {1, 2, 3}) {
        INFO(threads << " threads");
        const auto labelled = extractAllSurfaces(volume, iso, table, threads);
        requireSurfacesEqualExhaustive(volume, iso, table, labelled);
        REQUIRE(labelled.size() == tracked.size());
        for (std::size_t i = 0; i < tracked.size(); ++i) {
            CHECK(triangleSet(labelled[i].mesh, volume.dims()) == triangleSet(tracked[i].mesh, volume.dims()));
            checkSameFigures(labelled[i].stats, tracked[i].stats);
        }
    }
}

// Every tracked vertex, position and normal, is bit for bit the exhaustive pass's
// vertex on the same grid edge, inside the volume and on its border alike.
void requireSameVertexBits(const Volume& volume, double iso) {
    const Mesh whole = marchingCubes(volume, iso);
    std::map<std::uint64_t, Vertex> vertexOfEdge;
    for (std::size_t v = 0; v < whole.vertices.size(); ++v) {
        vertexOfEdge[isotrack::testing::edgeKey(whole.vertexEdges[v], volume.dims())] = whole.vertices[v];
    }
    std::size_t compared = 0;
    for (const Surface& s : trackAllSurfaces(volume, iso)) {
        for (std::size_t v = 0; v < s.mesh.vertices.size(); ++v) {
            const Vertex& expected = vertexOfEdge.at(isotrack::testing::edgeKey(s.mesh.vertexEdges[v], volume.dims()));
            REQUIRE(std::memcmp(&s.mesh.vertices[v], &expected, sizeof(Vertex)) == 0);
            ++compared;
        }
    }
    CHECK(compared == whole.vertices.size());
}

// White noise of size n as int16 samples (0..1000), with anisotropic spacing and an offset origin.
Volume int16Noise(int n) {
    const Volume noise = makeField({"noise", n});
    Volume volume(noise.dims(), ScalarType::Int16, {0.75, 1.0, 1.5}, {-3.0, 2.0, 0.5});
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) volume.setValue(x, y, z, std::round(1000.0 * noise.value(x, y, z)));
    return volume;
}

// The surface tracked on several threads is the one-thread surface: the same
// triangles, one vertex per crossed edge with the same bits, the same figures.
void requireSameSurfaceOnThreads(const Volume& volume, double iso, const GridEdge& seed) {
    const Surface one = trackSurface(volume, iso, seed);
    REQUIRE(one.stats.cellsVisited > 8192);  // more than a walk on several threads walks alone first
    std::map<std::uint64_t, Vertex> vertexOfEdge;
    for (std::size_t v = 0; v < one.mesh.vertices.size(); ++v) {
        vertexOfEdge[isotrack::testing::edgeKey(one.mesh.vertexEdges[v], volume.dims())] = one.mesh.vertices[v];
    }
    REQUIRE(vertexOfEdge.size() == one.mesh.vertices.size());
    for (int threads : {2, 3, 8}) {
        INFO(threads << " threads");
        const Surface many = trackSurface(volume, iso, seed, TableKind::Consistent, threads);
        REQUIRE(many.mesh.vertices.size() == one.mesh.vertices.size());
        REQUIRE(many.mesh.vertexEdges.size() == one.mesh.vertices.size());
        CHECK(triangleSet(many.mesh, volume.dims()) == triangleSet(one.mesh, volume.dims()));
        std::set<std::uint64_t> edges;
        std::size_t differing = 0;
        for (std::size_t v = 0; v < many.mesh.vertices.size(); ++v) {
            const std::uint64_t key = isotrack::testing::edgeKey(many.mesh.vertexEdges[v], volume.dims());
            edges.insert(key);
            const auto expected = vertexOfEdge.find(key);
            if (expected == vertexOfEdge.end() ||
                std::memcmp(&many.mesh.vertices[v], &expected->second, sizeof(Vertex)) != 0)
                ++differing;
        }
        CHECK(edges.size() == many.mesh.vertices.size());  // welded: no edge has two vertices
        CHECK(differing == 0);
        checkSameFigures(many.stats, one.stats, 1e-12);
        // Closed by every edge, not only by the border: seams between threads are welded.
        CHECK(measureSurface(many.mesh, volume, false).closed == one.stats.closed);
    }
}

}  // namespace

TEST_CASE("several threads track the same surface as one", "[core][tracking]") {
    // Threads walk tiles of 64^3 to 8^3 samples: these surfaces cross the seams at 64.
    SECTION("a sphere, closed, seeded on a seam") {
        const int n = 150;
        const Volume volume = makeField({"sphere", n});
        const Vec3d c = sphereFieldCenter(n);
        const double r = sphereFieldRadius(n), dx = 64.0 - c[0];
        const GridEdge seed = nearestCrossedEdge(volume, 0.0, {64.0, c[1] + std::sqrt(r * r - dx * dx), c[2]});
        REQUIRE((seed.x == 63 || seed.x == 64));
        requireSameSurfaceOnThreads(volume, 0.0, seed);
    }
    SECTION("a gyroid filling its volume, cut by the border") {
        const Volume volume = makeField({"gyroid", 72});
        requireSameSurfaceOnThreads(volume, 0.0, nearestCrossedEdge(volume, 0.0, {36.0, 36.0, 36.0}));
    }
    SECTION("int16 noise: the largest piece across a seam, anisotropic spacing") {
        const Volume volume = int16Noise(70);
        const double iso = 685.5;
        bool crossing = false;
        for (const Surface& s : extractAllSurfaces(volume, iso)) {
            int lo[3] = {70, 70, 70}, hi[3] = {0, 0, 0};
            for (const GridEdge e : s.mesh.vertexEdges) {
                const int p[3] = {e.x, e.y, e.z};
                for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
            }
            const bool acrossSeam =
                (lo[0] < 64 && hi[0] >= 64) || (lo[1] < 64 && hi[1] >= 64) || (lo[2] < 64 && hi[2] >= 64);
            if (acrossSeam && s.stats.cellsVisited > 8192) {
                requireSameSurfaceOnThreads(volume, iso, s.mesh.vertexEdges[0]);
                crossing = true;
                break;
            }
        }
        CHECK(crossing);
    }
}

TEST_CASE("tracked vertices are the exhaustive pass's, bit for bit", "[core][tracking]") {
    SECTION("float samples, cut by the border") { requireSameVertexBits(makeField({"noise", 24}), 0.5); }
    SECTION("int16 samples, anisotropic spacing, offset origin") {
        const Volume volume = int16Noise(20);
        requireSameVertexBits(volume, 400.0);
        requireSameVertexBits(volume, 500.5);
    }
}

TEST_CASE("the figures the tracker measures as it walks are measureSurface's, exactly", "[core][tracking]") {
    // Float samples cut by the border, int16 samples, and a surface filling its volume.
    const Volume noise = makeField({"noise", 24});
    const Volume ints = int16Noise(24);
    const Volume gyroid = makeField({"gyroid", 48});
    for (const auto& [volume, iso] : {std::pair<const Volume&, double>{noise, 0.5}, {ints, 500.5}, {gyroid, 0.0}}) {
        const Surface largest = extractAllSurfaces(volume, iso).front();
        const Surface tracked = trackSurface(volume, iso, largest.mesh.vertexEdges[0]);
        REQUIRE(tracked.mesh.triangleCount() == largest.mesh.triangleCount());
        const SurfaceStats measured = measureSurface(tracked.mesh, volume, true);
        CHECK(tracked.stats.area == measured.area);
        CHECK(tracked.stats.area == Approx(largest.stats.area));
        CHECK(tracked.stats.enclosedVolume == measured.enclosedVolume);
        CHECK(tracked.stats.touchesBorder == measured.touchesBorder);
        CHECK(tracked.stats.closed == measured.closed);
        CHECK(tracked.stats.boundsMin == measured.boundsMin);
        CHECK(tracked.stats.boundsMax == measured.boundsMax);
        CHECK(tracked.stats.bytes == measured.bytes);
    }
}

TEST_CASE("a tracked surface touches the border exactly when a vertex lies in a border plane", "[core][tracking]") {
    // The tracker learns it from exits cut by the border; measureSurface from the vertices' edges.
    const Volume noise = makeField({"noise", 24});
    for (const TableKind table : {TableKind::Consistent, TableKind::Classic}) {
        std::size_t touching = 0, inside = 0;
        for (const Surface& surface : extractAllSurfaces(noise, 0.5, table)) {
            const Surface tracked = trackSurface(noise, 0.5, surface.mesh.vertexEdges[0], table);
            const SurfaceStats measured = measureSurface(tracked.mesh, noise, table == TableKind::Consistent);
            CHECK(tracked.stats.touchesBorder == measured.touchesBorder);
            CHECK(surface.stats.touchesBorder == measured.touchesBorder);
            ++(measured.touchesBorder ? touching : inside);
        }
        CHECK(touching > 0);
        CHECK(inside > 0);
    }
}

TEST_CASE("continuation pieces partition each configuration's triangles and edges", "[core][tracking][tables]") {
    for (TableKind kind : {TableKind::Consistent, TableKind::Classic}) {
        const auto& table = continuationTable(kind);
        const TriangleTable& triangles = triangleTable(kind);
        for (int c = 0; c < 256; ++c) {
            INFO(tableKindName(kind) << " configuration " << c);
            const CaseContinuation& cc = table[c];
            int triangleTotal = 0;
            unsigned union_ = 0;
            for (int p = 0; p < cc.pieceCount; ++p) {
                const Piece& piece = cc.pieces[p];
                CHECK((union_ & piece.edgeMask) == 0);
                union_ |= piece.edgeMask;
                triangleTotal += piece.triangleCount;
                for (int t = piece.firstTriangle; t < piece.firstTriangle + piece.triangleCount; ++t) {
                    for (int k = 0; k < 3; ++k) CHECK(cc.pieceOfEdge[cc.triangles[t][k]] == p);
                }
                // A piece's edges on a face are reported for that face: one per segment
                // with the consistent table, all of them with the classic one.
                for (int f = 0; f < 6; ++f) {
                    int onFace = 0;
                    for (int e = 0; e < 12; ++e) onFace += (piece.edgeMask >> e & 1u) && cube::edgeOnFace(e, f);
                    int exits = 0;
                    while (exits < 4 && piece.exits[f][exits] >= 0) ++exits;
                    CHECK(onFace == (kind == TableKind::Consistent ? 2 * exits : exits));
                    for (int k = 0; k < exits; ++k) {
                        CHECK(cube::edgeOnFace(piece.exits[f][k], f));
                        CHECK(cc.pieceOfEdge[piece.exits[f][k]] == p);
                    }
                }
            }
            CHECK(triangleTotal == triangles[std::uint8_t(c)].count);
            unsigned crossed = 0;
            for (int e = 0; e < 12; ++e) {
                if ((c >> cube::kEdgeVertices[e][0] & 1) != (c >> cube::kEdgeVertices[e][1] & 1)) crossed |= 1u << e;
            }
            CHECK(union_ == crossed);
        }
    }
}

TEST_CASE("a configuration and its rotations have rotated pieces", "[core][tracking][tables]") {
    const auto& table = continuationTable(TableKind::Consistent);
    for (int c = 0; c < 256; ++c) {
        for (const cube::Rotation& r : cube::rotations()) {
            std::set<std::uint16_t> rotated;
            for (std::uint16_t mask : pieceMasks(table[c])) rotated.insert(rotateMask(mask, r));
            REQUIRE(rotated == pieceMasks(table[cube::rotateConfig(std::uint8_t(c), r)]));
        }
    }
}

TEST_CASE("tracking from any blob returns exactly that blob", "[core][tracking]") {
    const int n = 64;
    const Volume volume = makeField({"blobs", n});
    const double iso = fieldDefaultIso("blobs");
    const auto all = extractAllSurfaces(volume, iso);
    REQUIRE(all.size() == std::size_t(blobsFieldCount()));
    std::map<std::uint64_t, std::size_t> surfaceOfEdge;
    for (std::size_t i = 0; i < all.size(); ++i) {
        for (std::uint64_t e : vertexEdgeSet(all[i].mesh, volume.dims())) surfaceOfEdge[e] = i;
    }
    for (const Blob& blob : blobsFieldBlobs(n)) {
        const Vec3d onSurface{blob.centre[0] + blob.radius, blob.centre[1], blob.centre[2]};
        const GridEdge seed = nearestCrossedEdge(volume, iso, onSurface);
        const Surface s = trackSurface(volume, iso, seed);
        const std::size_t expected = surfaceOfEdge.at(isotrack::testing::edgeKey(seed, volume.dims()));
        CHECK(triangleSet(s.mesh, volume.dims()) == triangleSet(all[expected].mesh, volume.dims()));
        CHECK(s.stats.closed);
        CHECK_FALSE(s.stats.touchesBorder);
        if (blob.radius > 4.0) {  // smaller blobs are too coarsely sampled for a volume check
            CHECK(*s.stats.enclosedVolume == Approx(4.0 / 3.0 * M_PI * std::pow(blob.radius, 3)).epsilon(0.05));
        }
        // A closed surface visits one cell piece per cell it passes through.
        CHECK(s.stats.cellsVisited <= s.mesh.triangleCount());
    }
}

TEST_CASE("the smallest blob alone: one vertex per crossed edge around it", "[core][tracking]") {
    const int n = 128;
    const Volume volume = makeField({"blobs", n});
    const double iso = fieldDefaultIso("blobs");
    auto blobs = blobsFieldBlobs(n);
    const Blob smallest =
        *std::min_element(blobs.begin(), blobs.end(), [](const Blob& a, const Blob& b) { return a.radius < b.radius; });
    const Surface s = trackSurface(volume, iso, nearestCrossedEdge(volume, iso, smallest.centre));
    // Blobs are at least 2 voxels apart, so the crossed edges in a box around this one are its own.
    std::size_t crossed = 0;
    int lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
        lo[k] = int(std::floor(smallest.centre[k] - smallest.radius - 1.5));
        hi[k] = int(std::ceil(smallest.centre[k] + smallest.radius + 1.5));
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
        for (int y = lo[1]; y <= hi[1]; ++y)
            for (int x = lo[0]; x <= hi[0]; ++x)
                for (int axis = 0; axis < 3; ++axis) crossed += edgeIsCrossed(volume, iso, GridEdge{x, y, z, axis});
    CHECK(s.mesh.vertices.size() == crossed);
    CHECK(s.stats.closed);
    CHECK(connectedComponents(s.mesh) == 1);
    CHECK(s.stats.cellsVisited * 4 < volume.sampleCount() / 1000);

    // Its bookkeeping follows the surface: far less than a byte per voxel of the volume.
    SurfaceTracker tracker(volume, iso);
    tracker.start(nearestCrossedEdge(volume, iso, smallest.centre));
    while (!tracker.done()) tracker.step(1000);
    CHECK(tracker.workingBytes() < volume.sampleCount() / 50);
}

TEST_CASE("every surface together is the exhaustive mesh, triangle for triangle", "[core][tracking]") {
    SECTION("blobs") {
        requireAllEqualsExhaustive(makeField({"blobs", 64}), fieldDefaultIso("blobs"), TableKind::Consistent);
    }
    SECTION("shells") { requireAllEqualsExhaustive(makeField({"shells", 48}), 0.0, TableKind::Consistent); }
    // Rows whose length is not a multiple of 8 (the exhaustive pass keeps rows' flags 8 to a byte).
    SECTION("blobs, odd size") {
        requireAllEqualsExhaustive(makeField({"blobs", 61}), fieldDefaultIso("blobs"), TableKind::Consistent);
    }
    SECTION("shells, odd size") { requireAllEqualsExhaustive(makeField({"shells", 45}), 0.0, TableKind::Consistent); }
    SECTION("noise, consistent") { requireAllEqualsExhaustive(makeField({"noise", 32}), 0.5, TableKind::Consistent); }
    SECTION("noise, classic") { requireAllEqualsExhaustive(makeField({"noise", 32}), 0.5, TableKind::Classic); }
    SECTION("gyroid") { requireAllEqualsExhaustive(makeField({"gyroid", 48}), 0.0, TableKind::Consistent); }
    // The largest surface's vertices below the first of another surface stay in
    // place: here nearly all of them, on every range, the speck starting late.
    SECTION("a large sphere and a speck in the far corner") {
        const int n = 40;
        Volume volume({n, n, n}, ScalarType::Float32, {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0});
        for (int z = 0; z < n; ++z)
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x) {
                    const double large = 15.0 - std::hypot(x - 17.0, y - 17.5, z - 16.0);
                    const double speck = 1.5 - std::hypot(x - 35.2, y - 35.6, z - 35.4);
                    volume.setValue(x, y, z, std::max(large, speck));
                }
        const auto surfaces = extractAllSurfaces(volume, 0.0);
        REQUIRE(surfaces.size() == 2);
        REQUIRE(surfaces[0].mesh.triangleCount() > 100 * surfaces[1].mesh.triangleCount());
        requireAllEqualsExhaustive(volume, 0.0, TableKind::Consistent);
    }
}

TEST_CASE("every surface together is the exhaustive mesh for every sample type, across its whole range",
          "[core][tracking]") {
    // The tracker classifies cell by cell (two or four samples to a vector lane
    // for some types), the exhaustive pass row by row: both must agree on every
    // cell, at isovalues near either end of the type's range and in its middle.
    const Volume noise = makeField({"noise", 24});
    const std::array<int, 3> n = noise.dims();
    struct Case {
        ScalarType type;
        double low, high;  // the samples span [low, high]
    };
    const Case cases[] = {{ScalarType::UInt8, 0, 255},           {ScalarType::Int8, -128, 127},
                          {ScalarType::UInt16, 0, 65535},        {ScalarType::Int16, -32768, 32767},
                          {ScalarType::UInt32, 0, 4294967295.0}, {ScalarType::Int32, -2147483648.0, 2147483647.0},
                          {ScalarType::Float32, -1e6, 1e6},      {ScalarType::Float64, -1e6, 1e6}};
    for (const Case& c : cases) {
        Volume volume(n, c.type);
        const bool real = c.type == ScalarType::Float32 || c.type == ScalarType::Float64;
        for (int z = 0; z < n[2]; ++z) {
            for (int y = 0; y < n[1]; ++y) {
                for (int x = 0; x < n[0]; ++x) {
                    const double v = std::round(c.low + (c.high - c.low) * noise.value(x, y, z));
                    // A few NaN samples in the real types: below every isovalue.
                    volume.setValue(x, y, z, real && (x * 7 + y * 3 + z) % 61 == 0 ? std::nan("") : v);
                }
            }
        }
        for (const double fraction : {0.02, 0.5, 0.98}) {
            const double iso = c.low + fraction * (c.high - c.low) + 0.5;
            INFO("type " << int(c.type) << ", iso " << iso);
            requireAllEqualsExhaustive(volume, iso, TableKind::Consistent);
        }
    }
}

TEST_CASE("nested shells are three closed surfaces, one inside another", "[core][tracking]") {
    const auto surfaces = extractAllSurfaces(makeField({"shells", 64}), 0.0);
    REQUIRE(surfaces.size() == 3);
    const auto radii = shellsFieldRadii(64);
    for (const Surface& s : surfaces) CHECK(s.stats.closed);
    // Largest first: the shell's outer wall, its inner wall, then the ball.
    CHECK(surfaces[0].stats.area == Approx(4 * M_PI * radii[2] * radii[2]).epsilon(0.02));
    CHECK(surfaces[1].stats.area == Approx(4 * M_PI * radii[1] * radii[1]).epsilon(0.02));
    CHECK(surfaces[2].stats.area == Approx(4 * M_PI * radii[0] * radii[0]).epsilon(0.02));
}

TEST_CASE("incremental growth appends contiguous ranges that add up to the surface", "[core][tracking]") {
    const Volume volume = makeField({"sphere", 48});
    const GridEdge seed = nearestCrossedEdge(volume, 0.0, {0.0, 24.0, 24.0});
    SurfaceTracker tracker(volume, 0.0);
    tracker.start(seed);
    std::size_t vertices = 0, indices = 0, steps = 0;
    double firstStepReach = 0.0;
    while (!tracker.done()) {
        const auto step = tracker.step(50);
        CHECK(step.firstVertex == vertices);
        CHECK(step.firstIndex == indices);
        CHECK(step.cellsVisited <= 50);
        vertices += step.vertexCount;
        indices += step.indexCount;
        if (steps++ == 0) {
            const auto& m = tracker.mesh();
            for (std::size_t v = 0; v < m.vertices.size(); ++v) {
                const double dx = m.vertices[v].position[0] - m.vertices[0].position[0];
                const double dy = m.vertices[v].position[1] - m.vertices[0].position[1];
                const double dz = m.vertices[v].position[2] - m.vertices[0].position[2];
                firstStepReach = std::max(firstStepReach, std::sqrt(dx * dx + dy * dy + dz * dz));
            }
        }
    }
    CHECK(steps > 10);
    CHECK(firstStepReach < 10.0);  // breadth-first: the first 50 cells stay near the seed
    CHECK(vertices == tracker.mesh().vertices.size());
    CHECK(indices == tracker.mesh().indices.size());
    CHECK(triangleSet(tracker.mesh(), volume.dims()) == triangleSet(marchingCubes(volume, 0.0), volume.dims()));
}

TEST_CASE("seeds: nearest crossed edge, picked vertices, and refusals", "[core][tracking]") {
    const Volume volume = makeField({"sphere", 32});
    const Vec3d c = sphereFieldCenter(32);
    const double r = sphereFieldRadius(32);
    const GridEdge e = nearestCrossedEdge(volume, 0.0, {c[0], c[1], c[2] + r});
    CHECK(edgeIsCrossed(volume, 0.0, e));
    CHECK(std::abs(e.z - (c[2] + r)) < 1.5);
    // From far outside the volume the search still finds the surface.
    CHECK(edgeIsCrossed(volume, 0.0, nearestCrossedEdge(volume, 0.0, {-100.0, c[1], c[2]})));

    const Surface s = trackSurface(volume, 0.0, e);
    CHECK(edgeOfVertex(s.mesh, 7) == s.mesh.vertexEdges[7]);
    const float* p = s.mesh.vertices[s.mesh.indices[4]].position;
    CHECK(edgeOfTriangle(s.mesh, 1, {p[0], p[1], p[2]}) == s.mesh.vertexEdges[s.mesh.indices[4]]);

    CHECK_THROWS_AS(trackSurface(volume, 0.0, GridEdge{0, 0, 0, 0}), InputError);   // not crossed
    CHECK_THROWS_AS(trackSurface(volume, 0.0, GridEdge{31, 0, 0, 0}), InputError);  // leaves the volume
    CHECK_THROWS_AS(nearestCrossedEdge(volume, 1e9, c), InputError);                // no surface at all
}

TEST_CASE("surface statistics: bounds, area, volume and the border", "[core][tracking]") {
    const int n = 64;
    const Volume volume = makeField({"sphere", n});
    const Vec3d c = sphereFieldCenter(n);
    const double r = sphereFieldRadius(n);
    const Surface s = trackSurface(volume, 0.0, nearestCrossedEdge(volume, 0.0, c));
    CHECK(s.stats.closed);
    CHECK_FALSE(s.stats.touchesBorder);
    CHECK(s.stats.area == Approx(4 * M_PI * r * r).epsilon(0.01));
    CHECK(*s.stats.enclosedVolume == Approx(4.0 / 3.0 * M_PI * r * r * r).epsilon(0.01));
    for (int k = 0; k < 3; ++k) {
        CHECK(s.stats.boundsMin[k] == Approx(c[k] - r).margin(0.05));
        CHECK(s.stats.boundsMax[k] == Approx(c[k] + r).margin(0.05));
    }
    CHECK(s.stats.bytes == s.mesh.byteSize());
    // The gyroid fills the volume and is cut open by its border.
    const Volume gyroid = makeField({"gyroid", 32});
    const auto open = extractAllSurfaces(gyroid, 0.0);
    REQUIRE_FALSE(open.empty());
    CHECK(open[0].stats.touchesBorder);
    CHECK_FALSE(open[0].stats.closed);
}

TEST_CASE("CT skull: every surface equals the exhaustive mesh; as many surfaces as VTK finds", "[core][tracking][ct]") {
    const std::string path = std::string(ISOTRACK_SOURCE_DIR) + "/assets/ct/cranium.nrrd";
    if (!std::ifstream(path)) {
        WARN("skipped: " << path << " is missing (scripts/get_ct.sh makes it)");
        return;
    }
    const Volume volume = loadVolume(path);
    requireAllEqualsExhaustive(volume, 400.5, TableKind::Consistent);
    // vtkFlyingEdges3D + vtkPolyDataConnectivityFilter finds 240 regions (scripts/vtk_components.py).
    CHECK(extractAllSurfaces(volume, 400.5).size() == 240);
}
