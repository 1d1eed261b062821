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

#include "isotrack/chunks.h"
#include "isotrack/errors.h"
#include "isotrack/extract.h"
#include "isotrack/io.h"
#include "isotrack/isovalue.h"
#include "isotrack/mapped_file.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/mesh_processing.h"
#include "isotrack/orientation.h"
#include "isotrack/tables.h"
#include "isotrack/threads.h"
#include "isotrack/tracking.h"
#include "isotrack/volume.h"
#include "mesh_output.h"
#include "time_module.h"

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
    if (!level) return suggestIsovalue(volume, range);
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
    for (Surface& surface : surfaces) transformSurface(surface, transform);
}

// What track and surfaces do to each surface: capping (an extraction from a
// padded copy), then smoothing and decimation (core's processSurface), in
// grid coordinates, before the winding is reversed or the frame applied.
struct Processing {
    bool cap = false;
    MeshProcessing mesh;
};

Processing processingOf(bool cap, int smooth, double passband, double decimate,
                        const std::optional<double>& decimateError, const Volume& volume) {
    Processing p;
    p.cap = cap;
    p.mesh.smoothIterations = smooth;
    p.mesh.passband = passband;
    p.mesh.decimateRatio = decimate;
    p.mesh.decimateError = decimateError;
    applyVolumeDefaults(p.mesh, volume);
    checkMeshProcessing(p.mesh);
    return p;
}

void processAll(std::vector<Surface>& surfaces, const Processing& processing) {
    for (Surface& surface : surfaces) processSurface(surface, processing.mesh);
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
                           bool split, bool cap, int smooth, double passband, double decimate,
                           const std::optional<double>& decimateError) {
    const Volume volume = volumeView(array, geometry);
    const TableKind table = tableOf(tableName);
    const int threadCount = threadsOf(threads);
    if (split) {
        const Processing processing = processingOf(cap, smooth, passband, decimate, decimateError, volume);
        std::vector<Surface> surfaces;
        {
            py::gil_scoped_release unlocked;
            surfaces = processing.cap ? extractAllSurfaces(padVolume(volume, capPadValue(volume, level)), level, table,
                                                           threadCount)
                                      : extractAllSurfaces(volume, level, table, threadCount);
            processAll(surfaces, processing);
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
                   bool ascent, bool cap, int smooth, double passband, double decimate,
                   const std::optional<double>& decimateError) {
    const Volume volume = volumeView(array, geometry);
    const TableKind table = tableOf(tableName);
    const int threadCount = std::min(threadsOf(threads), kMaxTrackThreads);
    const Processing processing = processingOf(cap, smooth, passband, decimate, decimateError, volume);
    std::vector<Surface> surfaces(1);
    {
        py::gil_scoped_release unlocked;
        const GridEdge edge = seedEdgeOf(volume, geometry, level, seed, seedEdge);
        if (processing.cap) {  // the same edge, one sample further along each axis of the padded copy
            const GridEdge padded{edge.x + 1, edge.y + 1, edge.z + 1, edge.axis};
            surfaces[0] =
                trackSurface(padVolume(volume, capPadValue(volume, level)), level, padded, table, threadCount);
        } else {
            surfaces[0] = trackSurface(volume, level, edge, table, threadCount);
        }
        processAll(surfaces, processing);
        if (ascent) reverseWinding(surfaces[0].mesh);
        toFrame(surfaces, geometry, volume);
    }
    throwIfMappedDamaged(array);
    return surfaceList(std::move(surfaces), geometry.zyx())[py::int_(0)];
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

// Per vertex, the grid edge it lies on as (z, y, x, axis) sample indices, axis 0
// along z and 2 along x as seed_edge takes it (3: inside its cell, the
// trilinear table's). isotrack.dask names crossed edges globally with it.
py::array vertexEdgesOf(const PySurface& s) {
    const Buffer<PackedGridEdge>& edges = s.surface.mesh.vertexEdges;
    py::array_t<std::int32_t> out({py::ssize_t(edges.size()), py::ssize_t(4)});
    auto rows = out.mutable_unchecked<2>();
    for (std::size_t v = 0; v < edges.size(); ++v) {
        const GridEdge e = edges[v];
        const auto i = py::ssize_t(v);
        rows(i, 0) = e.z;
        rows(i, 1) = e.y;
        rows(i, 2) = e.x;
        rows(i, 3) = e.axis == kCellInterior ? 3 : 2 - e.axis;
    }
    return std::move(out);
}

// Many surfaces of one chunk of a raw array in one go, for isotrack.dask (a
// chunk's pieces can number thousands): the vertices (z, y, x), normals,
// vertex_edges and faces (indexing the concatenated vertices, uint64) of all of
// them one after the other; per surface its vertex and triangle counts, area,
// bounds and signed volume about `reference` (z, y, x), in double, additive over
// pieces; and per vertex core's global edge id and whether the edge lies on a
// face shared with another chunk or on the volume's border (isotrack/chunks.h).
// The chunk's samples start at `offset` and span `shape` in a volume of
// `volumeShape`, all (z, y, x).
Dims dimsOf(const std::array<int, 3>& zyx) { return {zyx[2], zyx[1], zyx[0]}; }

py::tuple concatenatedPy(const py::list& list, const Vec3d& reference, const std::array<int, 3>& offset,
                         const std::array<int, 3>& shape, const std::array<int, 3>& volumeShape) {
    std::vector<const Surface*> surfaces;
    for (const py::handle item : list) surfaces.push_back(&item.cast<const PySurface&>().surface);
    std::size_t vertexTotal = 0, faceTotal = 0;
    for (const Surface* s : surfaces) {
        vertexTotal += s->mesh.vertices.size();
        faceTotal += s->mesh.triangleCount();
    }
    const auto count = py::ssize_t(surfaces.size());
    py::array_t<float> positions({py::ssize_t(vertexTotal), py::ssize_t(3)}),
        normals({py::ssize_t(vertexTotal), py::ssize_t(3)});
    py::array_t<std::int32_t> edges({py::ssize_t(vertexTotal), py::ssize_t(4)});
    py::array_t<std::int64_t> ids{py::ssize_t(vertexTotal)};
    py::array_t<bool> shared{py::ssize_t(vertexTotal)}, onBorder{py::ssize_t(vertexTotal)};
    py::array_t<std::uint64_t> faces({py::ssize_t(faceTotal), py::ssize_t(3)});
    py::array_t<std::int64_t> vertexCounts(count), triangleCounts(count);
    py::array_t<double> areas(count), volumes(count), bounds({count, py::ssize_t(2), py::ssize_t(3)});
    auto p = positions.mutable_unchecked<2>(), n = normals.mutable_unchecked<2>();
    auto e = edges.mutable_unchecked<2>();
    auto f = faces.mutable_unchecked<2>();
    auto b = bounds.mutable_unchecked<3>();
    py::ssize_t v = 0, t = 0;
    for (py::ssize_t k = 0; k < count; ++k) {
        const Surface& s = *surfaces[std::size_t(k)];
        const py::ssize_t first = v;
        const ChunkEdges named = chunkEdges(s.mesh, dimsOf(offset), dimsOf(shape), dimsOf(volumeShape));
        for (std::size_t i = 0; i < s.mesh.vertices.size(); ++i, ++v) {
            ids.mutable_at(v) = std::int64_t(named.ids[i]);
            shared.mutable_at(v) = named.shared[i] != 0;
            onBorder.mutable_at(v) = named.onBorder[i] != 0;
            const Vertex& vertex = s.mesh.vertices[i];
            const GridEdge g = s.mesh.vertexEdges[i];
            for (py::ssize_t a = 0; a < 3; ++a) {
                p(v, a) = vertex.position[2 - a];
                n(v, a) = vertex.normal[2 - a];
            }
            e(v, 0) = g.z;
            e(v, 1) = g.y;
            e(v, 2) = g.x;
            e(v, 3) = g.axis == kCellInterior ? 3 : 2 - g.axis;
        }
        for (std::size_t i = 0; i < s.mesh.indices.size(); i += 3, ++t)
            for (py::ssize_t c = 0; c < 3; ++c) f(t, c) = std::uint64_t(first) + s.mesh.indices[i + std::size_t(c)];
        double sixfold = 0.0;
        for (std::size_t i = 0; i < s.mesh.indices.size(); i += 3) {
            std::array<std::array<double, 3>, 3> c{};
            for (std::size_t j = 0; j < 3; ++j)
                for (std::size_t a = 0; a < 3; ++a)
                    c[j][a] = double(s.mesh.vertices[s.mesh.indices[i + j]].position[a]) - reference[2 - a];
            sixfold += c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) +
                       c[0][1] * (c[1][2] * c[2][0] - c[1][0] * c[2][2]) +
                       c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0]);
        }
        volumes.mutable_at(k) = sixfold / 6.0;
        vertexCounts.mutable_at(k) = std::int64_t(s.mesh.vertices.size());
        triangleCounts.mutable_at(k) = std::int64_t(s.mesh.triangleCount());
        areas.mutable_at(k) = s.stats.area;
        for (py::ssize_t a = 0; a < 3; ++a) {
            b(k, 0, a) = s.stats.boundsMin[std::size_t(2 - a)];
            b(k, 1, a) = s.stats.boundsMax[std::size_t(2 - a)];
        }
    }
    return py::make_tuple(positions, normals, edges, faces, vertexCounts, triangleCounts, areas, bounds, volumes, ids,
                          shared, onBorder);
}

// Core's global edge ids of edges (z, y, x, axis with 0 along z) in a volume of
// shape (z, y, x), and back (isotrack/chunks.h).
py::array_t<std::int64_t> edgeIdsPy(const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& edges,
                                    const std::array<int, 3>& shape) {
    const auto rows = edges.unchecked<2>();
    if (rows.shape(1) != 4) throw InputError("edges: internal: expected (N, 4) rows of (z, y, x, axis)");
    py::array_t<std::int64_t> out(rows.shape(0));
    for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
        const GridEdge edge{int(rows(i, 2)), int(rows(i, 1)), int(rows(i, 0)), 2 - int(rows(i, 3))};
        out.mutable_at(i) = std::int64_t(globalEdgeId(edge, dimsOf(shape)));
    }
    return out;
}

py::array_t<std::int64_t> edgesOfIdsPy(const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& ids,
                                       const std::array<int, 3>& shape) {
    const auto in = ids.unchecked<1>();
    py::array_t<std::int64_t> out({in.shape(0), py::ssize_t(4)});
    auto rows = out.mutable_unchecked<2>();
    for (py::ssize_t i = 0; i < in.shape(0); ++i) {
        const GridEdge e = edgeOfGlobalId(std::uint64_t(in(i)), dimsOf(shape));
        rows(i, 0) = e.z;
        rows(i, 1) = e.y;
        rows(i, 2) = e.x;
        rows(i, 3) = 2 - e.axis;
    }
    return out;
}

// The crossed grid edge nearest a raw array's point (z, y, x), as (z, y, x, axis).
std::array<int, 4> nearestEdgePy(const py::array& array, double level, const Geometry& geometry, const Vec3d& point) {
    const Volume volume = volumeView(array, geometry);
    GridEdge e;
    {
        py::gil_scoped_release unlocked;
        e = nearestCrossedEdge(volume, level, {point[2], point[1], point[0]});
    }
    return {e.z, e.y, e.x, 2 - e.axis};
}

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
        .def_property_readonly("vertex_edges", &vertexEdgesOf,
                               "(V, 4) int32: per vertex its grid edge (z, y, x, axis), axis 0 along z (a copy).")
        .def(
            "__len__", [](const PySurface& s) { return statsOf(s).triangles; }, "Number of triangles.")
        .def_property_readonly(
            "degenerate_triangles",
            [](const PySurface& s) { return measureQuality(s.surface.mesh).degenerateTriangles; },
            "Triangles of zero area (corners at one place or on one line).")
        .def_property_readonly(
            "boundary_edges", [](const PySurface& s) { return measureQuality(s.surface.mesh).boundaryEdges; },
            "Edges of one triangle, once vertices at one position are welded (0 for a closed surface).")
        .def_property_readonly(
            "non_manifold_edges", [](const PySurface& s) { return measureQuality(s.surface.mesh).nonManifoldEdges; },
            "Edges of more than two triangles, once vertices at one position are welded.")
        .def_property_readonly(
            "min_angle_fractions",
            [](const PySurface& s) {
                const MeshQuality q = measureQuality(s.surface.mesh);
                return py::make_tuple(q.minAngleBelow1, q.minAngleBelow10, q.minAngleBelow20);
            },
            "Fractions of the triangles whose smallest angle is below 1, 10 and 20 degrees.")
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
          py::arg("split"), py::arg("cap") = false, py::arg("smooth") = 0, py::arg("passband") = 0.1,
          py::arg("decimate") = 1.0, py::arg("decimate_error") = py::none());
    m.def("track", &trackPy, py::arg("samples"), py::arg("level"), py::arg("geometry"), py::arg("table"),
          py::arg("threads"), py::arg("seed"), py::arg("seed_edge"), py::arg("ascent"), py::arg("cap") = false,
          py::arg("smooth") = 0, py::arg("passband") = 0.1, py::arg("decimate") = 1.0,
          py::arg("decimate_error") = py::none());
    m.def("concatenated", &concatenatedPy, py::arg("surfaces"), py::arg("reference"), py::arg("offset"),
          py::arg("shape"), py::arg("volume_shape"));
    m.def("edge_ids", &edgeIdsPy, py::arg("edges"), py::arg("shape"));
    m.def("edges_of_ids", &edgesOfIdsPy, py::arg("ids"), py::arg("shape"));
    m.def("nearest_edge", &nearestEdgePy, py::arg("samples"), py::arg("level"), py::arg("geometry"), py::arg("point"));
    addTimeFunctions(m);
    m.def("frame_affine", &frameAffinePy, py::arg("spacing"), py::arg("origin"), py::arg("direction"),
          py::arg("frame"));
    m.def("write_ply", &writePy<writePlyMesh>, py::arg("surface"), py::arg("path"));
    m.def("write_obj", &writePy<writeObjMesh>, py::arg("surface"), py::arg("path"));
    m.def("write_stl", &writePy<writeStl>, py::arg("surface"), py::arg("path"));
}
