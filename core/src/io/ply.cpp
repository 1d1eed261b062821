// Binary little-endian PLY meshes: the one layout writePly emits and readPly accepts.
#include <algorithm>
#include <cerrno>
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

constexpr std::size_t kChunkBytes = std::size_t(4) << 20;
constexpr std::size_t kMaxHeaderBytes = std::size_t(64) << 10;
constexpr std::size_t kVertexBytes = 6 * 4;
constexpr std::size_t kFaceBytes = 1 + 3 * 4;  // plus 4 with a component

using detail::FilePtr;
using detail::printable;

std::uint32_t getU32(const unsigned char* p) {
    return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 | std::uint32_t(p[3]) << 24;
}

float getFloat(const unsigned char* p) {
    const std::uint32_t bits = getU32(p);
    float f = 0;
    std::memcpy(&f, &bits, 4);
    return f;
}

// Parses "element NAME COUNT"; false when the line is not that element.
bool parseElement(const std::string& line, const std::string& name, std::uint64_t& count) {
    const std::string prefix = "element " + name + " ";
    if (line.compare(0, prefix.size(), prefix) != 0) return false;
    const std::string digits = line.substr(prefix.size());
    if (digits.empty() || digits.size() > 19 || digits.find_first_not_of("0123456789") != std::string::npos)
        return false;
    count = std::stoull(digits);
    return true;
}

void readExact(std::FILE* f, unsigned char* dst, std::size_t n, const std::string& path) {
    if (std::fread(dst, 1, n, f) != n) {
        if (std::ferror(f)) throw FormatError(path + ": cannot read: " + std::strerror(errno));
        throw FormatError(path + ": data is truncated");
    }
}

}  // namespace

void writePly(const std::string& path, const Mesh& mesh, const std::vector<std::int32_t>* faceComponent) {
    const std::size_t vertexCount = mesh.vertices.size();
    const std::size_t faceCount = mesh.triangleCount();
    if (vertexCount > std::size_t(std::numeric_limits<std::int32_t>::max()))
        throw InputError(path + ": mesh has " + std::to_string(vertexCount) +
                         " vertices, more than PLY int indices allow");
    detail::checkMesh(path, mesh, faceComponent);

    detail::BufferedOutput out(path);
    std::string header = "ply\nformat binary_little_endian 1.0\ncomment written by isotrack\n";
    header += "element vertex " + std::to_string(vertexCount) + "\n";
    header += "property float x\nproperty float y\nproperty float z\n";
    header += "property float nx\nproperty float ny\nproperty float nz\n";
    header += "element face " + std::to_string(faceCount) + "\nproperty list uchar int vertex_indices\n";
    if (faceComponent) header += "property int component\n";
    header += "end_header\n";

    std::string& buf = out.buffer();
    buf += header;
    for (const Vertex& v : mesh.vertices) {
        for (float c : v.position) detail::appendFloatLE(buf, c);
        for (float c : v.normal) detail::appendFloatLE(buf, c);
        out.maybeFlush();
    }
    for (std::size_t t = 0; t < faceCount; ++t) {
        buf += char(3);
        for (std::size_t k = 0; k < 3; ++k) detail::appendU32LE(buf, mesh.indices[3 * t + k]);
        if (faceComponent) detail::appendU32LE(buf, std::uint32_t((*faceComponent)[t]));
        out.maybeFlush();
    }
    out.close();
}

Mesh readPly(const std::string& path, std::vector<std::int32_t>* faceComponent) {
    FilePtr f = detail::openForReading(path);
    const std::uint64_t fileSize = detail::fileSizeOf(path, path);

    // Header lines, comments dropped; ends at end_header.
    std::vector<std::string> lines;
    std::uint64_t headerBytes = 0;
    for (std::string line;;) {
        const int c = std::fgetc(f.get());
        if (c == EOF) throw FormatError(path + ": not a PLY file written by isotrack: header has no end_header line");
        if (++headerBytes > kMaxHeaderBytes)
            throw FormatError(path + ": PLY header is longer than " + std::to_string(kMaxHeaderBytes >> 10) + " KiB");
        if (c != '\n') {
            line += char(c);
            continue;
        }
        line = detail::joinWords(line);
        if (lines.empty() && line != "ply")
            throw FormatError(path + ": not a PLY file: first line is \"" + printable(line) + "\"");
        if (line.compare(0, 8, "comment ") != 0 && line != "comment" && line.compare(0, 8, "obj_info") != 0)
            lines.push_back(line);
        if (line == "end_header") break;
        line.clear();
    }

    // Only writePly's layout is accepted, line for line.
    const std::vector<std::string> vertexProps = {"property float x",  "property float y",  "property float z",
                                                  "property float nx", "property float ny", "property float nz"};
    std::uint64_t vertexCount = 0, faceCount = 0;
    std::size_t at = 1;
    auto expect = [&](bool ok, const std::string& wanted) {
        if (!ok)
            throw FormatError(path + ": unsupported PLY layout: expected \"" + wanted + "\", got \"" +
                              printable(at < lines.size() ? lines[at] : "") + "\"");
        ++at;
    };
    auto lineIs = [&](const std::string& s) { return at < lines.size() && lines[at] == s; };
    expect(lineIs("format binary_little_endian 1.0"), "format binary_little_endian 1.0");
    expect(at < lines.size() && parseElement(lines[at], "vertex", vertexCount), "element vertex N");
    for (const std::string& p : vertexProps) expect(lineIs(p), p);
    expect(at < lines.size() && parseElement(lines[at], "face", faceCount), "element face M");
    expect(lineIs("property list uchar int vertex_indices"), "property list uchar int vertex_indices");
    const bool hasComponent = lineIs("property int component");
    if (hasComponent) ++at;
    expect(lineIs("end_header"), "end_header");

    // Counts are checked against the file size before anything is allocated.
    const std::size_t faceBytes = kFaceBytes + (hasComponent ? 4 : 0);
    const std::uint64_t dataBytes = fileSize - std::min(fileSize, headerBytes);
    if (vertexCount > dataBytes / kVertexBytes || faceCount > dataBytes / faceBytes ||
        vertexCount * kVertexBytes + faceCount * faceBytes != dataBytes)
        throw FormatError(path + ": element counts (" + std::to_string(vertexCount) + " vertices, " +
                          std::to_string(faceCount) + " faces) need " +
                          (vertexCount > dataBytes || faceCount > dataBytes
                               ? std::string("more")
                               : std::to_string(vertexCount * kVertexBytes + faceCount * faceBytes)) +
                          " data bytes, file has " + std::to_string(dataBytes));
    if (vertexCount > std::uint64_t(std::numeric_limits<std::int32_t>::max()))
        throw FormatError(path + ": element vertex " + std::to_string(vertexCount) + " is more than int indices allow");

    Mesh mesh;
    mesh.vertices.resize(std::size_t(vertexCount));
    std::vector<unsigned char> chunk(kChunkBytes);
    for (std::size_t done = 0; done < mesh.vertices.size();) {
        const std::size_t n = std::min(mesh.vertices.size() - done, kChunkBytes / kVertexBytes);
        readExact(f.get(), chunk.data(), n * kVertexBytes, path);
        for (std::size_t i = 0; i < n; ++i) {
            Vertex& v = mesh.vertices[done + i];
            const unsigned char* p = chunk.data() + i * kVertexBytes;
            for (std::size_t k = 0; k < 3; ++k) {
                v.position[k] = getFloat(p + 4 * k);
                v.normal[k] = getFloat(p + 12 + 4 * k);
            }
        }
        done += n;
    }
    mesh.indices.resize(std::size_t(faceCount) * 3);
    if (faceComponent) faceComponent->assign(hasComponent ? std::size_t(faceCount) : 0, 0);
    for (std::size_t done = 0; done < faceCount;) {
        const std::size_t n = std::min(std::size_t(faceCount) - done, kChunkBytes / faceBytes);
        readExact(f.get(), chunk.data(), n * faceBytes, path);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t face = done + i;
            const unsigned char* p = chunk.data() + i * faceBytes;
            if (p[0] != 3)
                throw FormatError(path + ": face " + std::to_string(face) + " has " + std::to_string(p[0]) +
                                  " vertices, expected 3");
            for (std::size_t k = 0; k < 3; ++k) {
                const std::uint32_t index = getU32(p + 1 + 4 * k);
                if (index >= vertexCount)
                    throw FormatError(path + ": face " + std::to_string(face) + ": vertex index " +
                                      std::to_string(std::int32_t(index)) + " is out of range (" +
                                      std::to_string(vertexCount) + " vertices)");
                mesh.indices[3 * face + k] = index;
            }
            if (faceComponent && hasComponent) (*faceComponent)[face] = std::int32_t(getU32(p + kFaceBytes));
        }
        done += n;
    }
    return mesh;
}

}  // namespace isotrack
