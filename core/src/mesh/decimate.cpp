// Decimation through meshoptimizer (Debian's libmeshoptimizer-dev, 0.18):
// meshopt_simplify collapses edges in order of their quadric error (Garland and
// Heckbert) until the index count reaches the target or the next collapse would
// exceed the error bound; vertices at equal positions are collapsed together, so
// the seams of coincident vertices isotrack's zero-area triangles leave do not
// open. meshopt_SimplifyLockBorder keeps the vertices on the mesh's border
// where they are, so a surface the volume cut keeps its outline and a closed
// one stays closed. The kept triangles index a subset of the vertices; the
// unused ones are dropped, the rest keep their order and grid edges. Collapses
// can leave a triangle over three vertices on one line (the snap table's grid
// points); it is flipped away (flip.h).
#include <meshoptimizer.h>

#include <limits>
#include <string>
#include <vector>

#include "isotrack/errors.h"
#include "isotrack/mesh_processing.h"
#include "mesh/flip.h"
#include "mesh/manifold.h"
#include "mesh/near_surface.h"
#include "mesh/weld.h"

namespace isotrack {
namespace {

// Rounds of meshopt_simplify: its quadric error underestimates how far a thin
// bone's rim or spike moves when collapsed (the planes around it barely
// change), so after each round the vertices of the input farther than the
// error bound from the result are locked, and the next round starts again from
// the input. meshoptimizer 0.18 locks border vertices only, so a vertex is
// locked by leaving its triangles out of the simplified part: their corners
// are then on a border, kept, and the triangles fit back unchanged.
constexpr int kLockingRounds = 8;

std::vector<std::uint32_t> simplifyRound(const Mesh& mesh, const std::vector<char>& locked, std::size_t targetTriangles,
                                         float relativeError) {
    std::vector<std::uint32_t> free, held;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t* corner = &mesh.indices[3 * t];
        auto& to = locked[corner[0]] || locked[corner[1]] || locked[corner[2]] ? held : free;
        to.insert(to.end(), corner, corner + 3);
    }
    const std::size_t heldTriangles = held.size() / 3;
    const std::size_t target = targetTriangles > heldTriangles ? 3 * (targetTriangles - heldTriangles) : 0;
    std::vector<std::uint32_t> kept(free.size());
    kept.resize(meshopt_simplify(kept.data(), free.data(), free.size(), mesh.vertices.front().position,
                                 mesh.vertices.size(), sizeof(Vertex), target, relativeError,
                                 meshopt_SimplifyLockBorder, nullptr));
    kept.insert(kept.end(), held.begin(), held.end());
    return kept;
}

// Locks the input's vertices farther than maxError from the result, and the
// corners of the result's triangles whose centre is farther than maxError from
// the input. False when there are none: the result stands.
void centreOf(const Mesh& mesh, const std::uint32_t* corner, float centre[3]) {
    for (int a = 0; a < 3; ++a) {
        double sum = 0.0;
        for (int k = 0; k < 3; ++k) sum += mesh.vertices[corner[k]].position[a];
        centre[a] = float(sum / 3.0);
    }
}

// Locks the input's vertices farther than maxError from the result, and the
// corners of the result's
// triangles whose centre is farther than maxError from the input. False when
// there are none: the result stands.
bool lockStrayVertices(const Mesh& mesh, const std::vector<std::uint32_t>& kept, const detail::NearSurface& original,
                       double maxError, std::vector<char>& locked) {
    bool locking = false;
    auto lockCorners = [&](const std::uint32_t* corner) {
        for (int k = 0; k < 3; ++k) {
            locking = locking || !locked[corner[k]];
            locked[corner[k]] = 1;
        }
    };
    const detail::NearSurface result(mesh.vertices, kept, maxError);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (locked[v] || result.near(mesh.vertices[v].position)) continue;
        locked[v] = 1;
        locking = true;
    }
    float centre[3];
    for (std::size_t t = 0; t < kept.size() / 3; ++t) {
        centreOf(mesh, &kept[3 * t], centre);
        if (!original.near(centre)) lockCorners(&kept[3 * t]);
    }
    return locking;
}

}  // namespace

void decimateMesh(Mesh& mesh, double ratio, std::optional<double> maxError) {
    if (!(ratio >= 0.0 && ratio <= 1.0))
        throw InputError("decimate: ratio " + std::to_string(ratio) + " is outside [0, 1]");
    if (ratio == 0.0 && !maxError) throw InputError("decimate: ratio 0 needs an error bound");
    if (maxError && !(*maxError >= 0.0))
        throw InputError("decimate: error " + std::to_string(*maxError) + " is negative");
    detail::weldCoincidentVertices(mesh);
    if (mesh.indices.empty()) return;
    const float* positions = mesh.vertices.front().position;
    const std::size_t target = std::size_t(double(mesh.triangleCount()) * ratio);
    // meshoptimizer's error is relative to the mesh's extent.
    float relativeError = std::numeric_limits<float>::max();
    if (maxError) {
        const float scale = meshopt_simplifyScale(positions, mesh.vertices.size(), sizeof(Vertex));
        relativeError = scale > 0.0f ? float(*maxError / double(scale)) : 0.0f;
    }
    std::vector<char> locked(mesh.vertices.size(), 0);
    std::vector<std::uint32_t> kept;
    const std::vector<std::uint32_t> input(mesh.indices.begin(), mesh.indices.end());
    std::optional<detail::NearSurface> original;
    if (maxError) original.emplace(mesh.vertices, input, *maxError);
    for (int round = 0; round < kLockingRounds; ++round) {
        kept = simplifyRound(mesh, locked, target, relativeError);
        detail::removeFins(kept);  // a thin part collapsed into fins is gone: lock it too
        if (!maxError) break;
        if (!lockStrayVertices(mesh, kept, *original, *maxError, locked)) break;
    }
    mesh.indices.assign(kept.begin(), kept.end());
    detail::dropUnusedVertices(mesh);
    detail::removeFinsAndSplitPinches(mesh);
    detail::flipZeroAreaTriangles(mesh);
    recomputeNormals(mesh);
}

}  // namespace isotrack
