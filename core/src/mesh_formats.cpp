// Mesh files by extension: PLY (ply.cpp), Wavefront OBJ and binary STL (here).
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "io_common.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"

namespace isotrack {

namespace {

using namespace detail;

constexpr std::size_t kFlushBytes = std::size_t(4) << 20;
constexpr std::size_t kStlHeaderBytes = 80;

void checkMesh(const std::string& path, const Mesh& mesh, const std::vector<std::int32_t>* faceComponent) {
    if (mesh.indices.size() % 3 != 0)
        throw InputError(path + ": mesh has " + std::to_string(mesh.indices.size()) + " indices, not a multiple of 3");
    for (std::uint32_t i : mesh.indices)
        if (i >= mesh.vertices.size())
            throw InputError(path + ": mesh index " + std::to_string(i) + " is out of range (" +
                             std::to_string(mesh.vertices.size()) + " vertices)");
    if (faceComponent && faceComponent->size() != mesh.triangleCount())
        throw InputError(path + ": " + std::to_string(faceComponent->size()) + " face components for " +
                         std::to_string(mesh.triangleCount()) + " triangles");
}

// Collects output and writes it a few MiB at a time.
class Output {
public:
    explicit Output(const std::string& path) : path_(path), file_(openForWriting(path)) { buf_.reserve(kFlushBytes + 256); }

    std::string& buffer() { return buf_; }
    void maybeFlush() {
        if (buf_.size() >= kFlushBytes) flush();
    }
    void close() {
        flush();
        if (std::fclose(file_.release()) != 0) throw FormatError(path_ + ": cannot write: " + std::strerror(errno));
    }

private:
    void flush() {
        if (std::fwrite(buf_.data(), 1, buf_.size(), file_.get()) != buf_.size())
            throw FormatError(path_ + ": cannot write: " + std::strerror(errno));
        buf_.clear();
    }
    const std::string& path_;
    FilePtr file_;
    std::string buf_;
};

// Shortest text that reads back as the same float.
void appendFloat(std::string& out, float v) {
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, result.ptr);
}

void appendU32LE(std::string& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xff);
}

void appendFloatLE(std::string& out, float f) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, 4);
    appendU32LE(out, bits);
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
    throw InputError(path + ": unsupported mesh file extension \"" + printable(ext) + "\" (supported: .ply, .obj, .stl)");
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
    Output out(path);
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
        throw InputError(path + ": " + std::to_string(mesh.triangleCount()) + " triangles, more than binary STL can count");
    Output out(path);
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
