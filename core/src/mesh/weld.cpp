// Welding coincident vertices and dropping unused ones (weld.h).
#include "mesh/weld.h"

#include <cstdint>
#include <limits>
#include <vector>

#include "mesh/mesh_edges.h"

namespace isotrack::detail {

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

void weldCoincidentVertices(Mesh& mesh) {
    const std::vector<std::uint32_t> weld = weldedIds(mesh);
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
    dropUnusedVertices(mesh);
}

}  // namespace isotrack::detail
