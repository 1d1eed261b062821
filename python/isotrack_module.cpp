// `isotrack._isotrack`: the compiled half of the `isotrack` package.
//
// The package's public functions are Python (python/isotrack/): they take
// whatever users pass (any real dtype, any strides, array-likes, Volume
// objects), check it with short messages, and call these private functions
// with C-contiguous arrays of core's sample types and geometry in isotrack's
// (x, y, z) and LPS. Nothing here is called with user input directly, so
// pybind11's argument errors (which print the arguments) never reach a user.
//
// Zero copy both ways: a volume wraps the array's samples (Volume::view), and a
// mesh's vertices, normals and faces are handed out as strided views whose base
// keeps the C++ mesh alive (mesh_output.h). The GIL is released while core
// works; core's InputError becomes ValueError and FormatError OSError.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "isotrack/errors.h"
#include "isotrack/extract.h"
#include "isotrack/io.h"
#include "isotrack/isovalue.h"
#include "isotrack/mapped_file.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/orientation.h"
#include "isotrack/tables.h"
#include "isotrack/threads.h"
#include "isotrack/time_series.h"
#include "isotrack/tracking.h"
#include "isotrack/volume.h"
#include "mesh_output.h"

namespace isotrack::python {
namespace {

using Rows = std::array<std::array<double, 4>, 4>;

TableKind tableOf(const std::string& name) { return parseTableKind(name); }

// threads = 0: core's default, one per hardware thread (isotrack/threads.h).
int threadsOf(int threads) {
    if (threads < 0) throw InputError("threads: must be 0 (every core) or more, got " + std::to_string(threads));
    if (threads == 0) return defaultThreadCount();
    return threads;
}

// Core's names, for the Python layer's argument checks.
template <class List, class NameOf>
py::tuple namesOf(const List& list, NameOf nameOf) {
    py::tuple names(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) names[i] = py::str(nameOf(list[i]));
    return names;
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

// A Python-owned heap object (a mesh, a volume) that numpy arrays can take as their base.
template <class T>
py::capsule ownerOf(T&& value) {
    return py::capsule(new T(std::forward<T>(value)), [](void* p) { delete static_cast<T*>(p); });
}

py::tuple triple(const Vec3d& v) { return py::make_tuple(v[0], v[1], v[2]); }

// The isovalue to extract at: the given one, checked finite (and, for
// marching_cubes, within the finite samples' range, as scikit-image checks), or
// for None core's suggested isovalue, the one the command line and viewer open on.
double levelPy(const py::array& array, std::optional<double> level, bool withinRange) {
    const Volume volume = volumeView(array, Geometry{});
    py::gil_scoped_release unlocked;
    if (level && !std::isfinite(*level)) throw InputError("level: must be a finite number");
    if (level && !withinRange) return *level;
    const std::array<double, 2> range = volume.range();
    if (!std::isfinite(range[0])) throw InputError("volume: no finite samples, give level");
    if (!level) return suggestIsovalue(volume);
    if (*level < range[0] || *level > range[1]) {
        std::ostringstream text;
        text << "Surface level must be within volume data range. (level " << *level << ", data " << range[0] << " to "
             << range[1] << ")";
        throw InputError(text.str());
    }
    return *level;
}

// Surfaces into a Volume's frame (a raw array's stay in grid coordinates).
void toFrame(std::vector<Surface>& surfaces, const Geometry& geometry, const Volume& volume) {
    if (!geometry.frame) return;
    const FrameTransform transform = gridToFrame(volume, *geometry.frame);
    for (Surface& surface : surfaces) surfaceToFrame(surface, transform);
}

py::list surfaceList(std::vector<Surface> surfaces, bool zyx) {
    py::list out;
    for (Surface& surface : surfaces) out.append(py::cast(PySurface{std::move(surface), zyx}));
    return out;
}

// A Volume's samples mapped from a file that was truncated or removed meanwhile
// read as zeros: an error naming the file (isotrack/mapped_file.h).
void throwIfMappedDamaged(const py::array& array) {
    if (const MappedFile* file = MappedFile::containing(array.data())) file->throwIfDamaged();
}

// One mesh (as scikit-image returns it) or, with `split`, every surface.
py::object marchingCubesPy(const py::array& array, double level, const Geometry& geometry, const std::string& tableName,
                           int threads, const std::optional<py::array>& cellMask, bool allowDegenerate, bool ascent,
                           bool split) {
    const Volume volume = volumeView(array, geometry);
    const TableKind table = tableOf(tableName);
    const int threadCount = threadsOf(threads);
    if (split) {
        std::vector<Surface> surfaces;
        {
            py::gil_scoped_release unlocked;
            surfaces = extractAllSurfaces(volume, level, table, threadCount);
            if (ascent)
                for (Surface& surface : surfaces) reverseWinding(surface.mesh);
            toFrame(surfaces, geometry, volume);
        }
        throwIfMappedDamaged(array);
        return surfaceList(std::move(surfaces), geometry.zyx());
    }
    const Dims& dims = volume.dims();
    const auto cells = py::ssize_t(dims[0] - 1) * (dims[1] - 1) * (dims[2] - 1);
    if (cellMask &&
        (cellMask->itemsize() != 1 || cellMask->size() != cells || !(cellMask->flags() & py::array::c_style)))
        throw InputError("mask: internal: expected one contiguous byte per cell");
    const std::uint8_t* mask = cellMask ? static_cast<const std::uint8_t*>(cellMask->data()) : nullptr;
    MeshOutput out;
    {
        py::gil_scoped_release unlocked;
        out.mesh = marchingCubes(volume, level, table, threadCount);
        out.values = edgeMaxima(out.mesh, volume);
        if (mask) keepMaskedCells(out, mask, volume.dims());
        out.mesh.vertexEdges = {};  // not handed out: keep only what the views need
        if (!allowDegenerate) removeDegenerateFaces(out);
        if (ascent) reverseWinding(out.mesh);
        if (geometry.frame) transformMesh(out.mesh, gridToFrame(volume, *geometry.frame));
    }
    throwIfMappedDamaged(array);
    py::capsule owner = ownerOf(std::move(out));
    const MeshOutput& kept = *static_cast<const MeshOutput*>(owner.get_pointer());
    const bool zyx = geometry.zyx();
    py::array values(py::dtype::of<float>(), {py::ssize_t(kept.values.size())}, kept.values.data(), owner);
    return py::make_tuple(vertexView(kept.mesh.vertices, false, zyx, owner), faceView(kept.mesh, owner),
                          vertexView(kept.mesh.vertices, true, zyx, owner), values);
}

// seed: a raw array's world point (z, y, x), or a Volume's in its frame (x, y, z).
// seed_edge: (z, y, x, axis) in array indices, axis 0 along z, 2 along x.
GridEdge seedEdgeOf(const Volume& volume, const Geometry& geometry, double iso, const std::optional<Vec3d>& seed,
                    const std::optional<std::array<int, 4>>& seedEdge) {
    if (seed) {
        if (geometry.zyx()) return nearestCrossedEdge(volume, iso, {(*seed)[2], (*seed)[1], (*seed)[0]});
        return nearestCrossedEdge(volume, iso, gridToFrame(volume, *geometry.frame).toGrid(*seed));
    }
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

py::object trackPy(const py::array& array, double level, const Geometry& geometry, const std::string& tableName,
                   int threads, const std::optional<Vec3d>& seed, const std::optional<std::array<int, 4>>& seedEdge,
                   bool ascent) {
    const Volume volume = volumeView(array, geometry);
    const TableKind table = tableOf(tableName);
    const int threadCount = std::min(threadsOf(threads), kMaxTrackThreads);
    std::vector<Surface> surfaces(1);
    {
        py::gil_scoped_release unlocked;
        const GridEdge edge = seedEdgeOf(volume, geometry, level, seed, seedEdge);
        surfaces[0] = trackSurface(volume, level, edge, table, threadCount);
        if (ascent) reverseWinding(surfaces[0].mesh);
        toFrame(surfaces, geometry, volume);
    }
    throwIfMappedDamaged(array);
    return surfaceList(std::move(surfaces), geometry.zyx())[py::int_(0)];
}

// (samples, spacing, origin, direction columns), isotrack's (x, y, z) and LPS, of
// time step `time` (0 for a single volume) and, for a .vti, PointData `array`.
py::tuple loadPy(const std::string& path, std::size_t time, const std::string& array) {
    Volume volume;
    {
        py::gil_scoped_release unlocked;
        volume = loadTimeStep(readTimeSeries(path), time, array);
    }
    const Dims dims = volume.dims();
    const Vec3d spacing = volume.spacing(), origin = volume.origin();
    const Mat3d direction = volume.direction();
    const ScalarType type = volume.type();
    py::capsule owner = ownerOf(std::move(volume));
    const Volume& kept = *static_cast<const Volume*>(owner.get_pointer());
    py::array samples(dtypeOf(type), {py::ssize_t(dims[2]), py::ssize_t(dims[1]), py::ssize_t(dims[0])},
                      static_cast<const void*>(kept.bytes()), owner);
    // Read-only: mapped samples live in a read-only map of the file (a write would
    // crash), and a loaded volume is the file's, in memory or not.
    samples.attr("setflags")(py::arg("write") = false);
    return py::make_tuple(samples, triple(spacing), triple(origin),
                          py::make_tuple(triple(direction[0]), triple(direction[1]), triple(direction[2])));
}

// The 4x4 matrix (rows) taking a sample's index (i, j, k, 1) to the frame, as core's gridToFrame does.
Rows frameAffinePy(const Vec3d& spacing, const Vec3d& origin, const Mat3d& direction, const std::string& frame) {
    Volume volume({1, 1, 1}, ScalarType::UInt8, spacing, origin);
    volume.setDirection(direction);
    const FrameTransform t = gridToFrame(volume, parseWorldFrame(frame));
    const Vec3d offset = t.apply(origin);  // index 0
    Rows rows{};
    for (std::size_t r = 0; r < 3; ++r) {
        for (std::size_t c = 0; c < 3; ++c) rows[r][c] = t.linear[c][r] * spacing[c];
        rows[r][3] = offset[r];
    }
    rows[3] = {0, 0, 0, 1};
    return rows;
}

template <void (*Write)(const std::string&, const Mesh&)>
void writePy(const PySurface& surface, const std::string& path) {
    py::gil_scoped_release unlocked;
    Write(path, surface.surface.mesh);
}

void writePlyMesh(const std::string& path, const Mesh& mesh) { writePly(path, mesh); }
void writeObjMesh(const std::string& path, const Mesh& mesh) { writeObj(path, mesh); }

py::tuple boundsOf(const PySurface& s) {
    const Vec3d &lo = s.surface.stats.boundsMin, &hi = s.surface.stats.boundsMax;
    if (!s.zyx) return py::make_tuple(triple(lo), triple(hi));
    return py::make_tuple(py::make_tuple(lo[2], lo[1], lo[0]), py::make_tuple(hi[2], hi[1], hi[0]));
}

std::string surfaceRepr(const PySurface& surface) {
    const SurfaceStats& s = surface.surface.stats;
    std::ostringstream text;
    text << "<isotrack.Surface: " << s.triangles << " triangles, " << s.vertices << " vertices, area " << s.area;
    if (s.enclosedVolume)
        text << ", closed, volume " << *s.enclosedVolume;
    else
        text << (s.closed ? ", closed" : ", open");
    text << '>';
    return text.str();
}

const SurfaceStats& statsOf(const PySurface& s) { return s.surface.stats; }

constexpr const char* kSurfaceDoc = R"(One isosurface: an indexed triangle mesh and its measures.

vertices, normals and faces are numpy views over the mesh isotrack built (no
copy); each keeps the surface's memory alive for as long as it lives, so they
stay valid after the Surface itself is gone. From a raw array coordinates are
(z, y, x) grid coordinates; from a Volume, world (x, y, z) in its frame.)";

void bindSurface(py::module_& m) {
    py::class_<PySurface>(m, "Surface", kSurfaceDoc)
        .def_property_readonly(
            "vertices",
            [](py::object self) {
                const PySurface& s = self.cast<const PySurface&>();
                return vertexView(s.surface.mesh.vertices, false, s.zyx, self);
            },
            "(V, 3) float32 vertex positions, (z, y, x) for a raw array, world (x, y, z) for a Volume (a view).")
        .def_property_readonly(
            "normals",
            [](py::object self) {
                const PySurface& s = self.cast<const PySurface&>();
                return vertexView(s.surface.mesh.vertices, true, s.zyx, self);
            },
            "(V, 3) float32 unit normals, in the vertices' order of axes, pointing towards lower values (a view).")
        .def_property_readonly(
            "faces", [](py::object self) { return faceView(self.cast<const PySurface&>().surface.mesh, self); },
            "(F, 3) uint32 vertex indices, one row per triangle (a view).")
        .def_property_readonly(
            "triangle_count", [](const PySurface& s) { return statsOf(s).triangles; }, "Number of triangles.")
        .def_property_readonly(
            "vertex_count", [](const PySurface& s) { return statsOf(s).vertices; }, "Number of vertices.")
        .def_property_readonly(
            "area", [](const PySurface& s) { return statsOf(s).area; }, "Surface area in world units squared.")
        .def_property_readonly(
            "volume", [](const PySurface& s) { return statsOf(s).enclosedVolume; },
            "Enclosed volume in world units cubed for a closed surface, else None.")
        .def_property_readonly(
            "closed", [](const PySurface& s) { return statsOf(s).closed; },
            "True when every mesh edge has exactly two triangles.")
        .def_property_readonly(
            "touches_border", [](const PySurface& s) { return statsOf(s).touchesBorder; },
            "True when the surface reaches a boundary cell of the volume.")
        .def_property_readonly("bounds", &boundsOf,
                               "(lowest, highest) corner of the vertices, in the vertices' coordinates.")
        .def_property_readonly(
            "cells_visited", [](const PySurface& s) { return statsOf(s).cellsVisited; },
            "(cell, piece) visits made while tracking.")
        .def_property_readonly(
            "nbytes", [](const PySurface& s) { return s.surface.mesh.drawByteSize(); },
            "Bytes of the vertex and index buffers.")
        .def_property_readonly(
            "seconds", [](const PySurface& s) { return statsOf(s).seconds; },
            "Seconds track took for it (0 for surfaces of surfaces()).")
        .def(
            "__len__", [](const PySurface& s) { return statsOf(s).triangles; }, "Number of triangles.")
        .def("__repr__", &surfaceRepr);
}

}  // namespace
}  // namespace isotrack::python

PYBIND11_MODULE(_isotrack, m) {
    using namespace isotrack;
    using namespace isotrack::python;
    m.doc() = "The compiled half of the isotrack package: private; use the functions of isotrack.";
    m.attr("__version__") = ISOTRACK_VERSION;
    m.attr("TABLES") = namesOf(kTableKinds, tableKindName);
    m.attr("FRAMES") = namesOf(kWorldFrames, worldFrameName);
    m.attr("METHODS") = namesOf(kMethods, methodName);

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
    py::class_<Geometry>(m, "Geometry")
        .def(py::init(&geometryOf), py::arg("spacing"), py::arg("origin"), py::arg("direction"), py::arg("frame"));
    m.def("level", &levelPy, py::arg("samples"), py::arg("level"), py::arg("within_range"));
    m.def("marching_cubes", &marchingCubesPy, py::arg("samples"), py::arg("level"), py::arg("geometry"),
          py::arg("table"), py::arg("threads"), py::arg("cell_mask"), py::arg("allow_degenerate"), py::arg("ascent"),
          py::arg("split"));
    m.def("track", &trackPy, py::arg("samples"), py::arg("level"), py::arg("geometry"), py::arg("table"),
          py::arg("threads"), py::arg("seed"), py::arg("seed_edge"), py::arg("ascent"));
    m.def("load", &loadPy, py::arg("path"), py::arg("time"), py::arg("array"));
    m.def(
        "steps",
        [](const std::string& path) {
            std::vector<std::pair<double, std::string>> steps;
            for (const TimeStep& step : readTimeSeries(path).steps) steps.emplace_back(step.time, step.file);
            return steps;
        },
        py::arg("path"));
    m.def("frame_affine", &frameAffinePy, py::arg("spacing"), py::arg("origin"), py::arg("direction"),
          py::arg("frame"));
    m.def("write_ply", &writePy<writePlyMesh>, py::arg("surface"), py::arg("path"));
    m.def("write_obj", &writePy<writeObjMesh>, py::arg("surface"), py::arg("path"));
    m.def("write_stl", &writePy<writeStl>, py::arg("surface"), py::arg("path"));
}
