#include <catch2/catch.hpp>

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

#include "isotrack/extract.h"
#include "isotrack/fields.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"

using namespace isotrack;

namespace {

std::uint64_t slabsOf(const Volume& volume) { return std::uint64_t(volume.dims()[2] - 1); }

}  // namespace

TEST_CASE("an exhaustive march counts each slab twice, the surfaces unchanged", "[core][extract]") {
    const Volume volume = makeField({"blobs", 40});
    const double iso = fieldDefaultIso("blobs");
    for (const int threads : {1, 3}) {
        for (const TableKind table : {TableKind::Consistent, TableKind::Classic}) {
            ExtractRequest request;
            request.iso = iso;
            request.table = table;
            request.threads = threads;
            request.method = Method::Exhaustive;
            ExtractProgress progress;
            request.progress = &progress;
            const std::vector<Surface> mc = extract(volume, request);
            CHECK(progress.slabsTotal == 2 * slabsOf(volume));
            CHECK(progress.slabsDone == progress.slabsTotal);
            const Mesh reference = marchingCubes(volume, iso, table, threads);
            REQUIRE(mc.size() == 1);
            CHECK(mc[0].mesh.triangleCount() == reference.triangleCount());
            CHECK(mc[0].mesh.vertices.size() == reference.vertices.size());

            ExtractProgress every;
            request.method = Method::All;
            request.progress = &every;
            const std::vector<Surface> all = extract(volume, request);
            CHECK(every.slabsTotal == 2 * slabsOf(volume));
            CHECK(every.slabsDone == every.slabsTotal);
            const std::vector<Surface> unobserved = extractAllSurfaces(volume, iso, table, threads);
            REQUIRE(all.size() == unobserved.size());
            for (std::size_t i = 0; i < all.size(); ++i)
                CHECK(all[i].mesh.triangleCount() == unobserved[i].mesh.triangleCount());
        }
    }
}

TEST_CASE("progress seen from another thread only rises, to the total", "[core][extract]") {
    const Volume volume = makeField({"shells", 160});
    ExtractRequest request;
    request.iso = fieldDefaultIso("shells");
    request.threads = 2;
    request.method = Method::All;
    ExtractProgress progress;
    request.progress = &progress;
    std::atomic<bool> finished{false};
    std::vector<std::uint64_t> seen;
    std::thread watcher([&] {
        while (!finished.load()) {
            seen.push_back(progress.slabsDone.load());
            std::this_thread::yield();
        }
    });
    extract(volume, request);
    finished = true;
    watcher.join();
    for (std::size_t i = 1; i < seen.size(); ++i) CHECK(seen[i] >= seen[i - 1]);
    for (const std::uint64_t done : seen) CHECK(done <= 2 * slabsOf(volume));
    CHECK(progress.slabsDone == 2 * slabsOf(volume));
}

TEST_CASE("methods without an exhaustive march leave the progress at zero", "[core][extract]") {
    const Volume volume = makeField({"blobs", 32});
    ExtractRequest request;
    request.iso = fieldDefaultIso("blobs");
    ExtractProgress progress;
    request.progress = &progress;
    request.method = Method::Track;
    request.seeds = {{16, 16, 16}};
    CHECK(!extract(volume, request).empty());
    request.method = Method::Exhaustive;
    request.table = TableKind::Trilinear;
    CHECK(!extract(volume, request).empty());
    CHECK(progress.slabsTotal == 0);
    CHECK(progress.slabsDone == 0);
}
