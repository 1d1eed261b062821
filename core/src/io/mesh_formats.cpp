// Mesh files by extension: PLY (ply.cpp), Wavefront OBJ and binary STL (here).
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "io_common.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"

namespace isotrack {

namespace {

using namespace detail;

constexpr std::size_t kStlHeaderBytes = 80;

// Shortest text that reads back as the same float.
void appendFloat(std::string& out, float v) {
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, result.ptr);
}

// The unit normal of triangle (a, b, c), right-handed; zero when it is degenerate.
std::array<float, 3> facetNormal(const float* a, const float* b, const float* c) {
    const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
    const double v[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(length > 0.0) || !std::isfinite(length)) return {0.0f, 0.0f, 0.0f};
    return {float(n[0] / length), float(n[1] / length), float(n[2] / length)};
}

}  // namespace

MeshFormat meshFormatOf(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".ply") return MeshFormat::Ply;
    if (ext == ".obj") return MeshFormat::Obj;
    if (ext == ".stl") return MeshFormat::Stl;
    throw InputError(path + ": unsupported mesh file extension \"" + printable(ext) +
                     "\" (supported: .ply, .obj, .stl)");
}

const char* meshFormatExtension(MeshFormat format) {
    switch (format) {
        case MeshFormat::Ply: return ".ply";
        case MeshFormat::Obj: return ".obj";
        case MeshFormat::Stl: return ".stl";
    }
    return "";
}

void writeMesh(const std::string& path, const Mesh& mesh, const std::vector<std::int32_t>* faceComponent) {
    switch (meshFormatOf(path)) {
        case MeshFormat::Ply: return writePly(path, mesh, faceComponent);
        case MeshFormat::Obj: return writeObj(path, mesh, faceComponent);
        case MeshFormat::Stl: return writeStl(path, mesh);
    }
}

void writeObj(const std::string& path, const Mesh& mesh, const std::vector<std::int32_t>* faceComponent) {
    checkMesh(path, mesh, faceComponent);
    BufferedOutput out(path);
    std::string& buf = out.buffer();
    buf += "# written by isotrack: " + std::to_string(mesh.vertices.size()) + " vertices, " +
           std::to_string(mesh.triangleCount()) + " triangles\n";
    for (const Vertex& v : mesh.vertices) {
        buf += "v";
        for (float c : v.position) buf += ' ', appendFloat(buf, c);
        buf += "\nvn";
        for (float c : v.normal) buf += ' ', appendFloat(buf, c);
        buf += '\n';
        out.maybeFlush();
    }
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        if (faceComponent && (t == 0 || (*faceComponent)[t] != (*faceComponent)[t - 1]))
            buf += "g component_" + std::to_string((*faceComponent)[t]) + "\n";
        buf += 'f';
        for (std::size_t k = 0; k < 3; ++k) {
            const std::string index = std::to_string(std::uint64_t(mesh.indices[3 * t + k]) + 1);
            buf += ' ' + index + "//" + index;
        }
        buf += '\n';
        out.maybeFlush();
    }
    out.close();
}

void writeStl(const std::string& path, const Mesh& mesh) {
    checkMesh(path, mesh, nullptr);
    if (mesh.triangleCount() > std::numeric_limits<std::uint32_t>::max())
        throw InputError(path + ": " + std::to_string(mesh.triangleCount()) +
                         " triangles, more than binary STL can count");
    BufferedOutput out(path);
    std::string& buf = out.buffer();
    // Readers take a header starting with "solid" for ASCII STL, so this one does not.
    std::string header = "binary STL written by isotrack";
    header.resize(kStlHeaderBytes, '\0');
    buf += header;
    appendU32LE(buf, std::uint32_t(mesh.triangleCount()));
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const float* p[3];
        for (std::size_t k = 0; k < 3; ++k) p[k] = mesh.vertices[mesh.indices[3 * t + k]].position;
        for (float c : facetNormal(p[0], p[1], p[2])) appendFloatLE(buf, c);
        for (const float* q : p)
            for (std::size_t k = 0; k < 3; ++k) appendFloatLE(buf, q[k]);
        buf += '\0';
        buf += '\0';  // attribute byte count
        out.maybeFlush();
    }
    out.close();
}

}  // namespace isotrack
