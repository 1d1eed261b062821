// NIfTI-1 volumes (https://nifti.nimh.nih.gov/nifti-1), single file .nii or .nii.gz.
//
// The 348-byte header is read first (through the gzip decoder for .nii.gz), its
// byte order told by sizeof_hdr == 348; the samples start at vox_offset.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include "io_common.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/orientation.h"

namespace isotrack {

namespace {

using namespace detail;

constexpr std::size_t kHeaderBytes = 348;

// Offsets into the header, from nifti1.h.
constexpr std::size_t kSizeofHdr = 0, kDim = 40, kDatatype = 70, kBitpix = 72, kPixdim = 76, kVoxOffset = 108,
                      kSclSlope = 112, kSclInter = 116, kToffset = 136, kQformCode = 252, kSformCode = 254,
                      kQuatern = 256, kQoffset = 268, kSrow = 280, kMagic = 344;

struct Datatype {
    int code;
    const char* name;
    std::optional<ScalarType> type;
};

const Datatype kDatatypes[] = {
    {2, "uint8", ScalarType::UInt8},      {4, "int16", ScalarType::Int16},      {8, "int32", ScalarType::Int32},
    {16, "float32", ScalarType::Float32}, {64, "float64", ScalarType::Float64}, {256, "int8", ScalarType::Int8},
    {512, "uint16", ScalarType::UInt16},  {768, "uint32", ScalarType::UInt32},  {1, "binary", std::nullopt},
    {32, "complex64", std::nullopt},      {128, "rgb24", std::nullopt},         {1024, "int64", std::nullopt},
    {1280, "uint64", std::nullopt},       {1536, "float128", std::nullopt},     {1792, "complex128", std::nullopt},
    {2048, "complex256", std::nullopt},   {2304, "rgba32", std::nullopt},
};

class HeaderBytes {
public:
    HeaderBytes(const unsigned char* bytes, bool swap) : bytes_(bytes), swap_(swap) {}

    std::int16_t i16(std::size_t at) const { return get<std::int16_t>(at); }
    std::int32_t i32(std::size_t at) const { return get<std::int32_t>(at); }
    float f32(std::size_t at) const { return get<float>(at); }

private:
    template <class T>
    T get(std::size_t at) const {
        unsigned char b[sizeof(T)];
        std::memcpy(b, bytes_ + at, sizeof(T));
        if (swap_) std::reverse(b, b + sizeof(T));
        T v;
        std::memcpy(&v, b, sizeof(T));
        return v;
    }
    const unsigned char* bytes_;
    bool swap_;
};

// Reads the header bytes; .nii.gz through the gzip decoder.
void readHeaderBytes(const std::string& path, bool gzip, unsigned char (&bytes)[kHeaderBytes]) {
    FilePtr file = openForReading(path);
    std::size_t got = 0;
    if (gzip) {
        Inflater inflater(file.get(), Compression::Gzip, path);
        got = inflater.read(bytes, kHeaderBytes);
    } else {
        got = std::fread(bytes, 1, kHeaderBytes, file.get());
    }
    if (got < kHeaderBytes)
        throw FormatError(path + ": not a NIfTI-1 file: " + std::to_string(got) + " bytes, shorter than the " +
                          std::to_string(kHeaderBytes) + "-byte header");
}

// Row by row, as srow_x..z write it.
std::string matrixText(const Mat3d& columns) {
    std::string text;
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c) text += (r + c ? " " : "") + numberText(columns[c][r]);
    return text;
}

// Interprets the 348 header bytes and reads the samples they locate.
class NiftiReader : public VolumeReader {
public:
    NiftiReader(std::string path, const unsigned char* bytes);
    Volume read(bool gzip, std::size_t step);
    // dim[4] when dim[0] >= 4, else 1; step t is at toffset + t * pixdim[4] (t when pixdim[4] is 0).
    std::size_t steps() const { return steps_; }
    double stepTime(std::size_t step) const {
        return stepOffset_ + double(step) * (stepSize_ != 0.0 ? stepSize_ : 1.0);
    }

private:
    void readDims(const HeaderBytes& h);
    void readType(const HeaderBytes& h);
    void readGeometry(const HeaderBytes& h);
    Mat3d qformRotation(const HeaderBytes& h) const;
    void readScaling(const HeaderBytes& h);

    SampleData data_;
    double slope_ = 0.0, inter_ = 0.0;
    std::size_t steps_ = 1;
    double stepSize_ = 0.0, stepOffset_ = 0.0;
};

NiftiReader::NiftiReader(std::string path, const unsigned char* bytes) : VolumeReader(std::move(path), "dim") {
    std::int32_t sizeofHdr = 0;
    std::memcpy(&sizeofHdr, bytes + kSizeofHdr, 4);
    const bool swap = sizeofHdr != 348;
    const HeaderBytes h(bytes, swap);
    if (h.i32(kSizeofHdr) != 348) {
        const bool nifti2 = sizeofHdr == 540 || HeaderBytes(bytes, true).i32(kSizeofHdr) == 540;
        fail("sizeof_hdr", nifti2 ? "540 is NIfTI-2, which is not supported (only NIfTI-1)"
                                  : "expected 348 in either byte order, got " + std::to_string(sizeofHdr));
    }
    data_.bigEndian = swap != hostIsBigEndian();

    const std::string magic(reinterpret_cast<const char*>(bytes + kMagic), 4);
    if (magic == std::string("ni1\0", 4))
        fail("magic", "\"ni1\" is a .hdr/.img pair, which is not supported (only single-file \"n+1\")");
    if (magic != std::string("n+1\0", 4)) fail("magic", "expected \"n+1\", got \"" + printable(magic) + "\"");

    readDims(h);
    if (steps_ > 1) {
        stepSize_ = double(h.f32(kPixdim + 16));
        stepOffset_ = double(h.f32(kToffset));
        if (!std::isfinite(stepSize_)) stepSize_ = 0.0;
        if (!std::isfinite(stepOffset_)) stepOffset_ = 0.0;
    }
    readType(h);
    readGeometry(h);
    readScaling(h);

    const float voxOffset = h.f32(kVoxOffset);
    if (!(voxOffset >= float(kHeaderBytes)) || !(voxOffset <= 1e12f) || voxOffset != std::floor(voxOffset))
        fail("vox_offset", "expected a whole number >= 348, got " + numberText(voxOffset));
    data_.path = geometry_.path;
    data_.trailingBytesAllowed = true;
    data_.skip = std::uint64_t(voxOffset);
}

void NiftiReader::readDims(const HeaderBytes& h) {
    std::int16_t dim[8];
    std::string text;
    for (std::size_t i = 0; i < 8; ++i) {
        dim[i] = h.i16(kDim + 2 * i);
        text += (i ? " " : "") + std::to_string(dim[i]);
    }
    if (dim[0] < 3 || dim[0] > 7) fail("dim", "expected 3 dimensions (dim[0] 3..7), got dim = " + text);
    // A fourth dimension is time: each step is one 3D volume after the other.
    if (dim[0] >= 4) {
        if (dim[4] < 1) fail("dim", "dimensions must be positive, got dim = " + text);
        steps_ = std::size_t(dim[4]);
    }
    for (int i = 5; i <= dim[0]; ++i)
        if (dim[i] != 1) fail("dim", "only 3D volumes and 3D time series are supported, got dim = " + text);
    for (std::size_t a = 0; a < 3; ++a) {
        if (dim[a + 1] < 1) fail("dim", "dimensions must be positive, got dim = " + text);
        geometry_.dims[a] = dim[a + 1];
    }
}

void NiftiReader::readType(const HeaderBytes& h) {
    const int code = h.i16(kDatatype);
    const Datatype* found = nullptr;
    for (const Datatype& d : kDatatypes)
        if (d.code == code) found = &d;
    if (!found) fail("datatype", "unknown datatype " + std::to_string(code));
    if (!found->type)
        fail("datatype", "unsupported datatype " + std::to_string(code) + " (" + found->name +
                             "; supported: uint8, int8, int16, uint16, int32, uint32, float32, float64)");
    geometry_.type = *found->type;
    const int bitpix = h.i16(kBitpix);
    if (std::size_t(bitpix) != 8 * scalarTypeSize(geometry_.type))
        fail("bitpix",
             std::to_string(bitpix) + " disagrees with datatype " + std::to_string(code) + " (" + found->name + ")");
}

void NiftiReader::readGeometry(const HeaderBytes& h) {
    // NIfTI's world is RAS; isotrack's is LPS (isotrack/orientation.h). Without
    // sform or qform (method 1) the grid is taken as given, as ANALYZE files are.
    for (std::size_t a = 0; a < 3; ++a) geometry_.spacing[a] = double(h.f32(kPixdim + 4 * (a + 1)));
    const char* spacingField = "pixdim";
    const char* originField = "qoffset";
    if (h.i16(kSformCode) > 0) {
        spacingField = originField = "srow";
        Mat3d axes{};
        Vec3d translation{};
        for (std::size_t r = 0; r < 3; ++r) {
            for (std::size_t c = 0; c < 3; ++c) axes[c][r] = double(h.f32(kSrow + 16 * r + 4 * c));
            translation[r] = double(h.f32(kSrow + 16 * r + 12));
        }
        const auto direction = directionFromAxes(axes, &geometry_.spacing);
        if (!direction)
            fail("srow", "the sform's columns must be non-zero and orthogonal (no shear), got " + matrixText(axes));
        geometry_.direction = flipRasLps(*direction);
        geometry_.origin = flipRasLps(translation);
    } else if (h.i16(kQformCode) > 0) {
        geometry_.direction = flipRasLps(qformRotation(h));
        Vec3d offset{};
        for (std::size_t a = 0; a < 3; ++a) offset[a] = double(h.f32(kQoffset + 4 * a));
        geometry_.origin = flipRasLps(offset);
    }
    checkGeometry(geometry_, spacingField, originField);
}

// The qform's rotation (quatern_b..d, a from the unit norm) with pixdim[0]'s
// qfac = -1 mirroring k, as nifti1.h defines it.
Mat3d NiftiReader::qformRotation(const HeaderBytes& h) const {
    const double b = double(h.f32(kQuatern)), c = double(h.f32(kQuatern + 4)), d = double(h.f32(kQuatern + 8));
    if (!std::isfinite(b) || !std::isfinite(c) || !std::isfinite(d))
        fail("quatern_b",
             "the quaternion must be finite, got " + numberText(b) + " " + numberText(c) + " " + numberText(d));
    const double sum = b * b + c * c + d * d;
    if (sum > 1.0 + 1e-6)
        fail("quatern_b", "the quaternion's (b, c, d) must have length <= 1, got " + numberText(b) + " " +
                              numberText(c) + " " + numberText(d));
    const double a = sum >= 1.0 ? 0.0 : std::sqrt(1.0 - sum);
    const double qfac = h.f32(kPixdim) < 0 ? -1.0 : 1.0;
    Mat3d r{};  // columns
    r[0] = {a * a + b * b - c * c - d * d, 2 * (b * c + a * d), 2 * (b * d - a * c)};
    r[1] = {2 * (b * c - a * d), a * a + c * c - b * b - d * d, 2 * (c * d + a * b)};
    r[2] = {qfac * 2 * (b * d + a * c), qfac * 2 * (c * d - a * b), qfac * (a * a + d * d - b * b - c * c)};
    const auto direction = directionFromAxes(r);
    if (!direction) fail("quatern_b", "the quaternion does not make a rotation");
    return *direction;
}

void NiftiReader::readScaling(const HeaderBytes& h) {
    const double s = double(h.f32(kSclSlope)), i = double(h.f32(kSclInter));
    if (s == 0.0 || std::isnan(s)) return;  // 0 (and, by common practice, NaN) means "not scaled"
    if (!std::isfinite(s)) fail("scl_slope", "expected a finite number, got " + numberText(s));
    if (!std::isfinite(i)) fail("scl_inter", "expected a finite number, got " + numberText(i));
    if (s == 1.0 && i == 0.0) return;
    slope_ = s;
    inter_ = i;
}

template <class T>
void scaleInto(const T* in, float* out, std::size_t n, double slope, double inter) {
    for (std::size_t k = 0; k < n; ++k) out[k] = static_cast<float>(slope * double(in[k]) + inter);
}

Volume NiftiReader::read(bool gzip, std::size_t step) {
    if (step >= steps_)
        fail("dim", "no time step " + std::to_string(step) + ": the file has " + std::to_string(steps_) +
                        (steps_ == 1 ? " step (0)" : " steps (0.." + std::to_string(steps_ - 1) + ")"));
    // Step t follows t whole 3D volumes; sampleBytes has checked each against the limit.
    const std::uint64_t stepBytes = sampleBytes(geometry_);
    if (std::uint64_t(step) > (std::uint64_t(1) << 62) / stepBytes) fail("dim", "time step out of range");
    data_.skip += std::uint64_t(step) * stepBytes;
    if (gzip) {
        data_.compression = Compression::Gzip;
    } else if (const std::uint64_t size = fileSizeOf(path(), path()); data_.skip > size) {
        fail("vox_offset",
             std::to_string(data_.skip) + " is beyond the end of the " + std::to_string(size) + "-byte file");
    }
    // The float32 copy counts against the volume limit too, before either is allocated.
    const bool scaled = slope_ != 0.0;
    if (scaled) sampleBytes(geometry_, ScalarType::Float32);

    Volume native = readVolume(data_);
    if (!scaled) return native;
    Volume scaledVolume(native.dims(), ScalarType::Float32, native.spacing(), native.origin());
    scaledVolume.setDirection(native.direction());
    visitSamples(native, [&](const auto* samples) {
        scaleInto(samples, scaledVolume.data<float>(), native.sampleCount(), slope_, inter_);
    });
    return scaledVolume;
}

}  // namespace

Volume loadNifti(const std::string& path, std::size_t step) {
    const bool gzip = lowerExtension(path) == ".nii.gz";
    unsigned char bytes[kHeaderBytes];
    readHeaderBytes(path, gzip, bytes);
    return NiftiReader(path, bytes).read(gzip, step);
}

std::vector<double> niftiStepTimes(const std::string& path) {
    const bool gzip = lowerExtension(path) == ".nii.gz";
    unsigned char bytes[kHeaderBytes];
    readHeaderBytes(path, gzip, bytes);
    const NiftiReader reader(path, bytes);
    std::vector<double> times;
    for (std::size_t t = 0; t < reader.steps(); ++t) times.push_back(reader.stepTime(t));
    return times;
}

}  // namespace isotrack
