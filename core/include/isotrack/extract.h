#pragma once
// One entry point for isotrack's three extractions, and the names they go by on
// the command line and in reports.
#include <array>
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "isotrack/contour_tree.h"
#include "isotrack/surface.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack {

// Exhaustive ("mc"): every cell, one mesh (marchingCubes). Track ("track"): the
// surface through each seed (trackSurface). All ("all"): every surface
// separately (extractAllSurfaces). Tree ("tree"): every surface, each tracked
// from its contour-tree arc's seed (trackTreeSurfaces), with no scan of the
// volume once the tree is built; consistent table only.
enum class Method { Exhaustive, Track, All, Tree };
// Every method, in the order front ends list them.
inline constexpr std::array<Method, 4> kMethods{Method::Exhaustive, Method::Track, Method::All, Method::Tree};

// "mc", "track", "all" or "tree"; throws InputError naming the text and the
// valid names otherwise.
Method parseMethod(const std::string& name);
// "mc", "track", "all" or "tree".
const char* methodName(Method method);

// How far an exhaustive pass has got, for a front end's progress bar. The
// march sets `slabsTotal` when it starts (its slabs of cells, twice: it counts,
// then writes) and adds each slab to `slabsDone` as a thread finishes it, so
// done/total rises from 0 to 1 while the volume streams past; the rest of an
// extraction (splitting every surface, measuring) comes after done == total.
// Methods mc and all with the consistent or classic table report; trilinear,
// track and tree leave both at 0.
struct ExtractProgress {
    std::atomic<std::uint64_t> slabsDone{0};
    std::atomic<std::uint64_t> slabsTotal{0};
};

struct ExtractRequest {
    Method method = Method::Exhaustive;
    double iso = 0.0;
    TableKind table = TableKind::Consistent;
    int threads = 1;  // track: at most kMaxTrackThreads are used
    // Track: world points; each is tracked from the crossed grid edge nearest to it.
    std::vector<Vec3d> seeds;
    // Exhaustive: also measure the mesh (area, bounds, closed, enclosed volume).
    // Off, its stats hold only its counts and bytes: measuring costs a pass over it.
    bool measure = false;
    // Tree: the volume's contour tree (computed here when null), and the
    // persistence below which its leaf branches are pruned (0: none).
    const ContourTree* tree = nullptr;
    double minPersistence = 0.0;
    // Tree: only the surfaces of this many arcs, those sweeping the most samples (0: all).
    std::size_t largestArcs = 0;
    // Tree: arcs whose surfaces are left out, not tracked (trackTreeSurfaces' leaveOut).
    std::vector<std::size_t> leaveOutArcs;
    // When another thread sets it, the extraction stops at its next check and
    // returns what it finished; the caller that set it discards the result.
    // Checked between passes and between seeds only, never in their loops.
    const std::atomic<bool>* cancel = nullptr;
    // When given, the march reports its slabs here (ExtractProgress); one
    // relaxed atomic add per slab, nothing when null.
    ExtractProgress* progress = nullptr;
    // Close the surfaces the volume's border cuts: extract from a copy padded with
    // one layer of samples below iso (isotrack/mesh_processing.h: capPadValue,
    // padVolume). Meshes stay in the volume's grid coordinates; their vertexEdges
    // index the padded grid (one sample more before each axis). Tree: the tree is
    // that of the padded copy (`tree` is not used).
    bool cap = false;
};

// Exhaustive: one surface, the whole mesh. Track: one surface per seed, in the
// seeds' order (two seeds on one surface give it twice). All: every surface,
// largest first. Tree: the surfaces of the arcs crossing iso, largest first.
// Throws InputError for a track without seeds, a tree with a table other than
// the consistent one, and as nearestCrossedEdge and trackSurface do.
std::vector<Surface> extract(const Volume& volume, const ExtractRequest& request);

}  // namespace isotrack
