#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "core/mesh_checks.h"
#include "isotrack/contour_tree.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/tracking.h"

using namespace isotrack;

namespace {

// Isovalues spread over the volume's range, ends excluded.
std::vector<double> isovalues(const Volume& volume, int count) {
    const auto [lo, hi] = volume.range();
    std::vector<double> out;
    for (int k = 1; k <= count; ++k) out.push_back(lo + (hi - lo) * k / (count + 1));
    return out;
}

void requireArcsCountSurfaces(const Volume& volume, const std::vector<double>& values) {
    const ContourTree tree = computeContourTree(volume, 2);
    for (const double v : values) {
        INFO("iso " << v);
        REQUIRE(tree.arcsAt(v).size() == extractAllSurfaces(volume, v, TableKind::Consistent, 2).size());
    }
}

// Each surface as its sorted triangles; the surfaces sorted.
std::vector<std::vector<std::array<std::uint64_t, 3>>> surfaceSets(const std::vector<Surface>& surfaces,
                                                                   const Dims& dims) {
    std::vector<std::vector<std::array<std::uint64_t, 3>>> out;
    for (const Surface& s : surfaces) {
        const auto set = testing::triangleSet(s.mesh, dims);
        out.emplace_back(set.begin(), set.end());
    }
    std::sort(out.begin(), out.end());
    return out;
}

void requireTreeSurfacesEqualAll(const Volume& volume, const ContourTree& tree, double v) {
    INFO("iso " << v);
    const std::vector<Surface> all = extractAllSurfaces(volume, v, TableKind::Consistent, 2);
    std::vector<std::size_t> arcs;
    const std::vector<Surface> fromTree = trackTreeSurfaces(tree, volume, v, 1, &arcs);
    REQUIRE(fromTree.size() == all.size());
    REQUIRE(arcs.size() == fromTree.size());
    CHECK(surfaceSets(fromTree, volume.dims()) == surfaceSets(all, volume.dims()));
}

// Small integers, many equal samples and saddles.
Volume randomIntegers(int n, int levels, unsigned seed) {
    Volume volume({n, n, n}, ScalarType::UInt8);
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> pick(0, levels - 1);
    auto* samples = volume.data<std::uint8_t>();
    for (std::size_t i = 0; i < volume.sampleCount(); ++i) samples[i] = std::uint8_t(pick(random));
    return volume;
}

// Uniform random samples: a saddle or an extremum at most samples.
Volume randomFloats(const Dims& dims, ScalarType type, unsigned seed) {
    Volume volume(dims, type);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> pick(0.0, 1000.0);
    for (int z = 0; z < dims[2]; ++z)
        for (int y = 0; y < dims[1]; ++y)
            for (int x = 0; x < dims[0]; ++x) volume.setValue(x, y, z, pick(random));
    return volume;
}

// A smooth field with many saddles: a sum of waves of random directions and phases.
Volume randomWaves(const Dims& dims, unsigned seed) {
    Volume volume(dims, ScalarType::Float32);
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> pick(-1.0, 1.0);
    std::vector<std::array<double, 4>> waves(6);
    for (auto& w : waves) w = {pick(random), pick(random), pick(random), 3.0 * pick(random)};
    for (int z = 0; z < dims[2]; ++z)
        for (int y = 0; y < dims[1]; ++y)
            for (int x = 0; x < dims[0]; ++x) {
                double v = 0;
                for (const auto& w : waves) v += std::cos(0.9 * (w[0] * x + w[1] * y + w[2] * z) + w[3]);
                volume.setValue(x, y, z, v);
            }
    return volume;
}

void requireSameTree(const ContourTree& a, const ContourTree& b) {
    REQUIRE(a.nodes.size() == b.nodes.size());
    REQUIRE(a.arcs.size() == b.arcs.size());
    for (std::size_t n = 0; n < a.nodes.size(); ++n) {
        CHECK(a.nodes[n].sample == b.nodes[n].sample);
        CHECK(a.nodes[n].up == b.nodes[n].up);
        CHECK(a.nodes[n].down == b.nodes[n].down);
    }
    for (std::size_t k = 0; k < a.arcs.size(); ++k) {
        CHECK(a.arcs[k].lower == b.arcs[k].lower);
        CHECK(a.arcs[k].upper == b.arcs[k].upper);
        CHECK(a.arcs[k].begin == b.arcs[k].begin);
        CHECK(a.arcs[k].end == b.arcs[k].end);
    }
    CHECK(a.samples == b.samples);
    CHECK(a.nodeArcs == b.nodeArcs);
}

}  // namespace

TEST_CASE("contour tree: random fields with many saddles, 50 isovalues", "[core][contour-tree]") {
    SECTION("uniform random samples") {
        for (unsigned seed = 1; seed <= 3; ++seed) {
            const Volume volume = randomFloats({17 + int(seed), 23, 19 - int(seed)}, ScalarType::Float32, seed);
            requireArcsCountSurfaces(volume, isovalues(volume, 50));
        }
    }
    SECTION("random waves") {
        for (unsigned seed = 1; seed <= 3; ++seed) {
            const Volume volume = randomWaves({29, 21 + int(seed), 25}, seed);
            requireArcsCountSurfaces(volume, isovalues(volume, 50));
        }
    }
    SECTION("noise, and random samples of a few levels (ties)") {
        const Volume noise = makeField({"noise", 32});
        requireArcsCountSurfaces(noise, isovalues(noise, 50));
        const Volume levels = randomIntegers(20, 5, 11);
        requireArcsCountSurfaces(levels, isovalues(levels, 50));
    }
}

TEST_CASE("contour tree: the same tree on any number of threads", "[core][contour-tree]") {
    // Over 2^16 samples, so that the sort and the class pass work in parts.
    for (const ScalarType type : {ScalarType::Float32, ScalarType::Int16, ScalarType::UInt8}) {
        INFO(scalarTypeName(type));
        const Volume volume = randomFloats({48, 40, 37}, type, 7);
        const ContourTree one = computeContourTree(volume, 1);
        CHECK(one.nodes.size() + one.samples.size() == volume.sampleCount());
        for (const int threads : {2, 3}) {
            INFO(threads << " threads");
            requireSameTree(one, computeContourTree(volume, threads));
        }
    }
    const Volume waves = randomWaves({64, 48, 40}, 5);
    requireSameTree(computeContourTree(waves, 1), computeContourTree(waves, 2));
}

TEST_CASE("contour tree: arcs crossing v are the surfaces at v", "[core][contour-tree]") {
    SECTION("sphere") { requireArcsCountSurfaces(makeField({"sphere", 24}), isovalues(makeField({"sphere", 24}), 50)); }
    SECTION("torus") { requireArcsCountSurfaces(makeField({"torus", 24}), isovalues(makeField({"torus", 24}), 50)); }
    SECTION("noise") { requireArcsCountSurfaces(makeField({"noise", 24}), isovalues(makeField({"noise", 24}), 50)); }
    SECTION("blobs") { requireArcsCountSurfaces(makeField({"blobs", 40}), isovalues(makeField({"blobs", 40}), 50)); }
    SECTION("gyroid") { requireArcsCountSurfaces(makeField({"gyroid", 32}), isovalues(makeField({"gyroid", 32}), 50)); }
    SECTION("random small integers, at and between the values") {
        for (unsigned seed = 1; seed <= 6; ++seed) {
            const Volume volume = randomIntegers(12 + int(seed), 3 + int(seed % 3), seed);
            std::vector<double> values;
            for (double v = 0.5; v < 6; v += 0.5) values.push_back(v);
            requireArcsCountSurfaces(volume, values);
        }
    }
}

TEST_CASE("contour tree: every sample is a node or on one arc, arcs sorted", "[core][contour-tree]") {
    const Volume volume = makeField({"noise", 16});
    const ContourTree tree = computeContourTree(volume, 1);
    CHECK(tree.nodes.size() + tree.samples.size() == volume.sampleCount());
    CHECK(tree.arcs.size() + 1 == tree.nodes.size());  // a tree
    for (const ContourTree::Arc& arc : tree.arcs) {
        CHECK(tree.nodes[arc.lower].value <= tree.nodes[arc.upper].value);
        for (std::size_t k = arc.begin; k + 1 < arc.end; ++k) {
            const auto a = tree.samples[k], b = tree.samples[k + 1];
            CHECK(volume.data<float>()[a] <= volume.data<float>()[b]);
        }
    }
    // One thread and two give the same tree.
    const ContourTree two = computeContourTree(volume, 2);
    CHECK(two.samples == tree.samples);
    CHECK(two.arcs.size() == tree.arcs.size());
}

TEST_CASE("contour tree: tracking each arc's seed gives every surface", "[core][contour-tree]") {
    for (const char* name : {"sphere", "torus", "noise", "blobs", "gyroid"}) {
        INFO(name);
        const Volume volume = makeField({name, 24});
        const ContourTree tree = computeContourTree(volume, 2);
        for (const double v : isovalues(volume, 12)) requireTreeSurfacesEqualAll(volume, tree, v);
    }
    for (unsigned seed = 1; seed <= 4; ++seed) {
        const Volume volume = randomIntegers(14, 4, seed);
        const ContourTree tree = computeContourTree(volume, 2);
        for (const double v : {0.5, 1.0, 1.5, 2.0, 2.5, 3.0}) requireTreeSurfacesEqualAll(volume, tree, v);
    }
}

TEST_CASE("contour tree: NaN is below everything, every sample type", "[core][contour-tree]") {
    Volume volume = makeField({"blobs", 24});
    volume.data<float>()[5] = NAN;
    volume.data<float>()[3000] = NAN;
    requireArcsCountSurfaces(volume, isovalues(volume, 10));
    for (const ScalarType type : {ScalarType::Int8, ScalarType::Int16, ScalarType::UInt16, ScalarType::Int32,
                                  ScalarType::UInt32, ScalarType::Float64}) {
        INFO(scalarTypeName(type));
        const Volume noise = makeField({"noise", 16});
        Volume typed(noise.dims(), type);
        for (int z = 0; z < 16; ++z)
            for (int y = 0; y < 16; ++y)
                for (int x = 0; x < 16; ++x) typed.setValue(x, y, z, std::round(noise.value(x, y, z) * 100));
        requireArcsCountSurfaces(typed, {10.5, 30.0, 49.5, 50.0, 60.0, 75.5});
    }
}

// Every surface but those of the arcs left out, each as it is when none is:
// the flexible isosurfaces' arcs at the common isovalue are never tracked.
TEST_CASE("contour tree: arcs left out leave the other surfaces as they were", "[core][contour-tree]") {
    std::vector<Volume> volumes;
    for (unsigned seed = 1; seed <= 2; ++seed) {
        volumes.push_back(randomIntegers(14, 5, seed));
        volumes.push_back(randomWaves({26, 22, 24}, seed));
    }
    volumes.push_back(makeField({"noise", 24}));
    for (const Volume& volume : volumes) {
        const ContourTree tree = computeContourTree(volume, 2);
        for (const double v : isovalues(volume, 5)) {
            INFO("iso " << v);
            std::vector<std::size_t> arcs;
            const std::vector<Surface> every = trackTreeSurfaces(tree, volume, v, 2, &arcs);
            if (arcs.empty()) continue;
            // The largest, the smallest, and every other one.
            std::vector<std::size_t> alternate;
            for (std::size_t k = 0; k < arcs.size(); k += 2) alternate.push_back(arcs[k]);
            for (const std::vector<std::size_t>& leave :
                 {std::vector<std::size_t>{arcs.front()}, std::vector<std::size_t>{arcs.back()}, alternate}) {
                std::vector<std::size_t> keptArcs;
                const std::vector<Surface> kept = trackTreeSurfaces(tree, volume, v, 2, &keptArcs, 0, leave);
                std::vector<std::size_t> expectedArcs;
                std::vector<Surface> expected;
                for (std::size_t k = 0; k < arcs.size(); ++k) {
                    if (std::find(leave.begin(), leave.end(), arcs[k]) != leave.end()) continue;
                    expectedArcs.push_back(arcs[k]);
                    expected.push_back(every[k]);
                }
                REQUIRE(keptArcs == expectedArcs);
                CHECK(surfaceSets(kept, volume.dims()) == surfaceSets(expected, volume.dims()));
            }
        }
    }
}

TEST_CASE("contour tree: simplification prunes small branches only", "[core][contour-tree]") {
    const Volume volume = makeField({"noise", 20});
    ContourTree tree = computeContourTree(volume, 2);
    const double v = 0.5;
    const std::size_t before = tree.arcsAt(v).size();
    simplifyContourTree(tree, 0.0);
    CHECK(tree.arcsAt(v).size() == before);
    simplifyContourTree(tree, 0.2);
    const std::size_t after = tree.arcsAt(v).size();
    CHECK(after < before);
    CHECK(after > 0);
    // What is left is still a tree: as many arcs kept as nodes with an arc, less one.
    std::vector<int> used(tree.nodes.size(), 0);
    std::size_t kept = 0;
    for (const ContourTree::Arc& arc : tree.arcs) {
        if (arc.pruned) continue;
        ++kept, used[arc.lower] = 1, used[arc.upper] = 1;
    }
    CHECK(kept + 1 == std::size_t(std::count(used.begin(), used.end(), 1)));
    ContourTree bySize = computeContourTree(volume, 2);
    simplifyContourTree(bySize, 0.0, 50);
    CHECK(bySize.arcsAt(v).size() < before);
}

TEST_CASE("contour tree of the CT: arcs are the surfaces, 240 at 400.5", "[core][contour-tree][ct]") {
    const std::string path = std::string(ISOTRACK_SOURCE_DIR) + "/assets/ct/cranium.nrrd";
    if (!std::ifstream(path)) {
        WARN("skipped: " << path << " is missing (scripts/get_ct.sh makes it)");
        return;
    }
    const Volume volume = loadVolume(path);
    const ContourTree tree = computeContourTree(volume, 2);
    CHECK(tree.arcsAt(400.5).size() == 240);
    for (const double v : isovalues(volume, 50)) {
        INFO("iso " << v);
        CHECK(tree.arcsAt(v).size() == extractAllSurfaces(volume, v, TableKind::Consistent, 2).size());
    }
    requireTreeSurfacesEqualAll(volume, tree, 400.5);
}

TEST_CASE("topology per surface: Euler characteristic, border loops, genus", "[core][contour-tree]") {
    const Volume sphere = makeField({"sphere", 32});
    const std::vector<Surface> spheres =
        trackTreeSurfaces(computeContourTree(sphere), sphere, fieldDefaultIso("sphere"));
    REQUIRE(spheres.size() == 1);
    CHECK(*spheres[0].stats.euler == 2);
    CHECK(*spheres[0].stats.borderLoops == 0);
    CHECK(*spheres[0].stats.genus == 0);
    CHECK(spheres[0].stats.persistence.has_value());
    Surface counted = spheres[0];  // the same figures from the edges themselves
    counted.stats.closed = false;
    measureTopology(counted);
    CHECK(*counted.stats.euler == 2);
    CHECK(*counted.stats.borderLoops == 0);
    const Volume torus = makeField({"torus", 32});
    const std::vector<Surface> tori = trackTreeSurfaces(computeContourTree(torus), torus, fieldDefaultIso("torus"));
    REQUIRE(tori.size() == 1);
    CHECK(*tori[0].stats.euler == 0);
    CHECK(*tori[0].stats.genus == 1);
    // A gyroid cut by the border: its loops are counted, the topology adds up.
    const Volume gyroid = makeField({"gyroid", 24});
    Surface open = extractAllSurfaces(gyroid, 0.0).front();
    measureTopology(open);
    CHECK(*open.stats.borderLoops > 0);
    CHECK(*open.stats.euler == 2 - 2 * *open.stats.genus - *open.stats.borderLoops);
    // Its edges counted one by one (mesh_checks.h): V - E + F.
    CHECK(*open.stats.euler == testing::topology(open.mesh, gyroid.dims()).euler());
}

TEST_CASE("topology per surface: a sheet and a tube cut by the border", "[core][contour-tree]") {
    // A ramp along z: one flat sheet across the box, a disc (one loop).
    Volume ramp({12, 10, 9}, ScalarType::Float32);
    // x^2 + y^2 about the box's axis: a tube open at both ends (two loops).
    Volume tube({16, 16, 10}, ScalarType::Float32);
    for (int z = 0; z < 10; ++z)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                if (x < 12 && y < 10 && z < 9) ramp.setValue(x, y, z, z);
                tube.setValue(x, y, z, (x - 7.5) * (x - 7.5) + (y - 7.5) * (y - 7.5));
            }
    for (const auto& [volume, iso, euler, loops] :
         {std::tuple<const Volume*, double, long, long>{&ramp, 4.5, 1, 1}, {&tube, 20.0, 0, 2}}) {
        std::vector<Surface> surfaces = extractAllSurfaces(*volume, iso);
        REQUIRE(surfaces.size() == 1);
        CHECK_FALSE(surfaces[0].stats.closed);
        measureTopology(surfaces[0]);
        CHECK(*surfaces[0].stats.euler == euler);
        CHECK(*surfaces[0].stats.borderLoops == loops);
        CHECK(*surfaces[0].stats.genus == 0);
    }
}

TEST_CASE("flexible isosurfaces: a surface followed along its arc to its own isovalue", "[core][contour-tree]") {
    const Volume volume = makeField({"noise", 24});
    const ContourTree tree = computeContourTree(volume, 2);
    const double from = 0.6, to = 0.45;
    std::vector<std::size_t> arcs;
    const std::vector<Surface> surfaces = trackTreeSurfaces(tree, volume, from, 1, &arcs);
    const std::vector<std::size_t> alive = tree.arcsAt(to);
    const auto all = surfaceSets(extractAllSurfaces(volume, to), volume.dims());
    std::size_t vanished = 0, followed = 0;
    for (const std::size_t arc : arcs) {
        CHECK(followArc(tree, arc, from) == arc);
        const std::size_t next = followArc(tree, arc, to);
        if (next == tree.arcs.size()) {
            ++vanished;
            continue;
        }
        REQUIRE(std::find(alive.begin(), alive.end(), next) != alive.end());
        if (followed++ % 16 != 0) continue;  // a sample of them tracked: one of all's surfaces at `to`
        const ArcSeed seed = arcSeeds(tree, volume, to, {next}).front();
        const Surface surface = trackSurface(volume, to, seed.edge);
        const auto set = testing::triangleSet(surface.mesh, volume.dims());
        const std::vector<std::array<std::uint64_t, 3>> sorted(set.begin(), set.end());
        CHECK(std::binary_search(all.begin(), all.end(), sorted));
    }
    CHECK(followed + vanished == arcs.size());
    CHECK(followed > 0);
    // Above the volume's maximum every surface vanishes.
    for (const std::size_t arc : arcs) CHECK(followArc(tree, arc, volume.range()[1] + 1) == tree.arcs.size());
}

namespace {

// Gaussian bumps of the given heights at the given centres, sigma 3 samples;
// negated, pits.
Volume bumps(const Dims& dims, const std::vector<std::array<double, 4>>& centresAndHeights, bool pits) {
    Volume volume(dims, ScalarType::Float32);
    for (int z = 0; z < dims[2]; ++z)
        for (int y = 0; y < dims[1]; ++y)
            for (int x = 0; x < dims[0]; ++x) {
                double v = 0;
                for (const auto& [cx, cy, cz, height] : centresAndHeights) {
                    const double d2 = (x - cx) * (x - cx) + (y - cy) * (y - cy) + (z - cz) * (z - cz);
                    v += height * std::exp(-d2 / 9.0);
                }
                volume.setValue(x, y, z, pits ? -v : v);
            }
    return volume;
}

}  // namespace

TEST_CASE("contour tree: an extremum swept after its sweep's components have become one", "[core][contour-tree]") {
    // Two bumps 6 samples apart meet at about 0.74, above the third's peak of 0.5:
    // the join sweep has one component from there until it meets that peak, and
    // only after it does every later sample join the one component (the sweep's
    // trunk). As pits, the same for the split sweep.
    const std::vector<std::array<double, 4>> three = {{8, 12, 12, 1.0}, {14, 12, 12, 1.0}, {31, 12, 12, 0.5}};
    for (const bool pits : {false, true}) {
        INFO((pits ? "pits" : "bumps"));
        const Volume volume = bumps({40, 24, 24}, three, pits);
        for (const int threads : {1, 2}) {
            const ContourTree tree = computeContourTree(volume, threads);
            CHECK(tree.arcsAt(pits ? -0.25 : 0.25).size() == 2);
        }
        requireArcsCountSurfaces(volume, isovalues(volume, 50));
        const ContourTree tree = computeContourTree(volume, 2);
        for (const double v : isovalues(volume, 8)) requireTreeSurfacesEqualAll(volume, tree, v);
    }
    // Random bumps: the sweeps' components become one at many different ranks.
    for (unsigned seed = 1; seed <= 6; ++seed) {
        std::mt19937 random(seed);
        std::uniform_real_distribution<double> at(2.0, 26.0), height(0.2, 1.0);
        std::vector<std::array<double, 4>> some(2 + seed % 4);
        for (auto& bump : some) bump = {at(random), at(random), at(random) * 0.8, height(random)};
        for (const bool pits : {false, true}) {
            INFO("seed " << seed << (pits ? ", pits" : ", bumps"));
            requireArcsCountSurfaces(bumps({28, 28, 22}, some, pits), isovalues(bumps({28, 28, 22}, some, pits), 50));
        }
    }
}
