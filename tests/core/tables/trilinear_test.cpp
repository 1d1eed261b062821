#include <catch2/catch.hpp>

#include <array>
#include <map>
#include <numeric>
#include <random>
#include <vector>

#include "core/mesh_checks.h"
#include "isotrack/cube.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/trilinear.h"

using namespace isotrack;

namespace {

bool shareFace(int a, int b) {
    if (a >= kInteriorVertex || b >= kInteriorVertex) return false;
    for (int f = 0; f < cube::kFaceCount; ++f) {
        if (cube::edgeOnFace(a, f) && cube::edgeOnFace(b, f)) return true;
    }
    return false;
}

int root(std::vector<int>& parent, int v) {
    while (parent[std::size_t(v)] != v) v = parent[std::size_t(v)] = parent[std::size_t(parent[std::size_t(v)])];
    return v;
}

// Connected pieces of a triangle list over `vertexCount` vertices (unused ones not counted).
template <class Triangles>
int pieces(const Triangles& triangles, std::size_t triangleCount, int vertexCount) {
    std::vector<int> parent(static_cast<std::size_t>(vertexCount));
    std::iota(parent.begin(), parent.end(), 0);
    std::vector<bool> used(static_cast<std::size_t>(vertexCount), false);
    for (std::size_t t = 0; t < triangleCount; ++t) {
        for (int k = 0; k < 3; ++k) {
            const int a = int(triangles[t][std::size_t(k)]), b = int(triangles[t][std::size_t((k + 1) % 3)]);
            used[std::size_t(a)] = true;
            parent[std::size_t(root(parent, a))] = root(parent, b);
        }
    }
    int count = 0;
    for (int v = 0; v < vertexCount; ++v) count += used[std::size_t(v)] && root(parent, v) == v;
    return count;
}

// The number of connected isosurface pieces of the trilinear interpolant of
// `values` in the unit cube, sampled on an n^3 grid: regions of each sign are
// flooded (6-connected for one sign, 26 for the other), and each pair of
// regions of opposite signs that touch is one piece of surface.
int sampledPieces(const std::array<double, 8>& values, int n, bool aboveIs6) {
    auto at = [&](int x, int y, int z) {
        return (std::size_t(z) * std::size_t(n) + std::size_t(y)) * std::size_t(n) + std::size_t(x);
    };
    std::vector<bool> above(std::size_t(n) * std::size_t(n) * std::size_t(n));
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const double u = double(x) / (n - 1), v = double(y) / (n - 1), w = double(z) / (n - 1);
                double value = 0.0;
                for (int c = 0; c < 8; ++c) {
                    const auto& o = cube::kVertexOffset[std::size_t(c)];
                    value += values[std::size_t(c)] * (o[0] ? u : 1 - u) * (o[1] ? v : 1 - v) * (o[2] ? w : 1 - w);
                }
                above[at(x, y, z)] = value >= 0.0;
            }
    std::vector<int> label(above.size(), -1);
    int labels = 0;
    for (std::size_t start = 0; start < above.size(); ++start) {
        if (label[start] >= 0) continue;
        const bool sign = above[start];
        const bool six = sign == aboveIs6;
        std::vector<std::size_t> stack{start};
        label[start] = labels;
        while (!stack.empty()) {
            const std::size_t i = stack.back();
            stack.pop_back();
            const int x = int(i % std::size_t(n)), y = int(i / std::size_t(n) % std::size_t(n)),
                      z = int(i / std::size_t(n) / std::size_t(n));
            for (int dz = -1; dz <= 1; ++dz)
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int steps = std::abs(dx) + std::abs(dy) + std::abs(dz);
                        if (steps == 0 || (six && steps > 1)) continue;
                        const int px = x + dx, py = y + dy, pz = z + dz;
                        if (px < 0 || py < 0 || pz < 0 || px >= n || py >= n || pz >= n) continue;
                        const std::size_t j = at(px, py, pz);
                        if (label[j] >= 0 || above[j] != sign) continue;
                        label[j] = labels;
                        stack.push_back(j);
                    }
        }
        ++labels;
    }
    std::map<std::pair<int, int>, bool> touching;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const std::size_t i = at(x, y, z);
                const std::size_t next[3] = {x + 1 < n ? at(x + 1, y, z) : i, y + 1 < n ? at(x, y + 1, z) : i,
                                             z + 1 < n ? at(x, y, z + 1) : i};
                for (const std::size_t j : next) {
                    if (above[i] != above[j])
                        touching[{std::min(label[i], label[j]), std::max(label[i], label[j])}] = true;
                }
            }
    return int(touching.size());
}

// The sampled count when two resolutions and both connectivity pairings agree; -1 otherwise.
int referencePieces(const std::array<double, 8>& values) {
    const int a = sampledPieces(values, 29, true);
    if (sampledPieces(values, 29, false) != a || sampledPieces(values, 41, true) != a ||
        sampledPieces(values, 41, false) != a)
        return -1;
    return a;
}

}  // namespace

TEST_CASE("every trilinear subcase is a closed surface within the cube, bounded by its face segments",
          "[tables][trilinear]") {
    const TrilinearTable& table = trilinearTable();
    std::size_t tunnels = 0, interior = 0;
    for (const TrilinearCase& subcase : table.cases()) {
        INFO("configuration " << int(subcase.config) << ", faces joined " << int(subcase.faceJoined) << ", tunnel "
                              << int(subcase.tunnel[0]) << "-" << int(subcase.tunnel[1]));
        tunnels += subcase.tunnel[0] >= 0;
        interior += subcase.interiorCount > 0;
        std::map<std::pair<int, int>, int> directed;
        std::uint16_t corners = 0;
        unsigned interiorUsed = 0;
        for (int t = 0; t < subcase.triangleCount; ++t) {
            for (int k = 0; k < 3; ++k) {
                const int a = subcase.triangles[std::size_t(t)][std::size_t(k)],
                          b = subcase.triangles[std::size_t(t)][std::size_t((k + 1) % 3)];
                ++directed[{a, b}];
                if (a >= kInteriorVertex)
                    interiorUsed |= 1u << (a - kInteriorVertex);
                else
                    corners = static_cast<std::uint16_t>(corners | 1u << a);
            }
        }
        CHECK(interiorUsed == (1u << subcase.interiorCount) - 1);  // each interior vertex, and only those, used
        // Exactly the crossed edges carry vertices.
        std::uint16_t crossed = 0;
        for (int e = 0; e < cube::kEdgeCount; ++e) {
            const auto& v = cube::kEdgeVertices[std::size_t(e)];
            if ((subcase.config >> v[0] & 1) != (subcase.config >> v[1] & 1))
                crossed = static_cast<std::uint16_t>(crossed | 1u << e);
        }
        CHECK(corners == crossed);
        for (const auto& [side, uses] : directed) {
            const auto [a, b] = side;
            CHECK(uses == 1);  // a side twice the same way: the winding flips
            const bool reversed = directed.count({b, a}) != 0;
            // A side on a face is a segment of the surface's boundary, drawn once; any other is shared by two
            // triangles.
            CHECK(reversed != shareFace(a, b));
        }
        CHECK(pieces(subcase.triangles, subcase.triangleCount, kInteriorVertex + kMaxInteriorVertices) ==
              subcase.pieceCount);
    }
    CHECK(tunnels > 0);
    CHECK(interior > 0);
}

TEST_CASE("the asymptotic decider reads only a face's samples, symmetrically", "[tables][trilinear]") {
    // The face is decided alike whichever of its corners the cube numbers first: here,
    // a cube and its image under each rotation agree on every face.
    std::mt19937 random(7);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    for (int trial = 0; trial < 2000; ++trial) {
        double values[8];
        std::uint8_t config = 0;
        for (int v = 0; v < 8; ++v) {
            values[v] = value(random);
            if (values[v] >= 0.0) config = static_cast<std::uint8_t>(config | 1u << v);
        }
        const std::uint8_t joined = decideFaces(values, config);
        for (const cube::Rotation& r : cube::rotations()) {
            double turned[8];
            for (int v = 0; v < 8; ++v) turned[r.vertex[std::size_t(v)]] = values[v];
            const std::uint8_t turnedJoined = decideFaces(turned, cube::rotateConfig(config, r));
            for (int f = 0; f < cube::kFaceCount; ++f) {
                REQUIRE(((joined >> f) & 1) == ((turnedJoined >> r.face[std::size_t(f)]) & 1));
            }
        }
    }
}

TEST_CASE("on single cubes, the trilinear table has the interpolant's number of pieces", "[tables][trilinear][mc]") {
    std::mt19937 random(33);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::uniform_real_distribution<double> scale(0.02, 1.0);
    int checked = 0, skipped = 0, tunnels = 0;
    std::map<int, int> subcasesSeen;
    while (checked < 1000) {
        std::array<double, 8> values{};
        std::uint8_t config = 0;
        for (int v = 0; v < 8; ++v) {
            // Magnitudes over two orders, so that saddles fall near the isovalue and tunnels open.
            values[std::size_t(v)] = value(random) * scale(random);
            if (values[std::size_t(v)] >= 0.0) config = static_cast<std::uint8_t>(config | 1u << v);
        }
        // Cubes with an ambiguous face or a possible tunnel (Lorensen & Cline's case 4 has no ambiguous face).
        if (ambiguousFaces(config) == 0 && trilinearTable().count(config, 0) == 1) continue;
        const int reference = referencePieces(values);
        if (reference < 0) {
            ++skipped;  // too close to a change of topology for sampling to tell
            continue;
        }
        ++checked;
        const TrilinearCase& subcase = classifyTrilinear(values.data(), config);
        tunnels += subcase.tunnel[0] >= 0;
        ++subcasesSeen[int(&subcase - trilinearTable().cases().data())];
        INFO("values " << values[0] << " " << values[1] << " " << values[2] << " " << values[3] << " " << values[4]
                       << " " << values[5] << " " << values[6] << " " << values[7]);
        REQUIRE(int(subcase.pieceCount) == reference);

        // The exhaustive pass on the cube as a 2x2x2 volume draws the same pieces.
        Volume volume({2, 2, 2}, ScalarType::Float64);
        for (int v = 0; v < 8; ++v) {
            const auto& o = cube::kVertexOffset[std::size_t(v)];
            volume.setValue(o[0], o[1], o[2], values[std::size_t(v)]);
        }
        const Mesh mesh = marchingCubes(volume, 0.0, TableKind::Trilinear);
        std::vector<std::array<std::uint32_t, 3>> triangles(mesh.triangleCount());
        for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
            for (int k = 0; k < 3; ++k) triangles[t][std::size_t(k)] = mesh.indices[3 * t + std::size_t(k)];
        }
        REQUIRE(pieces(triangles, triangles.size(), int(mesh.vertices.size())) == reference);
        const auto topology = isotrack::testing::topology(mesh, volume.dims());
        REQUIRE(topology.nonManifoldEdges == 0);
        REQUIRE(topology.repeatedDirectedEdges == 0);
    }
    CHECK(skipped * 20 < checked);
    CHECK(tunnels > 0);
    CHECK(subcasesSeen.size() > 100);
}
