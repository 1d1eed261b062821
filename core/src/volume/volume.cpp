#include "isotrack/volume.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "isotrack/errors.h"
#include "isotrack/mapped_file.h"
#include "support/huge_pages.h"
#include "support/slice_release.h"

namespace isotrack {

const char* scalarTypeName(ScalarType type) {
    switch (type) {
        case ScalarType::UInt8: return "uint8";
        case ScalarType::Int8: return "int8";
        case ScalarType::UInt16: return "uint16";
        case ScalarType::Int16: return "int16";
        case ScalarType::UInt32: return "uint32";
        case ScalarType::Int32: return "int32";
        case ScalarType::Float32: return "float32";
        case ScalarType::Float64: return "float64";
    }
    return "unknown";
}

ScalarType parseScalarType(const std::string& name) {
    std::string names;
    for (ScalarType type : kScalarTypes) {
        if (name == scalarTypeName(type)) return type;
        names += std::string(names.empty() ? "" : ", ") + scalarTypeName(type);
    }
    throw InputError("sample type \"" + name + "\": not one of " + names);
}

std::size_t scalarTypeSize(ScalarType type) {
    switch (type) {
        case ScalarType::UInt8:
        case ScalarType::Int8: return 1;
        case ScalarType::UInt16:
        case ScalarType::Int16: return 2;
        case ScalarType::UInt32:
        case ScalarType::Int32:
        case ScalarType::Float32: return 4;
        case ScalarType::Float64: return 8;
    }
    return 0;
}

namespace {

// The byte size of dims samples of `type`; throws InputError when a dimension is
// out of range or the size would exceed kMaxVolumeBytes (overflow).
std::size_t checkedByteSize(const Dims& dims, ScalarType type) {
    const std::string dimsText =
        std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " + std::to_string(dims[2]);
    if (dims[0] < 1 || dims[1] < 1 || dims[2] < 1)
        throw InputError("volume: dimensions must be positive, got " + dimsText);
    if (dims[0] > kMaxDimension || dims[1] > kMaxDimension || dims[2] > kMaxDimension)
        throw InputError("volume: dimensions must be at most " + std::to_string(kMaxDimension) + ", got " + dimsText);
    // Check step by step so the product itself can never overflow.
    const std::uint64_t maxSamples = kMaxVolumeBytes / scalarTypeSize(type);
    const auto nx = std::uint64_t(dims[0]), ny = std::uint64_t(dims[1]), nz = std::uint64_t(dims[2]);
    if (nx > maxSamples || ny > maxSamples / nx || nz > maxSamples / (nx * ny))
        throw InputError("volume: " + dimsText + " " + scalarTypeName(type) + " samples are too many to address");
    return std::size_t(nx * ny * nz) * scalarTypeSize(type);
}

std::string gibText(std::uint64_t bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GiB", double(bytes) / double(std::uint64_t(1) << 30));
    return text;
}

// checkedByteSize, and InputError when that many bytes exceed the memory available.
std::size_t allocatableByteSize(const Dims& dims, ScalarType type) {
    const std::size_t bytes = checkedByteSize(dims, type);
    const std::uint64_t available = availableMemoryBytes();
    if (bytes > available)
        throw InputError("volume: " + std::to_string(dims[0]) + " x " + std::to_string(dims[1]) + " x " +
                         std::to_string(dims[2]) + " " + scalarTypeName(type) + " samples need " + gibText(bytes) +
                         " of memory, more than the " + gibText(available) + " available");
    return bytes;
}

}  // namespace

Volume::Volume(Dims dims, ScalarType type, Vec3d spacing, Vec3d origin)
    : dims_(dims), type_(type), spacing_(spacing), origin_(origin) {
    // Zeroed samples, on huge pages where the kernel offers them (huge_pages.h).
    detail::resizeOnHugePages(bytes_, allocatableByteSize(dims, type));
}

Volume Volume::view(Dims dims, ScalarType type, const void* samples, Vec3d spacing, Vec3d origin) {
    Volume volume;
    volume.viewBytes_ = checkedByteSize(dims, type);
    volume.dims_ = dims;
    volume.type_ = type;
    volume.spacing_ = spacing;
    volume.origin_ = origin;
    volume.view_ = static_cast<const std::byte*>(samples);
    return volume;
}

Volume Volume::mapped(Dims dims, ScalarType type, std::shared_ptr<const MappedFile> file, Vec3d spacing, Vec3d origin) {
    Volume volume = view(dims, type, file->data(), spacing, origin);
    if (file->size() < volume.viewBytes_) throw InputError(file->where() + ": the mapping is shorter than its samples");
    volume.mapped_ = std::move(file);
    return volume;
}

void Volume::releaseSlices(int zBegin, int zEnd) const {
    if (!mapped_ || zBegin >= zEnd) return;
    const std::size_t slice = std::size_t(dims_[0]) * std::size_t(dims_[1]) * scalarTypeSize(type_);
    mapped_->release(std::size_t(std::max(zBegin, 0)) * slice, std::size_t(std::min(zEnd, dims_[2])) * slice);
}

void Volume::throwIfDamaged() const {
    if (mapped_) mapped_->throwIfDamaged();
}

namespace {

template <class T>
T toSample(double v) {
    if constexpr (std::is_floating_point_v<T>) {
        return static_cast<T>(v);
    } else {
        // Integers saturate rather than wrap, so out-of-range writes stay predictable.
        if (std::isnan(v)) return T(0);
        const double lo = double(std::numeric_limits<T>::min());
        const double hi = double(std::numeric_limits<T>::max());
        return static_cast<T>(std::clamp(std::nearbyint(v), lo, hi));
    }
}

}  // namespace

double Volume::value(int x, int y, int z) const {
    const std::size_t i = index(x, y, z);
    return visitSamples(*this, [i](const auto* samples) { return double(samples[i]); });
}

void Volume::setValue(int x, int y, int z, double v) {
    const std::size_t i = index(x, y, z);
    switch (type_) {
        case ScalarType::UInt8: data<std::uint8_t>()[i] = toSample<std::uint8_t>(v); return;
        case ScalarType::Int8: data<std::int8_t>()[i] = toSample<std::int8_t>(v); return;
        case ScalarType::UInt16: data<std::uint16_t>()[i] = toSample<std::uint16_t>(v); return;
        case ScalarType::Int16: data<std::int16_t>()[i] = toSample<std::int16_t>(v); return;
        case ScalarType::UInt32: data<std::uint32_t>()[i] = toSample<std::uint32_t>(v); return;
        case ScalarType::Int32: data<std::int32_t>()[i] = toSample<std::int32_t>(v); return;
        case ScalarType::Float32: data<float>()[i] = toSample<float>(v); return;
        case ScalarType::Float64: data<double>()[i] = v; return;
    }
}

namespace {

// fn(samples, begin, end) over the samples slice by slice, letting a mapped
// volume's passed slices go (support/slice_release.h).
template <class Fn>
void streamSlices(const Volume& volume, Fn&& fn) {
    if (volume.byteSize() == 0) return;
    const std::size_t slice = std::size_t(volume.dims()[0]) * std::size_t(volume.dims()[1]);
    detail::SliceRelease release(volume, 0);
    visitSamples(volume, [&](const auto* samples) {
        for (int z = 0; z < volume.dims()[2]; ++z) {
            fn(samples, std::size_t(z) * slice, std::size_t(z + 1) * slice);
            release.passed(z + 1);
        }
    });
    release.finish(volume.dims()[2]);
}

}  // namespace

std::array<double, 2> Volume::range() const {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    streamSlices(*this, [&](const auto* samples, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const double v = double(samples[i]);
            if (!std::isfinite(v)) continue;
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    });
    throwIfDamaged();
    if (lo > hi) return std::array<double, 2>{std::nan(""), std::nan("")};
    return std::array<double, 2>{lo, hi};
}

std::vector<std::uint64_t> sampleHistogram(const Volume& volume, const std::array<double, 2>& range, std::size_t bins) {
    std::vector<std::uint64_t> counts(bins, 0);
    if (bins == 0) return counts;
    const double span = range[1] - range[0];
    const double scale = span > 0.0 ? double(bins) / span : 0.0;
    streamSlices(volume, [&](const auto* samples, std::size_t begin, std::size_t end) {
        for (std::size_t i = begin; i < end; ++i) {
            const double v = static_cast<double>(samples[i]);
            if (!std::isfinite(v)) continue;
            ++counts[static_cast<std::size_t>(std::clamp((v - range[0]) * scale, 0.0, double(bins - 1)))];
        }
    });
    volume.throwIfDamaged();
    return counts;
}

}  // namespace isotrack
