// Surfaces followed through time steps (isotrack/follow_time.h and
// FollowRequest::nextStep), on Gaussian blobs built here (sigma 4 voxels, in a
// 48x24x24 grid): a tall one (peak 1.0) moving 2 voxels a step towards a short
// one (peak 0.8) that stays put, until at isovalue 0.5 they meet.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "isotrack/errors.h"
#include "isotrack/follow_time.h"

using namespace isotrack;

namespace {

constexpr double kIso = 0.5;
constexpr double kShortX = 34.0;
// The tall blob's centre at each step: 22 voxels from the short one down to 10 (joined at iso 0.5).
const std::vector<double> kTallX = {12.0, 14.0, 16.0, 18.0, 20.0, 24.0};

Volume blobsAt(double tallX) {
    Volume volume({48, 24, 24}, ScalarType::Float32);
    const double sigma = 4.0;
    for (int z = 0; z < 24; ++z)
        for (int y = 0; y < 24; ++y)
            for (int x = 0; x < 48; ++x) {
                const double r2 = (y - 11.5) * (y - 11.5) + (z - 11.5) * (z - 11.5);
                const double tall = std::exp(-((x - tallX) * (x - tallX) + r2) / (2 * sigma * sigma));
                const double low = 0.8 * std::exp(-((x - kShortX) * (x - kShortX) + r2) / (2 * sigma * sigma));
                volume.data<float>()[volume.index(x, y, z)] = static_cast<float>(tall + low);
            }
    return volume;
}

std::vector<std::size_t> shownTriangles(const StepSurfaces& step) {
    std::vector<std::size_t> counts;
    for (const StepSurface& s : step.surfaces)
        if (s.surface) counts.push_back(s.surface->mesh.triangleCount());
    std::sort(counts.begin(), counts.end());
    return counts;
}

std::vector<std::size_t> aloneTriangles(const Volume& volume, Method method) {
    ExtractRequest request;
    request.method = method;
    request.iso = kIso;
    std::vector<std::size_t> counts;
    for (const Surface& s : extract(volume, request)) counts.push_back(s.mesh.triangleCount());
    std::sort(counts.begin(), counts.end());
    return counts;
}

const StepSurface* find(const StepSurfaces& step, std::uint32_t id) {
    for (const StepSurface& s : step.surfaces)
        if (s.id == id) return &s;
    return nullptr;
}

}  // namespace

TEST_CASE("blobs through time keep their ids, extract as alone, and report their merge", "[follow]") {
    for (Method method : {Method::All, Method::Tree}) {
        CAPTURE(methodName(method));
        TimeFollowOptions options;
        options.iso = kIso;
        options.method = method;
        SurfaceTimeline timeline(options);
        for (std::size_t k = 0; k < kTallX.size(); ++k) {
            CAPTURE(k);
            const Volume volume = blobsAt(kTallX[k]);
            const StepSurfaces step = timeline.next(volume, 0.5 * double(k));
            CHECK(step.step == k);
            CHECK(step.time == 0.5 * double(k));
            CHECK(shownTriangles(step) == aloneTriangles(volume, method));
            const StepSurface* tall = find(step, 0);
            REQUIRE(tall);
            CHECK(tall->presence == Presence::Shown);
            CHECK_FALSE(tall->split);
            if (k > 0) CHECK(tall->continues == 0u);
            const StepSurface* low = find(step, 1);
            REQUIRE(low);
            if (k + 1 < kTallX.size()) {
                CHECK(step.surfaces.size() == 2);
                CHECK(low->presence == Presence::Shown);
                CHECK(low->surface->stats.boundsMin[0] > 24.0);  // the short blob, where it stays
                CHECK_FALSE(low->ended);
            } else {  // met: one surface, the tall blob's; the short one ended in it
                CHECK(step.surfaces.size() == 2);
                CHECK(low->ended);
                CHECK(low->presence == Presence::Merged);
                CHECK(low->mergedInto == 0u);
                CHECK_FALSE(low->surface);
            }
        }
    }
}

TEST_CASE("a tracked surface follows its feature from step to step", "[follow]") {
    TimeFollowOptions options;
    options.iso = kIso;
    options.method = Method::Track;
    options.seed = Vec3d{kTallX[0], 11.5, 11.5 + 4.0};  // inside the moving blob, near its top
    SurfaceTimeline timeline(options);
    for (std::size_t k = 0; k < kTallX.size(); ++k) {
        CAPTURE(k);
        const Volume volume = blobsAt(kTallX[k]);
        const StepSurfaces step = timeline.next(volume, double(k));
        REQUIRE(step.surfaces.size() == 1);
        const StepSurface& tracked = step.surfaces[0];
        CHECK(tracked.id == 0);
        CHECK(tracked.presence == Presence::Shown);
        REQUIRE(tracked.surface);
        // Its box is centred on the moving blob (until it holds both).
        const auto& stats = tracked.surface->stats;
        if (k + 1 < kTallX.size()) CHECK(std::abs(0.5 * (stats.boundsMin[0] + stats.boundsMax[0]) - kTallX[k]) < 1.0);
        CHECK(tracked.surface->mesh.triangleCount() > 0);
        CHECK(stats.area > 0.0);
    }
}

TEST_CASE("the next step's contour tree is not asked about the previous step's arcs", "[follow][tree]") {
    // The previous arcs index the first step's tree; the next step's is another
    // tree: with nextStep the surfaces are matched by footprint.
    const Volume before = blobsAt(12.0), after = blobsAt(14.0);
    FollowRequest first;
    first.volume = &before;
    first.iso = kIso;
    first.method = Method::Tree;
    NextSurfaces shown = followSurfaces(first, std::nullopt);
    REQUIRE(shown.surfaces.size() == 2);
    std::vector<PreviousSurface> previous(2);
    for (std::uint32_t i = 0; i < 2; ++i) {
        previous[i].id = 10 + i;
        previous[i].arc = shown.surfaces[i].surface->stats.arc;
        previous[i].footprint = &shown.surfaces[i].footprint;
    }
    FollowRequest next = first;
    next.volume = &after;
    next.previous = previous;
    next.nextStep = true;
    const NextSurfaces followed = followSurfaces(next, kIso);
    REQUIRE(followed.surfaces.size() == 2);
    CHECK(followed.surfaces[0].continues == 10u);
    CHECK(followed.surfaces[1].continues == 11u);
    CHECK(followed.surfaces[0].surface->stats.boundsMax[0] < 24.0);  // the tall blob, moved
    CHECK(followed.ended.empty());
}

TEST_CASE("following through time refuses mc and a misplaced seed", "[follow]") {
    TimeFollowOptions mc;
    mc.method = Method::Exhaustive;
    CHECK_THROWS_AS(SurfaceTimeline(mc), InputError);
    TimeFollowOptions track;
    track.method = Method::Track;
    CHECK_THROWS_AS(SurfaceTimeline(track), InputError);
    TimeFollowOptions all;
    all.seed = Vec3d{1, 2, 3};
    CHECK_THROWS_AS(SurfaceTimeline(all), InputError);
}
