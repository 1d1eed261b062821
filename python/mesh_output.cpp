// Volumes over numpy samples, scikit-image's mesh options, frames and views:
// see mesh_output.h.
#include "mesh_output.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <utility>

#include "isotrack/errors.h"
#include "isotrack/mapped_file.h"

namespace isotrack::python {

namespace {

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

// Rebuilds a mesh from the triangles `keepFace` marks, each corner mapped
// through `target`, and the vertices `keepVertex` marks, in their order.
void rebuild(MeshOutput& out, const std::vector<char>& keepFace, const std::vector<std::uint32_t>& target,
             const std::vector<char>& keepVertex) {
    Mesh& mesh = out.mesh;
    std::vector<std::uint32_t> renumbered(mesh.vertices.size(), 0);
    std::size_t kept = 0;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (!keepVertex[v]) continue;
        renumbered[v] = std::uint32_t(kept);
        mesh.vertices[kept] = mesh.vertices[v];
        out.values[kept] = out.values[v];
        if (!mesh.vertexEdges.empty()) mesh.vertexEdges[kept] = mesh.vertexEdges[v];
        ++kept;
    }
    mesh.vertices.resize(kept);
    out.values.resize(kept);
    if (!mesh.vertexEdges.empty()) mesh.vertexEdges.resize(kept);
    std::size_t corner = 0;
    for (std::size_t t = 0; t < keepFace.size(); ++t) {
        if (!keepFace[t]) continue;
        for (std::size_t c = 0; c < 3; ++c) mesh.indices[corner++] = renumbered[target[mesh.indices[3 * t + c]]];
    }
    mesh.indices.resize(corner);
}

// The cell a triangle was made in: along each axis, the one cell coordinate
// shared by the cells around its three corners' edges (an edge along that axis,
// or a cell's interior vertex, fixes it; an edge across it allows two). Only a
// triangle lying in a cube's face would leave two, and isotrack's tables make
// none (the tests compare masked meshes with scikit-image's); should one come,
// the cell inside the grid, the lower one when both are, takes it.
Dims cellOf(const GridEdge (&corners)[3], const Dims& dims) {
    Dims cell{};
    for (int b = 0; b < 3; ++b) {
        int lo = std::numeric_limits<int>::min(), hi = std::numeric_limits<int>::max();
        for (const GridEdge& e : corners) {
            const int c = b == 0 ? e.x : b == 1 ? e.y : e.z;
            const bool fixed = e.axis == b || e.axis == kCellInterior;
            lo = std::max(lo, fixed ? c : c - 1);
            hi = std::min(hi, c);
        }
        cell[b] = lo >= 0 ? lo : hi;
        cell[b] = std::clamp(cell[b], 0, std::max(dims[b] - 2, 0));
    }
    return cell;
}

std::uint32_t root(std::vector<std::uint32_t>& parent, std::uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

bool samePosition(const Vertex& a, const Vertex& b) {
    return a.position[0] == b.position[0] && a.position[1] == b.position[1] && a.position[2] == b.position[2];
}

}  // namespace

Geometry geometryOf(const Vec3d& spacing, const Vec3d& origin, const Mat3d& direction, const std::string& frame) {
    Geometry geometry{spacing, origin, direction, std::nullopt};
    if (!frame.empty()) geometry.frame = parseWorldFrame(frame);
    return geometry;
}

Volume volumeView(const py::array& array, const Geometry& geometry) {
    const std::optional<ScalarType> type = scalarTypeOf(array.dtype());
    if (array.ndim() != 3 || !type || !(array.flags() & py::array::c_style) ||
        !array.dtype().attr("isnative").cast<bool>() || !array.attr("flags").attr("aligned").cast<bool>())
        throw InputError("volume: internal: expected a C-contiguous, aligned, native 3D array of a core sample type");
    for (py::ssize_t a = 0; a < 3; ++a) {
        if (array.shape(a) < 1 || array.shape(a) > kMaxDimension)
            throw InputError("volume: each dimension must be 1 to " + std::to_string(kMaxDimension) + ", got " +
                             std::to_string(array.shape(a)));
    }
    const Dims dims{int(array.shape(2)), int(array.shape(1)), int(array.shape(0))};
    // A Volume's samples mapped from a file (isotrack.open): a volume over the mapping
    // itself, so that streaming passes let passed slices go and a truncated file is an
    // error. The array, held for the call, keeps the mapping alive: the pointer owns nothing.
    const MappedFile* file = MappedFile::containing(array.data());
    Volume volume = file && file->data() == array.data() && file->size() == std::uint64_t(array.nbytes())
                        ? Volume::mapped(dims, *type, std::shared_ptr<const MappedFile>(std::shared_ptr<void>(), file),
                                         geometry.spacing, geometry.origin)
                        : Volume::view(dims, *type, array.data(), geometry.spacing, geometry.origin);
    volume.setDirection(geometry.direction);
    return volume;
}

std::vector<float> edgeMaxima(const Mesh& mesh, const Volume& volume) {
    std::vector<float> out(mesh.vertices.size());
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
    return out;
}

void keepMaskedCells(MeshOutput& out, const std::uint8_t* cellMask, const Dims& dims) {
    const Mesh& mesh = out.mesh;
    const std::size_t cellsX = std::size_t(std::max(dims[0] - 1, 1)), cellsY = std::size_t(std::max(dims[1] - 1, 1));
    std::vector<char> keepFace(mesh.triangleCount(), 0), used(mesh.vertices.size(), 0);
    for (std::size_t t = 0; t < keepFace.size(); ++t) {
        const GridEdge corners[3] = {mesh.vertexEdges[mesh.indices[3 * t]], mesh.vertexEdges[mesh.indices[3 * t + 1]],
                                     mesh.vertexEdges[mesh.indices[3 * t + 2]]};
        const Dims cell = cellOf(corners, dims);
        keepFace[t] = cellMask[std::size_t(cell[0]) + cellsX * (std::size_t(cell[1]) + cellsY * std::size_t(cell[2]))];
        if (keepFace[t])
            for (std::size_t c = 0; c < 3; ++c) used[mesh.indices[3 * t + c]] = 1;
    }
    std::vector<std::uint32_t> identity(mesh.vertices.size());
    std::iota(identity.begin(), identity.end(), 0u);
    rebuild(out, keepFace, identity, used);
}

void removeDegenerateFaces(MeshOutput& out) {
    const Mesh& mesh = out.mesh;
    std::vector<std::uint32_t> parent(mesh.vertices.size());
    std::iota(parent.begin(), parent.end(), 0u);
    std::vector<char> keepFace(mesh.triangleCount(), 1);
    for (std::size_t t = 0; t < keepFace.size(); ++t) {
        const std::uint32_t* corner = &mesh.indices[3 * t];
        for (std::size_t c = 0; c < 3; ++c) {
            const std::uint32_t a = corner[c], b = corner[(c + 1) % 3];
            if (!samePosition(mesh.vertices[a], mesh.vertices[b])) continue;
            keepFace[t] = 0;
            const std::uint32_t ra = root(parent, a), rb = root(parent, b);
            parent[std::max(ra, rb)] = std::min(ra, rb);
        }
    }
    std::vector<char> representative(mesh.vertices.size());
    for (std::uint32_t v = 0; v < parent.size(); ++v) {
        parent[v] = root(parent, v);
        representative[v] = parent[v] == v;
    }
    rebuild(out, keepFace, parent, representative);
}

void reverseWinding(Mesh& mesh) {
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
}

py::array vertexView(const Buffer<Vertex>& vertices, bool normals, bool zyx, py::handle owner) {
    if (vertices.empty()) return py::array_t<float>(std::vector<py::ssize_t>{0, 3});
    const float* first = normals ? vertices.front().normal : vertices.front().position;
    const py::ssize_t along = zyx ? -py::ssize_t(sizeof(float)) : py::ssize_t(sizeof(float));
    return py::array(py::dtype::of<float>(), {py::ssize_t(vertices.size()), py::ssize_t(3)},
                     {py::ssize_t(sizeof(Vertex)), along}, zyx ? first + 2 : first, owner);
}

py::array faceView(const Mesh& mesh, py::handle owner) {
    if (mesh.indices.empty()) return py::array_t<std::uint32_t>(std::vector<py::ssize_t>{0, 3});
    return py::array(py::dtype::of<std::uint32_t>(), {py::ssize_t(mesh.triangleCount()), py::ssize_t(3)},
                     mesh.indices.data(), owner);
}

}  // namespace isotrack::python
