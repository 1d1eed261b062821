#pragma once
// Surfaces followed through the steps of a time series, each keeping one id
// for as long as it lives: the records behind `extract --all-times` (its
// track.json) and Python's follow_through_time, so that both say the same.
//
// Who a surface is from one step to the next is followSurfaces' answer
// (isotrack/follow.h, with FollowRequest::nextStep), at one isovalue for every
// step; this class only keeps the list between steps and hands out ids:
//  - the first step's surfaces get ids 0, 1, ... in the extraction's order
//    (largest first for all and tree); with method track the one tracked
//    surface is id 0, from the seed (the crossed edge nearest it, as extract
//    --method track takes it);
//  - a surface that continues one of the previous step keeps its id; the
//    further parts of a split (split true) and surfaces born in this step get
//    new ids, in order, never reused;
//  - a previous surface that nothing continues has ended: it is listed once
//    more, in the step where it ended, with presence Merged and the id of the
//    surface it merged into, or Gone when it vanished, and then no longer;
//  - a tracked surface keeps its seed (and its place, id 0) while it is Gone
//    or Merged, so it comes back when its feature does.
// Meshes leave in the frame asked for (LPS by default, as extract --frame);
// area and enclosed volume are in world units, whatever the frame.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "isotrack/extract.h"
#include "isotrack/follow.h"
#include "isotrack/orientation.h"
#include "isotrack/surface.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack {

struct TimeFollowOptions {
    // The one isovalue of every step; nullopt: the first step's suggested
    // isovalue (suggestIsovalue, as extract and the viewer open a file on).
    std::optional<double> iso;
    Method method = Method::All;  // all, tree or track (mc gives no surfaces to follow)
    TableKind table = TableKind::Consistent;
    int threads = 1;
    std::optional<Vec3d> seed;  // method track: a point on the surface to follow, in `frame`, at the first step
    WorldFrame frame = WorldFrame::Lps;  // of the seed and of the meshes and bounds handed out
    double minPersistence = 0.0;         // method tree: each step's tree simplified so
    std::size_t minSize = 0;
};

// One surface of one step.
struct StepSurface {
    std::uint32_t id = 0;
    std::optional<std::uint32_t>
        continues;       // the previous step's surface it continues (its own id, or the split one's)
    bool split = false;  // a further part of `continues`, which split
    Presence presence = Presence::Shown;
    std::optional<std::uint32_t> mergedInto;  // Merged: the surface that now holds it
    bool ended = false;                       // not followed past this step
    std::optional<Surface> surface;           // Shown: its mesh and bounds in the frame, and its measures
};

struct StepSurfaces {
    std::size_t step = 0;
    double time = 0.0;
    double seconds = 0.0;               // extraction and following, not reading
    std::vector<StepSurface> surfaces;  // the shown list's order, then the ended ones
};

class SurfaceTimeline {
public:
    // InputError for method mc, for track without a seed, or a seed with another method.
    explicit SurfaceTimeline(TimeFollowOptions options);

    // The surfaces of the next step (`volume`, at `time`), followed from the
    // previous one's. Every step must share the first step's grid
    // (TimeStepReader checks it). InputError when the first step has no
    // finite sample and no isovalue was given, or no crossed edge at all for
    // method track's seed.
    StepSurfaces next(const Volume& volume, double time);

    // The isovalue of every step: the options' or, once the first step is in, its suggested one.
    std::optional<double> iso() const { return options_.iso; }

private:
    TimeFollowOptions options_;
    std::size_t step_ = 0;
    std::uint32_t nextId_ = 0;
    std::vector<PreviousSurface> shown_;
    std::vector<SurfaceFootprint> footprints_;  // one per shown_ surface
};

}  // namespace isotrack
