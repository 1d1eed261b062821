// NRRD volumes (http://teem.sourceforge.net/nrrd/format.html), 3D only.
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "isotrack/errors.h"
#include "isotrack/io.h"

namespace isotrack {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxHeaderBytes = std::size_t(1) << 20;
constexpr std::size_t kIoChunk = std::size_t(1) << 20;
// deflate never expands more than about 1032:1; bounds gzip output by the file size.
constexpr std::uint64_t kMaxDeflateRatio = 1032;

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

FilePtr openFile(const std::string& path, const char* mode) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) throw FormatError(path + ": cannot open: " + std::strerror(EISDIR));
    FilePtr f(std::fopen(path.c_str(), mode));
    if (!f) throw FormatError(path + ": cannot open: " + std::strerror(errno));
    return f;
}

bool hostIsBigEndian() {
    const std::uint16_t probe = 1;
    unsigned char first = 0;
    std::memcpy(&first, &probe, 1);
    return first == 0;
}

void swapBytes(std::byte* data, std::size_t count, std::size_t width) {
    for (std::size_t i = 0; i < count; ++i) std::reverse(data + i * width, data + (i + 1) * width);
}

// Header text goes into one-line messages, so it is trimmed and made printable.
std::string printable(const std::string& s) {
    std::string out;
    for (char c : s.substr(0, 60)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
    if (s.size() > 60) out += "...";
    return out;
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
    if (s.empty()) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end != s.c_str() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

// "(a,b,c) (d,e,f) ..." as NRRD writes vectors; nullopt on anything else, "none" included.
std::optional<std::vector<Vec3d>> parseVectors(const std::string& s) {
    std::vector<Vec3d> vectors;
    std::size_t pos = 0;
    while (true) {
        while (pos < s.size() && std::isspace(static_cast<unsigned char>(s[pos]))) ++pos;
        if (pos == s.size()) break;
        if (s[pos] != '(') return std::nullopt;
        const std::size_t close = s.find(')', pos);
        if (close == std::string::npos) return std::nullopt;
        std::vector<std::string> parts;
        std::istringstream in(s.substr(pos + 1, close - pos - 1));
        for (std::string part; std::getline(in, part, ',');) parts.push_back(joinWords(part));
        if (parts.size() != 3) return std::nullopt;
        Vec3d v{};
        for (std::size_t a = 0; a < 3; ++a) {
            const auto c = parseFinite(parts[a]);
            if (!c) return std::nullopt;
            v[a] = *c;
        }
        vectors.push_back(v);
        pos = close + 1;
    }
    return vectors;
}

struct TypeName {
    const char* name;
    ScalarType type;
};

const TypeName kTypeNames[] = {
    {"uchar", ScalarType::UInt8},        {"unsigned char", ScalarType::UInt8},
    {"uint8", ScalarType::UInt8},        {"uint8_t", ScalarType::UInt8},
    {"signed char", ScalarType::Int8},   {"int8", ScalarType::Int8},
    {"int8_t", ScalarType::Int8},        {"short", ScalarType::Int16},
    {"short int", ScalarType::Int16},    {"signed short", ScalarType::Int16},
    {"signed short int", ScalarType::Int16}, {"int16", ScalarType::Int16},
    {"int16_t", ScalarType::Int16},      {"ushort", ScalarType::UInt16},
    {"unsigned short", ScalarType::UInt16}, {"unsigned short int", ScalarType::UInt16},
    {"uint16", ScalarType::UInt16},      {"uint16_t", ScalarType::UInt16},
    {"int", ScalarType::Int32},          {"signed int", ScalarType::Int32},
    {"int32", ScalarType::Int32},        {"int32_t", ScalarType::Int32},
    {"uint", ScalarType::UInt32},        {"unsigned int", ScalarType::UInt32},
    {"uint32", ScalarType::UInt32},      {"uint32_t", ScalarType::UInt32},
    {"float", ScalarType::Float32},      {"double", ScalarType::Float64},
};

const char* nrrdTypeName(ScalarType type) {
    switch (type) {
        case ScalarType::Float32: return "float";
        case ScalarType::Float64: return "double";
        default: return scalarTypeName(type);
    }
}

struct Header {
    std::map<std::string, std::string> fields;
    std::uint64_t length = 0;  // bytes up to and including the blank line
    bool endsWithBlankLine = false;
};

std::string canonicalField(const std::string& key) {
    if (key == "datafile") return "data file";
    if (key == "lineskip") return "line skip";
    if (key == "byteskip") return "byte skip";
    if (key == "centers") return "centerings";
    return key;
}

// Reads one line without its terminator; false at end of file with nothing read.
bool readLine(std::FILE* f, std::string& line, std::uint64_t& consumed, const std::string& path) {
    line.clear();
    int c = 0;
    while ((c = std::fgetc(f)) != EOF) {
        if (++consumed > kMaxHeaderBytes)
            throw FormatError(path + ": header is longer than " + std::to_string(kMaxHeaderBytes >> 20) +
                              " MiB or lacks the blank line that ends it");
        if (c == '\n') break;
        line += char(c);
    }
    if (c == EOF && std::ferror(f)) throw FormatError(path + ": cannot read: " + std::strerror(errno));
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return c != EOF || !line.empty();
}

Header readHeader(std::FILE* f, const std::string& path) {
    char magic[8] = {};
    const std::size_t got = std::fread(magic, 1, sizeof magic, f);
    const std::string magicText(magic, got);
    if (got != sizeof magic || magicText.compare(0, 7, "NRRD000") != 0 || magic[7] < '1' || magic[7] > '5')
        throw FormatError(path + ": not a NRRD file: expected magic \"NRRD0001\"..\"NRRD0005\", got \"" +
                          printable(magicText) + "\"");
    Header header;
    header.length = sizeof magic;
    std::string line;
    if (!readLine(f, line, header.length, path)) throw FormatError(path + ": header ends right after the magic");
    if (!line.empty())
        throw FormatError(path + ": not a NRRD file: unexpected text after magic: \"" + printable(line) + "\"");
    for (int lineNo = 2; readLine(f, line, header.length, path); ++lineNo) {
        if (line.empty()) {
            header.endsWithBlankLine = true;
            break;
        }
        if (line[0] == '#') continue;
        const std::size_t field = line.find(": ");
        const std::size_t keyValue = line.find(":=");
        if (keyValue != std::string::npos && (field == std::string::npos || keyValue < field)) continue;
        if (field == std::string::npos)
            throw FormatError(path + ": header line " + std::to_string(lineNo) + ": expected \"field: value\", got \"" +
                              printable(line) + "\"");
        const std::string key = canonicalField(line.substr(0, field));
        if (!header.fields.emplace(key, joinWords(line.substr(field + 2))).second)
            throw FormatError(path + ": field \"" + printable(key) + "\" appears twice");
    }
    return header;
}

// Interprets the header and locates the samples, all before anything is allocated.
class NrrdReader {
public:
    NrrdReader(std::string path, Header header) : path_(std::move(path)), header_(std::move(header)) {}

    Volume read(FilePtr headerFile);

private:
    [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
        throw FormatError(path_ + ": field \"" + field + "\": " + problem);
    }
    const std::string* find(const std::string& field) const {
        const auto it = header_.fields.find(field);
        return it == header_.fields.end() ? nullptr : &it->second;
    }
    const std::string& require(const std::string& field) const {
        const std::string* v = find(field);
        if (!v) throw FormatError(path_ + ": missing required field \"" + field + "\"");
        return *v;
    }
    long long skipField(const std::string& field, long long minimum) const;
    void parseGeometry();
    std::uint64_t neededBytes() const;
    void readRaw(std::FILE* f, const std::string& dataPath, std::uint64_t needed, Volume& vol) const;
    void readGzip(std::FILE* f, const std::string& dataPath, std::uint64_t needed, Volume& vol) const;

    std::string path_;
    Header header_;
    ScalarType type_ = ScalarType::UInt8;
    Dims dims_{};
    Vec3d spacing_{1, 1, 1};
    Vec3d origin_{0, 0, 0};
};

long long NrrdReader::skipField(const std::string& field, long long minimum) const {
    const std::string* text = find(field);
    if (!text) return 0;
    const auto v = parseInteger(*text);
    if (!v || *v < minimum) fail(field, "expected an integer >= " + std::to_string(minimum) + ", got \"" +
                                            printable(*text) + "\"");
    return *v;
}

void NrrdReader::parseGeometry() {
    const std::string& dimension = require("dimension");
    if (dimension != "3") fail("dimension", "expected 3, got \"" + printable(dimension) + "\"");

    const std::string& typeText = require("type");
    const auto* t = std::find_if(std::begin(kTypeNames), std::end(kTypeNames),
                                 [&](const TypeName& n) { return typeText == n.name; });
    if (t == std::end(kTypeNames))
        fail("type", "unsupported type \"" + printable(typeText) +
                         "\" (supported: uint8, int8, uint16, int16, uint32, int32, float, double)");
    type_ = t->type;

    const std::string& sizesText = require("sizes");
    const std::vector<std::string> sizes = splitWords(sizesText);
    bool sizesOk = sizes.size() == 3;
    for (std::size_t a = 0; sizesOk && a < 3; ++a) {
        const auto v = parseInteger(sizes[a]);
        sizesOk = v && *v > 0 && *v <= INT_MAX;
        if (sizesOk) dims_[a] = int(*v);
    }
    if (!sizesOk) fail("sizes", "expected 3 positive integers, got \"" + printable(sizesText) + "\"");

    if (const std::string* dirs = find("space directions")) {
        const auto vectors = parseVectors(*dirs);
        if (!vectors || vectors->size() != 3)
            fail("space directions", "expected 3 vectors like (1,0,0), got \"" + printable(*dirs) + "\"");
        // Only the lengths survive: Volume is axis-aligned.
        for (std::size_t a = 0; a < 3; ++a) {
            const Vec3d& v = (*vectors)[a];
            spacing_[a] = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        }
        if (std::any_of(spacing_.begin(), spacing_.end(), [](double s) { return !(s > 0) || !std::isfinite(s); }))
            fail("space directions", "expected 3 non-zero vectors, got \"" + printable(*dirs) + "\"");
    } else if (const std::string* spacings = find("spacings")) {
        const std::vector<std::string> words = splitWords(*spacings);
        bool ok = words.size() == 3;
        for (std::size_t a = 0; ok && a < 3; ++a) {
            const auto v = parseFinite(words[a]);
            ok = v && *v > 0;
            if (ok) spacing_[a] = *v;
        }
        if (!ok) fail("spacings", "expected 3 positive numbers, got \"" + printable(*spacings) + "\"");
    }

    if (const std::string* originText = find("space origin")) {
        const auto vectors = parseVectors(*originText);
        if (!vectors || vectors->size() != 1)
            fail("space origin", "expected one vector like (0,0,0), got \"" + printable(*originText) + "\"");
        origin_ = vectors->front();
    }
}

std::uint64_t NrrdReader::neededBytes() const {
    // Step by step so hostile sizes cannot overflow the product.
    const std::uint64_t maxSamples = kMaxVolumeBytes / scalarTypeSize(type_);
    const auto nx = std::uint64_t(dims_[0]), ny = std::uint64_t(dims_[1]), nz = std::uint64_t(dims_[2]);
    if (nx > maxSamples || ny > maxSamples / nx || nz > maxSamples / (nx * ny))
        fail("sizes", std::to_string(nx) + " x " + std::to_string(ny) + " x " + std::to_string(nz) + " " +
                          nrrdTypeName(type_) + " samples exceed the " + std::to_string(kMaxVolumeBytes >> 30) +
                          " GiB volume limit");
    return nx * ny * nz * scalarTypeSize(type_);
}

Volume NrrdReader::read(FilePtr headerFile) {
    parseGeometry();
    const std::string encoding = require("encoding");
    const bool gzip = encoding == "gzip" || encoding == "gz";
    if (!gzip && encoding != "raw")
        fail("encoding", "unsupported encoding \"" + printable(encoding) + "\" (supported: raw, gzip)");

    bool swap = false;
    if (const std::string* endian = find("endian")) {
        if (*endian != "little" && *endian != "big")
            fail("endian", "expected \"little\" or \"big\", got \"" + printable(*endian) + "\"");
        swap = (*endian == "big") != hostIsBigEndian();
    } else if (scalarTypeSize(type_) > 1) {
        throw FormatError(path_ + ": missing required field \"endian\" for type " + nrrdTypeName(type_));
    }
    const long long lineSkip = skipField("line skip", 0);
    const long long byteSkip = skipField("byte skip", -1);
    if (gzip && byteSkip != 0) fail("byte skip", "only supported with raw encoding, got " + std::to_string(byteSkip));

    // Samples follow the header unless a "data file" names where they are.
    FilePtr dataFile = std::move(headerFile);
    std::string dataPath = path_;
    std::uint64_t offset = header_.length;
    if (const std::string* name = find("data file")) {
        if (*name == "LIST" || name->find('%') != std::string::npos)
            fail("data file", "multi-file data is not supported, got \"" + printable(*name) + "\"");
        const fs::path p(*name);
        dataPath = (p.is_absolute() ? p : fs::path(path_).parent_path() / p).string();
        dataFile = openFile(dataPath, "rb");
        offset = 0;
    } else if (!header_.endsWithBlankLine) {
        throw FormatError(path_ + ": header ends without a blank line and no \"data file\" field");
    }
    std::error_code ec;
    const std::uint64_t fileSize = fs::file_size(dataPath, ec);
    if (ec) throw FormatError(dataPath + ": cannot read: " + ec.message());

    std::FILE* f = dataFile.get();
    if (std::fseek(f, long(offset), SEEK_SET) != 0) throw FormatError(dataPath + ": cannot seek: " + std::strerror(errno));
    for (long long i = 0; i < lineSkip; ++i) {
        int c = 0;
        while ((c = std::fgetc(f)) != EOF && c != '\n') ++offset;
        if (c == EOF) fail("line skip", std::to_string(lineSkip) + " lines run past the end of " + dataPath);
        ++offset;
    }
    const std::uint64_t needed = neededBytes();
    const std::string shape = std::to_string(dims_[0]) + " x " + std::to_string(dims_[1]) + " x " +
                              std::to_string(dims_[2]) + " " + nrrdTypeName(type_);
    if (byteSkip == -1)
        offset = fileSize >= needed ? std::max(offset, fileSize - needed) : offset;
    else
        offset += std::uint64_t(byteSkip);
    const std::uint64_t available = fileSize > offset ? fileSize - offset : 0;
    if (!gzip && available < needed)
        fail("sizes", shape + " needs " + std::to_string(needed) + " data bytes but " + dataPath + " has only " +
                          std::to_string(available) + " (truncated?)");
    if (gzip && needed > available * kMaxDeflateRatio + 1024)
        fail("sizes", shape + " needs " + std::to_string(needed) + " bytes, more than " + std::to_string(available) +
                          " gzip bytes in " + dataPath + " can hold");
    if (std::fseek(f, long(offset), SEEK_SET) != 0) throw FormatError(dataPath + ": cannot seek: " + std::strerror(errno));

    Volume vol(dims_, type_, spacing_, origin_);
    if (gzip)
        readGzip(f, dataPath, needed, vol);
    else
        readRaw(f, dataPath, needed, vol);
    if (swap) swapBytes(vol.bytes(), vol.sampleCount(), scalarTypeSize(type_));
    return vol;
}

void NrrdReader::readRaw(std::FILE* f, const std::string& dataPath, std::uint64_t needed, Volume& vol) const {
    for (std::uint64_t done = 0; done < needed;) {
        const std::size_t chunk = std::size_t(std::min<std::uint64_t>(needed - done, kIoChunk));
        const std::size_t got = std::fread(vol.bytes() + done, 1, chunk, f);
        if (got != chunk) {
            if (std::ferror(f)) throw FormatError(dataPath + ": cannot read: " + std::strerror(errno));
            throw FormatError(dataPath + ": data is truncated: got " + std::to_string(done + got) + " of " +
                              std::to_string(needed) + " bytes");
        }
        done += got;
    }
}

void NrrdReader::readGzip(std::FILE* f, const std::string& dataPath, std::uint64_t needed, Volume& vol) const {
    z_stream zs{};
    if (inflateInit2(&zs, 16 + MAX_WBITS) != Z_OK) throw FormatError(dataPath + ": cannot start gzip decoder");
    const std::unique_ptr<z_stream, int (*)(z_stream*)> guard(&zs, inflateEnd);
    std::vector<unsigned char> in(kIoChunk);
    unsigned char probe = 0;
    bool probing = false, ended = false;
    std::uint64_t produced = 0;
    while (!ended) {
        if (zs.avail_out == 0) {
            // Full: one more byte of output would mean the stream holds more than "sizes" says.
            probing = produced == needed;
            const std::uint64_t chunk = probing ? 1 : std::min<std::uint64_t>(needed - produced, std::uint64_t(1) << 30);
            zs.next_out = probing ? &probe : reinterpret_cast<unsigned char*>(vol.bytes()) + produced;
            zs.avail_out = uInt(chunk);
        }
        if (zs.avail_in == 0) {
            const std::size_t got = std::fread(in.data(), 1, in.size(), f);
            if (got == 0) {
                if (std::ferror(f)) throw FormatError(dataPath + ": cannot read: " + std::strerror(errno));
                break;
            }
            zs.next_in = in.data();
            zs.avail_in = uInt(got);
        }
        const uInt before = zs.avail_out;
        const int ret = inflate(&zs, Z_NO_FLUSH);
        if (probing && zs.avail_out == 0)
            throw FormatError(dataPath + ": gzip data holds more than the " + std::to_string(needed) +
                              " bytes field \"sizes\" describes");
        if (!probing) produced += before - zs.avail_out;
        if (ret == Z_STREAM_END) {
            ended = true;
        } else if (ret != Z_OK && !(ret == Z_BUF_ERROR && zs.avail_in == 0)) {
            throw FormatError(dataPath + ": gzip data is corrupt: " + (zs.msg ? zs.msg : "error " + std::to_string(ret)));
        }
    }
    if (produced < needed)
        throw FormatError(dataPath + ": gzip data is truncated: got " + std::to_string(produced) + " of " +
                          std::to_string(needed) + " bytes");
    if (!ended) throw FormatError(dataPath + ": gzip data is truncated: stream has no end");
}

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

}  // namespace

Volume loadNrrd(const std::string& path) {
    FilePtr f = openFile(path, "rb");
    Header header = readHeader(f.get(), path);
    return NrrdReader(path, std::move(header)).read(std::move(f));
}

void writeNrrd(const Volume& volume, const std::string& path) {
    if (volume.byteSize() == 0) throw InputError(path + ": cannot write an empty volume");
    FilePtr f = openFile(path, "wb");
    char buf[256];
    std::string header = "NRRD0004\n# written by isotrack\n";
    header += std::string("type: ") + nrrdTypeName(volume.type()) + "\ndimension: 3\nspace dimension: 3\n";
    header += "sizes: " + std::to_string(volume.dims()[0]) + " " + std::to_string(volume.dims()[1]) + " " +
              std::to_string(volume.dims()[2]) + "\n";
    const Vec3d& s = volume.spacing();
    const Vec3d& o = volume.origin();
    // %.17g so spacing and origin read back bit-exact.
    std::snprintf(buf, sizeof buf, "space directions: (%.17g,0,0) (0,%.17g,0) (0,0,%.17g)\n", s[0], s[1], s[2]);
    header += buf;
    std::snprintf(buf, sizeof buf, "space origin: (%.17g,%.17g,%.17g)\n", o[0], o[1], o[2]);
    header += buf;
    header += "endian: little\nencoding: raw\n\n";
    bool ok = std::fwrite(header.data(), 1, header.size(), f.get()) == header.size();

    const std::size_t width = scalarTypeSize(volume.type());
    const bool swap = hostIsBigEndian() && width > 1;
    std::vector<std::byte> chunk;
    for (std::size_t done = 0; ok && done < volume.byteSize();) {
        const std::size_t n = std::min(volume.byteSize() - done, kIoChunk);
        const std::byte* src = volume.bytes() + done;
        if (swap) {
            chunk.assign(src, src + n);
            swapBytes(chunk.data(), n / width, width);
            src = chunk.data();
        }
        ok = std::fwrite(src, 1, n, f.get()) == n;
        done += n;
    }
    if (!ok || std::fclose(f.release()) != 0) throw FormatError(path + ": cannot write: " + std::strerror(errno));
}

Volume loadVolume(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".nrrd" || ext == ".nhdr") return loadNrrd(path);
    throw FormatError(path + ": unsupported volume file extension \"" + printable(ext) +
                      "\" (supported: .nrrd, .nhdr)");
}

}  // namespace isotrack
