// Decimation through meshoptimizer (Debian's libmeshoptimizer-dev, 0.18):
// meshopt_simplify collapses edges in order of their quadric error (Garland and
// Heckbert) until the index count reaches the target or the next collapse would
// exceed the error bound; vertices at equal positions are collapsed together, so
// the seams of coincident vertices isotrack's zero-area triangles leave do not
// open. meshopt_SimplifyLockBorder keeps the vertices on the mesh's border
// where they are, so a surface the volume cut keeps its outline and a closed
// one stays closed. The kept triangles index a subset of the vertices; the
// unused ones are dropped, the rest keep their order and grid edges.
#include <meshoptimizer.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "isotrack/errors.h"
#include "isotrack/mesh_processing.h"
#include "mesh/manifold.h"
#include "mesh/mesh_edges.h"

namespace isotrack {
namespace {

void dropUnusedVertices(Mesh& mesh) {
    constexpr std::uint32_t kUnused = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> remap(mesh.vertices.size(), kUnused);
    for (std::uint32_t index : mesh.indices) remap[index] = 0;
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < remap.size(); ++v) {
        if (remap[v] == kUnused) continue;
        remap[v] = next;
        mesh.vertices[next] = mesh.vertices[v];
        if (v < mesh.vertexEdges.size()) mesh.vertexEdges[next] = mesh.vertexEdges[v];
        ++next;
    }
    mesh.vertices.resize(next);
    if (mesh.vertexEdges.size() > next) mesh.vertexEdges.resize(next);
    for (std::uint32_t& index : mesh.indices) index = remap[index];
}

// Vertices at one position become one, and the triangles that collapses (the
// zero-area ones between coincident vertices) go: the edge collapses then see
// one connected surface rather than seams.
void weldCoincidentVertices(Mesh& mesh) {
    const std::vector<std::uint32_t> weld = detail::weldedIds(mesh);
    std::size_t kept = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t a = weld[mesh.indices[3 * t]], b = weld[mesh.indices[3 * t + 1]],
                            c = weld[mesh.indices[3 * t + 2]];
        if (a == b || b == c || a == c) continue;
        mesh.indices[kept++] = a;
        mesh.indices[kept++] = b;
        mesh.indices[kept++] = c;
    }
    mesh.indices.resize(kept);
}

}  // namespace

void decimateMesh(Mesh& mesh, double ratio, std::optional<double> maxError) {
    if (!(ratio >= 0.0 && ratio <= 1.0))
        throw InputError("decimate: ratio " + std::to_string(ratio) + " is outside [0, 1]");
    if (ratio == 0.0 && !maxError) throw InputError("decimate: ratio 0 needs an error bound");
    if (maxError && !(*maxError >= 0.0))
        throw InputError("decimate: error " + std::to_string(*maxError) + " is negative");
    weldCoincidentVertices(mesh);
    dropUnusedVertices(mesh);
    if (mesh.indices.empty()) return;
    const float* positions = mesh.vertices.front().position;
    const std::size_t target = std::size_t(double(mesh.triangleCount()) * ratio) * 3;
    // meshoptimizer's error is relative to the mesh's extent.
    float relativeError = std::numeric_limits<float>::max();
    if (maxError) {
        const float scale = meshopt_simplifyScale(positions, mesh.vertices.size(), sizeof(Vertex));
        relativeError = scale > 0.0f ? float(*maxError / double(scale)) : 0.0f;
    }
    Buffer<std::uint32_t> kept(mesh.indices.size());
    const std::size_t count =
        meshopt_simplify(kept.data(), mesh.indices.data(), mesh.indices.size(), positions, mesh.vertices.size(),
                         sizeof(Vertex), target, relativeError, meshopt_SimplifyLockBorder, nullptr);
    kept.resize(count);
    mesh.indices = std::move(kept);
    dropUnusedVertices(mesh);
    detail::removeFinsAndSplitPinches(mesh);
    recomputeNormals(mesh);
}

}  // namespace isotrack
