// processSurface: smoothing, then decimation, of one surface, and its figures
// measured again afterwards.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "extract/measure/surface_measure.h"
#include "isotrack/errors.h"
#include "isotrack/mesh_processing.h"

namespace isotrack {
namespace {

// The figures processing changes; the walk's (cells, seconds, border) stay.
void remeasure(Surface& surface) {
    const Mesh& mesh = surface.mesh;
    SurfaceStats& stats = surface.stats;
    stats.triangles = mesh.triangleCount();
    stats.vertices = mesh.vertices.size();
    stats.bytes = mesh.byteSize();
    detail::TriangleMeasure measure;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        measure.add(mesh.vertices[mesh.indices[3 * t]], mesh.vertices[mesh.indices[3 * t + 1]],
                    mesh.vertices[mesh.indices[3 * t + 2]]);
    }
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        for (int a = 0; a < 3; ++a) {
            const double c = mesh.vertices[v].position[a];
            stats.boundsMin[a] = v == 0 ? c : std::min(stats.boundsMin[a], c);
            stats.boundsMax[a] = v == 0 ? c : std::max(stats.boundsMax[a], c);
        }
    stats.area = measure.area();
    stats.closed = detail::meshIsClosed(mesh);
    stats.enclosedVolume.reset();
    if (stats.closed) stats.enclosedVolume = std::abs(measure.signedVolume());
    if (stats.euler) {
        stats.euler.reset();
        stats.borderLoops.reset();
        stats.genus.reset();
        measureTopology(surface);
    }
}

}  // namespace

double defaultDecimateError(const Volume& volume) {
    const Vec3d& s = volume.spacing();
    return 0.98 * std::min({s[0], s[1], s[2]});
}

double defaultSmoothTolerance(const Volume& volume) {
    const Vec3d& s = volume.spacing();
    return 0.5 * std::min({s[0], s[1], s[2]});
}

void applyVolumeDefaults(MeshProcessing& processing, const Volume& volume) {
    if (processing.decimateRatio < 1.0 && !processing.decimateError)
        processing.decimateError = defaultDecimateError(volume);
    if (processing.smooths() && !processing.smoothTolerance)
        processing.smoothTolerance = defaultSmoothTolerance(volume);
}

void checkMeshProcessing(const MeshProcessing& p) {
    if (p.smoothIterations < 0)
        throw InputError("smooth: iterations " + std::to_string(p.smoothIterations) + " is negative");
    if (!(p.passband > 0.0 && p.passband < 2.0))
        throw InputError("smooth: pass band " + std::to_string(p.passband) + " is outside (0, 2)");
    if (p.smoothTolerance && !(*p.smoothTolerance > 0.0))
        throw InputError("smooth: tolerance " + std::to_string(*p.smoothTolerance) + " is not positive");
    if (!(p.decimateRatio > 0.0 && p.decimateRatio <= 1.0))
        throw InputError("decimate: ratio " + std::to_string(p.decimateRatio) + " is outside (0, 1]");
    if (p.decimateError && !(*p.decimateError >= 0.0))
        throw InputError("decimate: error " + std::to_string(*p.decimateError) + " is negative");
}

void processSurface(Surface& surface, const MeshProcessing& processing) {
    checkMeshProcessing(processing);
    if (!processing.smooths() && !processing.decimates()) return;
    if (processing.smooths())
        smoothMesh(surface.mesh, processing.smoothIterations, processing.passband,
                   processing.smoothTolerance.value_or(std::numeric_limits<double>::infinity()));
    if (processing.decimates()) {
        const bool errorAlone = processing.decimateRatio == 1.0 && processing.decimateError;
        decimateMesh(surface.mesh, errorAlone ? 0.0 : processing.decimateRatio, processing.decimateError);
    }
    remeasure(surface);
}

}  // namespace isotrack
