// measureSurface: a whole mesh's figures, with the measuring the walks and the
// split of every surface do as they go (surface_measure.h).
#include "extract/measure/surface_measure.h"

#include "isotrack/surface.h"

namespace isotrack {

SurfaceStats measureSurface(const Mesh& mesh, const Volume& volume, bool closedUnlessOnBorder) {
    detail::SurfaceMeasure measure;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        measure.addVertex(mesh.vertices[v], mesh.vertexEdges[v], volume.dims());
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        measure.addTriangle(mesh.vertices.data(), mesh.indices[3 * t], mesh.indices[3 * t + 1],
                            mesh.indices[3 * t + 2]);
    }
    return detail::surfaceStats(mesh, measure, closedUnlessOnBorder);
}

}  // namespace isotrack
