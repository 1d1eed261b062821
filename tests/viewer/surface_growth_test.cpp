// A tracked surface grown a budget at a time, as the viewer grows it: the GPU
// buffers receive exactly the tracker's mesh, range by range, and end at
// exactly its size, the same surface as tracking it whole (which walks in
// another order). Drawn headless (OSMesa), no window.
#include <catch2/catch.hpp>
#include <cstring>
#include <memory>

#include "core/mesh_checks.h"
#include "gl/check.h"
#include "headless/headless_context.h"
#include "isotrack/fields.h"
#include "isotrack/tracking.h"
#include "viewer/extraction_worker.h"
#include "viewer/surface_structure.h"

using namespace isotrack;

TEST_CASE("a surface grown cell budget by cell budget ends as the tracked surface, in exact GPU buffers",
          "[viewer][growth]") {
    const headless::HeadlessContext context;
    gl::setErrorChecks(true);
    auto volume = std::make_shared<viewer::LoadedVolume>();
    volume->volume = makeField(parseFieldSpec("torus:40"));
    const double iso = fieldDefaultIso("torus");
    const Vec3d point = {19.5, 5.0, 19.5};
    const GridEdge seed = nearestCrossedEdge(volume->volume, iso, point);
    const Surface whole = trackSurface(volume->volume, iso, seed);

    render::SurfaceArena arena;
    viewer::SurfaceStructure surface(arena, 7, volume, iso, TableKind::Consistent, seed, point, glm::vec3(1.0f), 1);
    viewer::GrowthBudget budget;
    budget.cells = 300;
    int frames = 0;
    while (surface.growing()) {
        const viewer::GrowthStep step = surface.grow(budget);
        CHECK(step.cells <= budget.cells + 64);  // whole pieces: a little over the budget at most
        REQUIRE(++frames < 10000);
    }
    CHECK(frames > 3);
    const Mesh& grown = surface.mesh();
    const Dims& dims = volume->volume.dims();
    CHECK(testing::triangleSet(grown, dims) == testing::triangleSet(whole.mesh, dims));
    CHECK(testing::vertexEdgeSet(grown, dims) == testing::vertexEdgeSet(whole.mesh, dims));
    CHECK(grown.vertices.size() == whole.mesh.vertices.size());
    CHECK(surface.stats().triangles == whole.stats.triangles);
    CHECK(surface.stats().area == Approx(whole.stats.area).epsilon(1e-9));
    CHECK(surface.stats().closed == whole.stats.closed);
    // shrunk to fit once complete: vertices, their slot numbers, indices
    CHECK(surface.gpuBytes() == grown.drawByteSize() + grown.vertices.size() * sizeof(std::uint32_t));
    CHECK(surface.drawnIndexCount() == grown.indices.size());
    CHECK(surface.pickId() == 8);

    surface.restartGrowth();
    CHECK(surface.growing());
    CHECK(surface.mesh().indices.empty());
}
