// MetaImage volumes (ITK's MetaIO: https://itk.org/Wiki/ITK/MetaIO/Documentation).
//
// A text header of "Key = Value" lines ending with ElementDataFile, which names
// the data file (relative to the header) or says LOCAL: the data follows the
// header in the same file, as .mha files have it.
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
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

constexpr std::uint64_t kMaxHeaderBytes = std::uint64_t(1) << 20;

const std::pair<const char*, ScalarType> kElementTypes[] = {
    {"MET_UCHAR", ScalarType::UInt8},   {"MET_CHAR", ScalarType::Int8},      {"MET_USHORT", ScalarType::UInt16},
    {"MET_SHORT", ScalarType::Int16},   {"MET_UINT", ScalarType::UInt32},    {"MET_INT", ScalarType::Int32},
    {"MET_FLOAT", ScalarType::Float32}, {"MET_DOUBLE", ScalarType::Float64},
};

struct Header {
    std::map<std::string, std::pair<std::string, std::string>> fields;  // lower-case key -> (key, value)
    std::uint64_t length = 0;                                           // bytes up to the data
};

Header readHeader(std::FILE* f, const std::string& path) {
    Header header;
    std::string line;
    for (int lineNo = 1;; ++lineNo) {
        line.clear();
        int c = 0;
        while ((c = std::fgetc(f)) != EOF && c != '\n') {
            if (++header.length > kMaxHeaderBytes)
                throw FormatError(path +
                                  ": header is longer than 1 MiB or lacks the ElementDataFile line that ends it");
            line += char(c);
        }
        if (c == EOF && std::ferror(f)) throw FormatError(path + ": cannot read: " + std::strerror(errno));
        if (c == '\n') ++header.length;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (c == EOF && line.empty()) throw FormatError(path + ": header ends without an ElementDataFile line");
        if (joinWords(line).empty()) continue;
        const std::size_t eq = line.find('=');
        if (eq == std::string::npos)
            throw FormatError(path + ": header line " + std::to_string(lineNo) + ": expected \"Key = Value\", got \"" +
                              printable(line) + "\"");
        const std::string key = joinWords(line.substr(0, eq));
        const std::string value = joinWords(line.substr(eq + 1));
        if (lineNo == 1 && lowerCase(key) != "objecttype" && lowerCase(key) != "ndims")
            throw FormatError(path + ": not a MetaImage header: it starts with \"" + printable(key) +
                              "\", not ObjectType or NDims");
        if (!header.fields.emplace(lowerCase(key), std::make_pair(key, value)).second)
            throw FormatError(path + ": field \"" + printable(key) + "\" appears twice");
        if (lowerCase(key) == "elementdatafile") return header;
        if (c == EOF) throw FormatError(path + ": header ends without an ElementDataFile line");
    }
}

class MetaImageReader : public VolumeReader {
public:
    MetaImageReader(std::string path, Header header)
        : VolumeReader(std::move(path), "DimSize"), header_(std::move(header)) {}
    Volume read();

private:
    const std::string* find(const std::string& field) const {
        const auto it = header_.fields.find(lowerCase(field));
        return it == header_.fields.end() ? nullptr : &it->second.second;
    }
    const std::string& require(const std::string& field) const { return required(find(field), field); }
    bool flag(const std::string& field, bool otherwise) const;
    Vec3d numbers(const std::string& field, Vec3d otherwise, bool positive) const;
    void parseGeometry();
    void parseDirection();
    SampleData locateData() const;

    Header header_;
};

bool MetaImageReader::flag(const std::string& field, bool otherwise) const {
    const std::string* text = find(field);
    if (!text) return otherwise;
    const std::string v = lowerCase(*text);
    if (v == "true" || v == "1") return true;
    if (v == "false" || v == "0") return false;
    fail(field, "expected True or False, got \"" + printable(*text) + "\"");
}

Vec3d MetaImageReader::numbers(const std::string& field, Vec3d otherwise, bool positive) const {
    const std::string* text = find(field);
    if (!text) return otherwise;
    const auto out = parseVec3(splitWords(*text), positive);
    if (!out)
        fail(field,
             std::string("expected 3 ") + (positive ? "positive " : "") + "numbers, got \"" + printable(*text) + "\"");
    return *out;
}

void MetaImageReader::parseGeometry() {
    if (const std::string* objectType = find("ObjectType"); objectType && lowerCase(*objectType) != "image")
        fail("ObjectType", "expected Image, got \"" + printable(*objectType) + "\"");
    const std::string& ndims = require("NDims");
    if (ndims != "3") fail("NDims", "expected 3, got \"" + printable(ndims) + "\"");

    const std::string& sizesText = require("DimSize");
    const auto sizes = parseDims(splitWords(sizesText));
    if (!sizes) fail("DimSize", "expected 3 positive integers, got \"" + printable(sizesText) + "\"");
    geometry_.dims = *sizes;

    const std::string& typeText = require("ElementType");
    bool typeOk = false;
    for (const auto& [name, type] : kElementTypes)
        if (typeText == name) geometry_.type = type, typeOk = true;
    if (!typeOk)
        fail("ElementType", "unsupported type \"" + printable(typeText) +
                                "\" (supported: MET_UCHAR, MET_CHAR, MET_SHORT, MET_USHORT, MET_INT, MET_UINT, "
                                "MET_FLOAT, MET_DOUBLE)");
    if (const std::string* channels = find("ElementNumberOfChannels"); channels && *channels != "1")
        fail("ElementNumberOfChannels", "expected 1, got \"" + printable(*channels) + "\"");

    const std::string spacingField = find("ElementSpacing") || !find("ElementSize") ? "ElementSpacing" : "ElementSize";
    geometry_.spacing = numbers(spacingField, {1, 1, 1}, true);
    std::string originField = "Offset";
    for (const char* name : {"Offset", "Origin", "Position"})
        if (find(name)) originField = name;
    geometry_.origin = numbers(originField, {0, 0, 0}, false);
    parseDirection();
    checkGeometry(geometry_, spacingField, originField);
}

// TransformMatrix (or its older names) lists each index axis's LPS vector in
// turn, as ITK writes it; without one, AnatomicalOrientation's letters name the
// side each axis comes from (ITK's "RAI" is the identity).
void MetaImageReader::parseDirection() {
    for (const char* field : {"TransformMatrix", "Rotation", "Orientation"}) {
        const std::string* text = find(field);
        if (!text) continue;
        const std::vector<std::string> words = splitWords(*text);
        Mat3d axes{};
        bool ok = words.size() == 9;
        for (std::size_t k = 0; ok && k < 9; ++k) {
            const auto v = parseFinite(words[k]);
            ok = v.has_value();
            if (ok) axes[k / 3][k % 3] = *v;
        }
        const auto direction = ok ? directionFromAxes(axes) : std::nullopt;
        if (!direction)
            fail(field, "expected 9 numbers making 3 orthogonal unit vectors, got \"" + printable(*text) + "\"");
        geometry_.direction = *direction;
        return;
    }
    const std::string* code = find("AnatomicalOrientation");
    if (!code || lowerCase(*code) == "?" || code->empty()) return;
    // The LPS axis and sign of each letter, pointing away from that side.
    Mat3d direction{};
    bool used[3] = {false, false, false};
    bool ok = code->size() == 3;
    for (std::size_t a = 0; ok && a < 3; ++a) {
        const char letter = char(std::toupper(static_cast<unsigned char>((*code)[a])));
        const char* from = "RAILPS";
        const char* at = std::strchr(from, letter);
        ok = letter != '\0' && at != nullptr;
        if (!ok) break;
        const auto k = std::size_t(at - from);
        const std::size_t axis = k % 3;
        ok = !used[axis];
        used[axis] = true;
        direction[a] = {0, 0, 0};
        direction[a][axis] = k < 3 ? 1.0 : -1.0;
    }
    if (!ok)
        fail("AnatomicalOrientation",
             "expected three letters, one from each of R/L, A/P, I/S, got \"" + printable(*code) + "\"");
    geometry_.direction = direction;
}

SampleData MetaImageReader::locateData() const {
    SampleData data;
    if (!flag("BinaryData", true)) fail("BinaryData", "ASCII MetaImage data is not supported");
    const bool msb =
        find("BinaryDataByteOrderMSB") ? flag("BinaryDataByteOrderMSB", false) : flag("ElementByteOrderMSB", false);
    data.bigEndian = msb;
    data.compression = flag("CompressedData", false) ? Compression::Zlib : Compression::None;

    const std::string& name = require("ElementDataFile");
    if (name == "LOCAL" || name == "Local" || name == "local") {
        data.path = path();
        data.offset = header_.length;
    } else if (name == "LIST" || name.find('%') != std::string::npos || splitWords(name).size() > 1) {
        fail("ElementDataFile", "multi-file data is not supported, got \"" + printable(name) + "\"");
    } else {
        const fs::path p(name);
        data.path = (p.is_absolute() ? p : fs::path(path()).parent_path() / p).string();
    }

    if (const std::string* headerSize = find("HeaderSize")) {
        const auto skip = parseInteger(*headerSize);
        if (!skip || *skip < -1)
            fail("HeaderSize", "expected an integer >= -1, got \"" + printable(*headerSize) + "\"");
        if (data.compression != Compression::None && *skip != 0)
            fail("HeaderSize", "only supported for uncompressed data, got " + *headerSize);
        if (*skip == -1) {
            // The samples are the last bytes of the file.
            const std::uint64_t size = fileSizeOf(data.path, dataWhere(geometry_, data));
            const std::uint64_t needed = sampleBytes(geometry_);
            data.offset = size >= needed ? std::max(data.offset, size - needed) : data.offset;
        } else {
            data.offset += std::uint64_t(*skip);
        }
    }
    if (const std::string* compressedSize = find("CompressedDataSize");
        compressedSize && data.compression != Compression::None) {
        const auto n = parseInteger(*compressedSize);
        if (!n || *n < 1)
            fail("CompressedDataSize", "expected a positive integer, got \"" + printable(*compressedSize) + "\"");
        const std::uint64_t size = fileSizeOf(data.path, dataWhere(geometry_, data));
        const std::uint64_t available = size > data.offset ? size - data.offset : 0;
        if (std::uint64_t(*n) != available)
            fail("CompressedDataSize",
                 *compressedSize + " disagrees with the " + std::to_string(available) + " bytes of " +
                     (data.path == path() ? "data in the file" : "\"" + printable(data.path, 200) + "\""));
    }
    return data;
}

Volume MetaImageReader::read() {
    parseGeometry();
    return readVolume(locateData());
}

}  // namespace

Volume loadMetaImage(const std::string& path) {
    Header header;
    {
        FilePtr f = openForReading(path);
        header = readHeader(f.get(), path);
    }
    return MetaImageReader(path, std::move(header)).read();
}

}  // namespace isotrack
