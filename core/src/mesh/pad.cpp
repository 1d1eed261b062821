// Capping by padding: a surface the volume's border cuts is closed by extracting
// it from a copy of the volume with one more layer of samples below the
// isovalue on every side. The outside then counts as below, so the objects
// (above the isovalue) are closed where they meet the border, with vertices on
// the grid edges between the border samples and the pad, exactly where any
// padded copy of the volume puts them.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "isotrack/errors.h"
#include "isotrack/mesh_processing.h"

namespace isotrack {
namespace {

bool integerType(ScalarType type) { return type != ScalarType::Float32 && type != ScalarType::Float64; }

double lowestOf(ScalarType type) {
    switch (type) {
        case ScalarType::UInt8:
        case ScalarType::UInt16:
        case ScalarType::UInt32: return 0.0;
        case ScalarType::Int8: return std::numeric_limits<std::int8_t>::lowest();
        case ScalarType::Int16: return std::numeric_limits<std::int16_t>::lowest();
        case ScalarType::Int32: return std::numeric_limits<std::int32_t>::lowest();
        case ScalarType::Float32: return std::numeric_limits<float>::lowest();
        case ScalarType::Float64: break;
    }
    return std::numeric_limits<double>::lowest();
}

template <class T>
void fillPadded(const Volume& source, Volume& padded, double padValue) {
    T* out = padded.data<T>();
    std::fill(out, out + padded.sampleCount(), static_cast<T>(padValue));
    const T* in = source.data<T>();
    const Dims& n = source.dims();
    for (int z = 0; z < n[2]; ++z)
        for (int y = 0; y < n[1]; ++y)
            std::memcpy(out + padded.index(1, y + 1, z + 1), in + source.index(0, y, z), std::size_t(n[0]) * sizeof(T));
}

}  // namespace

double capPadValue(const Volume& volume, double iso) {
    const double lowest = volume.range()[0];
    if (lowest < iso) return lowest;
    double pad = integerType(volume.type()) ? std::floor(iso - 1.0) : iso - 1.0;
    if (volume.type() == ScalarType::Float32) pad = double(float(pad));
    if (!(pad < iso) || pad < lowestOf(volume.type())) {
        throw InputError(std::string("cap: a ") + scalarTypeName(volume.type()) + " volume has no value below iso " +
                         std::to_string(iso) + " to pad it with");
    }
    return pad;
}

Volume padVolume(const Volume& volume, double padValue) {
    const Dims& n = volume.dims();
    for (int a = 0; a < 3; ++a) {
        if (n[a] + 2 > kMaxDimension) {
            throw InputError("cap: dimension " + std::to_string(a) + " (" + std::to_string(n[a]) +
                             " samples) is too large to pad");
        }
    }
    const Vec3d& s = volume.spacing();
    const Vec3d& o = volume.origin();
    Volume padded({n[0] + 2, n[1] + 2, n[2] + 2}, volume.type(), s, {o[0] - s[0], o[1] - s[1], o[2] - s[2]});
    padded.setDirection(volume.direction());
    switch (volume.type()) {
        case ScalarType::UInt8: fillPadded<std::uint8_t>(volume, padded, padValue); break;
        case ScalarType::Int8: fillPadded<std::int8_t>(volume, padded, padValue); break;
        case ScalarType::UInt16: fillPadded<std::uint16_t>(volume, padded, padValue); break;
        case ScalarType::Int16: fillPadded<std::int16_t>(volume, padded, padValue); break;
        case ScalarType::UInt32: fillPadded<std::uint32_t>(volume, padded, padValue); break;
        case ScalarType::Int32: fillPadded<std::int32_t>(volume, padded, padValue); break;
        case ScalarType::Float32: fillPadded<float>(volume, padded, padValue); break;
        case ScalarType::Float64: fillPadded<double>(volume, padded, padValue); break;
    }
    volume.throwIfDamaged();
    return padded;
}

}  // namespace isotrack
