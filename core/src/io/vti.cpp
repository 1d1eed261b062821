// VTK XML ImageData (.vti, https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html):
// one Piece, the samples of one PointData DataArray with one component.
//
// Expat parses the XML part. Inline data (format="ascii" or "binary", the latter
// base64) is the chosen array's character data. Appended data follows the
// AppendedData start tag and a '_' and is not XML (raw bytes, or base64 that
// VTK writes without separators), so the parser stops at that tag and each
// array's bytes are read from the file at the '_' plus the array's offset.
//
// A binary array is a header of header_type words, then the samples: without a
// compressor the header is one word, the byte count; with vtkZLibDataCompressor
// it is the block count, the uncompressed block size, the last block's size (0:
// a full block) and each block's compressed size, and each block is a zlib
// stream. In base64 the header and the data may be two streams, each padded.
#include <expat.h>
#include <zlib.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "io_common.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/orientation.h"

namespace isotrack {

namespace {

using namespace detail;

constexpr int kMaxDepth = 8;
constexpr std::size_t kChunkBytes = std::size_t(1) << 16;

const std::pair<const char*, ScalarType> kTypes[] = {
    {"Int8", ScalarType::Int8},       {"UInt8", ScalarType::UInt8},     {"Int16", ScalarType::Int16},
    {"UInt16", ScalarType::UInt16},   {"Int32", ScalarType::Int32},     {"UInt32", ScalarType::UInt32},
    {"Float32", ScalarType::Float32}, {"Float64", ScalarType::Float64},
};

struct DataArray {
    std::string name;
    std::string type;
    std::string format;
    std::string offset;
};

// What expat gathers from the XML part.
struct Head {
    std::string wanted;                // --array, or "" for the first one-component array
    std::vector<std::string> element;  // the open elements
    std::string fileType, byteOrder, headerType, compressor;
    std::optional<std::string> wholeExtent, origin, spacing, direction, pieceExtent;
    int pieces = 0;
    std::optional<DataArray> chosen;
    std::string names;  // every PointData array, for messages
    std::string text;   // the chosen array's inline data
    bool collecting = false;
    bool appended = false;
    std::string appendedEncoding;
    std::uint64_t appendedAt = 0;  // the byte index of "<AppendedData"
    std::string error;
    XML_Parser parser = nullptr;
};

const char* attribute(const XML_Char** attrs, const char* name) {
    for (int i = 0; attrs[i]; i += 2)
        if (std::strcmp(attrs[i], name) == 0) return attrs[i + 1];
    return nullptr;
}

// The attribute's value, or `fallback` when the element has none.
std::string attributeOr(const XML_Char** attrs, const char* name, const char* fallback = "") {
    const char* v = attribute(attrs, name);
    return v ? v : fallback;
}

std::optional<std::string> optionalAttribute(const XML_Char** attrs, const char* name) {
    const char* v = attribute(attrs, name);
    return v ? std::optional<std::string>(v) : std::nullopt;
}

void stop(Head& head, const std::string& error) {
    if (head.error.empty()) head.error = error;
    XML_StopParser(head.parser, XML_FALSE);
}

void startPointArray(Head& head, const XML_Char** attrs) {
    DataArray array;
    array.name = attributeOr(attrs, "Name");
    array.type = attributeOr(attrs, "type");
    array.format = attributeOr(attrs, "format");
    array.offset = attributeOr(attrs, "offset");
    const char* comps = attribute(attrs, "NumberOfComponents");
    const bool scalar = !comps || std::string(comps) == "1";
    head.names += (head.names.empty() ? "\"" : ", \"") + printable(array.name, 40) + "\"";
    if (head.chosen) return;
    if (head.wanted.empty() ? !scalar : array.name != head.wanted) return;
    if (!scalar)
        return stop(head, "DataArray \"" + printable(array.name) + "\" has " + printable(comps) +
                              " components; only one-component (scalar) arrays can be read");
    head.chosen = array;
    head.collecting = array.format != "appended";
}

void XMLCALL startElement(void* user, const XML_Char* name, const XML_Char** attrs) {
    Head& head = *static_cast<Head*>(user);
    const std::string parent = head.element.empty() ? "" : head.element.back();
    head.element.emplace_back(name);
    if (head.element.size() > std::size_t(kMaxDepth))
        return stop(head, "elements are nested deeper than " + std::to_string(kMaxDepth));
    const std::string element = name;
    if (parent.empty()) {
        if (element != "VTKFile")
            return stop(head, "not a VTK XML file: the root element is <" + printable(element) + ">");
        head.fileType = attributeOr(attrs, "type");
        head.byteOrder = attributeOr(attrs, "byte_order", "LittleEndian");
        head.headerType = attributeOr(attrs, "header_type", "UInt32");
        head.compressor = attributeOr(attrs, "compressor");
    } else if (parent == "VTKFile" && element == "ImageData") {
        head.wholeExtent = optionalAttribute(attrs, "WholeExtent");
        head.origin = optionalAttribute(attrs, "Origin");
        head.spacing = optionalAttribute(attrs, "Spacing");
        head.direction = optionalAttribute(attrs, "Direction");
    } else if (parent == "ImageData" && element == "Piece") {
        if (++head.pieces > 1) return stop(head, "more than one Piece: only single-piece files can be read");
        head.pieceExtent = optionalAttribute(attrs, "Extent");
    } else if (parent == "PointData" && element == "DataArray") {
        startPointArray(head, attrs);
    } else if (parent == "VTKFile" && element == "AppendedData") {
        head.appended = true;
        head.appendedEncoding = attributeOr(attrs, "encoding");
        head.appendedAt = std::uint64_t(XML_GetCurrentByteIndex(head.parser));
        XML_StopParser(head.parser, XML_FALSE);
    }
}

void XMLCALL endElement(void* user, const XML_Char*) {
    Head& head = *static_cast<Head*>(user);
    head.element.pop_back();
    head.collecting = false;
}

void XMLCALL characters(void* user, const XML_Char* s, int len) {
    Head& head = *static_cast<Head*>(user);
    if (head.collecting) head.text.append(s, std::size_t(len));
}

void XMLCALL doctype(void* user, const XML_Char*, const XML_Char*, const XML_Char*, int) {
    stop(*static_cast<Head*>(user), "a DOCTYPE is not allowed in a VTK XML file");
}

// Base64 that may be several padded streams back to back; white space is skipped.
std::optional<std::vector<unsigned char>> decodeBase64(const std::string& text) {
    std::vector<unsigned char> out;
    out.reserve(text.size() / 4 * 3);
    unsigned quad[4];
    int have = 0, pad = 0;
    for (const char c : text) {
        int v = -1;
        if (c >= 'A' && c <= 'Z')
            v = c - 'A';
        else if (c >= 'a' && c <= 'z')
            v = c - 'a' + 26;
        else if (c >= '0' && c <= '9')
            v = c - '0' + 52;
        else if (c == '+')
            v = 62;
        else if (c == '/')
            v = 63;
        else if (c == '=')
            v = 0, ++pad;
        else if (c == ' ' || c == '\n' || c == '\r' || c == '\t')
            continue;
        else
            return std::nullopt;
        if (pad && c != '=') return std::nullopt;
        if (pad > 2 || (pad && have < 2)) return std::nullopt;
        quad[have++] = unsigned(v);
        if (have < 4) continue;
        const unsigned bits = quad[0] << 18 | quad[1] << 12 | quad[2] << 6 | quad[3];
        out.push_back((unsigned char)(bits >> 16));
        if (pad < 2) out.push_back((unsigned char)(bits >> 8));
        if (pad < 1) out.push_back((unsigned char)bits);
        have = pad = 0;
    }
    if (have != 0) return std::nullopt;
    return out;
}

class VtiReader : public VolumeReader {
public:
    VtiReader(const std::string& path, std::string array) : VolumeReader(path, "WholeExtent") {
        head_.wanted = std::move(array);
    }
    Volume read();

private:
    void parseHead();
    void readGeometry();
    std::vector<double> numbers(const std::optional<std::string>& text, const std::string& field,
                                std::size_t count) const;
    Volume readAscii() const;
    Volume readBinary(const std::vector<unsigned char>& bytes) const;
    Volume readAppended() const;
    std::vector<unsigned char> compressedRaw(std::FILE* f, std::uint64_t left) const;
    std::uint64_t word(const unsigned char* p) const;
    std::string arrayField() const { return "DataArray " + printable(head_.chosen->name); }

    Head head_;
    std::uint64_t fileSize_ = 0;
    std::size_t wordBytes_ = 4;
    bool bigEndian_ = false;
    bool zlib_ = false;
};

void VtiReader::parseHead() {
    fileSize_ = fileSizeOf(path(), path());
    FilePtr f = openForReading(path());
    std::unique_ptr<std::remove_pointer_t<XML_Parser>, void (*)(XML_Parser)> parser(XML_ParserCreate(nullptr),
                                                                                    XML_ParserFree);
    if (!parser) failFile("cannot create an XML parser");
    head_.parser = parser.get();
    XML_SetUserData(parser.get(), &head_);
    XML_SetElementHandler(parser.get(), startElement, endElement);
    XML_SetCharacterDataHandler(parser.get(), characters);
    XML_SetStartDoctypeDeclHandler(parser.get(), doctype);
    std::vector<char> chunk(kChunkBytes);
    for (;;) {
        const std::size_t n = std::fread(chunk.data(), 1, chunk.size(), f.get());
        if (std::ferror(f.get())) failFile(std::string("cannot read: ") + std::strerror(errno));
        const bool last = n < chunk.size();
        if (XML_Parse(parser.get(), chunk.data(), int(n), last) == XML_STATUS_OK) {
            if (last) break;
            continue;
        }
        if (!head_.error.empty()) failFile(head_.error);
        if (head_.appended) break;
        failFile("XML error at line " + std::to_string(XML_GetCurrentLineNumber(parser.get())) + ": " +
                 XML_ErrorString(XML_GetErrorCode(parser.get())));
    }
    if (head_.fileType != "ImageData")
        fail("VTKFile", "type \"" + printable(head_.fileType) + "\" is not ImageData (only .vti image data is read)");
}

std::vector<double> VtiReader::numbers(const std::optional<std::string>& text, const std::string& field,
                                       std::size_t count) const {
    const std::vector<std::string> words = splitWords(text ? *text : "");
    std::vector<double> values;
    for (const std::string& w : words)
        if (const auto v = parseFinite(w)) values.push_back(*v);
    if (values.size() != count || words.size() != count)
        fail(field, "expected " + std::to_string(count) + " numbers, got \"" + printable(text ? *text : "") + "\"");
    return values;
}

void VtiReader::readGeometry() {
    if (!head_.wholeExtent) failFile("missing required field \"WholeExtent\" of ImageData");
    const std::vector<double> extent = numbers(head_.wholeExtent, "WholeExtent", 6);
    Dims& dims = geometry_.dims;
    for (int a = 0; a < 3; ++a) {
        const double lo = extent[2 * a], hi = extent[2 * a + 1];
        // Whole numbers within an int's range (a cast of a larger one is undefined), then the span.
        const bool whole = std::fabs(lo) < 2147483648.0 && std::fabs(hi) < 2147483648.0 && lo == std::floor(lo) &&
                           hi == std::floor(hi);
        if (!whole || hi < lo || hi - lo + 1 > kMaxDimension)
            fail("WholeExtent", "expected 3 integer ranges of at most " + std::to_string(kMaxDimension) +
                                    " points, got \"" + printable(*head_.wholeExtent) + "\"");
        dims[a] = int(hi - lo + 1);
    }
    if (head_.pieceExtent && numbers(head_.pieceExtent, "Piece Extent", 6) != extent)
        fail("Piece Extent", "\"" + printable(*head_.pieceExtent) + "\" is not the WholeExtent \"" +
                                 printable(*head_.wholeExtent) + "\"");
    const std::vector<double> spacing =
        head_.spacing ? numbers(head_.spacing, "Spacing", 3) : std::vector<double>{1, 1, 1};
    const std::vector<double> origin = head_.origin ? numbers(head_.origin, "Origin", 3) : std::vector<double>{0, 0, 0};
    if (head_.direction) {
        // Row major: column a is axis a's world vector.
        const std::vector<double> d = numbers(head_.direction, "Direction", 9);
        const Mat3d axes{{{d[0], d[3], d[6]}, {d[1], d[4], d[7]}, {d[2], d[5], d[8]}}};
        const auto direction = directionFromAxes(axes);
        if (!direction)
            fail("Direction", "expected 3 orthogonal unit vectors, got \"" + printable(*head_.direction) + "\"");
        geometry_.direction = *direction;
    }
    Vec3d first{};
    for (int a = 0; a < 3; ++a) {
        geometry_.spacing[a] = spacing[a];
        first[a] = extent[2 * a] * spacing[a];
    }
    // The WholeExtent's first index lies Direction * (index * Spacing) from Origin.
    const Vec3d shift = multiply(geometry_.direction, first);
    for (int a = 0; a < 3; ++a) geometry_.origin[a] = origin[a] + shift[a];
}

std::uint64_t VtiReader::word(const unsigned char* p) const {
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < wordBytes_; ++i) {
        const std::size_t at = bigEndian_ ? i : wordBytes_ - 1 - i;
        v = v << 8 | p[at];
    }
    return v;
}

template <class T>
bool parseNumber(const std::string& word, T& out) {
    char* end = nullptr;
    errno = 0;
    if constexpr (std::is_floating_point_v<T>) {
        out = static_cast<T>(std::strtod(word.c_str(), &end));
    } else {
        const long long v = std::strtoll(word.c_str(), &end, 10);
        if (errno != 0 || v < (long long)std::numeric_limits<T>::min() || v > (long long)std::numeric_limits<T>::max())
            return false;
        out = static_cast<T>(v);
    }
    return !word.empty() && end == word.c_str() + word.size();
}

Volume VtiReader::readAscii() const {
    const std::vector<std::string> words = splitWords(head_.text);
    const std::uint64_t count = sampleBytes(geometry_) / scalarTypeSize(geometry_.type);
    if (words.size() != count)
        fail(arrayField(), "expected " + std::to_string(count) + " ASCII numbers (WholeExtent " +
                               dimsText(geometry_.dims) + "), got " + std::to_string(words.size()));
    Volume volume(geometry_.dims, geometry_.type, geometry_.spacing, geometry_.origin);
    volume.setDirection(geometry_.direction);
    visitSamples(volume, [&](const auto* typed) {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(typed)>>;
        T* out = volume.data<T>();
        for (std::uint64_t i = 0; i < count; ++i)
            if (!parseNumber(words[i], out[i]))
                fail(arrayField(), "sample " + std::to_string(i) + " is \"" + printable(words[i]) + "\", not a " +
                                       scalarTypeName(geometry_.type) + " number");
    });
    return volume;
}

// `bytes` holds the header and the (compressed) samples, as described at the top.
Volume VtiReader::readBinary(const std::vector<unsigned char>& bytes) const {
    const std::uint64_t expected = sampleBytes(geometry_);
    const std::uint64_t n = bytes.size(), w = wordBytes_;
    const std::string field = arrayField();
    auto truncated = [&](const std::string& what) {
        fail(field, what + " needs more than the " + std::to_string(n) + " bytes there are (truncated?)");
    };
    if (n < w) truncated("the header");
    std::vector<std::pair<std::uint64_t, std::uint64_t>> blocks;  // (offset in bytes, compressed size)
    std::uint64_t blockSize = expected, lastSize = expected;
    if (!zlib_) {
        const std::uint64_t size = word(bytes.data());
        if (size != expected)
            fail(field, "header says " + std::to_string(size) + " bytes, WholeExtent " + dimsText(geometry_.dims) +
                            " of " + scalarTypeName(geometry_.type) + " needs " + std::to_string(expected));
        if (n - w < expected) truncated(std::to_string(expected) + " bytes of samples");
    } else {
        if (n < 3 * w) truncated("the compression header");
        const std::uint64_t count = word(bytes.data());
        blockSize = word(bytes.data() + w);
        lastSize = word(bytes.data() + 2 * w);
        if (count > (n - 3 * w) / w) truncated("the compression header of " + std::to_string(count) + " blocks");
        if (lastSize == 0) lastSize = blockSize;
        // One block may be shorter than its nominal size (VTK writes 32768 and the last size).
        const bool sizesOk = count > 0 && blockSize > 0 && lastSize <= blockSize && lastSize <= expected &&
                             (count == 1 ? lastSize == expected
                                         : blockSize <= expected && count - 1 <= (expected - lastSize) / blockSize &&
                                               (count - 1) * blockSize + lastSize == expected);
        if (!sizesOk)
            fail(field, "compression header says " + std::to_string(count) + " blocks of " + std::to_string(blockSize) +
                            " bytes, the last " + std::to_string(lastSize) + ", not the " + std::to_string(expected) +
                            " bytes WholeExtent " + dimsText(geometry_.dims) + " needs");
        std::uint64_t at = (3 + count) * w;
        for (std::uint64_t b = 0; b < count; ++b) {
            const std::uint64_t size = word(bytes.data() + (3 + b) * w);
            if (size > n - at) truncated("block " + std::to_string(b) + " of " + std::to_string(size) + " bytes");
            blocks.emplace_back(at, size);
            at += size;
        }
    }
    Volume volume(geometry_.dims, geometry_.type, geometry_.spacing, geometry_.origin);
    volume.setDirection(geometry_.direction);
    auto* out = reinterpret_cast<unsigned char*>(volume.bytes());
    if (!zlib_) std::memcpy(out, bytes.data() + w, expected);
    for (std::size_t b = 0; b < blocks.size(); ++b) {
        const std::uint64_t want = b + 1 == blocks.size() ? lastSize : blockSize;
        uLongf got = uLongf(want);
        const int rc = uncompress(out + b * blockSize, &got, bytes.data() + blocks[b].first, uLong(blocks[b].second));
        if (rc != Z_OK || got != want)
            fail(field, "block " + std::to_string(b) + " is not a zlib stream of " + std::to_string(want) + " bytes (" +
                            (rc == Z_OK ? "got " + std::to_string(got) : std::string(zError(rc))) + ")");
    }
    if (bigEndian_ != hostIsBigEndian())
        swapBytes(volume.bytes(), volume.sampleCount(), scalarTypeSize(geometry_.type));
    return volume;
}

// Appended raw zlib blocks: the header, then only as many bytes as its block sizes sum to.
std::vector<unsigned char> VtiReader::compressedRaw(std::FILE* f, std::uint64_t left) const {
    const std::uint64_t w = wordBytes_;
    std::vector<unsigned char> bytes(std::size_t(std::min<std::uint64_t>(left, 3 * w)));
    bytes.resize(std::fread(bytes.data(), 1, bytes.size(), f));
    if (bytes.size() < 3 * w) return bytes;  // readBinary says what is missing
    const std::uint64_t count = word(bytes.data());
    if (count > (left - 3 * w) / w) return bytes;
    bytes.resize(std::size_t((3 + count) * w));
    bytes.resize(3 * w + std::fread(bytes.data() + 3 * w, 1, std::size_t(count * w), f));
    if (bytes.size() < (3 + count) * w) return bytes;
    std::uint64_t total = (3 + count) * w;
    for (std::uint64_t b = 0; b < count; ++b) {
        total += word(bytes.data() + (3 + b) * w);
        if (total > left) return bytes;
    }
    const std::size_t header = bytes.size();
    bytes.resize(std::size_t(total));
    bytes.resize(header + std::fread(bytes.data() + header, 1, bytes.size() - header, f));
    return bytes;
}

Volume VtiReader::readAppended() const {
    const std::string field = arrayField();
    const auto offset = parseInteger(head_.chosen->offset);
    if (!offset || *offset < 0) fail(field, "offset \"" + printable(head_.chosen->offset) + "\" is not a byte offset");
    // The data starts after the AppendedData tag's '>', white space and '_'.
    FilePtr f = openForReading(path());
    if (std::fseek(f.get(), long(head_.appendedAt), SEEK_SET) != 0) failFile("cannot seek to AppendedData");
    std::uint64_t start = head_.appendedAt;
    int c = 0;
    while ((c = std::fgetc(f.get())) != EOF && (++start, c != '>')) {
    }
    while ((c = std::fgetc(f.get())) != EOF && (++start, c == ' ' || c == '\n' || c == '\r' || c == '\t')) {
    }
    if (c != '_') fail("AppendedData", "expected '_' before the appended data");
    if (std::uint64_t(*offset) > fileSize_ - std::min(fileSize_, start))
        fail(field, "offset " + std::to_string(*offset) + " is past the end of the file");
    const std::uint64_t at = start + std::uint64_t(*offset);
    if (head_.appendedEncoding == "raw" && !zlib_) {
        unsigned char header[8] = {};
        std::fseek(f.get(), long(at), SEEK_SET);
        if (std::fread(header, 1, wordBytes_, f.get()) != wordBytes_) fail(field, "the file ends in its header");
        const std::uint64_t size = word(header), expected = sampleBytes(geometry_);
        if (size != expected)
            fail(field, "header says " + std::to_string(size) + " bytes, WholeExtent " + dimsText(geometry_.dims) +
                            " of " + scalarTypeName(geometry_.type) + " needs " + std::to_string(expected));
        SampleData data;
        data.path = path();
        data.offset = at + wordBytes_;
        data.bigEndian = bigEndian_;
        data.trailingBytesAllowed = true;
        Volume volume = readVolume(data);
        volume.setDirection(geometry_.direction);
        return volume;
    }
    std::fseek(f.get(), long(at), SEEK_SET);
    const std::uint64_t left = fileSize_ - at;
    if (head_.appendedEncoding == "raw") return readBinary(compressedRaw(f.get(), left));
    // Base64: the rest of the file, which the sizes in the header then bound.
    std::vector<unsigned char> rest(static_cast<std::size_t>(left));
    rest.resize(std::fread(rest.data(), 1, rest.size(), f.get()));
    if (head_.appendedEncoding != "base64")
        fail("AppendedData", "encoding \"" + printable(head_.appendedEncoding) + "\" is not raw or base64");
    std::size_t end = 0;
    while (end < rest.size() && rest[end] != '_' && rest[end] != '<' && rest[end] != ' ' && rest[end] != '\n') ++end;
    const auto decoded = decodeBase64(std::string(rest.begin(), rest.begin() + std::ptrdiff_t(end)));
    if (!decoded) fail(field, "appended data is not valid base64");
    return readBinary(*decoded);
}

Volume VtiReader::read() {
    parseHead();
    bigEndian_ = head_.byteOrder == "BigEndian";
    if (!bigEndian_ && head_.byteOrder != "LittleEndian")
        fail("byte_order", "expected LittleEndian or BigEndian, got \"" + printable(head_.byteOrder) + "\"");
    if (head_.headerType == "UInt64")
        wordBytes_ = 8;
    else if (head_.headerType != "UInt32")
        fail("header_type", "expected UInt32 or UInt64, got \"" + printable(head_.headerType) + "\"");
    zlib_ = head_.compressor == "vtkZLibDataCompressor";
    if (!zlib_ && !head_.compressor.empty())
        fail("compressor", "\"" + printable(head_.compressor) + "\" is not supported (only vtkZLibDataCompressor)");
    if (!head_.chosen) {
        if (!head_.wanted.empty())
            failFile("no PointData array \"" + printable(head_.wanted) +
                     "\" (there are: " + (head_.names.empty() ? std::string("none") : head_.names) + ")");
        failFile("no one-component PointData array (there are: " +
                 (head_.names.empty() ? std::string("none") : head_.names) + ")");
    }
    bool typeOk = false;
    for (const auto& [name, type] : kTypes)
        if (head_.chosen->type == name) geometry_.type = type, typeOk = true;
    if (!typeOk)
        fail(arrayField(), "type \"" + printable(head_.chosen->type) +
                               "\" is not supported (Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64)");
    readGeometry();
    sampleBytes(geometry_);
    checkGeometry(geometry_, "Spacing", "Origin");
    const std::string& format = head_.chosen->format;
    if (format == "ascii") return readAscii();
    if (format == "binary") {
        const auto bytes = decodeBase64(head_.text);
        if (!bytes) fail(arrayField(), "inline binary data is not valid base64");
        return readBinary(*bytes);
    }
    if (format != "appended")
        fail(arrayField(), "format \"" + printable(format) + "\" is not ascii, binary or appended");
    if (!head_.appended) fail(arrayField(), "format is appended but the file has no AppendedData");
    return readAppended();
}

}  // namespace

Volume loadVti(const std::string& path, const std::string& array) { return VtiReader(path, array).read(); }

}  // namespace isotrack
