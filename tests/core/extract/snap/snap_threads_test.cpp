// The 3-state table on several threads: the sample states (snapStates, whose
// passes are split by slices and runs of candidates) and so the marched mesh
// and every surface are those of one thread, vertex for vertex; a tracked
// surface has one thread's triangles over the same vertices (in an order that
// may depend on the threads: snap_walk_threads_test.cpp).
#include <catch2/catch.hpp>

#include <cstddef>
#include <cstring>
#include <random>
#include <vector>

#include "core/extract/snap/random_integers.h"
#include "core/extract/snap/same_triangles.h"
#include "extract/snap/snap_march.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/snap_table.h"
#include "isotrack/tracking.h"

using namespace isotrack;

namespace {

using test::randomIntegers;

bool sameMesh(const Mesh& a, const Mesh& b) {
    return a.indices == b.indices && a.vertices.size() == b.vertices.size() &&
           std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vertex)) == 0;
}

}  // namespace

TEST_CASE("snap: the same states, meshes and tracked triangles on 1 to 5 threads", "[core][snap][threads]") {
    std::mt19937 rng(47);
    for (const double iso : {0.0, 0.5}) {
        INFO("iso " << iso);
        const Volume v = randomIntegers({41, 37, 29}, rng, 3);
        const std::vector<SampleState> one = detail::snapStates(v, iso, 1);
        std::size_t snapped = 0, i = 0;
        for (int z = 0; z < v.dims()[2]; ++z)
            for (int y = 0; y < v.dims()[1]; ++y)
                for (int x = 0; x < v.dims()[0]; ++x, ++i) snapped += isAt(one[i]) && v.value(x, y, z) != iso;
        // More snapped samples than one run of candidates, so several threads share pass 3.
        CHECK(snapped > 4096);
        const Mesh mesh = marchingCubes(v, iso, TableKind::Snap, 1);
        const std::vector<Surface> all = extractAllSurfaces(v, iso, TableKind::Snap, 1);
        REQUIRE(!all.empty());
        GridEdge seed{};
        for (const GridEdge e : all.front().mesh.vertexEdges) {
            if (e.axis == kCellInterior) continue;
            int q[3] = {e.x, e.y, e.z};
            ++q[e.axis];
            if ((v.value(e.x, e.y, e.z) >= iso) == (v.value(q[0], q[1], q[2]) >= iso)) continue;
            seed = e;
            break;
        }
        const Surface tracked = trackSurface(v, iso, seed, TableKind::Snap, 1);
        for (int threads = 2; threads <= 5; ++threads) {
            INFO(threads << " threads");
            CHECK(detail::snapStates(v, iso, threads) == one);
            CHECK(sameMesh(marchingCubes(v, iso, TableKind::Snap, threads), mesh));
            const std::vector<Surface> allThreaded = extractAllSurfaces(v, iso, TableKind::Snap, threads);
            REQUIRE(allThreaded.size() == all.size());
            for (std::size_t s = 0; s < all.size(); ++s) CHECK(sameMesh(allThreaded[s].mesh, all[s].mesh));
            CHECK(test::sameTriangles(trackSurface(v, iso, seed, TableKind::Snap, threads).mesh, tracked.mesh));
        }
    }
}
