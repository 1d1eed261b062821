#pragma once
// A surface as the extractions give it: its mesh and its figures, and measuring
// a mesh's figures.
#include <cstddef>
#include <optional>

#include "isotrack/mesh.h"
#include "isotrack/volume.h"

namespace isotrack {

struct SurfaceStats {
    std::size_t triangles = 0;
    std::size_t vertices = 0;
    std::size_t cellsVisited = 0;  // (cell, piece) visits
    std::size_t bytes = 0;         // vertex and index buffers
    double seconds = 0.0;
    Vec3d boundsMin{0, 0, 0}, boundsMax{0, 0, 0};
    double area = 0.0;
    bool closed = false;                   // every mesh edge has exactly two triangles
    std::optional<double> enclosedVolume;  // for closed surfaces
    bool touchesBorder = false;            // reaches a boundary cell of the volume
    // Set by measureTopology: V - E + F, the loops of edges with one triangle,
    // and the genus of the orientable surface that has them (2 - 2g - b = euler).
    std::optional<long> euler;
    std::optional<long> borderLoops;
    std::optional<long> genus;
    // The tree method: the surface's contour-tree arc and that arc's persistence.
    std::optional<std::size_t> arc;
    std::optional<double> persistence;
};

struct Surface {
    Mesh mesh;
    SurfaceStats stats;
};

// Computes area, bounds, closedness and enclosed volume of a mesh. With
// `closedUnlessOnBorder`, for meshes of the consistent table, which have no holes,
// the mesh counts as closed exactly when no vertex lies on the volume's border,
// instead of checking every edge.
SurfaceStats measureSurface(const Mesh& mesh, const Volume& volume, bool closedUnlessOnBorder = false);

// Fills stats' euler, borderLoops and genus from the mesh's connectivity (a
// sort of its edges, O(F log F), unless stats.closed says every edge has two
// triangles). A sphere: 2, 0, 0; a torus: 0, 0, 1.
void measureTopology(Surface& surface);

}  // namespace isotrack
