// Who a surface is from one extraction to the next (isotrack/follow.h:
// followSurfaces), on two Gaussian blobs built here: a tall one (peak 1.0) and
// a short one (peak 0.8), sigma 4 voxels, 16 voxels apart. At isovalue 0.5
// they are two surfaces; at 0.2 one (the saddle between them is about 0.24);
// above 0.8 only the tall one is left.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include "isotrack/follow.h"

using namespace isotrack;

namespace {

constexpr double kApart = 0.5, kJoined = 0.2, kAboveShort = 0.9;

struct Blob {
    double x, amplitude;
};

// Two blobs along x (y and z at the grid's middle) in a 44x24x24 grid.
Volume blobs(const std::vector<Blob>& list) {
    Volume volume({44, 24, 24}, ScalarType::Float32);
    const double sigma = 4.0;
    for (int z = 0; z < 24; ++z)
        for (int y = 0; y < 24; ++y)
            for (int x = 0; x < 44; ++x) {
                double v = 0.0;
                for (const Blob& b : list) {
                    const double d2 = (x - b.x) * (x - b.x) + (y - 11.5) * (y - 11.5) + (z - 11.5) * (z - 11.5);
                    v += b.amplitude * std::exp(-d2 / (2.0 * sigma * sigma));
                }
                volume.data<float>()[volume.index(x, y, z)] = static_cast<float>(v);
            }
    return volume;
}

Volume twoBlobs(double shift = 0.0) { return blobs({{14.0 + shift, 1.0}, {30.0 + shift, 0.8}}); }

// A point on the blob centred at x along the +y direction, at isovalue iso.
Vec3d pointOn(const Volume& volume, double x, double iso) {
    double y = 11.5;
    while (y < 23.0 && volume.value(static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)), 12) >= iso)
        y += 0.25;
    return {x, y, 11.5};
}

// The caller's side: surfaces with ids, their footprints and arcs kept alive.
struct Shown {
    std::vector<PreviousSurface> surfaces;
    std::map<std::uint32_t, SurfaceFootprint> footprints;
    std::map<std::uint32_t, std::size_t> triangles;
    std::uint32_t nextId = 0;

    // Takes `next` as the caller would: continuing surfaces keep their ids, the others get new ones.
    void take(const NextSurfaces& next) {
        std::vector<PreviousSurface> kept;
        for (const NextSurface& n : next.surfaces) {
            PreviousSurface p;
            if (n.continues && !n.split) {
                const auto old = std::find_if(surfaces.begin(), surfaces.end(),
                                              [&](const PreviousSurface& s) { return s.id == *n.continues; });
                REQUIRE(old != surfaces.end());
                p = *old;
                if (n.seed) p.seed = n.seed->point;
            } else {
                p.id = nextId++;
            }
            if (n.surface) {
                footprints[p.id] = n.footprint;
                triangles[p.id] = n.surface->mesh.triangleCount();
                p.arc = n.surface->stats.arc;
            }
            kept.push_back(p);
        }
        surfaces = kept;
        for (PreviousSurface& p : surfaces) p.footprint = &footprints[p.id];
    }
};

NextSurfaces follow(const Volume& volume, double iso, Method method, const Shown& shown,
                    std::optional<double> previousIso, std::shared_ptr<const ContourTree> tree = nullptr,
                    bool nextStep = false) {
    FollowRequest request;
    request.volume = &volume;
    request.nextStep = nextStep;
    request.iso = iso;
    request.method = method;
    request.tree = std::move(tree);
    request.previous = shown.surfaces;
    return followSurfaces(request, previousIso);
}

std::size_t trianglesOf(const NextSurface& n) { return n.surface ? n.surface->mesh.triangleCount() : 0; }

}  // namespace

TEST_CASE("the first extraction names every surface new, largest first", "[follow]") {
    const Volume volume = twoBlobs();
    const NextSurfaces next = follow(volume, kApart, Method::All, Shown{}, std::nullopt);
    REQUIRE(next.surfaces.size() == 2);
    CHECK_FALSE(next.surfaces[0].continues);
    CHECK_FALSE(next.surfaces[1].continues);
    CHECK(trianglesOf(next.surfaces[0]) > trianglesOf(next.surfaces[1]));
    CHECK(next.ended.empty());
    CHECK(next.iso == kApart);
}

TEST_CASE("a surface that splits continues in both parts, the largest first", "[follow]") {
    const Volume volume = twoBlobs();
    for (Method method : {Method::All, Method::Tree}) {
        CAPTURE(methodName(method));
        const auto tree = std::make_shared<const ContourTree>(computeContourTree(volume, 1));
        Shown shown;
        shown.nextId = 7;
        shown.take(follow(volume, kJoined, method, shown, std::nullopt, tree));
        REQUIRE(shown.surfaces.size() == 1);
        REQUIRE(shown.surfaces[0].id == 7);
        const NextSurfaces next = follow(volume, kApart, method, shown, kJoined, tree);
        REQUIRE(next.surfaces.size() == 2);
        CHECK(next.surfaces[0].continues == 7u);
        CHECK_FALSE(next.surfaces[0].split);
        CHECK(next.surfaces[1].continues == 7u);
        CHECK(next.surfaces[1].split);
        CHECK(trianglesOf(next.surfaces[0]) > trianglesOf(next.surfaces[1]));
        CHECK(next.ended.empty());
    }
}

TEST_CASE("surfaces that merge continue the largest; the other ends, merged into it", "[follow]") {
    const Volume volume = twoBlobs();
    for (Method method : {Method::All, Method::Tree}) {
        CAPTURE(methodName(method));
        const auto tree = std::make_shared<const ContourTree>(computeContourTree(volume, 1));
        Shown shown;
        shown.nextId = 1;
        shown.take(follow(volume, kApart, method, shown, std::nullopt, tree));
        REQUIRE(shown.surfaces.size() == 2);
        REQUIRE(shown.triangles[1] > shown.triangles[2]);  // 1 is the tall blob
        // Listed the other way round: the merged surface still continues the tall blob.
        std::swap(shown.surfaces[0], shown.surfaces[1]);
        const NextSurfaces next = follow(volume, kJoined, method, shown, kApart, tree);
        REQUIRE(next.surfaces.size() == 1);
        CHECK(next.surfaces[0].continues == 1u);
        CHECK_FALSE(next.surfaces[0].split);
        REQUIRE(next.ended.size() == 1);
        CHECK(next.ended[0].id == 2);
        CHECK(next.ended[0].mergedInto == 1u);
    }
}

TEST_CASE("a tracked surface is gone above its peak, keeps its place, and comes back", "[follow]") {
    const Volume volume = twoBlobs();
    for (Method method : {Method::Track, Method::All, Method::Exhaustive}) {
        CAPTURE(methodName(method));
        Shown shown;
        PreviousSurface tracked;
        tracked.id = 4;
        tracked.seed = pointOn(volume, 30.0, kApart);  // on the short blob
        shown.surfaces = {tracked};
        shown.nextId = 5;

        NextSurfaces gone = follow(volume, kAboveShort, method, shown, kApart);
        const NextSurface& first = gone.surfaces.front();
        CHECK(first.continues == 4u);
        CHECK(first.presence == Presence::Gone);
        CHECK_FALSE(first.seed);  // the caller keeps the seed it had
        CHECK_FALSE(first.surface);
        // all and mc show the tall blob (mc as one mesh), as a new surface after it.
        CHECK(gone.surfaces.size() == (method == Method::Track ? 1u : 2u));
        if (method == Method::Exhaustive) CHECK(gone.surfaces[1].wholeVolume);

        const NextSurfaces back = follow(volume, kApart, method, shown, kAboveShort);
        const NextSurface& again = back.surfaces.front();
        CHECK(again.continues == 4u);
        CHECK(again.presence == Presence::Shown);
        REQUIRE(again.seed);
        REQUIRE(again.surface);
        // It is the short blob: its box lies around x = 30.
        CHECK(again.surface->stats.boundsMin[0] > 22.0);
        CHECK(again.surface->stats.boundsMax[0] < 38.0);
    }
}

TEST_CASE("a tracked seed on another tracked surface's surface is merged into it, and splits again", "[follow]") {
    const Volume volume = twoBlobs();
    for (Method method : {Method::Track, Method::All}) {
        CAPTURE(methodName(method));
        Shown shown;
        PreviousSurface tall, small;
        tall.id = 10;
        tall.seed = pointOn(volume, 14.0, kApart);
        small.id = 11;
        small.seed = pointOn(volume, 30.0, kApart);
        shown.surfaces = {small, tall};  // the first in the list shows the merged surface

        const NextSurfaces merged = follow(volume, kJoined, method, shown, kApart);
        REQUIRE(merged.surfaces.size() == 2);
        CHECK(merged.surfaces[0].continues == 11u);
        CHECK(merged.surfaces[0].presence == Presence::Shown);
        CHECK(merged.surfaces[1].continues == 10u);
        CHECK(merged.surfaces[1].presence == Presence::Merged);
        CHECK(merged.surfaces[1].mergedInto == 11u);
        CHECK(merged.surfaces[1].seed);  // found, on the merged surface
        CHECK_FALSE(merged.surfaces[1].surface);

        const NextSurfaces apart = follow(volume, kApart, method, shown, kJoined);
        REQUIRE(apart.surfaces.size() == 2);
        CHECK(apart.surfaces[0].presence == Presence::Shown);
        CHECK(apart.surfaces[1].presence == Presence::Shown);
        CHECK(trianglesOf(apart.surfaces[1]) > trianglesOf(apart.surfaces[0]));  // 10 is the tall blob again
    }
}

TEST_CASE("a tracked surface the extraction had no seed for stays unchanged", "[follow]") {
    const Volume volume = twoBlobs();
    FollowRequest request;
    request.volume = &volume;
    request.iso = kApart;
    request.method = Method::Track;
    NextExtraction extraction = extractNext(request);  // asked before the surface was tracked
    PreviousSurface late;
    late.id = 3;
    late.seed = pointOn(volume, 14.0, kApart);
    const NextSurfaces next = continueSurfaces({late}, kApart, std::move(extraction));
    REQUIRE(next.surfaces.size() == 1);
    CHECK(next.surfaces[0].continues == 3u);
    CHECK(next.surfaces[0].unchanged);
}

TEST_CASE("a surface at its own isovalue past its arc's end is gone; its stand-in stays out", "[follow][tree]") {
    const Volume volume = twoBlobs();
    const auto tree = std::make_shared<const ContourTree>(computeContourTree(volume, 1));
    Shown shown;
    shown.nextId = 1;
    shown.take(follow(volume, kApart, Method::Tree, shown, std::nullopt, tree));
    REQUIRE(shown.surfaces.size() == 2);
    PreviousSurface& small = shown.surfaces[1];  // 2: the short blob
    REQUIRE(small.arc);
    small.own = OwnIsovalue{kAboveShort, *small.arc, *small.arc, true};

    const NextSurfaces past = follow(volume, kApart, Method::Tree, shown, kApart, tree);
    REQUIRE(past.surfaces.size() == 2);  // the short blob at the common isovalue is not a new surface
    CHECK(past.surfaces[0].continues == 1u);
    CHECK(past.surfaces[0].presence == Presence::Shown);
    CHECK(past.surfaces[1].continues == 2u);
    CHECK(past.surfaces[1].presence == Presence::Gone);
    CHECK(past.surfaces[1].ownIsovalue);
    CHECK(past.surfaces[1].ownShown == kAboveShort);
    CHECK(past.ended.empty());

    // Within its arc it is shown at its own isovalue, smaller than at the common one.
    small.own->iso = 0.7;
    FollowRequest only;
    only.volume = &volume;
    only.iso = kApart;
    only.method = Method::Tree;
    only.tree = tree;
    only.previous = shown.surfaces;
    only.onlyOwnIsovalues = true;
    const NextSurfaces own = followSurfaces(only, kApart);
    REQUIRE(own.surfaces.size() == 2);
    CHECK(own.surfaces[0].unchanged);
    CHECK(own.surfaces[1].presence == Presence::Shown);
    CHECK(own.surfaces[1].ownArc);
    CHECK(trianglesOf(own.surfaces[1]) < shown.triangles[2]);

    // Another method: own isovalues lapse, and the surface is matched as the others are.
    const NextSurfaces lapsed = follow(volume, kApart, Method::All, shown, kApart);
    REQUIRE(lapsed.surfaces.size() == 2);
    CHECK(lapsed.surfaces[1].continues == 2u);
    CHECK_FALSE(lapsed.surfaces[1].ownIsovalue);
    CHECK(lapsed.surfaces[1].presence == Presence::Shown);
}

TEST_CASE("a time step: blobs that moved a little keep their ids; blobs that meet report a merge", "[follow]") {
    const Volume before = twoBlobs();
    Shown shown;
    shown.nextId = 1;
    shown.take(follow(before, kApart, Method::All, shown, std::nullopt));
    REQUIRE(shown.surfaces.size() == 2);

    // The next step: the same isovalue, the field moved by a voxel and a half.
    const Volume moved = twoBlobs(1.5);
    const NextSurfaces next = follow(moved, kApart, Method::All, shown, kApart);
    REQUIRE(next.surfaces.size() == 2);
    CHECK(next.surfaces[0].continues == 1u);
    CHECK(next.surfaces[1].continues == 2u);
    CHECK(next.ended.empty());
    for (const NextSurface& n : next.surfaces) CHECK_FALSE(n.split);

    // A tracked blob follows its seed into the next step.
    Shown tracking;
    PreviousSurface tracked;
    tracked.id = 9;
    tracked.seed = pointOn(before, 30.0, kApart);
    tracking.surfaces = {tracked};
    const NextSurfaces seeded = follow(moved, kApart, Method::Track, tracking, kApart);
    REQUIRE(seeded.surfaces.size() == 1);
    CHECK(seeded.surfaces[0].continues == 9u);
    CHECK(seeded.surfaces[0].presence == Presence::Shown);
    REQUIRE(seeded.surfaces[0].seed);
    CHECK(seeded.surfaces[0].seed->point[0] > 24.0);  // still on the short blob
    REQUIRE(seeded.surfaces[0].surface);
    CHECK(seeded.surfaces[0].surface->stats.boundsMin[0] > 22.0);

    // Then the blobs drift together until they meet.
    shown.take(next);
    const Volume met = blobs({{18.0, 1.0}, {26.0, 0.8}});
    const NextSurfaces merged = follow(met, kApart, Method::All, shown, kApart);
    REQUIRE(merged.surfaces.size() == 1);
    CHECK(merged.surfaces[0].continues == 1u);
    REQUIRE(merged.ended.size() == 1);
    CHECK(merged.ended[0].id == 2);
    CHECK(merged.ended[0].mergedInto == 1u);
}

TEST_CASE("a time step with the contour tree matches by footprint: the arcs are another tree's", "[follow][tree]") {
    // Three blobs whose peaks change order: the two steps' trees number their arcs apart.
    const Volume before = blobs({{8.0, 0.9}, {22.0, 1.0}, {36.0, 0.8}});
    Shown shown;
    shown.nextId = 1;
    shown.take(follow(before, kApart, Method::Tree, shown, std::nullopt));
    REQUIRE(shown.surfaces.size() == 3);
    const Volume after = blobs({{9.0, 1.0}, {23.0, 0.8}, {37.0, 0.9}});  // peaks in another order
    const NextSurfaces next = follow(after, kApart, Method::Tree, shown, kApart, nullptr, true);
    REQUIRE(next.surfaces.size() == 3);
    for (const NextSurface& n : next.surfaces) {
        REQUIRE(n.continues);
        REQUIRE(n.surface);
        const double x = 0.5 * (n.surface->stats.boundsMin[0] + n.surface->stats.boundsMax[0]);
        const auto old = std::find_if(shown.surfaces.begin(), shown.surfaces.end(),
                                      [&](const PreviousSurface& s) { return s.id == *n.continues; });
        REQUIRE(old != shown.surfaces.end());
        const SurfaceFootprint& f = *old->footprint;
        const double was = 0.5 * (f.boundsMin[0] + f.boundsMax[0]);
        CHECK(std::abs(x - was - 1.0) < 0.75);  // the same blob, a voxel on
    }
    CHECK(next.ended.empty());
}
