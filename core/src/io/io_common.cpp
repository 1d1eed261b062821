#include "io_common.h"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <utility>

#include "isotrack/errors.h"
#include "isotrack/mapped_file.h"

namespace isotrack::detail {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kIoChunk = std::size_t(1) << 20;
// Compressed input and discarded output go through small buffers: small files stay cheap.
constexpr std::size_t kInflateChunk = std::size_t(64) << 10;
// deflate never expands more than about 1032:1, which bounds what a compressed
// file can hold before a single byte is inflated.
constexpr std::uint64_t kMaxDeflateRatio = 1032;
// Vertex positions are floats; a grid reaching past this could overflow them.
constexpr double kMaxWorldCoordinate = 1e30;

const char* compressionName(Compression c) { return c == Compression::Gzip ? "gzip" : "zlib"; }

void seekTo(std::FILE* f, std::uint64_t offset, const std::string& where) {
    if (std::fseek(f, long(offset), SEEK_SET) != 0) throw FormatError(where + ": cannot seek: " + std::strerror(errno));
}

void readExact(std::FILE* f, std::byte* dst, std::uint64_t n, const std::string& where) {
    for (std::uint64_t done = 0; done < n;) {
        const std::size_t chunk = std::size_t(std::min<std::uint64_t>(n - done, kIoChunk));
        const std::size_t got = std::fread(dst + done, 1, chunk, f);
        if (got != chunk) {
            if (std::ferror(f)) throw FormatError(where + ": cannot read: " + std::strerror(errno));
            throw FormatError(where + ": data is truncated: got " + std::to_string(done + got) + " of " +
                              std::to_string(n) + " bytes");
        }
        done += got;
    }
}

}  // namespace

FilePtr openForReading(const std::string& path, const std::string& where) {
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status)) throw FormatError(where + ": cannot open: " + std::strerror(ENOENT));
    if (fs::is_directory(status)) throw FormatError(where + ": cannot open: " + std::strerror(EISDIR));
    if (!fs::is_regular_file(status)) throw FormatError(where + ": cannot open: not a regular file");
    FilePtr f(std::fopen(path.c_str(), "rb"));
    if (!f) throw FormatError(where + ": cannot open: " + std::strerror(errno));
    return f;
}

FilePtr openForReading(const std::string& path) { return openForReading(path, path); }

std::uint64_t fileSizeOf(const std::string& path, const std::string& where) {
    std::error_code ec;
    const std::uint64_t size = fs::file_size(path, ec);
    if (ec) throw FormatError(where + ": cannot read: " + ec.message());
    return size;
}

std::string printable(const std::string& s, std::size_t maxChars) {
    std::string out;
    for (char c : s.substr(0, maxChars)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
    if (s.size() > maxChars) out += "...";
    return out;
}

std::string lowerCase(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::string lowerExtension(const std::string& path) {
    const fs::path p(path);
    std::string ext = lowerCase(p.extension().string());
    if (ext == ".gz") ext = lowerCase(p.stem().extension().string()) + ext;
    return ext;
}

std::vector<std::string> splitWords(const std::string& s) {
    std::istringstream in(s);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

std::string joinWords(const std::string& s) {
    std::string out;
    for (const std::string& w : splitWords(s)) out += (out.empty() ? "" : " ") + w;
    return out;
}

std::optional<long long> parseInteger(const std::string& s) {
    if (s.empty()) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const long long v = std::strtoll(s.c_str(), &end, 10);
    if (errno != 0 || end != s.c_str() + s.size()) return std::nullopt;
    return v;
}

std::optional<double> parseFinite(const std::string& s) {
    if (s.empty() || std::isspace(static_cast<unsigned char>(s[0]))) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

std::optional<Dims> parseDims(const std::vector<std::string>& words) {
    if (words.size() != 3) return std::nullopt;
    Dims dims{};
    for (std::size_t a = 0; a < 3; ++a) {
        const auto v = parseInteger(words[a]);
        if (!v || *v <= 0 || *v > INT32_MAX) return std::nullopt;
        dims[a] = int(*v);
    }
    return dims;
}

std::optional<Vec3d> parseVec3(const std::vector<std::string>& words, bool positive) {
    if (words.size() != 3) return std::nullopt;
    Vec3d out{};
    for (std::size_t a = 0; a < 3; ++a) {
        const auto v = parseFinite(words[a]);
        if (!v || (positive && !(*v > 0))) return std::nullopt;
        out[a] = *v;
    }
    return out;
}

std::string dimsText(const Dims& dims) {
    return std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]);
}

std::string numberText(double v) {
    char buf[32];
    const auto result = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, result.ptr);
}

bool hostIsBigEndian() {
    const std::uint16_t probe = 1;
    unsigned char first = 0;
    std::memcpy(&first, &probe, 1);
    return first == 0;
}

void swapBytes(std::byte* data, std::size_t count, std::size_t width) {
    if (width < 2) return;
    for (std::size_t i = 0; i < count; ++i) std::reverse(data + i * width, data + (i + 1) * width);
}

std::uint64_t sampleBytes(const VolumeHeader& header) { return sampleBytes(header, header.type); }

std::uint64_t sampleBytes(const VolumeHeader& header, ScalarType type) {
    const Dims& d = header.dims;
    const std::string field = header.path + ": field \"" + header.sizeField + "\": ";
    if (d[0] < 1 || d[1] < 1 || d[2] < 1) throw FormatError(field + "dimensions must be positive, got " + dimsText(d));
    // Step by step so hostile sizes cannot overflow the product.
    const std::uint64_t maxSamples = kMaxVolumeBytes / scalarTypeSize(type);
    const auto nx = std::uint64_t(d[0]), ny = std::uint64_t(d[1]), nz = std::uint64_t(d[2]);
    if (nx > maxSamples || ny > maxSamples / nx || nz > maxSamples / (nx * ny))
        throw FormatError(field + dimsText(d) + " " + scalarTypeName(type) + " samples exceed the " +
                          std::to_string(kMaxVolumeBytes >> 30) + " GiB volume limit");
    return nx * ny * nz * scalarTypeSize(type);
}

void checkGeometry(const VolumeHeader& header, const std::string& spacingField, const std::string& originField) {
    const Vec3d& s = header.spacing;
    const Vec3d& o = header.origin;
    const std::string sText = numberText(s[0]) + " " + numberText(s[1]) + " " + numberText(s[2]);
    const std::string oText = numberText(o[0]) + " " + numberText(o[1]) + " " + numberText(o[2]);
    for (int a = 0; a < 3; ++a) {
        if (!(s[a] > 0) || !std::isfinite(s[a]))
            throw FormatError(header.path + ": field \"" + spacingField +
                              "\": spacing must be positive and finite, got " + sText);
        if (!std::isfinite(o[a]))
            throw FormatError(header.path + ": field \"" + originField + "\": origin must be finite, got " + oText);
        const double reach = std::fabs(o[a]) + double(std::max(header.dims[a] - 1, 0)) * s[a];
        if (!(reach <= kMaxWorldCoordinate))
            throw FormatError(header.path + ": fields \"" + spacingField + "\" and \"" + originField +
                              "\": grid reaches " + numberText(reach) + " along axis " + std::to_string(a) +
                              ", beyond float range");
    }
}

std::string dataWhere(const VolumeHeader& header, const SampleData& data) {
    if (data.path == header.path) return header.path;
    return header.path + ": data file \"" + printable(data.path, 200) + "\"";
}

void requireMemoryFor(const VolumeHeader& header, std::uint64_t bytes, const std::string& how) {
    const std::uint64_t available = availableMemoryBytes();
    if (bytes <= available) return;
    const auto gib = [](std::uint64_t b) {
        char text[32];
        std::snprintf(text, sizeof text, "%.1f GiB", double(b) / double(std::uint64_t(1) << 30));
        return std::string(text);
    };
    throw FormatError(header.path + ": " + dimsText(header.dims) + " " + scalarTypeName(header.type) + " samples, " +
                      how + ", need " + gib(bytes) + " of memory, more than the " + gib(available) + " available");
}

Volume readSamples(const VolumeHeader& header, const SampleData& data) {
    const std::uint64_t needed = sampleBytes(header);
    const std::string where = dataWhere(header, data);
    const std::string holder = data.path == header.path ? "the file" : "\"" + printable(data.path, 200) + "\"";
    auto refuse = [&](const std::string& problem) {
        throw FormatError(header.path + ": field \"" + header.sizeField + "\": " + dimsText(header.dims) + " " +
                          scalarTypeName(header.type) + " needs " + std::to_string(needed) + " data bytes but " +
                          problem);
    };

    FilePtr file = openForReading(data.path, where);
    const std::uint64_t fileSize = fileSizeOf(data.path, where);
    const std::uint64_t available = fileSize > data.offset ? fileSize - data.offset : 0;
    std::FILE* f = file.get();

    if (data.compression == Compression::None) {
        const std::uint64_t afterSkip = available > data.skip ? available - data.skip : 0;
        if (afterSkip < needed) refuse(holder + " has only " + std::to_string(afterSkip) + " (truncated?)");
        if (afterSkip > needed && !data.trailingBytesAllowed)
            refuse(holder + " has " + std::to_string(afterSkip) + " (the sizes disagree)");
        // Samples that start at a multiple of their size in the file: a mapped
        // view of them is aligned for their type. Others (an attached header of
        // odd length) are read into memory, as are samples in the other byte order.
        const bool alignedInFile = (data.offset + data.skip) % scalarTypeSize(header.type) == 0;
        if (data.bigEndian == hostIsBigEndian() && alignedInFile) {
            // In the host's order: mapped where it lies, never copied (isotrack/mapped_file.h).
            file.reset();
            Volume volume =
                Volume::mapped(header.dims, header.type,
                               std::make_shared<const MappedFile>(data.path, data.offset + data.skip, needed, where),
                               header.spacing, header.origin);
            volume.setDirection(header.direction);
            return volume;
        }
        const bool swap = data.bigEndian != hostIsBigEndian();
        requireMemoryFor(header, needed, swap ? "byte-swapped" : "unaligned in the file");
        Volume volume(header.dims, header.type, header.spacing, header.origin);
        volume.setDirection(header.direction);
        seekTo(f, data.offset + data.skip, where);
        readExact(f, volume.bytes(), needed, where);
        if (swap) swapBytes(volume.bytes(), volume.sampleCount(), scalarTypeSize(header.type));
        return volume;
    }

    const char* codec = compressionName(data.compression);
    requireMemoryFor(header, needed, std::string(codec) + "-compressed");
    if (needed > available * kMaxDeflateRatio + 1024 || data.skip > available * kMaxDeflateRatio + 1024)
        refuse(std::to_string(available) + " " + codec + " bytes in " + holder + " cannot hold that many");

    // First pass: measure the stream without storing it, so that a short, long
    // or corrupt stream is refused before the volume is allocated.
    seekTo(f, data.offset, where);
    {
        Inflater counter(f, data.compression, where);
        const std::uint64_t skipped = counter.skip(data.skip);
        if (skipped < data.skip)
            throw FormatError(where + ": " + codec + " data is truncated: it ends after " + std::to_string(skipped) +
                              " of the " + std::to_string(data.skip) + " header bytes");
        const std::uint64_t held = counter.skip(needed + 1);
        if (held < needed)
            throw FormatError(where + ": " + codec + " data is truncated: it holds " + std::to_string(held) +
                              " of the " + std::to_string(needed) + " bytes field \"" + header.sizeField +
                              "\" describes");
        if (held > needed && !data.trailingBytesAllowed)
            throw FormatError(where + ": " + codec + " data holds more than the " + std::to_string(needed) +
                              " bytes field \"" + header.sizeField + "\" describes");
    }
    Volume volume(header.dims, header.type, header.spacing, header.origin);
    volume.setDirection(header.direction);
    seekTo(f, data.offset, where);
    Inflater reader(f, data.compression, where);
    reader.skip(data.skip);
    if (reader.read(reinterpret_cast<unsigned char*>(volume.bytes()), std::size_t(needed)) != needed)
        throw FormatError(where + ": " + codec + " data changed while it was read");
    if (data.bigEndian != hostIsBigEndian())
        swapBytes(volume.bytes(), volume.sampleCount(), scalarTypeSize(header.type));
    return volume;
}

struct Inflater::State {
    z_stream zs{};
    std::FILE* file = nullptr;
    Compression compression = Compression::Gzip;
    std::string where;
    std::vector<unsigned char> in = std::vector<unsigned char>(kInflateChunk);
    bool ended = false;

    [[noreturn]] void fail(const std::string& problem) const {
        throw FormatError(where + ": " + compressionName(compression) + " data is " + problem);
    }
    // Tops up the input buffer so that at least `want` bytes are available, if the file has them.
    void fill(std::size_t want) {
        if (zs.avail_in >= want) return;
        std::memmove(in.data(), zs.next_in, zs.avail_in);
        const std::size_t got = std::fread(in.data() + zs.avail_in, 1, in.size() - zs.avail_in, file);
        if (got == 0 && std::ferror(file)) throw FormatError(where + ": cannot read: " + std::strerror(errno));
        zs.next_in = in.data();
        zs.avail_in += uInt(got);
    }
    // After one gzip member, another may follow (as `cat a.gz b.gz` makes).
    bool nextMember() {
        fill(2);
        if (zs.avail_in < 2 || zs.next_in[0] != 0x1f || zs.next_in[1] != 0x8b) return false;
        if (inflateReset(&zs) != Z_OK) fail("corrupt: cannot restart the decoder");
        return true;
    }
};

Inflater::Inflater(std::FILE* file, Compression compression, std::string where) : state_(std::make_unique<State>()) {
    State& s = *state_;
    s.file = file;
    s.compression = compression;
    s.where = std::move(where);
    s.zs.next_in = s.in.data();
    const int windowBits = compression == Compression::Gzip ? 16 + MAX_WBITS : 32 + MAX_WBITS;
    if (inflateInit2(&s.zs, windowBits) != Z_OK) throw FormatError(s.where + ": cannot start the decoder");
}

Inflater::~Inflater() { inflateEnd(&state_->zs); }

std::size_t Inflater::read(unsigned char* dst, std::size_t n) {
    State& s = *state_;
    std::size_t produced = 0;
    while (produced < n && !s.ended) {
        if (s.zs.avail_in == 0) {
            s.fill(1);
            if (s.zs.avail_in == 0) s.fail("truncated: the file ends before the stream does");
        }
        const std::size_t chunk = std::min<std::size_t>(n - produced, std::size_t(1) << 30);
        s.zs.next_out = dst + produced;
        s.zs.avail_out = uInt(chunk);
        const uInt inBefore = s.zs.avail_in;
        const int ret = inflate(&s.zs, Z_NO_FLUSH);
        produced += chunk - s.zs.avail_out;
        if (ret == Z_STREAM_END) {
            s.ended = !s.nextMember();
        } else if (ret == Z_BUF_ERROR && s.zs.avail_in == 0) {
            continue;  // needs more input
        } else if (ret != Z_OK || (s.zs.avail_out == chunk && s.zs.avail_in == inBefore)) {
            s.fail(std::string("corrupt: ") + (s.zs.msg ? s.zs.msg : "error " + std::to_string(ret)));
        }
    }
    return produced;
}

std::uint64_t Inflater::skip(std::uint64_t n) {
    std::vector<unsigned char> scratch(std::size_t(std::min<std::uint64_t>(n, kInflateChunk)));
    std::uint64_t done = 0;
    while (done < n) {
        const std::size_t want = std::size_t(std::min<std::uint64_t>(n - done, scratch.size()));
        const std::size_t got = read(scratch.data(), want);
        done += got;
        if (got < want) break;
    }
    return done;
}

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

BufferedOutput::BufferedOutput(const std::string& path) : file_(path) { buf_.reserve(kFlushBytes + 256); }

void BufferedOutput::close() {
    flush();
    file_.commit();
}

void BufferedOutput::flush() {
    file_.write(buf_);
    buf_.clear();
}

void appendU32LE(std::string& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xff);
}

void appendFloatLE(std::string& out, float f) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, 4);
    appendU32LE(out, bits);
}

VolumeReader::VolumeReader(std::string path, std::string sizeField) {
    geometry_.path = std::move(path);
    geometry_.sizeField = std::move(sizeField);
}

void VolumeReader::failFile(const std::string& problem) const { throw FormatError(path() + ": " + problem); }

void VolumeReader::fail(const std::string& field, const std::string& problem) const {
    failFile("field \"" + field + "\": " + problem);
}

const std::string& VolumeReader::required(const std::string* value, const std::string& field) const {
    if (value == nullptr) failFile("missing required field \"" + field + "\"");
    return *value;
}

}  // namespace isotrack::detail
