// The volume's side of following surfaces (isotrack/follow.h): one extraction
// by the request's method, then each surface with an isovalue of its own
// followed along the contour tree, then each seed followed to the isovalue
// (and its surface tracked when the method has not extracted it), then every
// surface's footprint. Nothing here decides who a surface is.
#include <algorithm>

#include "isotrack/errors.h"
#include "isotrack/follow.h"
#include "isotrack/tracking.h"

namespace isotrack {
namespace {

bool cancelled(const FollowRequest& request) {
    return request.cancel != nullptr && request.cancel->load(std::memory_order_relaxed);
}

bool meshHasEdge(const Mesh& mesh, const GridEdge& edge) {
    return std::any_of(mesh.vertexEdges.begin(), mesh.vertexEdges.end(),
                       [&](const PackedGridEdge& e) { return GridEdge(e) == edge; });
}

bool treeMethod(const FollowRequest& request) {
    return request.method == Method::Tree && request.table == TableKind::Consistent;
}

// The request's tree, or the volume's own when it gave none.
std::shared_ptr<const ContourTree> treeFor(const FollowRequest& request) {
    if (request.tree) return request.tree;
    return std::make_shared<const ContourTree>(computeContourTree(*request.volume, request.threads));
}

// The arcs at the common isovalue whose surfaces the surfaces with an
// isovalue of their own stand in for: left out of the others, never tracked.
std::vector<std::size_t> displacedArcs(const FollowRequest& request, const ContourTree& tree) {
    std::vector<std::size_t> arcs;
    if (request.nextStep) return arcs;  // another step's arcs: they lapse
    for (const PreviousSurface& previous : request.previous) {
        if (!previous.own) continue;
        const std::size_t origin = followArc(tree, previous.own->origin, request.iso);
        if (origin < tree.arcs.size()) arcs.push_back(origin);
    }
    return arcs;
}

// Every surface the method gives at once (none for track).
void extractEvery(const FollowRequest& request, NextExtraction& out) {
    if (request.method == Method::Track) return;  // only the seeds' surfaces, below
    ExtractRequest every;
    every.method = request.method;
    every.iso = request.iso;
    every.table = request.table;
    every.threads = request.threads;
    every.measure = true;
    every.cancel = request.cancel;
    every.progress = request.progress ? &request.progress->march : nullptr;
    if (treeMethod(request)) {
        out.tree = treeFor(request);
        every.tree = out.tree.get();
        every.leaveOutArcs = displacedArcs(request, *out.tree);
    }
    out.surfaces = extract(*request.volume, every);
    if (request.progress) request.progress->march.slabsTotal = 0;
}

// Each surface with an isovalue of its own, at it (the surface it stands in for
// at the common isovalue extractEvery left out, untracked: displacedArcs).
void followOwnIsovalues(const FollowRequest& request, NextExtraction& out) {
    const bool any = std::any_of(request.previous.begin(), request.previous.end(),
                                 [](const PreviousSurface& s) { return s.own.has_value(); });
    if (!any || !treeMethod(request) || request.nextStep) return;  // another step's arcs: they lapse
    if (!out.tree) out.tree = treeFor(request);
    const ContourTree& tree = *out.tree;
    for (const PreviousSurface& previous : request.previous) {
        if (!previous.own) continue;
        if (cancelled(request)) throw Cancelled{};
        const OwnIsovalue& own = *previous.own;
        if (!own.extract) continue;
        NextExtraction::Own followed;
        followed.id = previous.id;
        followed.iso = own.iso;
        followed.surface = surfaceAtOwnIsovalue(tree, *request.volume, own.arc, own.iso, request.threads);
        if (followed.surface) followed.footprint = footprintOf(followed.surface->mesh);
        out.own.push_back(std::move(followed));
    }
}

// Each seed followed to the isovalue; with all and tree it names the surface
// that holds its edge, otherwise its surface is tracked (once, however many
// seeds it holds).
void followSeeds(const FollowRequest& request, NextExtraction& out) {
    std::size_t total = 0;
    for (const PreviousSurface& previous : request.previous) total += previous.seed ? 1 : 0;
    if (request.progress) {
        request.progress->seedsTotal = static_cast<int>(total);
        request.progress->seedsDone = 0;
    }
    const bool every = request.method == Method::All || request.method == Method::Tree;
    const std::size_t extracted = out.surfaces.size();
    for (const PreviousSurface& previous : request.previous) {
        if (!previous.seed) continue;
        if (cancelled(request)) throw Cancelled{};
        if (request.progress) ++request.progress->seedsDone;
        NextExtraction::Seed seed;
        seed.id = previous.id;
        seed.seed = followSeed(*request.volume, request.iso, *previous.seed);
        if (seed.seed) {
            const GridEdge edge = seed.seed->edge;
            const std::size_t from = every ? 0 : extracted;  // mc: not the whole mesh
            for (std::size_t i = from; i < out.surfaces.size() && seed.surface < 0; ++i) {
                if (meshHasEdge(out.surfaces[i].mesh, edge)) seed.surface = static_cast<int>(i);
            }
            if (seed.surface < 0 && !every) {
                out.surfaces.push_back(
                    trackSurface(*request.volume, request.iso, edge, request.table, request.threads));
                seed.surface = static_cast<int>(out.surfaces.size() - 1);
            }
            if (seed.surface < 0) seed.seed.reset();  // all: no surface holds it (cannot happen for a crossed edge)
        }
        out.seeds.push_back(seed);
    }
    if (request.progress) request.progress->seedsTotal = 0;
}

}  // namespace

NextExtraction extractNext(const FollowRequest& request) {
    if (request.volume == nullptr) throw InputError("extractNext: the request names no volume");
    NextExtraction out;
    out.iso = request.iso;
    out.method = request.method;
    out.onlyOwnIsovalues = request.onlyOwnIsovalues;
    out.nextStep = request.nextStep;
    if (request.onlyOwnIsovalues) {
        followOwnIsovalues(request, out);
        return out;
    }
    if (request.progress) {
        request.progress->march.slabsDone = 0;
        request.progress->march.slabsTotal = 0;
    }
    extractEvery(request, out);
    if (cancelled(request)) throw Cancelled{};
    followOwnIsovalues(request, out);
    followSeeds(request, out);
    out.footprints.reserve(out.surfaces.size());
    for (const Surface& surface : out.surfaces) out.footprints.push_back(footprintOf(surface.mesh));
    return out;
}

NextSurfaces followSurfaces(const FollowRequest& request, std::optional<double> previousIso) {
    return continueSurfaces(request.previous, previousIso, extractNext(request));
}

}  // namespace isotrack
