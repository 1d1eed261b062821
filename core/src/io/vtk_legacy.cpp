// VTK legacy volumes (https://vtk.org/wp-content/uploads/2015/04/file-formats.pdf):
// DATASET STRUCTURED_POINTS with POINT_DATA scalars, BINARY (big-endian) or ASCII.
//
// After three lines (version, title, ASCII|BINARY) the file is keywords and
// numbers separated by white space. Binary samples start after the line that
// names the lookup table; ASCII samples are the next POINT_DATA numbers.
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "io_common.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"

namespace isotrack {

namespace {

using namespace detail;

constexpr std::uint64_t kMaxHeaderBytes = std::uint64_t(1) << 20;
constexpr std::size_t kMaxTokenChars = 256;

const std::pair<const char*, ScalarType> kScalarTypes[] = {
    {"unsigned_char", ScalarType::UInt8}, {"char", ScalarType::Int8},
    {"signed_char", ScalarType::Int8},    {"unsigned_short", ScalarType::UInt16},
    {"short", ScalarType::Int16},         {"unsigned_int", ScalarType::UInt32},
    {"int", ScalarType::Int32},           {"float", ScalarType::Float32},
    {"double", ScalarType::Float64},
};

// White-space separated words, counting the bytes consumed so that binary data can be found.
class Tokens {
public:
    Tokens(std::FILE* f, std::string path) : f_(f), path_(std::move(path)) {}

    std::uint64_t consumed() const { return consumed_; }

    // The next word, or "" at end of file.
    std::string next() {
        int c = 0;
        while ((c = get()) != EOF && std::isspace(c)) {
        }
        std::string word;
        while (c != EOF && !std::isspace(c)) {
            if (word.size() == kMaxTokenChars)
                throw FormatError(path_ + ": word \"" + printable(word) + "\" is longer than " +
                                  std::to_string(kMaxTokenChars) + " characters");
            word += char(c);
            c = get();
        }
        if (c != EOF) unget(c);
        return word;
    }

    // The rest of the current line, its newline consumed.
    std::string line() {
        std::string text;
        int c = 0;
        while ((c = get()) != EOF && c != '\n') {
            if (text.size() == kMaxTokenChars * 4)
                throw FormatError(path_ + ": header line is longer than " + std::to_string(kMaxTokenChars * 4) +
                                  " characters");
            text += char(c);
        }
        if (!text.empty() && text.back() == '\r') text.pop_back();
        return text;
    }

    void limitHeader(bool on) { limited_ = on; }

private:
    int get() {
        const int c = std::fgetc(f_);
        if (c == EOF) {
            if (std::ferror(f_)) throw FormatError(path_ + ": cannot read: " + std::strerror(errno));
            return EOF;
        }
        if (++consumed_ > kMaxHeaderBytes && limited_) throw FormatError(path_ + ": header is longer than 1 MiB");
        return c;
    }
    void unget(int c) {
        std::ungetc(c, f_);
        --consumed_;
    }

    std::FILE* f_;
    std::string path_;
    std::uint64_t consumed_ = 0;
    bool limited_ = true;
};

class VtkReader : public VolumeReader {
public:
    VtkReader(std::FILE* f, const std::string& path) : VolumeReader(path, "DIMENSIONS"), tokens_(f, path) {}
    Volume read();

private:
    std::string keyword();
    Vec3d numbers(const std::string& field, bool positive);
    std::vector<std::string> threeWords();  // the next three tokens
    static std::string wordsText(const std::vector<std::string>& words);
    void readPreamble();
    void readStructure();
    void readScalarsHeader();
    Volume readAscii();
    template <class T>
    void readAsciiSamples(T* out, std::uint64_t count);

    Tokens tokens_;
    std::string word_;  // the last keyword as written
    bool binary_ = false;
};

std::string VtkReader::keyword() {
    word_ = tokens_.next();
    return lowerCase(word_);
}

std::vector<std::string> VtkReader::threeWords() {
    std::vector<std::string> words;
    for (int a = 0; a < 3; ++a) words.push_back(tokens_.next());
    return words;
}

std::string VtkReader::wordsText(const std::vector<std::string>& words) {
    return words[0] + " " + words[1] + " " + words[2];
}

Vec3d VtkReader::numbers(const std::string& field, bool positive) {
    const std::vector<std::string> words = threeWords();
    const auto v = parseVec3(words, positive);
    if (!v)
        fail(field, std::string("expected 3 ") + (positive ? "positive " : "") + "numbers, got \"" +
                        printable(wordsText(words)) + "\"");
    return *v;
}

void VtkReader::readPreamble() {
    const std::string version = tokens_.line();
    if (lowerCase(version).compare(0, 14, "# vtk datafile") != 0)
        failFile("not a VTK legacy file: first line is \"" + printable(version) +
                 "\", not \"# vtk DataFile Version ...\"");
    tokens_.line();  // title
    const std::string encoding = joinWords(tokens_.line());
    if (lowerCase(encoding) == "binary")
        binary_ = true;
    else if (lowerCase(encoding) != "ascii")
        fail("ASCII|BINARY", "third line must be ASCII or BINARY, got \"" + printable(encoding) + "\"");
    const std::string dataset = keyword();
    if (dataset != "dataset") fail("DATASET", "expected DATASET, got \"" + printable(word_) + "\"");
    const std::string kind = tokens_.next();
    if (lowerCase(kind) != "structured_points")
        fail("DATASET", "only STRUCTURED_POINTS is supported, got \"" + printable(kind) + "\"");
}

void VtkReader::readStructure() {
    bool haveDims = false;
    std::string spacingField = "SPACING";
    for (std::string key = keyword();; key = keyword()) {
        if (key == "dimensions") {
            const std::vector<std::string> words = threeWords();
            const auto dims = parseDims(words);
            if (!dims) fail("DIMENSIONS", "expected 3 positive integers, got \"" + printable(wordsText(words)) + "\"");
            geometry_.dims = *dims;
            haveDims = true;
        } else if (key == "spacing" || key == "aspect_ratio") {
            spacingField = key == "spacing" ? "SPACING" : "ASPECT_RATIO";
            geometry_.spacing = numbers(spacingField, true);
        } else if (key == "origin") {
            geometry_.origin = numbers("ORIGIN", false);
        } else if (key == "point_data") {
            break;
        } else if (key.empty()) {
            failFile("file ends before POINT_DATA");
        } else {
            fail("DATASET", "expected DIMENSIONS, SPACING, ORIGIN or POINT_DATA, got \"" + printable(word_) + "\"");
        }
    }
    if (!haveDims) failFile("missing required field \"DIMENSIONS\" before POINT_DATA");
    sampleBytes(geometry_);
    checkGeometry(geometry_, spacingField, "ORIGIN");

    const std::string countText = tokens_.next();
    const auto count = parseInteger(countText);
    const Dims& d = geometry_.dims;
    const auto points = std::uint64_t(d[0]) * std::uint64_t(d[1]) * std::uint64_t(d[2]);
    if (!count || *count < 0 || std::uint64_t(*count) != points)
        fail("POINT_DATA", "expected " + std::to_string(points) + " (DIMENSIONS " + dimsText(d) + "), got \"" +
                               printable(countText) + "\"");
}

void VtkReader::readScalarsHeader() {
    const std::string key = keyword();
    if (key != "scalars")
        fail("POINT_DATA", "expected SCALARS as the first point data, got \"" + printable(word_) + "\"");
    const std::string line = tokens_.line();
    const std::vector<std::string> words = splitWords(line);
    if (words.size() < 2 || words.size() > 3)
        fail("SCALARS", "expected \"SCALARS name type [1]\", got \"SCALARS " + printable(joinWords(line)) + "\"");
    bool typeOk = false;
    for (const auto& [name, type] : kScalarTypes)
        if (lowerCase(words[1]) == name) geometry_.type = type, typeOk = true;
    if (!typeOk)
        fail("SCALARS",
             "unsupported type \"" + printable(words[1]) +
                 "\" (supported: unsigned_char, char, unsigned_short, short, unsigned_int, int, float, double)");
    if (words.size() == 3 && words[2] != "1")
        fail("SCALARS", "expected 1 component, got \"" + printable(words[2]) + "\"");
    const std::string table = keyword();
    if (table != "lookup_table")
        fail("LOOKUP_TABLE", "expected LOOKUP_TABLE after SCALARS, got \"" + printable(word_) + "\"");
    if (tokens_.next().empty()) failFile("file ends in the LOOKUP_TABLE line");
}

template <class T>
bool parseSample(const std::string& word, T& out) {
    if (word.empty()) return false;
    char* end = nullptr;
    if constexpr (std::is_floating_point_v<T>) {
        const double v = std::strtod(word.c_str(), &end);
        out = static_cast<T>(v);
    } else {
        errno = 0;
        const long long v = std::strtoll(word.c_str(), &end, 10);
        if (errno != 0 || v < (long long)std::numeric_limits<T>::min() || v > (long long)std::numeric_limits<T>::max())
            return false;
        out = static_cast<T>(v);
    }
    return end == word.c_str() + word.size();
}

Volume VtkReader::readAscii() {
    const std::uint64_t samples = sampleBytes(geometry_) / scalarTypeSize(geometry_.type);
    // Each sample takes at least one character and one separator.
    const std::uint64_t size = fileSizeOf(path(), path());
    const std::uint64_t left = size > tokens_.consumed() ? size - tokens_.consumed() : 0;
    if (samples > (left + 1) / 2)
        fail("POINT_DATA", dimsText(geometry_.dims) + " needs " + std::to_string(samples) + " ASCII numbers but only " +
                               std::to_string(left) + " bytes follow (truncated?)");
    Volume volume(geometry_.dims, geometry_.type, geometry_.spacing, geometry_.origin);
    tokens_.limitHeader(false);
    visitSamples(volume, [&](const auto* typed) {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(typed)>>;
        readAsciiSamples(volume.data<T>(), samples);
    });
    return volume;
}

template <class T>
void VtkReader::readAsciiSamples(T* out, std::uint64_t count) {
    for (std::uint64_t i = 0; i < count; ++i) {
        const std::string word = tokens_.next();
        if (word.empty())
            fail("POINT_DATA",
                 "data is truncated: got " + std::to_string(i) + " of " + std::to_string(count) + " numbers");
        if (!parseSample(word, out[i]))
            fail("SCALARS", "sample " + std::to_string(i) + " is \"" + printable(word) + "\", not a " +
                                scalarTypeName(geometry_.type) + " number");
    }
}

Volume VtkReader::read() {
    readPreamble();
    readStructure();
    readScalarsHeader();
    if (!binary_) return readAscii();
    tokens_.line();  // the binary samples start on the next line
    SampleData data;
    data.path = path();
    data.offset = tokens_.consumed();
    data.bigEndian = true;
    data.trailingBytesAllowed = true;  // further attributes may follow
    return readVolume(data);
}

}  // namespace

Volume loadVtkLegacy(const std::string& path) {
    FilePtr f = openForReading(path);
    return VtkReader(f.get(), path).read();
}

}  // namespace isotrack
