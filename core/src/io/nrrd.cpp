// NRRD volumes (http://teem.sourceforge.net/nrrd/format.html), 3D only.
#include <algorithm>
#include <cctype>
#include <cerrno>
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

#include "io_common.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/orientation.h"

namespace isotrack {

namespace {

namespace fs = std::filesystem;
using namespace detail;

constexpr std::size_t kMaxHeaderBytes = std::size_t(1) << 20;
constexpr std::size_t kIoChunk = std::size_t(1) << 20;

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
    {"uchar", ScalarType::UInt8},
    {"unsigned char", ScalarType::UInt8},
    {"uint8", ScalarType::UInt8},
    {"uint8_t", ScalarType::UInt8},
    {"signed char", ScalarType::Int8},
    {"int8", ScalarType::Int8},
    {"int8_t", ScalarType::Int8},
    {"short", ScalarType::Int16},
    {"short int", ScalarType::Int16},
    {"signed short", ScalarType::Int16},
    {"signed short int", ScalarType::Int16},
    {"int16", ScalarType::Int16},
    {"int16_t", ScalarType::Int16},
    {"ushort", ScalarType::UInt16},
    {"unsigned short", ScalarType::UInt16},
    {"unsigned short int", ScalarType::UInt16},
    {"uint16", ScalarType::UInt16},
    {"uint16_t", ScalarType::UInt16},
    {"int", ScalarType::Int32},
    {"signed int", ScalarType::Int32},
    {"int32", ScalarType::Int32},
    {"int32_t", ScalarType::Int32},
    {"uint", ScalarType::UInt32},
    {"unsigned int", ScalarType::UInt32},
    {"uint32", ScalarType::UInt32},
    {"uint32_t", ScalarType::UInt32},
    {"float", ScalarType::Float32},
    {"double", ScalarType::Float64},
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

// Interprets the header and locates the samples; readSamples checks the sizes.
class NrrdReader : public VolumeReader {
public:
    NrrdReader(std::string path, Header header) : VolumeReader(std::move(path), "sizes"), header_(std::move(header)) {}

    Volume read(std::FILE* headerFile, std::size_t step);
    // The fourth axis's size for "dimension: 4", else 1.
    std::size_t steps() {
        parseGeometry();
        return steps_;
    }

private:
    const std::string* find(const std::string& field) const {
        const auto it = header_.fields.find(field);
        return it == header_.fields.end() ? nullptr : &it->second;
    }
    const std::string& require(const std::string& field) const { return required(find(field), field); }
    long long skipField(const std::string& field, long long minimum) const;
    void parseSpace();
    void parseGeometry();
    Vec3d toLps(const Vec3d& v) const { return {v[0] * toLps_[0], v[1] * toLps_[1], v[2] * toLps_[2]}; }
    Mat3d toLps(const Mat3d& m) const { return {toLps(m[0]), toLps(m[1]), toLps(m[2])}; }
    std::uint64_t skipLines(long long lines, const SampleData& data, std::FILE* headerFile) const;

    void parseTimeAxis(std::vector<std::string>& sizeWords);

    Header header_;
    Vec3d toLps_{1, 1, 1};  // signs that take "space" to LPS
    std::size_t steps_ = 1;
    bool parsed_ = false;
};

// "dimension: 4": the last axis is time (kinds, when given, say so: time, list or
// domain, and the first three domain or space); its entry of "space directions"
// is "none", of "spacings" anything. Removes it from `sizeWords`.
void NrrdReader::parseTimeAxis(std::vector<std::string>& sizeWords) {
    const auto steps = sizeWords.size() == 4 ? parseInteger(sizeWords[3]) : std::nullopt;
    if (!steps || *steps < 1 || *steps > (1LL << 31))
        fail("sizes", "expected 4 positive integers for dimension 4, got \"" + printable(*find("sizes")) + "\"");
    steps_ = std::size_t(*steps);
    sizeWords.pop_back();
    if (const std::string* kinds = find("kinds")) {
        const std::vector<std::string> words = splitWords(lowerCase(*kinds));
        bool ok = words.size() == 4 && (words[3] == "time" || words[3] == "list" || words[3] == "domain");
        for (std::size_t a = 0; ok && a < 3; ++a) ok = words[a] == "domain" || words[a] == "space";
        if (!ok)
            fail("kinds",
                 "a 4D volume needs three space axes and time last (e.g. \"domain domain domain time\"), got \"" +
                     printable(*kinds) + "\"");
    }
    if (auto it = header_.fields.find("space directions"); it != header_.fields.end()) {
        const std::size_t none = it->second.rfind("none");
        if (none == std::string::npos || joinWords(it->second.substr(none)) != "none")
            fail("space directions", "the time axis's entry must be \"none\", got \"" + printable(it->second) + "\"");
        it->second.erase(none);
    }
    if (auto it = header_.fields.find("spacings"); it != header_.fields.end()) {
        std::vector<std::string> words = splitWords(it->second);
        if (words.size() == 4) words.pop_back();
        std::string text;
        for (const std::string& w : words) text += (text.empty() ? "" : " ") + w;
        it->second = text;
    }
}

// The anatomical spaces isotrack knows; others (scanner-xyz, 3D-right-handed...)
// and no "space" at all are taken as given.
void NrrdReader::parseSpace() {
    const std::string* space = find("space");
    if (!space) return;
    const std::string name = lowerCase(*space);
    if (name == "right-anterior-superior" || name == "ras") {
        toLps_ = {-1, -1, 1};
    } else if (name == "left-anterior-superior" || name == "las") {
        toLps_ = {1, -1, 1};
    } else if (name.find("time") != std::string::npos) {
        fail("space", "\"" + printable(*space) + "\" has a time axis; only 3D spaces are supported");
    }
}

long long NrrdReader::skipField(const std::string& field, long long minimum) const {
    const std::string* text = find(field);
    if (!text) return 0;
    const auto v = parseInteger(*text);
    if (!v || *v < minimum)
        fail(field, "expected an integer >= " + std::to_string(minimum) + ", got \"" + printable(*text) + "\"");
    return *v;
}

void NrrdReader::parseGeometry() {
    parseSpace();
    if (parsed_) return;
    parsed_ = true;
    const std::string& dimension = require("dimension");
    if (dimension != "3" && dimension != "4")
        fail("dimension", "expected 3 (or 4, time last), got \"" + printable(dimension) + "\"");

    const std::string& typeText = require("type");
    const auto* t = std::find_if(std::begin(kTypeNames), std::end(kTypeNames),
                                 [&](const TypeName& n) { return typeText == n.name; });
    if (t == std::end(kTypeNames))
        fail("type", "unsupported type \"" + printable(typeText) +
                         "\" (supported: uint8, int8, uint16, int16, uint32, int32, float, double)");
    geometry_.type = t->type;

    const std::string& sizesText = require("sizes");
    std::vector<std::string> sizeWords = splitWords(sizesText);
    if (dimension == "4") parseTimeAxis(sizeWords);
    const auto sizes = parseDims(sizeWords);
    if (!sizes) fail("sizes", "expected 3 positive integers, got \"" + printable(sizesText) + "\"");
    geometry_.dims = *sizes;

    Vec3d& spacing = geometry_.spacing;
    if (const std::string* dirs = find("space directions")) {
        const auto vectors = parseVectors(*dirs);
        if (!vectors || vectors->size() != 3)
            fail("space directions", "expected 3 vectors like (1,0,0), got \"" + printable(*dirs) + "\"");
        const auto direction = directionFromAxes({(*vectors)[0], (*vectors)[1], (*vectors)[2]}, &spacing);
        if (!direction)
            fail("space directions", "expected 3 non-zero, orthogonal vectors, got \"" + printable(*dirs) + "\"");
        geometry_.direction = toLps(*direction);
    } else if (const std::string* spacings = find("spacings")) {
        const auto parsed = parseVec3(splitWords(*spacings), true);
        if (!parsed) fail("spacings", "expected 3 positive numbers, got \"" + printable(*spacings) + "\"");
        spacing = *parsed;
    }

    if (const std::string* originText = find("space origin")) {
        const auto vectors = parseVectors(*originText);
        if (!vectors || vectors->size() != 1)
            fail("space origin", "expected one vector like (0,0,0), got \"" + printable(*originText) + "\"");
        geometry_.origin = toLps(vectors->front());
    }
    checkGeometry(geometry_, find("space directions") ? "space directions" : "spacings", "space origin");
}

// "line skip" counts lines of the data file, so the data has to be read to find them.
std::uint64_t NrrdReader::skipLines(long long lines, const SampleData& data, std::FILE* headerFile) const {
    FilePtr detached;
    std::FILE* f = headerFile;
    if (data.path != path()) {
        detached = openForReading(data.path, dataWhere(geometry_, data));
        f = detached.get();
    }
    std::uint64_t offset = data.offset;
    if (std::fseek(f, long(offset), SEEK_SET) != 0) failFile(std::string("cannot seek: ") + std::strerror(errno));
    for (long long i = 0; i < lines; ++i) {
        int c = 0;
        while ((c = std::fgetc(f)) != EOF && c != '\n') ++offset;
        if (c == EOF) fail("line skip", std::to_string(lines) + " lines run past the end of the data");
        ++offset;
    }
    return offset;
}

Volume NrrdReader::read(std::FILE* headerFile, std::size_t step) {
    parseGeometry();
    if (step >= steps_)
        fail("sizes", "no time step " + std::to_string(step) + ": the file has " + std::to_string(steps_) +
                          (steps_ == 1 ? " step (0)" : " steps (0.." + std::to_string(steps_ - 1) + ")"));
    const std::uint64_t stepBytes = sampleBytes(geometry_);
    if (std::uint64_t(steps_) > kMaxVolumeBytes / stepBytes) fail("sizes", "the time steps exceed the volume limit");
    const std::string encoding = require("encoding");
    const bool gzip = encoding == "gzip" || encoding == "gz";
    if (!gzip && encoding != "raw")
        fail("encoding", "unsupported encoding \"" + printable(encoding) + "\" (supported: raw, gzip)");

    SampleData data;
    data.compression = gzip ? Compression::Gzip : Compression::None;
    if (const std::string* endian = find("endian")) {
        if (*endian != "little" && *endian != "big")
            fail("endian", "expected \"little\" or \"big\", got \"" + printable(*endian) + "\"");
        data.bigEndian = *endian == "big";
    } else if (scalarTypeSize(geometry_.type) > 1) {
        failFile(std::string("missing required field \"endian\" for type ") + nrrdTypeName(geometry_.type));
    } else {
        data.bigEndian = hostIsBigEndian();
    }
    const long long lineSkip = skipField("line skip", 0);
    const long long byteSkip = skipField("byte skip", -1);
    if (gzip && byteSkip < 0) fail("byte skip", "-1 (data at the end) needs raw encoding");

    // Samples follow the header unless a "data file" names where they are.
    data.path = path();
    data.offset = header_.length;
    if (const std::string* name = find("data file")) {
        if (*name == "LIST" || name->find('%') != std::string::npos)
            fail("data file", "multi-file data is not supported, got \"" + printable(*name) + "\"");
        const fs::path p(*name);
        data.path = (p.is_absolute() ? p : fs::path(path()).parent_path() / p).string();
        data.offset = 0;
    } else if (!header_.endsWithBlankLine) {
        failFile("header ends without a blank line and no \"data file\" field");
    }
    if (lineSkip > 0) data.offset = skipLines(lineSkip, data, headerFile);
    if (byteSkip == -1) {
        // The samples are the last bytes of the file.
        const std::uint64_t size = fileSizeOf(data.path, dataWhere(geometry_, data));
        const std::uint64_t needed = stepBytes * steps_;
        if (size >= needed) data.offset = std::max(data.offset, size - needed);
    } else if (gzip) {
        data.skip = std::uint64_t(byteSkip);  // counts decompressed bytes
    } else {
        data.offset += std::uint64_t(byteSkip);
    }
    // Step t follows t whole volumes.
    if (gzip)
        data.skip += step * stepBytes;
    else
        data.offset += step * stepBytes;
    // Raw data may be followed by anything; a gzip stream must hold the samples exactly (its last step).
    data.trailingBytesAllowed = !gzip || step + 1 < steps_;
    return readVolume(data);
}

}  // namespace

Volume loadNrrd(const std::string& path, std::size_t step) {
    FilePtr f = openForReading(path);
    Header header = readHeader(f.get(), path);
    return NrrdReader(path, std::move(header)).read(f.get(), step);
}

std::size_t nrrdSteps(const std::string& path) {
    FilePtr f = openForReading(path);
    Header header = readHeader(f.get(), path);
    return NrrdReader(path, std::move(header)).steps();
}

void writeNrrd(const Volume& volume, const std::string& path) {
    if (volume.byteSize() == 0) throw InputError(path + ": cannot write an empty volume");
    SafeWriter f(path);
    char buf[256];
    std::string header = "NRRD0004\n# written by isotrack\n";
    // An axis-aligned volume keeps the header it always had; a turned one says its space.
    const bool aligned = isIdentity(volume.direction());
    header += std::string("type: ") + nrrdTypeName(volume.type()) + "\ndimension: 3\n" +
              (aligned ? "space dimension: 3\n" : "space: left-posterior-superior\n");
    header += "sizes: " + std::to_string(volume.dims()[0]) + " " + std::to_string(volume.dims()[1]) + " " +
              std::to_string(volume.dims()[2]) + "\n";
    const Vec3d& s = volume.spacing();
    const Vec3d& o = volume.origin();
    // %.17g so spacing and origin read back bit-exact.
    if (aligned) {
        std::snprintf(buf, sizeof buf, "space directions: (%.17g,0,0) (0,%.17g,0) (0,0,%.17g)\n", s[0], s[1], s[2]);
        header += buf;
    } else {
        header += "space directions:";
        for (std::size_t a = 0; a < 3; ++a) {
            const Vec3d& d = volume.direction()[a];
            std::snprintf(buf, sizeof buf, " (%.17g,%.17g,%.17g)", s[a] * d[0], s[a] * d[1], s[a] * d[2]);
            header += buf;
        }
        header += "\n";
    }
    std::snprintf(buf, sizeof buf, "space origin: (%.17g,%.17g,%.17g)\n", o[0], o[1], o[2]);
    header += buf;
    header += "endian: little\nencoding: raw\n\n";
    // The samples start at a multiple of 8 bytes (the comment line padded), so
    // a reader maps them aligned for their type (io_common.cpp reads
    // unaligned samples into memory instead).
    const std::size_t comment = std::string("NRRD0004\n# written by isotrack").size();
    header.insert(comment, (8 - header.size() % 8) % 8, ' ');
    f.write(header);

    const std::size_t width = scalarTypeSize(volume.type());
    const bool swap = hostIsBigEndian() && width > 1;
    std::vector<std::byte> chunk;
    for (std::size_t done = 0; done < volume.byteSize();) {
        const std::size_t n = std::min(volume.byteSize() - done, kIoChunk);
        const std::byte* src = volume.bytes() + done;
        if (swap) {
            chunk.assign(src, src + n);
            swapBytes(chunk.data(), n / width, width);
            src = chunk.data();
        }
        f.write(src, n);
        done += n;
    }
    f.commit();
}

}  // namespace isotrack
