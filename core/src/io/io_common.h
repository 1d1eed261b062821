#pragma once
// Plumbing shared by the volume loaders and mesh writers: files, one-line
// messages, header numbers, byte order, the one path by which samples reach
// memory, and buffered output.
//
// Every loader ends in readSamples(): it checks the dimensions against the
// volume limit and against the bytes the data actually holds (for compressed
// data, by a first inflate pass that stores nothing), and only then allocates.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/safe_write.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

// Opens a regular file for reading; a directory, FIFO or device is refused so
// that a hostile header naming /dev/zero or a pipe cannot hang or flood a loader.
// `where` names the file in messages (a detached data file also names its header).
FilePtr openForReading(const std::string& path, const std::string& where);
FilePtr openForReading(const std::string& path);
std::uint64_t fileSizeOf(const std::string& path, const std::string& where);

// Text quoted in a message: at most maxChars characters, non-printables as '?'.
std::string printable(const std::string& s, std::size_t maxChars = 60);
// ".nii.gz" is one extension here; the result is lower case.
std::string lowerExtension(const std::string& path);
std::string lowerCase(std::string s);
std::vector<std::string> splitWords(const std::string& s);
std::string joinWords(const std::string& s);
std::optional<long long> parseInteger(const std::string& s);
std::optional<double> parseFinite(const std::string& s);
// Exactly three words: positive integers that fit an int (a header's sizes), or
// finite numbers, positive when asked (spacings, origins).
std::optional<Dims> parseDims(const std::vector<std::string>& words);
std::optional<Vec3d> parseVec3(const std::vector<std::string>& words, bool positive);
std::string dimsText(const Dims& dims);
std::string numberText(double v);  // shortest form that reads back exactly

bool hostIsBigEndian();
void swapBytes(std::byte* data, std::size_t count, std::size_t width);

// What a loader learned from its header, and the field blamed when it is wrong.
struct VolumeHeader {
    std::string path;
    std::string sizeField;  // e.g. "sizes", "DimSize", "dim", "DIMENSIONS"
    Dims dims{0, 0, 0};
    ScalarType type = ScalarType::UInt8;
    Vec3d spacing{1, 1, 1};
    Vec3d origin{0, 0, 0};
    Mat3d direction = kIdentityDirection;  // world (LPS) axes, see isotrack/volume.h
};

// The sample buffer size, or a FormatError naming sizeField when a dimension is
// not positive or the product exceeds kMaxVolumeBytes (checked without overflow).
std::uint64_t sampleBytes(const VolumeHeader& header);
std::uint64_t sampleBytes(const VolumeHeader& header, ScalarType type);
// Spacing positive and finite, origin finite, and the whole grid within float
// range, so that vertex positions can never overflow to infinity.
void checkGeometry(const VolumeHeader& header, const std::string& spacingField, const std::string& originField);

enum class Compression { None, Gzip, Zlib };  // Zlib also accepts a gzip stream

// Where the samples are: `path` from byte `offset` (of the file), possibly
// compressed, after `skip` further bytes (of the decompressed stream).
struct SampleData {
    std::string path;
    std::uint64_t offset = 0;
    std::uint64_t skip = 0;
    Compression compression = Compression::None;
    bool bigEndian = false;
    bool trailingBytesAllowed = false;  // else the data must end with the samples
};

// Names the data file in messages: "hdr.mhd: data file \"x.raw\"" when detached.
std::string dataWhere(const VolumeHeader& header, const SampleData& data);

// Validates every size, then maps uncompressed samples in the host's byte order
// where they lie (a view that keeps the file mapped, isotrack/mapped_file.h), or,
// for compressed or byte-swapped ones, checks that they fit in the memory
// available, allocates once, reads and converts to host order.
Volume readSamples(const VolumeHeader& header, const SampleData& data);
// FormatError "PATH: DIMS TYPE samples, HOW, need X GiB of memory, more than the
// Y GiB available" when `bytes` exceed the memory available.
void requireMemoryFor(const VolumeHeader& header, std::uint64_t bytes, const std::string& how);

// What every volume loader (NRRD, NIfTI, MetaImage, VTK legacy, raw) shares:
// the file it reads and the header it fills, one-line errors that name the
// file and the field, and the one way to the samples (readSamples).
class VolumeReader {
public:
    const std::string& path() const { return geometry_.path; }

protected:
    // `sizeField` is the field blamed for bad sizes: "sizes", "dim", "DimSize"...
    VolumeReader(std::string path, std::string sizeField);

    // FormatError "PATH: PROBLEM".
    [[noreturn]] void failFile(const std::string& problem) const;
    // FormatError "PATH: field \"FIELD\": PROBLEM".
    [[noreturn]] void fail(const std::string& field, const std::string& problem) const;
    // `value`, or FormatError "PATH: missing required field \"FIELD\"" when it is null.
    const std::string& required(const std::string* value, const std::string& field) const;
    // The samples `data` locates, as geometry_ describes them.
    Volume readVolume(const SampleData& data) const { return readSamples(geometry_, data); }

    VolumeHeader geometry_;
};

// A mesh a writer can write: whole triangles, every index in range, and one
// component per triangle when given; else an InputError naming `path`.
void checkMesh(const std::string& path, const Mesh& mesh, const std::vector<std::int32_t>* faceComponent);

// A file written through a buffer that goes out a few MiB at a time, safely
// (isotrack/safe_write.h): until close() the target is untouched.
class BufferedOutput {
public:
    explicit BufferedOutput(const std::string& path);
    std::string& buffer() { return buf_; }
    void maybeFlush() {
        if (buf_.size() >= kFlushBytes) flush();
    }
    // Writes what is left and puts the file in place; a FormatError when either fails.
    void close();

private:
    static constexpr std::size_t kFlushBytes = std::size_t(4) << 20;
    void flush();
    SafeWriter file_;
    std::string buf_;
};

// Byte by byte little endian, so the file layout does not depend on the host.
void appendU32LE(std::string& out, std::uint32_t v);
void appendFloatLE(std::string& out, float f);

// Inflates a gzip or zlib stream from `file`'s current position, a chunk at a time.
class Inflater {
public:
    Inflater(std::FILE* file, Compression compression, std::string where);
    ~Inflater();
    Inflater(const Inflater&) = delete;
    Inflater& operator=(const Inflater&) = delete;

    // Fills up to n bytes; fewer only when the stream has ended. Throws FormatError
    // when the stream is corrupt or the file ends before the stream does.
    std::size_t read(unsigned char* dst, std::size_t n);
    // Reads and drops up to n bytes; returns how many there were.
    std::uint64_t skip(std::uint64_t n);

private:
    struct State;
    std::unique_ptr<State> state_;
};

}  // namespace isotrack::detail
