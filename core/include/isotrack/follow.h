#pragma once
// Who a surface is, from one extraction to the next: the one answer, for every
// front end, to "which new surface continues which old one". The viewer asks
// it at each new isovalue so that a surface keeps its id, colour, visibility,
// offset and selection; the same question comes back for the next time step
// of a series (the same grid, other samples: pass that step's volume).
//
// The caller names the surfaces it shows (PreviousSurface, in its list order)
// and what to extract (FollowRequest: the volume, the isovalue, the method);
// it gets back the next surfaces (NextSurfaces), in the order its list should
// take, each saying which previous surface it continues, if any, and whether
// it is shown, gone or merged, or is a further part of a split.
//
// Three kinds of surface, three rules:
//
// Tracked surfaces (a seed: a world point on the surface). The seed is
// followed to the new isovalue (followSeed, below). With methods all and tree
// it names the new surface that holds its crossed edge; with mc and track
// that surface is tracked from it (once, however many seeds lie on it). The
// first tracked surface in the caller's list to claim a new surface shows it;
// a later one whose seed lies on the same surface is Merged into the first;
// one whose seed found no surface is Gone. Both keep their seed (and their
// place in the list), so they come back when the surfaces split again or the
// isovalue returns. A tracked surface the extraction had no seed for (the
// caller started tracking it after asking) stays unchanged.
//
// Surfaces with an isovalue of their own (method tree, consistent table:
// Carr & Snoeyink's flexible isosurfaces). Each is followed along the contour
// tree from its arc to its own isovalue (followArc) and tracked from that
// arc's seed (trackArc); it is Gone when its arc ends on the way (an extremum
// passed). At the common isovalue it stands in for the surface on the arc its
// origin leads to, which is left out of the others. With another method own
// isovalues lapse: those surfaces are matched as the others are.
//
// The others. With the contour tree (method tree, and the previous isovalue
// known), a new surface is its arc: it continues the previous surface on the
// arc it leads back to at the previous isovalue (matchSurfacesByArc). Without
// it, by footprint (matchSurfaces): the previous surface it shares the most
// 4x4x4-cell blocks with. The largest new surface continuing a previous one
// takes that one's place in the list; further parts of a split come right
// after it (split set); previous surfaces nothing continues have ended
// (NextSurfaces::ended, saying which surface they merged into, if any); new
// surfaces continuing nothing come last, in the extraction's order (largest
// first for all and tree). Tracked surfaces and those with their own
// isovalue keep their places. So the list does not reshuffle while the
// isovalue moves.
//
// Time steps. The previous surfaces' arcs and own isovalues live on their own
// volume's contour tree; with FollowRequest::nextStep (the volume is the next
// time step's, not the same samples at another isovalue) they are not looked
// up in the new volume's tree: every surface that is not tracked is matched by
// footprint (a blob that moved less than its own size shares blocks with where
// it was; one that moved further still holds the other's box centre), and own
// isovalues lapse, as with another method. Seeds are followed as above: the
// walk along the gradient finds the surface where the feature moved to.
//
// Two steps. extractNext does the volume's work (the extraction, the seeds,
// the own isovalues: seconds on a large volume); continueSurfaces decides who
// each surface is (no volume, milliseconds). followSurfaces does both. A front
// end whose list may change while the extraction runs (the viewer's worker
// thread: the user deletes or tracks a surface, an earlier result is shown)
// runs extractNext off its frame loop and continueSurfaces with its list as it
// is when the result arrives.
//
// Seeds. At a new isovalue the surface has moved along its gradient (up the
// gradient when the isovalue rose, down when it fell), so followSeed walks
// from the point along the gradient of the trilinear interpolant until it
// crosses the new isovalue, then takes the crossed grid edge nearest that
// crossing. When the walk finds no crossing within kFollowWalkVoxels, the
// crossed edge nearest the point itself within kFollowNeighbourhood voxels is
// taken; when there is none, the surface is gone at this isovalue (nullopt).
//
// Footprints. Each surface's footprint is the set of 4x4x4-cell blocks its
// vertices lie in (at most 16,384 vertices looked at, evenly spread, so that a
// large surface costs little). A new surface continues the previous surface
// with which it shares the most blocks; when it shares blocks with several
// that each have at least a quarter of the best one's share (surfaces that
// merged), the largest of those (by triangles) is the one it continues. A new
// surface sharing no block continues the previous one whose bounding box holds
// its centre while its own box holds the previous one's (the same surface,
// moved further than a block), the most overlapping if several do.
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "isotrack/contour_tree.h"
#include "isotrack/extract.h"
#include "isotrack/mesh.h"
#include "isotrack/surface.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack {

inline constexpr double kFollowWalkVoxels = 24.0;
inline constexpr int kFollowNeighbourhood = 3;
inline constexpr int kFootprintBlockShift = 2;  // 4x4x4 cells a block

// ---- the building blocks ----

struct FollowedSeed {
    GridEdge edge;
    Vec3d point{0, 0, 0};  // where the surface crosses `edge`, in world units
};

// The crossed edge of the surface through `point` at isovalue `iso` (see above).
std::optional<FollowedSeed> followSeed(const Volume& volume, double iso, const Vec3d& point);

// Where the surface crosses `edge` (which must be crossed), in world units.
Vec3d edgeCrossing(const Volume& volume, double iso, const GridEdge& edge);

struct SurfaceFootprint {
    std::vector<std::uint64_t> blocks;  // sorted, unique
    std::size_t triangles = 0;
    Vec3d boundsMin{0, 0, 0}, boundsMax{0, 0, 0};
};

// From the mesh's vertex grid edges (a mesh without them has an empty block set).
SurfaceFootprint footprintOf(const Mesh& mesh);

// For each new surface, the index of the previous surface it continues, or -1.
std::vector<int> matchSurfaces(const std::vector<const SurfaceFootprint*>& previous,
                               const std::vector<const SurfaceFootprint*>& next);

// By the contour tree: for each new surface (on arc newArcs[k] at the new
// isovalue), the index of the previous surface (on oldArcs[i] at `oldIso`) on
// the arc it leads back to (followArc), or -1. On the same arc it is the same
// surface; after a split every part leads back to the surface that split;
// after a merge the merged surface leads back to the branch sweeping the most
// samples; a surface born on the way continues nothing. nullopt when a surface
// has no arc (it came from another method): match by footprint then.
std::optional<std::vector<int>> matchSurfacesByArc(const ContourTree& tree, double oldIso,
                                                   const std::vector<std::optional<std::size_t>>& oldArcs,
                                                   const std::vector<std::optional<std::size_t>>& newArcs);

// The surface on `arc` followed along the tree to isovalue `iso` (followArc),
// tracked from that arc's seed (trackArc); nullopt when it vanishes on the way.
std::optional<Surface> surfaceAtOwnIsovalue(const ContourTree& tree, const Volume& volume, std::size_t arc, double iso,
                                            int threads = 1);

// ---- following a list of surfaces ----

// Whether a surface shows a mesh at the new isovalue (or time step).
enum class Presence { Shown, Gone, Merged };

// "shown", "gone" or "merged": the name every front end reports (JSON, Python).
const char* presenceName(Presence presence);

// A surface's own isovalue (method tree).
struct OwnIsovalue {
    double iso = 0.0;        // the isovalue it is wanted at
    std::size_t arc = 0;     // its contour-tree arc at its last isovalue
    std::size_t origin = 0;  // its arc when it got its own isovalue: the surface it stands in for
    bool extract = true;     // false: its mesh is at `iso` already (only the one it stands in for is left out)
};

// A surface the caller shows, named by the caller's id.
struct PreviousSurface {
    std::uint32_t id = 0;
    std::optional<Vec3d> seed;       // a tracked surface: a world point on it
    std::optional<OwnIsovalue> own;  // a surface with an isovalue of its own
    std::optional<std::size_t> arc;  // its mesh's contour-tree arc (SurfaceStats::arc)
    // Its mesh's footprint; read by continueSurfaces only, for a surface with
    // neither seed nor own isovalue (must outlive that call).
    const SurfaceFootprint* footprint = nullptr;
};

// How far extractNext has got, for another thread to show.
struct FollowProgress {
    ExtractProgress march;                         // mc and all: the slabs marched (extract.h)
    std::atomic<int> seedsDone{0}, seedsTotal{0};  // while the seeds are followed
};

struct FollowRequest {
    const Volume* volume = nullptr;  // the volume to extract from: another isovalue's, or the next time step's
    double iso = 0.0;
    Method method = Method::All;
    TableKind table = TableKind::Consistent;
    int threads = 1;
    // Method tree (consistent table): the volume's contour tree, simplified as
    // wanted; computed (unsimplified) when null.
    std::shared_ptr<const ContourTree> tree;
    // The caller's surfaces; extractNext reads their ids, seeds and own isovalues.
    std::vector<PreviousSurface> previous;
    // Only the surfaces with an isovalue of their own are extracted again; the
    // others keep their meshes (and the common isovalue stays as it was).
    bool onlyOwnIsovalues = false;
    // The volume is the next time step's (see "Time steps" above): arcs and own
    // isovalues lapse, surfaces are matched by footprint.
    bool nextStep = false;
    // When another thread sets it, the work stops at its next check (between
    // passes and seeds) and throws Cancelled.
    const std::atomic<bool>* cancel = nullptr;
    FollowProgress* progress = nullptr;
};

// What extractNext found, before anyone is named.
struct NextExtraction {
    double iso = 0.0;
    Method method = Method::All;
    bool onlyOwnIsovalues = false;
    bool nextStep = false;
    std::shared_ptr<const ContourTree> tree;  // method tree: the tree the surfaces' arcs are on
    // mc: the whole mesh first, then the seeds' surfaces; all and tree: every
    // surface, largest first (the ones own isovalues stand in for left out);
    // track: the seeds' surfaces.
    std::vector<Surface> surfaces;
    std::vector<SurfaceFootprint> footprints;  // one per surface
    struct Seed {
        std::uint32_t id = 0;
        std::optional<FollowedSeed> seed;  // nullopt: no surface near it
        int surface = -1;                  // into `surfaces`; shared by seeds on one surface
    };
    std::vector<Seed> seeds;  // one per tracked previous surface, in their order
    struct Own {
        std::uint32_t id = 0;
        double iso = 0.0;
        std::optional<Surface> surface;  // nullopt: its arc ended on the way
        SurfaceFootprint footprint;
    };
    std::vector<Own> own;  // one per previous surface with an own isovalue to extract
};

// One surface of the next list.
struct NextSurface {
    std::optional<std::uint32_t> continues;  // the previous surface's id; nullopt: a new surface
    bool split = false;      // a further part of `continues`, which split (its largest part has split false)
    bool unchanged = false;  // nothing was extracted for it: it stays as it was
    Presence presence = Presence::Shown;
    std::uint32_t mergedInto = 0;       // Merged: the id of the tracked surface showing its seed's surface
    std::optional<Surface> surface;     // Shown (and not unchanged): its mesh
    SurfaceFootprint footprint;         // of that mesh
    std::optional<FollowedSeed> seed;   // a tracked surface whose seed was found: the seed now (Shown or Merged)
    bool ownIsovalue = false;           // it keeps an isovalue of its own
    std::optional<double> ownShown;     // extracted at its own isovalue: that isovalue (also when Gone)
    std::optional<std::size_t> ownArc;  // ... and its arc now, when it is Shown
    bool wholeVolume = false;           // method mc: the one mesh of every cell
};

// A previous surface that nothing continues.
struct EndedSurface {
    std::uint32_t id = 0;
    // The previous surface whose continuation now holds its blocks or its arc
    // (they merged); nullopt: it vanished.
    std::optional<std::uint32_t> mergedInto;
};

struct NextSurfaces {
    double iso = 0.0;                   // the common isovalue (of the extraction)
    std::vector<NextSurface> surfaces;  // in the order the caller's list takes
    // The previous surfaces kept by neither seed nor own isovalue that nothing
    // continues, in the previous list's order (a tracked surface never ends:
    // it is Gone or Merged and keeps its place).
    std::vector<EndedSurface> ended;
};

// The volume's work: extraction, seeds, own isovalues and footprints. Throws
// InputError as extract does, and Cancelled when request.cancel is set.
NextExtraction extractNext(const FollowRequest& request);

// Who each surface is: `previous` is the caller's list now (it may differ from
// the request's), `previousIso` the common isovalue of its surfaces (nullopt:
// none shown yet). Consumes the extraction's meshes.
NextSurfaces continueSurfaces(const std::vector<PreviousSurface>& previous, std::optional<double> previousIso,
                              NextExtraction extraction);

// Both: the next surfaces of request.previous.
NextSurfaces followSurfaces(const FollowRequest& request, std::optional<double> previousIso);

}  // namespace isotrack
