// The Python module `isotrack`: core's extractors over numpy arrays.
//
// Axis order. numpy users index a volume as a[z, y, x] with x varying fastest,
// which is exactly isotrack's sample layout (index = x + nx * (y + ny * z)), so
// an array of shape (nz, ny, nx) is wrapped as a Volume of dims (nx, ny, nz)
// without a copy (Volume::view). Everything the module takes or gives in
// coordinates (spacing, origin, seeds, vertices, normals, bounds) is in (z, y, x)
// order, as scikit-image has it.
//
// Zero copy on output. A mesh's vertices are interleaved {position[3],
// normal[3]} floats; the arrays handed out are strided views over them whose
// base keeps the C++ mesh alive. Reading (x, y, z) backwards with a stride of -4
// bytes gives (z, y, x). The swap is a reflection, so in (z, y, x) a triangle's
// right-handed normal points towards higher values, against the vertex normals,
// exactly as in scikit-image's marching_cubes; in files, written in (x, y, z),
// the two agree.
//
// The GIL is released while core works; core's InputError becomes ValueError
// and FormatError becomes OSError, with core's messages.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tables.h"
#include "isotrack/tracking.h"
#include "isotrack/volume.h"

namespace py = pybind11;

namespace isotrack::python {
namespace {

using Zyx = std::array<double, 3>;

// ---- Input -------------------------------------------------------------------

std::optional<ScalarType> scalarTypeOf(const py::dtype& dtype) {
    const char kind = dtype.kind();
    const auto size = dtype.itemsize();
    if (kind == 'u') {
        if (size == 1) return ScalarType::UInt8;
        if (size == 2) return ScalarType::UInt16;
        if (size == 4) return ScalarType::UInt32;
    } else if (kind == 'i') {
        if (size == 1) return ScalarType::Int8;
        if (size == 2) return ScalarType::Int16;
        if (size == 4) return ScalarType::Int32;
    } else if (kind == 'f') {
        if (size == 4) return ScalarType::Float32;
        if (size == 8) return ScalarType::Float64;
    }
    return std::nullopt;
}

py::dtype dtypeOf(ScalarType type) {
    switch (type) {
        case ScalarType::UInt8: return py::dtype::of<std::uint8_t>();
        case ScalarType::Int8: return py::dtype::of<std::int8_t>();
        case ScalarType::UInt16: return py::dtype::of<std::uint16_t>();
        case ScalarType::Int16: return py::dtype::of<std::int16_t>();
        case ScalarType::UInt32: return py::dtype::of<std::uint32_t>();
        case ScalarType::Int32: return py::dtype::of<std::int32_t>();
        case ScalarType::Float32: return py::dtype::of<float>();
        case ScalarType::Float64: break;
    }
    return py::dtype::of<double>();
}

std::string shapeText(const py::array& array) {
    std::ostringstream text;
    text << '(';
    for (py::ssize_t a = 0; a < array.ndim(); ++a) text << (a ? ", " : "") << array.shape(a);
    text << (array.ndim() == 1 ? ",)" : ")");
    return text.str();
}

// (z, y, x) from Python to isotrack's (x, y, z), checked finite (and positive for spacing).
Vec3d worldTriple(const Zyx& zyx, const char* name, bool positive) {
    for (double v : zyx) {
        if (!std::isfinite(v) || (positive && v <= 0.0)) {
            std::ostringstream text;
            text << name << ": expected three " << (positive ? "positive " : "") << "finite numbers (z, y, x), got ("
                 << zyx[0] << ", " << zyx[1] << ", " << zyx[2] << ")";
            throw InputError(text.str());
        }
    }
    return {zyx[2], zyx[1], zyx[0]};
}

// A read-only Volume over the samples of a C-contiguous (nz, ny, nx) array; the
// caller keeps `array` alive while the Volume is in use.
Volume volumeView(const py::array& array, const Zyx& spacing, const Zyx& origin) {
    if (array.ndim() != 3)
        throw InputError("volume: expected a 3D array indexed (z, y, x), got shape " + shapeText(array));
    const std::optional<ScalarType> type = scalarTypeOf(array.dtype());
    if (!type)
        throw InputError("volume: unsupported dtype " + py::str(array.dtype()).cast<std::string>() +
                         " (expected uint8, int8, uint16, int16, uint32, int32, float32 or float64)");
    if (!array.dtype().attr("isnative").cast<bool>())
        throw InputError(
            "volume: samples must be in the machine's byte order (use array.astype(array.dtype.newbyteorder('=')))");
    if (!(array.flags() & py::array::c_style))
        throw InputError("volume: the array must be C-contiguous (use numpy.ascontiguousarray(volume))");
    if (!array.attr("flags").attr("aligned").cast<bool>())
        throw InputError("volume: the array's samples must be aligned (use volume.copy())");
    for (py::ssize_t a = 0; a < 3; ++a) {
        if (array.shape(a) < 1 || array.shape(a) > kMaxDimension)
            throw InputError("volume: each dimension must be 1 to " + std::to_string(kMaxDimension) + ", got shape " +
                             shapeText(array));
    }
    const Dims dims{int(array.shape(2)), int(array.shape(1)), int(array.shape(0))};
    return Volume::view(dims, *type, array.data(), worldTriple(spacing, "spacing", true),
                        worldTriple(origin, "origin", false));
}

// The level as given, or, for None, the middle of the finite samples' range (as the CLI picks).
double levelOf(const Volume& volume, const std::optional<double>& level) {
    if (!level) {
        const auto range = volume.range();
        if (!std::isfinite(range[0])) throw InputError("volume: no finite samples, give level");
        return (range[0] + range[1]) / 2.0;
    }
    if (!std::isfinite(*level)) throw InputError("level: must be a finite number");
    return *level;
}

TableKind tableOf(const std::string& name) {
    if (name == "consistent") return TableKind::Consistent;
    if (name == "classic") return TableKind::Classic;
    if (name == "trilinear") return TableKind::Trilinear;
    throw InputError("table: unknown table \"" + name + "\" (expected consistent, classic or trilinear)");
}

// threads = 0: every core.
int threadsOf(int threads) {
    if (threads < 0) throw InputError("threads: must be 0 (every core) or more, got " + std::to_string(threads));
    if (threads == 0) return std::max(1, int(std::thread::hardware_concurrency()));
    return threads;
}

// ---- Output ------------------------------------------------------------------

// (n, 3) float32 in (z, y, x) order over the position or normal of each vertex.
py::array vertexView(const Buffer<Vertex>& vertices, bool normals, py::handle owner) {
    if (vertices.empty()) return py::array_t<float>(std::vector<py::ssize_t>{0, 3});
    const float* z = normals ? &vertices.front().normal[2] : &vertices.front().position[2];
    return py::array(py::dtype::of<float>(), {py::ssize_t(vertices.size()), py::ssize_t(3)},
                     {py::ssize_t(sizeof(Vertex)), -py::ssize_t(sizeof(float))}, z, owner);
}

py::array positionView(const Mesh& mesh, py::handle owner) { return vertexView(mesh.vertices, false, owner); }
py::array normalView(const Mesh& mesh, py::handle owner) { return vertexView(mesh.vertices, true, owner); }

// (m, 3) uint32 over the triangles' corner indices.
py::array faceView(const Mesh& mesh, py::handle owner) {
    if (mesh.indices.empty()) return py::array_t<std::uint32_t>(std::vector<py::ssize_t>{0, 3});
    return py::array(py::dtype::of<std::uint32_t>(), {py::ssize_t(mesh.triangleCount()), py::ssize_t(3)},
                     mesh.indices.data(), owner);
}

// Per vertex, the larger of the two samples at the ends of its grid edge (for
// a vertex inside a cell, the trilinear table's, the largest of the cell's eight).
py::array_t<float> edgeMaxima(const Mesh& mesh, const Volume& volume) {
    py::array_t<float> values(py::ssize_t(mesh.vertices.size()));
    float* out = values.mutable_data();
    visitSamples(volume, [&](const auto* samples) {
        const std::size_t step[3] = {1, std::size_t(volume.dims()[0]),
                                     std::size_t(volume.dims()[0]) * std::size_t(volume.dims()[1])};
        for (std::size_t v = 0; v < mesh.vertexEdges.size(); ++v) {
            const GridEdge e = mesh.vertexEdges[v];
            const std::size_t i = volume.index(e.x, e.y, e.z);
            if (e.axis == kCellInterior) {
                double largest = double(samples[i]);
                for (int c = 1; c < 8; ++c)
                    largest = std::max(
                        largest, double(samples[i + (c & 1) * step[0] + (c >> 1 & 1) * step[1] + (c >> 2) * step[2]]));
                out[v] = float(largest);
                continue;
            }
            out[v] = float(std::max(double(samples[i]), double(samples[i + step[e.axis]])));
        }
    });
    return values;
}

py::tuple boundsOf(const SurfaceStats& stats) {
    const auto zyx = [](const Vec3d& v) { return py::make_tuple(v[2], v[1], v[0]); };
    return py::make_tuple(zyx(stats.boundsMin), zyx(stats.boundsMax));
}

std::string surfaceRepr(const Surface& surface) {
    const SurfaceStats& s = surface.stats;
    std::ostringstream text;
    text << "<isotrack.Surface: " << s.triangles << " triangles, " << s.vertices << " vertices, area " << s.area;
    if (s.enclosedVolume)
        text << ", closed, volume " << *s.enclosedVolume;
    else
        text << (s.closed ? ", closed" : ", open");
    text << '>';
    return text.str();
}

py::list surfaceList(std::vector<Surface> surfaces) {
    py::list out;
    for (Surface& surface : surfaces) out.append(py::cast(std::move(surface)));
    return out;
}

// A Python-owned heap object (a mesh, a volume) that numpy arrays can take as their base.
template <class T>
py::capsule ownerOf(T&& value) {
    return py::capsule(new T(std::forward<T>(value)), [](void* p) { delete static_cast<T*>(p); });
}

// ---- Functions ---------------------------------------------------------------

py::object marchingCubesPy(const py::array& array, std::optional<double> level, const Zyx& spacing,
                           const std::string& method, const std::string& tableName, int threads, const Zyx& origin) {
    const Volume volume = volumeView(array, spacing, origin);
    const double iso = levelOf(volume, level);
    const TableKind table = tableOf(tableName);
    const int threadCount = threadsOf(threads);
    if (method == "all") {
        std::vector<Surface> surfaces;
        {
            py::gil_scoped_release unlocked;
            surfaces = extractAllSurfaces(volume, iso, table, threadCount);
        }
        return surfaceList(std::move(surfaces));
    }
    if (method != "mc" && method != "lewiner" && method != "lorensen")
        throw InputError("method: unknown method \"" + method + "\" (expected mc or all)");
    Mesh mesh;
    {
        py::gil_scoped_release unlocked;
        mesh = marchingCubes(volume, iso, table, threadCount);
    }
    py::array values = edgeMaxima(mesh, volume);
    mesh.vertexEdges = {};  // not handed out: keep only what the views need
    py::capsule owner = ownerOf(std::move(mesh));
    const Mesh& kept = *static_cast<const Mesh*>(owner.get_pointer());
    return py::make_tuple(positionView(kept, owner), faceView(kept, owner), normalView(kept, owner), values);
}

GridEdge seedEdgeOf(const Volume& volume, double iso, const std::optional<Zyx>& seed,
                    const std::optional<std::array<int, 4>>& seedEdge) {
    if (seed.has_value() == seedEdge.has_value())
        throw InputError("track: give exactly one of seed=(z, y, x) (a world point) or seed_edge=(z, y, x, axis)");
    if (seed) return nearestCrossedEdge(volume, iso, worldTriple(*seed, "seed", false));
    const auto& e = *seedEdge;
    if (e[3] < 0 || e[3] > 2)
        throw InputError("seed_edge: axis must be 0 (z), 1 (y) or 2 (x), got " + std::to_string(e[3]));
    const GridEdge edge{e[2], e[1], e[0], 2 - e[3]};
    // Checked here, so that the messages speak of (z, y, x) as the caller does.
    const std::string given = "seed_edge (" + std::to_string(e[0]) + ", " + std::to_string(e[1]) + ", " +
                              std::to_string(e[2]) + ", " + std::to_string(e[3]) + ")";
    const Dims& dims = volume.dims();
    const int end[3] = {edge.x + (edge.axis == 0), edge.y + (edge.axis == 1), edge.z + (edge.axis == 2)};
    if (edge.x < 0 || edge.y < 0 || edge.z < 0 || end[0] >= dims[0] || end[1] >= dims[1] || end[2] >= dims[2])
        throw InputError(given + " lies outside the volume of shape (" + std::to_string(dims[2]) + ", " +
                         std::to_string(dims[1]) + ", " + std::to_string(dims[0]) + ")");
    if (!edgeIsCrossed(volume, iso, edge)) {
        std::ostringstream text;
        text << given << " is not crossed at level " << iso;
        throw InputError(text.str());
    }
    return edge;
}

Surface trackPy(const py::array& array, double level, const std::optional<Zyx>& seed,
                const std::optional<std::array<int, 4>>& seedEdge, const Zyx& spacing, const std::string& tableName,
                int threads, const Zyx& origin) {
    const Volume volume = volumeView(array, spacing, origin);
    const double iso = levelOf(volume, level);
    const TableKind table = tableOf(tableName);
    const int threadCount = std::min(threadsOf(threads), kMaxTrackThreads);
    py::gil_scoped_release unlocked;
    const GridEdge edge = seedEdgeOf(volume, iso, seed, seedEdge);
    return trackSurface(volume, iso, edge, table, threadCount);
}

py::list surfacesPy(const py::array& array, double level, const Zyx& spacing, const std::string& tableName, int threads,
                    const Zyx& origin) {
    const Volume volume = volumeView(array, spacing, origin);
    const double iso = levelOf(volume, level);
    const TableKind table = tableOf(tableName);
    const int threadCount = threadsOf(threads);
    std::vector<Surface> surfaces;
    {
        py::gil_scoped_release unlocked;
        surfaces = extractAllSurfaces(volume, iso, table, threadCount);
    }
    return surfaceList(std::move(surfaces));
}

py::tuple loadPy(const std::string& path) {
    Volume volume;
    {
        py::gil_scoped_release unlocked;
        volume = loadVolume(path);
    }
    const Dims dims = volume.dims();
    const Vec3d spacing = volume.spacing(), origin = volume.origin();
    const ScalarType type = volume.type();
    py::capsule owner = ownerOf(std::move(volume));
    const Volume& kept = *static_cast<const Volume*>(owner.get_pointer());
    py::array samples(dtypeOf(type), {py::ssize_t(dims[2]), py::ssize_t(dims[1]), py::ssize_t(dims[0])},
                      static_cast<const void*>(kept.bytes()), owner);
    return py::make_tuple(samples, py::make_tuple(spacing[2], spacing[1], spacing[0]),
                          py::make_tuple(origin[2], origin[1], origin[0]));
}

template <void (*Write)(const std::string&, const Mesh&)>
void writePy(const Surface& surface, const std::string& path) {
    py::gil_scoped_release unlocked;
    Write(path, surface.mesh);
}

void writePlyMesh(const std::string& path, const Mesh& mesh) { writePly(path, mesh); }
void writeObjMesh(const std::string& path, const Mesh& mesh) { writeObj(path, mesh); }

// ---- Docstrings -------------------------------------------------------------

constexpr const char* kModuleDoc = R"(Isosurfaces of 3D numpy arrays: isotrack's marching cubes and surface tracking.

Arrays are indexed (z, y, x), x varying fastest, as numpy and scikit-image have
them; a C-contiguous array of uint8, int8, uint16, int16, uint32, int32,
float32 or float64 samples is used in place, without a copy. Coordinates
(spacing, origin, seeds, vertices, normals, bounds) are in (z, y, x) order too;
a sample's world position is origin + index * spacing.

Functions: marching_cubes (a drop-in for skimage.measure.marching_cubes),
track (the one surface through a seed), surfaces (every connected surface),
load (NRRD, NIfTI, MetaImage, VTK files) and write_ply, write_obj, write_stl.
Bad input raises ValueError; unreadable files and write failures raise OSError.)";

constexpr const char* kMarchingCubesDoc = R"(Marching cubes over every cell of a volume.

Args:
    volume: 3D array indexed (z, y, x); C-contiguous, of uint8, int8, uint16,
        int16, uint32, int32, float32 or float64 samples (used without a copy).
    level: the isovalue; None takes the middle of the finite samples' range.
    spacing: the distance between samples along (z, y, x).
    method: "mc" for one mesh ("lewiner" and "lorensen" are accepted as its
        names, so code written for scikit-image runs unchanged), or "all" for
        a list of Surface objects, one per connected surface, largest first.
    table: "consistent" (isotrack's, no holes between cells), "classic", or
        "trilinear" (the trilinear interpolant's topology, MC33; its subcases
        may add vertices inside cells).
    threads: threads to use; 0 uses every core. With more than one, the
        vertices and triangles come in another order; they are the same.
    origin: the world position of sample (0, 0, 0), in (z, y, x).

Returns:
    For "mc", (verts, faces, normals, values) like
    skimage.measure.marching_cubes: verts (V, 3) float32 positions in (z, y, x),
    origin + index * spacing; faces (F, 3) uint32 vertex indices; normals
    (V, 3) float32 unit vectors pointing towards lower values; values (V,)
    float32, the larger of the two samples at the ends of each vertex's grid
    edge. Each crossed grid edge yields exactly one vertex. verts, faces and
    normals are views over the mesh isotrack built, not copies.
    For "all", a list of Surface.

Raises:
    ValueError: a volume of another dtype or shape, not C-contiguous, a level
        that is not finite, an unknown method or table.

Example:
    >>> import numpy as np, isotrack
    >>> z, y, x = np.mgrid[-1:1:32j, -1:1:32j, -1:1:32j]
    >>> verts, faces, normals, values = isotrack.marching_cubes(
    ...     (x*x + y*y + z*z).astype(np.float32), 0.5)
)";

constexpr const char* kTrackDoc = R"(The one connected surface through a seed, touching only the cells it crosses.

Args:
    volume: 3D array indexed (z, y, x), as for marching_cubes.
    level: the isovalue (finite).
    seed: a world point (z, y, x); tracking starts at the crossed grid edge
        whose midpoint is nearest to it.
    seed_edge: or a grid edge (z, y, x, axis) crossed by the surface: the edge
        from sample [z, y, x] one step along axis (0: z, 1: y, 2: x).
    spacing, origin: as for marching_cubes, in (z, y, x).
    table: "consistent" or "classic".
    threads: threads to use (at most 64); 0 uses every core.

Returns:
    A Surface.

Raises:
    ValueError: neither or both of seed and seed_edge; a seed edge outside the
        volume or not crossed at level; no crossed edge at all; bad volume.

Example:
    >>> skull = isotrack.track(ct, 400, seed=(160, 122, 122), spacing=(1.5, 0.957, 0.957))
    >>> skull.triangle_count, skull.area, skull.closed
)";

constexpr const char* kSurfacesDoc = R"(Every connected surface of a volume, largest (most triangles) first.

Together they hold exactly the triangles of marching_cubes with the same
table. Arguments as for marching_cubes; returns a list of Surface.)";

constexpr const char* kLoadDoc = R"(Reads a volume with isotrack's loaders.

Formats by extension: .nrrd .nhdr, .nii .nii.gz, .mhd .mha, .vtk; and DICOM:
a .dcm file, or a folder or DICOMDIR, whose largest series that forms a volume
is read (files that are not readable DICOM images are skipped; `isotrack info`
lists the series and the files skipped).

Returns:
    (samples, spacing, origin): samples a 3D array indexed (z, y, x) in the
    file's own sample type; spacing and origin as (z, y, x) tuples, ready to
    pass on: isotrack.marching_cubes(samples, level, spacing=spacing).

Raises:
    OSError: the file cannot be read or is malformed (the message names the
        file, the field and the value).)";

constexpr const char* kSurfaceDoc = R"(One isosurface: an indexed triangle mesh and its measures.

vertices, normals and faces are numpy views over the mesh isotrack built (no
copy); each keeps the surface's memory alive for as long as it lives, so they
stay valid after the Surface itself is gone. Coordinates are in (z, y, x).)";

void bindSurface(py::module_& m) {
    py::class_<Surface>(m, "Surface", kSurfaceDoc)
        .def_property_readonly(
            "vertices", [](py::object self) { return positionView(self.cast<const Surface&>().mesh, self); },
            "(V, 3) float32 vertex positions in (z, y, x), world units (a view).")
        .def_property_readonly(
            "normals", [](py::object self) { return normalView(self.cast<const Surface&>().mesh, self); },
            "(V, 3) float32 unit normals in (z, y, x), pointing towards lower values (a view).")
        .def_property_readonly(
            "faces", [](py::object self) { return faceView(self.cast<const Surface&>().mesh, self); },
            "(F, 3) uint32 vertex indices, one row per triangle (a view).")
        .def_property_readonly(
            "triangle_count", [](const Surface& s) { return s.stats.triangles; }, "Number of triangles.")
        .def_property_readonly(
            "vertex_count", [](const Surface& s) { return s.stats.vertices; }, "Number of vertices.")
        .def_property_readonly(
            "area", [](const Surface& s) { return s.stats.area; }, "Surface area in world units squared.")
        .def_property_readonly(
            "volume", [](const Surface& s) { return s.stats.enclosedVolume; },
            "Enclosed volume in world units cubed for a closed surface, else None.")
        .def_property_readonly(
            "closed", [](const Surface& s) { return s.stats.closed; },
            "True when every mesh edge has exactly two triangles.")
        .def_property_readonly(
            "touches_border", [](const Surface& s) { return s.stats.touchesBorder; },
            "True when the surface reaches a boundary cell of the volume.")
        .def_property_readonly(
            "bounds", [](const Surface& s) { return boundsOf(s.stats); },
            "((zmin, ymin, xmin), (zmax, ymax, xmax)) in world units.")
        .def_property_readonly(
            "cells_visited", [](const Surface& s) { return s.stats.cellsVisited; },
            "(cell, piece) visits made while tracking.")
        .def_property_readonly(
            "nbytes", [](const Surface& s) { return s.mesh.drawByteSize(); }, "Bytes of the vertex and index buffers.")
        .def_property_readonly(
            "seconds", [](const Surface& s) { return s.stats.seconds; },
            "Seconds track took for it (0 for surfaces of surfaces()).")
        .def(
            "__len__", [](const Surface& s) { return s.stats.triangles; }, "Number of triangles.")
        .def("__repr__", &surfaceRepr);
}

}  // namespace
}  // namespace isotrack::python

PYBIND11_MODULE(isotrack, m) {
    using namespace isotrack;
    using namespace isotrack::python;
    m.doc() = kModuleDoc;
    m.attr("__version__") = ISOTRACK_VERSION;

    py::register_exception_translator([](std::exception_ptr error) {
        try {
            if (error) std::rethrow_exception(error);
        } catch (const InputError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const FormatError& e) {
            PyErr_SetString(PyExc_OSError, e.what());
        }
    });

    bindSurface(m);
    const Zyx ones{1, 1, 1}, zeros{0, 0, 0};
    m.def("marching_cubes", &marchingCubesPy, kMarchingCubesDoc, py::arg("volume"), py::arg("level") = py::none(),
          py::kw_only(), py::arg_v("spacing", ones, "(1.0, 1.0, 1.0)"), py::arg("method") = "mc",
          py::arg("table") = "consistent", py::arg("threads") = 0, py::arg_v("origin", zeros, "(0.0, 0.0, 0.0)"));
    m.def("track", &trackPy, kTrackDoc, py::arg("volume"), py::arg("level"), py::kw_only(),
          py::arg("seed") = py::none(), py::arg("seed_edge") = py::none(),
          py::arg_v("spacing", ones, "(1.0, 1.0, 1.0)"), py::arg("table") = "consistent", py::arg("threads") = 0,
          py::arg_v("origin", zeros, "(0.0, 0.0, 0.0)"));
    m.def("surfaces", &surfacesPy, kSurfacesDoc, py::arg("volume"), py::arg("level"), py::kw_only(),
          py::arg_v("spacing", ones, "(1.0, 1.0, 1.0)"), py::arg("table") = "consistent", py::arg("threads") = 0,
          py::arg_v("origin", zeros, "(0.0, 0.0, 0.0)"));
    m.def("load", &loadPy, kLoadDoc, py::arg("path"));
    m.def("write_ply", &writePy<writePlyMesh>,
          "Writes a Surface as binary little-endian PLY (x, y, z order, as files have it).", py::arg("surface"),
          py::arg("path"));
    m.def("write_obj", &writePy<writeObjMesh>, "Writes a Surface as Wavefront OBJ (x, y, z order, as files have it).",
          py::arg("surface"), py::arg("path"));
    m.def("write_stl", &writePy<writeStl>, "Writes a Surface as binary STL (x, y, z order, as files have it).",
          py::arg("surface"), py::arg("path"));
}
