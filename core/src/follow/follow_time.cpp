// Surfaces followed through a time series' steps (isotrack/follow_time.h): the
// list and the ids kept between steps; who continues whom is followSurfaces'.
#include "isotrack/follow_time.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <utility>

#include "isotrack/contour_tree.h"
#include "isotrack/errors.h"
#include "isotrack/isovalue.h"
#include "isotrack/tracking.h"

namespace isotrack {
namespace {}  // namespace

SurfaceTimeline::SurfaceTimeline(TimeFollowOptions options) : options_(std::move(options)) {
    const Method method = options_.method;
    if (method == Method::Exhaustive)
        throw InputError("following surfaces through time needs method all, tree or track, not mc (one mesh)");
    if (method == Method::Track && !options_.seed)
        throw InputError("following a tracked surface through time needs a seed point");
    if (method != Method::Track && options_.seed)
        throw InputError(std::string("a seed is for method track only, not ") + methodName(method));
}

StepSurfaces SurfaceTimeline::next(const Volume& volume, double time) {
    const auto start = std::chrono::steady_clock::now();
    if (!options_.iso) {
        const auto range = volume.range();
        if (!std::isfinite(range[0])) throw InputError("the first time step has no finite sample: give an isovalue");
        options_.iso = suggestIsovalue(volume, range);
    }
    const double iso = *options_.iso;
    FollowRequest request;
    request.volume = &volume;
    request.iso = iso;
    request.method = options_.method;
    request.table = options_.table;
    request.threads = options_.threads;
    request.nextStep = step_ > 0;
    if (options_.method == Method::Tree && options_.table == TableKind::Consistent) {
        ContourTree tree = computeContourTree(volume, options_.threads);
        if (options_.minPersistence > 0 || options_.minSize > 0)
            simplifyContourTree(tree, options_.minPersistence, options_.minSize);
        request.tree = std::make_shared<const ContourTree>(std::move(tree));
    }
    if (step_ == 0 && options_.method == Method::Track) {
        // The crossed edge nearest the seed, as extract --method track takes it; its crossing is then followed.
        const Vec3d seed = gridToFrame(volume, options_.frame).toGrid(*options_.seed);
        const GridEdge edge = nearestCrossedEdge(volume, iso, seed);
        PreviousSurface tracked;
        tracked.id = nextId_++;
        tracked.seed = edgeCrossing(volume, iso, edge);
        shown_ = {tracked};
        footprints_.assign(1, SurfaceFootprint{});
    }
    for (std::size_t i = 0; i < shown_.size(); ++i) shown_[i].footprint = &footprints_[i];
    request.previous = shown_;
    NextSurfaces next = followSurfaces(request, step_ > 0 ? std::optional<double>(iso) : std::nullopt);

    const FrameTransform transform = gridToFrame(volume, options_.frame);
    StepSurfaces out;
    out.step = step_;
    out.time = time;
    std::vector<PreviousSurface> kept;
    std::vector<SurfaceFootprint> keptFootprints;
    for (NextSurface& n : next.surfaces) {
        PreviousSurface surface;
        SurfaceFootprint footprint;
        const auto old = std::find_if(shown_.begin(), shown_.end(), [&](const PreviousSurface& s) {
            return n.continues && !n.split && s.id == *n.continues;
        });
        if (old != shown_.end()) {
            surface = *old;  // its id, and its seed while the feature is gone
            footprint = footprints_[std::size_t(old - shown_.begin())];
        } else {
            surface.id = nextId_++;
        }
        if (n.seed) surface.seed = n.seed->point;  // the seed moves with its feature
        StepSurface record;
        record.id = surface.id;
        record.continues = n.continues;
        record.split = n.split;
        record.presence = n.presence;
        if (n.presence == Presence::Merged) record.mergedInto = n.mergedInto;
        if (n.surface) {
            surface.arc = n.surface->stats.arc;
            footprint = std::move(n.footprint);
            record.surface = std::move(n.surface);
            transformSurface(*record.surface, transform);
        }
        kept.push_back(surface);
        keptFootprints.push_back(std::move(footprint));
        out.surfaces.push_back(std::move(record));
    }
    for (const EndedSurface& ended : next.ended) {
        StepSurface record;
        record.id = ended.id;
        record.presence = ended.mergedInto ? Presence::Merged : Presence::Gone;
        record.mergedInto = ended.mergedInto;
        record.ended = true;
        out.surfaces.push_back(std::move(record));
    }
    shown_ = std::move(kept);
    footprints_ = std::move(keptFootprints);
    ++step_;
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

}  // namespace isotrack
