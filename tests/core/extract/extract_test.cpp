#include <catch2/catch.hpp>

#include <atomic>
#include <set>
#include <string>

#include "core/mesh_checks.h"
#include "isotrack/errors.h"
#include "isotrack/extract.h"
#include "isotrack/fields.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"

using namespace isotrack;

TEST_CASE("methods by name", "[core][extract]") {
    std::set<std::string> names;
    for (const Method method : kMethods) {
        CHECK(parseMethod(methodName(method)) == method);
        names.insert(methodName(method));
    }
    CHECK(names.size() == kMethods.size());  // no two share a name
    CHECK(std::string(methodName(Method::Tree)) == "tree");
    CHECK(std::string(methodName(Method::Exhaustive)) == "mc");
    CHECK(std::string(methodName(Method::Track)) == "track");
    CHECK(std::string(methodName(Method::All)) == "all");
    CHECK_THROWS_AS(parseMethod("flying-edges"), InputError);
    CHECK_THROWS_WITH(parseMethod("MC"), Catch::Contains("\"MC\""));
    CHECK_THROWS_AS(parseMethod(""), InputError);
}

TEST_CASE("an unknown method's message is one line naming it and every method", "[core][extract]") {
    try {
        parseMethod("flying-edges");
        FAIL("flying-edges was accepted");
    } catch (const InputError& error) {
        const std::string message = error.what();
        CHECK(message.find('\n') == std::string::npos);
        CHECK(message.find("\"flying-edges\"") != std::string::npos);
        for (const Method method : kMethods) CHECK(message.find(methodName(method)) != std::string::npos);
        CHECK(message.find("--") == std::string::npos);  // no command-line option: Python and scripts show it too
    }
}

TEST_CASE("extract gives what each method's own function gives", "[core][extract]") {
    const Volume volume = makeField({"shells", 40});
    const double iso = fieldDefaultIso("shells");
    ExtractRequest request;
    request.iso = iso;
    request.threads = 2;

    request.method = Method::Exhaustive;
    const std::vector<Surface> mc = extract(volume, request);
    REQUIRE(mc.size() == 1);
    const Mesh whole = marchingCubes(volume, iso, TableKind::Consistent, 2);
    CHECK(testing::triangleSet(mc[0].mesh, volume.dims()) == testing::triangleSet(whole, volume.dims()));
    CHECK(mc[0].stats.triangles == whole.triangleCount());
    CHECK(mc[0].stats.area == 0.0);  // unmeasured unless asked
    request.measure = true;
    const Surface measured = extract(volume, request).front();
    CHECK(measured.stats.area == measureSurface(measured.mesh, volume, true).area);
    CHECK(measured.stats.area > 0.0);

    request.method = Method::All;
    const std::vector<Surface> all = extract(volume, request);
    CHECK(all.size() == 3);
    CHECK(all.size() == extractAllSurfaces(volume, iso, TableKind::Consistent, 2).size());

    request.method = Method::Tree;
    const std::vector<Surface> fromTree = extract(volume, request);
    REQUIRE(fromTree.size() == all.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        CHECK(testing::triangleSet(fromTree[i].mesh, volume.dims()) ==
              testing::triangleSet(all[i].mesh, volume.dims()));
        CHECK(fromTree[i].stats.arc.has_value());
    }
    request.table = TableKind::Classic;
    CHECK_THROWS_WITH(extract(volume, request), Catch::Contains("consistent table only"));
    request.table = TableKind::Consistent;

    request.method = Method::Track;
    request.threads = 1;
    CHECK_THROWS_AS(extract(volume, request), InputError);  // no seed
    const Vec3d centre = sphereFieldCenter(40);
    request.seeds = {centre, centre};
    const std::vector<Surface> tracked = extract(volume, request);
    REQUIRE(tracked.size() == 2);
    const Surface direct = trackSurface(volume, iso, nearestCrossedEdge(volume, iso, centre));
    CHECK(testing::triangleSet(tracked[0].mesh, volume.dims()) == testing::triangleSet(direct.mesh, volume.dims()));
    CHECK(tracked[1].stats.triangles == direct.stats.triangles);
}

TEST_CASE("a cancelled extraction stops before its next pass", "[core][extract]") {
    const Volume volume = makeField({"blobs", 32});
    std::atomic<bool> cancel{true};
    ExtractRequest request;
    request.iso = fieldDefaultIso("blobs");
    request.cancel = &cancel;
    for (const Method method : {Method::Exhaustive, Method::Track, Method::All}) {
        request.method = method;
        request.seeds = {{16, 16, 16}};
        CHECK(extract(volume, request).empty());
    }
    cancel = false;
    request.method = Method::All;
    CHECK(extract(volume, request).size() == extractAllSurfaces(volume, request.iso).size());
}
