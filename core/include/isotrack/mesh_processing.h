#pragma once
// Per-surface mesh processing after extraction: closing surfaces the volume's
// border cuts (capping, an extraction option: ExtractRequest::cap), smoothing
// without shrinkage (windowed sinc), decimation (meshoptimizer) and the quality
// figures of a mesh. Applied in that order, per surface, in the grid frame.
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/surface.h"
#include "isotrack/volume.h"

namespace isotrack {

// ---- Capping ----------------------------------------------------------------

// The value of the layer of samples a capped extraction sees around the volume:
// its smallest finite sample when that is below `iso`, else the largest value of
// the sample type below `iso` by at least one (iso - 1, floored for integer
// types). Throws InputError when the sample type holds no value below `iso`.
double capPadValue(const Volume& volume, double iso);

// A copy of the volume with one more layer of samples on each of its six sides,
// all equal to `padValue`, and its origin one spacing lower on each axis, so
// that sample (i, j, k) of `volume` is sample (i + 1, j + 1, k + 1) of the copy
// at the same grid coordinates. Throws InputError when a padded dimension would
// exceed kMaxDimension.
Volume padVolume(const Volume& volume, double padValue);

// ---- Smoothing --------------------------------------------------------------

// Windowed-sinc smoothing (Taubin, Zhang and Golub, "Optimal surface smoothing as
// filter design", 1996; as VTK's vtkWindowedSincPolyDataFilter): a Chebyshev
// polynomial of the umbrella Laplacian approximating a low-pass filter with the
// given pass band (in (0, 2); 0.1 is VTK's default), Nuttall-windowed, its cut-off
// offset so that the filter is exactly 1 at the pass band: low frequencies,
// the shape and its volume, pass unchanged. Vertices on border or non-manifold
// edges stay where they are. Coordinates are centred and scaled to unit size
// while smoothing (VTK's NormalizeCoordinates), in double precision. Then a
// vertex that moved farther than `tolerance` is pulled back along its move to
// that distance, so that the smoothed mesh stays within `tolerance` of the
// input both ways (Hausdorff). Normals are recomputed (recomputeNormals). Throws
// InputError for iterations < 1, a pass band outside (0, 2) or a tolerance that
// is not positive.
void smoothMesh(Mesh& mesh, int iterations, double passband = 0.1,
                double tolerance = std::numeric_limits<double>::infinity());

// Vertex normals as the area-weighted sum of the normals of the triangles around
// each vertex, oriented as the extractors orient theirs (from above the isovalue
// towards below): after smoothing or decimation the volume's gradient no longer
// describes the moved surface.
void recomputeNormals(Mesh& mesh);

// ---- Decimation -------------------------------------------------------------

// Simplifies the mesh with meshoptimizer's edge collapses (meshopt_simplify,
// borders locked), after welding vertices at one position, down to `ratio` of
// its triangles, stopping earlier when meshoptimizer's error estimate exceeds
// `maxError` world units (ratio 0: as far as the error allows). Its estimate
// misses thin parts collapsed whole, so with `maxError` the result is checked
// and redone, up to 8 rounds, with the stray vertices locked: those of the
// input farther than maxError from the result, and the corners of the result's
// triangles whose centres are farther than maxError from the input. Collapses
// that leave back-to-back triangles or edges of four are undone by removing
// the pairs and splitting the pinched vertices, so a closed input stays closed.
// Unused vertices are dropped; normals are recomputed. Throws InputError for a
// ratio outside [0, 1], a ratio of 0 without an error, or a negative error.
void decimateMesh(Mesh& mesh, double ratio, std::optional<double> maxError = std::nullopt);

// ---- Quality ----------------------------------------------------------------

struct MeshQuality {
    std::size_t degenerateTriangles = 0;  // zero area (two corners at one place, or three in a line)
    // After welding vertices at identical positions (and dropping the triangles
    // that welding collapses): edges of one triangle, and of more than two.
    std::size_t boundaryEdges = 0;
    std::size_t nonManifoldEdges = 0;
    // Fractions of the triangles whose smallest angle is below 1, 10 and 20
    // degrees (a degenerate triangle's is 0).
    double minAngleBelow1 = 0.0, minAngleBelow10 = 0.0, minAngleBelow20 = 0.0;
};

MeshQuality measureQuality(const Mesh& mesh);

// ---- Per surface ------------------------------------------------------------

struct MeshProcessing {
    int smoothIterations = 0;  // 0: no smoothing
    double passband = 0.1;
    std::optional<double> smoothTolerance;  // world units; none: unbounded
    double decimateRatio = 1.0;             // 1 with no error: no decimation
    std::optional<double> decimateError;    // world units; alone (ratio 1): as far as it allows
    bool smooths() const { return smoothIterations > 0; }
    bool decimates() const { return decimateRatio < 1.0 || decimateError.has_value(); }
};

// The error bound decimation uses unless told otherwise: 0.98 of the volume's
// smallest spacing, so the result stays within a voxel of the input both ways
// (decimate.cpp checks it).
double defaultDecimateError(const Volume& volume);

// How far smoothing may move a vertex unless told otherwise: half the volume's
// smallest spacing, within the data's resolution.
double defaultSmoothTolerance(const Volume& volume);

// The front ends' defaults for the volume a surface comes from: the decimation
// bound when decimating without one, the smoothing tolerance when smoothing
// without one.
void applyVolumeDefaults(MeshProcessing& processing, const Volume& volume);

// Throws InputError naming the setting for iterations < 0, a pass band outside
// (0, 2), a tolerance that is not positive, a ratio outside (0, 1] or a negative
// error.
void checkMeshProcessing(const MeshProcessing& processing);

// Smooths then decimates a surface as `processing` says, then measures it again:
// triangles, vertices, bytes, bounds, area, closed (every edge of two
// triangles), enclosed volume, and topology when it was measured before; cells
// visited, seconds, arc, persistence and touchesBorder stay. Nothing when
// `processing` asks for nothing.
void processSurface(Surface& surface, const MeshProcessing& processing);

}  // namespace isotrack
