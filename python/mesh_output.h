#pragma once
// What the compiled half of the `isotrack` package (`isotrack._isotrack`) does
// between core's extractors and numpy: volumes over numpy samples, the
// scikit-image options core has no notion of (a mask of cells, degenerate
// triangles, the winding), frames, and zero-copy views of the result.
//
// Coordinates. The extractors emit grid coordinates, origin + index * spacing
// in (x, y, z). A raw array's caller speaks (z, y, x), as numpy and
// scikit-image do, so its vertices are read backwards and nothing moves. A
// Volume's caller gets world coordinates in (x, y, z) in the frame asked for,
// exactly as `isotrack extract --frame` writes them (core's gridToFrame and
// transformMesh).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/orientation.h"
#include "isotrack/surface.h"
#include "isotrack/volume.h"

namespace isotrack::python {

namespace py = pybind11;

// A volume's placement, in isotrack's (x, y, z) and LPS, and the coordinates
// its meshes leave in: no frame for a raw array ((z, y, x) grid coordinates).
struct Geometry {
    Vec3d spacing{1, 1, 1};
    Vec3d origin{0, 0, 0};
    Mat3d direction = kIdentityDirection;  // columns
    std::optional<WorldFrame> frame;

    bool zyx() const { return !frame.has_value(); }
};

// frame "" for a raw array, else lps, ras or voxel.
Geometry geometryOf(const Vec3d& spacing, const Vec3d& origin, const Mat3d& direction, const std::string& frame);

// A read-only Volume over the samples of a C-contiguous, aligned, native (nz, ny, nx)
// array of one of core's sample types (the Python half converts anything else);
// the caller keeps `array` alive while the Volume is in use.
Volume volumeView(const py::array& array, const Geometry& geometry);

// A surface as Python sees it: its mesh already in the caller's coordinates.
struct PySurface {
    Surface surface;
    bool zyx = true;
};

// A Python-owned heap object (a mesh, a volume) that numpy arrays can take as their base.
template <class T>
py::capsule ownerOf(T&& value) {
    return py::capsule(new T(std::forward<T>(value)), [](void* p) { delete static_cast<T*>(p); });
}

// A mesh and its per-vertex values, kept alive by the arrays viewing them.
struct MeshOutput {
    Mesh mesh;
    std::vector<float> values;
};

// Per vertex, the larger of the two samples at the ends of its grid edge (for
// a vertex inside a cell, the trilinear table's, the largest of the cell's eight).
std::vector<float> edgeMaxima(const Mesh& mesh, const Volume& volume);

// Keeps the triangles made in cells whose entry in `cellMask` (nx-1 by ny-1 by
// nz-1, x fastest) is non-zero, and the vertices they use.
void keepMaskedCells(MeshOutput& out, const std::uint8_t* cellMask, const Dims& dims);

// scikit-image's allow_degenerate=False: drops triangles with two corners at one
// position and merges those corners into the lowest-numbered of them.
void removeDegenerateFaces(MeshOutput& out);

// gradient_direction="ascent": every triangle wound the other way.
void reverseWinding(Mesh& mesh);

// (n, 3) float32 views over the positions or normals of `vertices`, in (z, y, x)
// (read backwards) or (x, y, z); `owner` keeps them alive.
py::array vertexView(const Buffer<Vertex>& vertices, bool normals, bool zyx, py::handle owner);
// (m, 3) uint32 over the triangles' corner indices.
py::array faceView(const Mesh& mesh, py::handle owner);

}  // namespace isotrack::python
