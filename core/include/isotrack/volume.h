#pragma once
// A regular scalar grid kept in its native sample type.
//
// Samples are stored x-fastest: index = x + nx * (y + ny * z). The extractors
// work on the axis-aligned grid: sample (i, j, k) is at origin + (i * sx, j * sy, k * sz)
// ("grid coordinates"). Its world position (LPS, as DICOM and ITK) also turns
// about the origin by the direction matrix D:
//     world = origin + D * (i * sx, j * sy, k * sz)
// D's columns (direction()[a]) are unit vectors, orthogonal, det +1 or -1; they
// are the identity for an axis-aligned volume. isotrack/orientation.h applies it.
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

namespace isotrack {

class MappedFile;

enum class ScalarType : std::uint8_t { UInt8, Int8, UInt16, Int16, UInt32, Int32, Float32, Float64 };

// Every sample type, in the enum's order.
constexpr std::array<ScalarType, 8> kScalarTypes = {ScalarType::UInt8,   ScalarType::Int8,   ScalarType::UInt16,
                                                    ScalarType::Int16,   ScalarType::UInt32, ScalarType::Int32,
                                                    ScalarType::Float32, ScalarType::Float64};

// "uint8", "int8", ..., "float64": the names info, extract --json and raw --type use.
const char* scalarTypeName(ScalarType type);
// scalarTypeName's inverse; throws InputError naming the text and the valid names otherwise.
ScalarType parseScalarType(const std::string& name);
std::size_t scalarTypeSize(ScalarType type);

// Largest sample count times size a Volume may describe (a sanity bound against
// overflow, far above any file). Samples held in memory are bounded by the memory
// available instead (isotrack/mapped_file.h), mapped ones by their file.
inline constexpr std::uint64_t kMaxVolumeBytes = std::uint64_t(1) << 44;  // 16 TiB
// Grid coordinates are packed in 20 bits per axis (see PackedGridEdge).
inline constexpr int kMaxDimension = 1 << 20;

using Dims = std::array<int, 3>;
using Vec3d = std::array<double, 3>;
// Three columns: m[a] is column a.
using Mat3d = std::array<Vec3d, 3>;
inline constexpr Mat3d kIdentityDirection{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};

class Volume {
public:
    Volume() = default;
    // Allocates dims[0]*dims[1]*dims[2] zeroed samples. Throws InputError when a
    // dimension is not positive, the sample count would overflow or the samples
    // would not fit in the memory available.
    Volume(Dims dims, ScalarType type, Vec3d spacing = {1, 1, 1}, Vec3d origin = {0, 0, 0});
    // A Volume over samples it does not own (a numpy array, a mapped file), laid
    // out as above: nothing is copied, so the caller keeps them alive and
    // unchanged while this Volume or a copy of it is in use. Dimensions are
    // checked as by the constructor. A view is read-only: its non-const
    // accessors are not to be called.
    static Volume view(Dims dims, ScalarType type, const void* samples, Vec3d spacing = {1, 1, 1},
                       Vec3d origin = {0, 0, 0});
    // A view over a mapped file's samples (isotrack/mapped_file.h), which it and
    // its copies keep mapped.
    static Volume mapped(Dims dims, ScalarType type, std::shared_ptr<const MappedFile> file, Vec3d spacing = {1, 1, 1},
                         Vec3d origin = {0, 0, 0});
    bool isView() const { return view_ != nullptr; }
    // The file a mapped volume reads, else null.
    const MappedFile* mappedFile() const { return mapped_.get(); }
    // A streaming pass is done with slices [zBegin, zEnd): a mapped volume lets
    // their pages go (they are read again if touched); others keep them.
    void releaseSlices(int zBegin, int zEnd) const;
    // FormatError naming the file when a mapped volume's file was truncated or
    // removed while it was read (its samples then read as zeros); else nothing.
    void throwIfDamaged() const;

    const Dims& dims() const { return dims_; }
    ScalarType type() const { return type_; }
    const Vec3d& spacing() const { return spacing_; }
    const Vec3d& origin() const { return origin_; }
    void setSpacing(const Vec3d& spacing) { spacing_ = spacing; }
    void setOrigin(const Vec3d& origin) { origin_ = origin; }
    // World (LPS) unit vector of each index axis; see the top of this file.
    const Mat3d& direction() const { return direction_; }
    void setDirection(const Mat3d& direction) { direction_ = direction; }

    std::size_t sampleCount() const { return std::size_t(dims_[0]) * std::size_t(dims_[1]) * std::size_t(dims_[2]); }
    std::size_t byteSize() const { return view_ ? viewBytes_ : bytes_.size(); }
    std::size_t index(int x, int y, int z) const {
        return std::size_t(x) + std::size_t(dims_[0]) * (std::size_t(y) + std::size_t(dims_[1]) * std::size_t(z));
    }

    std::byte* bytes() {
        assert(!view_ && "a view's samples are read-only");
        return bytes_.data();
    }
    const std::byte* bytes() const { return view_ ? view_ : bytes_.data(); }

    template <class T>
    T* data() {
        return reinterpret_cast<T*>(bytes());
    }
    template <class T>
    const T* data() const {
        return reinterpret_cast<const T*>(bytes());
    }

    // Sample as double, whatever the native type. For tests and tools, not inner loops.
    double value(int x, int y, int z) const;
    void setValue(int x, int y, int z, double v);

    // Smallest and largest finite sample (NaN and infinities are skipped).
    std::array<double, 2> range() const;

private:
    Dims dims_{0, 0, 0};
    ScalarType type_ = ScalarType::Float32;
    Vec3d spacing_{1, 1, 1};
    Vec3d origin_{0, 0, 0};
    Mat3d direction_ = kIdentityDirection;
    std::vector<std::byte> bytes_;
    const std::byte* view_ = nullptr;  // the samples of a view, bytes_ then empty
    std::size_t viewBytes_ = 0;
    std::shared_ptr<const MappedFile> mapped_;  // a mapped view's file
};

// Calls fn(const T* samples) with the volume's samples in their native type.
template <class Fn>
decltype(auto) visitSamples(const Volume& volume, Fn&& fn) {
    switch (volume.type()) {
        case ScalarType::UInt8: return fn(volume.data<std::uint8_t>());
        case ScalarType::Int8: return fn(volume.data<std::int8_t>());
        case ScalarType::UInt16: return fn(volume.data<std::uint16_t>());
        case ScalarType::Int16: return fn(volume.data<std::int16_t>());
        case ScalarType::UInt32: return fn(volume.data<std::uint32_t>());
        case ScalarType::Int32: return fn(volume.data<std::int32_t>());
        case ScalarType::Float32: return fn(volume.data<float>());
        case ScalarType::Float64: break;
    }
    return fn(volume.data<double>());
}

// Counts of the finite samples in `bins` equal bins over [range[0], range[1]]
// (values outside go to the end bins); NaN and infinities are not counted.
std::vector<std::uint64_t> sampleHistogram(const Volume& volume, const std::array<double, 2>& range, std::size_t bins);

}  // namespace isotrack
