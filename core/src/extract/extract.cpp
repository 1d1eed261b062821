// extract: the one place that turns a method and its settings into surfaces.
// The methods live in the rooms beside this file (marching_cubes, surfaces,
// tracking, trilinear, contour_tree; measure and common serve them), each
// described at the top of its main header.
#include "isotrack/extract.h"

#include <utility>

#include "extract/common/cancel.h"
#include "extract/marching_cubes/march.h"
#include "extract/surfaces/all_surfaces.h"
#include "isotrack/contour_tree.h"
#include "isotrack/errors.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/mesh_processing.h"
#include "isotrack/tracking.h"

namespace isotrack {
namespace {

Surface exhaustiveSurface(const Volume& volume, const ExtractRequest& request) {
    Surface surface;
    surface.mesh = detail::marchingCubes(volume, request.iso, request.table, request.threads, request.progress);
    if (request.measure && !detail::cancelled(request.cancel)) {
        surface.stats = measureSurface(surface.mesh, volume, request.table == TableKind::Consistent);
    } else {
        surface.stats.triangles = surface.mesh.triangleCount();
        surface.stats.vertices = surface.mesh.vertices.size();
        surface.stats.bytes = surface.mesh.byteSize();
    }
    return surface;
}

std::vector<Surface> treeSurfaces(const Volume& volume, const ExtractRequest& request) {
    if (request.table != TableKind::Consistent) {
        throw InputError(std::string("method tree works with the consistent table only, not the ") +
                         tableKindName(request.table) + " table");
    }
    ContourTree own;
    const ContourTree* tree = request.tree;
    if (!tree || request.minPersistence > 0) {
        own = tree ? *tree : computeContourTree(volume, request.threads);
        if (request.minPersistence > 0) simplifyContourTree(own, request.minPersistence);
        tree = &own;
    }
    if (detail::cancelled(request.cancel)) return {};
    return trackTreeSurfaces(*tree, volume, request.iso, request.threads, nullptr, request.largestArcs,
                             request.leaveOutArcs);
}

}  // namespace

Method parseMethod(const std::string& name) {
    if (name == "mc") return Method::Exhaustive;
    if (name == "track") return Method::Track;
    if (name == "all") return Method::All;
    if (name == "tree") return Method::Tree;
    throw InputError("unknown method \"" + name + "\" (expected mc, track, all or tree)");
}

const char* methodName(Method method) {
    switch (method) {
        case Method::Exhaustive: return "mc";
        case Method::Track: return "track";
        case Method::All: return "all";
        case Method::Tree: return "tree";
    }
    return "mc";
}

std::vector<Surface> extract(const Volume& volume, const ExtractRequest& request) {
    std::vector<Surface> surfaces;
    if (detail::cancelled(request.cancel)) return surfaces;
    if (request.cap) {
        const Volume padded = padVolume(volume, capPadValue(volume, request.iso));
        ExtractRequest inner = request;
        inner.cap = false;
        inner.tree = nullptr;
        return extract(padded, inner);
    }
    switch (request.method) {
        case Method::Exhaustive: surfaces.push_back(exhaustiveSurface(volume, request)); break;
        case Method::All:
            surfaces = detail::extractAllSurfaces(volume, request.iso, request.table, request.threads, request.cancel,
                                                  request.progress);
            break;
        case Method::Track:
            if (request.seeds.empty()) throw InputError("method track needs a seed (a world point near the surface)");
            for (const Vec3d& point : request.seeds) {
                if (detail::cancelled(request.cancel)) break;
                const GridEdge edge = nearestCrossedEdge(volume, request.iso, point);
                surfaces.push_back(trackSurface(volume, request.iso, edge, request.table, request.threads));
            }
            break;
        case Method::Tree: surfaces = treeSurfaces(volume, request); break;
    }
    volume.throwIfDamaged();  // a mapped file that shrank meanwhile read as zeros
    return surfaces;
}

}  // namespace isotrack
