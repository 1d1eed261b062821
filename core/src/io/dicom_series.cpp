// The DICOM loader's assembly of a series into a volume (see dicom_internal.h):
// the series is checked as a whole (sizes, orientation, positions, spacing) and
// sized against the volume limit and its files' bytes before anything is
// allocated; only then is each file's pixel data decoded into its slice. No
// GDCM here but through dicom_gdcm.cpp.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "dicom_internal.h"
#include "isotrack/errors.h"
#include "isotrack/orientation.h"

namespace isotrack::detail::dicom {

namespace {

// Decoded bytes a file may claim per byte it holds (lossless JPEG of a flat image
// compresses about this far); beyond it a header is taken to be lying.
constexpr std::uint64_t kMaxDecodeRatio = 2000;
// Slices are even when each gap is within this share of the mean gap (DS values
// carry at most 16 characters).
constexpr double kSpacingTolerance = 0.01;

double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d minus(const Vec3d& a, const Vec3d& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double norm(const Vec3d& a) { return std::sqrt(dot(a, a)); }

ScalarType nativeType(const Image& image) {
    const bool isSigned = image.pixelRepresentation == 1;
    switch (image.bitsAllocated) {
        case 8: return isSigned ? ScalarType::Int8 : ScalarType::UInt8;
        case 16: return isSigned ? ScalarType::Int16 : ScalarType::UInt16;
        default: return isSigned ? ScalarType::Int32 : ScalarType::UInt32;
    }
}

void checkSameShape(const std::vector<Image>& images) {
    const Image& first = images.front();
    for (const Image& image : images) {
        if (image.rows != first.rows || image.columns != first.columns)
            refuse(image, DicomProblem::MixedSizes,
                   "mixed sizes in one series: " + std::to_string(image.columns) + " x " + std::to_string(image.rows) +
                       " here, " + std::to_string(first.columns) + " x " + std::to_string(first.rows) + " in " +
                       first.path);
        if (image.bitsAllocated != first.bitsAllocated || image.pixelRepresentation != first.pixelRepresentation)
            refuse(
                image, DicomProblem::MixedSampleTypes,
                "mixed sample types in one series (BitsAllocated/PixelRepresentation differ from " + first.path + ")");
        if (image.pixelSpacing != first.pixelSpacing)
            refuse(image, DicomProblem::MixedPixelSpacing,
                   "mixed PixelSpacing in one series (differs from " + first.path + ")");
        if (images.size() > 1 && image.frames != 1)
            refuse(image, DicomProblem::MultiFrameAmongOthers,
                   "a multi-frame file in a series of " + std::to_string(images.size()) +
                       " files is not supported (give the file itself)");
        if (images.size() > 1 && (!image.position || !image.orientation))
            refuse(image, DicomProblem::Unordered,
                   "no ImagePositionPatient or ImageOrientationPatient, so the slices cannot be ordered");
    }
}

// Sorts the slices along the normal and measures the gap between them.
double orderSlices(Layout& layout, const Vec3d& normal) {
    std::vector<const Image*>& s = layout.slices;
    std::sort(s.begin(), s.end(),
              [&](const Image* a, const Image* b) { return dot(*a->position, normal) < dot(*b->position, normal); });
    const double first = dot(*s.front()->position, normal), last = dot(*s.back()->position, normal);
    const double mean = (last - first) / double(s.size() - 1);
    for (std::size_t k = 1; k < s.size(); ++k)
        if (!(dot(minus(*s[k]->position, *s[k - 1]->position), normal) > 1e-6 * std::max(1.0, std::fabs(mean))))
            refuse(*s[k], DicomProblem::DuplicateSlices,
                   "at the same ImagePositionPatient as " + s[k - 1]->path + " (duplicate slice?)");
    for (std::size_t k = 1; k < s.size(); ++k) {
        const Vec3d step = minus(*s[k]->position, *s[k - 1]->position);
        const double gap = dot(step, normal);
        if (std::fabs(gap - mean) > kSpacingTolerance * mean)
            refuse(*s[k], DicomProblem::UnevenSpacing,
                   "uneven slice spacing: " + numberText(gap) + " mm from " + s[k - 1]->path + ", " + numberText(mean) +
                       " mm on average (missing slice?)");
        const Vec3d across = minus(step, {gap * normal[0], gap * normal[1], gap * normal[2]});
        if (norm(across) > kSpacingTolerance * mean)
            refuse(*s[k], DicomProblem::GantryTilt,
                   "slices are not stacked along their normal (gantry tilt of " +
                       numberText(std::atan2(norm(across), gap) * 180.0 / M_PI) + " degrees?): not supported");
    }
    return mean;
}

// Whether slope * v + intercept is an int16 for every value BitsStored allows.
bool rescalesToInt16(const Image& image) {
    if (image.slope != std::floor(image.slope) || image.intercept != std::floor(image.intercept)) return false;
    const int bits = std::min(image.bitsStored, 32);
    const double lo = image.pixelRepresentation == 1 ? -std::ldexp(1.0, bits - 1) : 0.0;
    const double hi = image.pixelRepresentation == 1 ? std::ldexp(1.0, bits - 1) - 1 : std::ldexp(1.0, bits) - 1;
    for (double v : {lo, hi}) {
        const double out = image.slope * v + image.intercept;
        if (out < -32768.0 || out > 32767.0) return false;
    }
    return true;
}

template <class T, class Out>
void rescale(const T* in, std::size_t n, double slope, double intercept, Out* out) {
    for (std::size_t k = 0; k < n; ++k) out[k] = static_cast<Out>(slope * double(in[k]) + intercept);
}

}  // namespace

[[noreturn]] void refuse(const Image& image, const std::string& problem) {
    throw FormatError(image.path + ": " + problem);
}

[[noreturn]] void refuse(const Image& image, DicomProblem why, const std::string& problem) {
    throw NotAVolume(why, image.path + ": " + problem);
}

std::size_t sliceCount(const std::vector<Image>& images) {
    std::size_t n = 0;
    for (const Image& i : images) n += std::size_t(i.frames);
    return n;
}

std::vector<const std::vector<Image>*> ordered(const SeriesMap& series) {
    std::vector<const std::vector<Image>*> out;
    for (const auto& entry : series) out.push_back(&entry.second);
    std::stable_sort(out.begin(), out.end(), [](auto* a, auto* b) { return sliceCount(*a) > sliceCount(*b); });
    return out;
}

Mat3d directionOf(const Image& image) {
    if (!image.orientation) return kIdentityDirection;
    const auto& o = *image.orientation;
    const Vec3d row{o[0], o[1], o[2]}, column{o[3], o[4], o[5]};
    const Vec3d normal{row[1] * column[2] - row[2] * column[1], row[2] * column[0] - row[0] * column[2],
                       row[0] * column[1] - row[1] * column[0]};
    const auto direction = directionFromAxes({row, column, normal});
    if (!direction || std::fabs(norm(row) - 1) > 1e-3 || std::fabs(norm(column) - 1) > 1e-3)
        refuse(image, DicomProblem::BadOrientation,
               "field \"ImageOrientationPatient\": expected two orthogonal unit vectors, got " + numberText(o[0]) +
                   " " + numberText(o[1]) + " " + numberText(o[2]) + " " + numberText(o[3]) + " " + numberText(o[4]) +
                   " " + numberText(o[5]));
    return *direction;
}

Layout layoutOf(const std::string& path, const std::vector<Image>& images) {
    checkSameShape(images);
    const Image& first = images.front();
    Layout layout;
    for (const Image& image : images) layout.slices.push_back(&image);
    VolumeHeader& h = layout.header;
    h.path = path;
    h.sizeField = "Rows/Columns";
    h.type = nativeType(first);
    h.direction = directionOf(first);
    h.spacing = {first.pixelSpacing[1], first.pixelSpacing[0], 1.0};
    if (first.position) h.origin = *first.position;
    h.dims = {first.columns, first.rows,
              int(std::min<std::size_t>(sliceCount(images), std::size_t(kMaxDimension) + 1))};
    if (sliceCount(images) > std::size_t(kMaxDimension))
        refuse(first, DicomProblem::TooLarge,
               std::to_string(sliceCount(images)) + " slices, more than " + std::to_string(kMaxDimension));
    if (images.size() > 1) {
        for (const Image& image : images)
            if (directionOf(image) != h.direction) {
                const Mat3d d = directionOf(image);
                for (std::size_t a = 0; a < 3; ++a)
                    if (norm(minus(d[a], h.direction[a])) > 1e-4)
                        refuse(image, DicomProblem::MixedOrientation,
                               "mixed ImageOrientationPatient in one series (differs from " + first.path + ")");
            }
        h.spacing[2] = orderSlices(layout, h.direction[2]);
        h.origin = *layout.slices.front()->position;
    }
    try {
        sampleBytes(h);  // the volume limit, before anything else
    } catch (const FormatError& e) {
        throw NotAVolume(DicomProblem::TooLarge, e.what());
    }
    try {
        checkGeometry(h, "PixelSpacing", "ImagePositionPatient");
    } catch (const FormatError& e) {
        throw NotAVolume(DicomProblem::BadGeometry, e.what());
    }
    for (const Image* image : layout.slices) {
        const std::uint64_t bytes = std::uint64_t(image->rows) * std::uint64_t(image->columns) *
                                    std::uint64_t(image->frames) * std::uint64_t(image->bitsAllocated / 8);
        const DicomStructure& st = image->structure;
        const std::string samples = std::to_string(image->columns) + " x " + std::to_string(image->rows) + " x " +
                                    std::to_string(image->frames) + " samples need " + std::to_string(bytes) + " bytes";
        if (!st.hasPixelData) refuse(*image, DicomProblem::PixelDataShort, "no pixel data");
        if (!st.encapsulated && st.pixelDataBytes < bytes)
            refuse(*image, DicomProblem::PixelDataShort,
                   samples + ", but its pixel data holds " + std::to_string(st.pixelDataBytes));
        if (st.encapsulated && bytes > st.pixelDataBytes * kMaxDecodeRatio + 4096)
            refuse(*image, DicomProblem::PixelDataShort,
                   samples + ", more than its " + std::to_string(st.pixelDataBytes) + " compressed bytes can hold");
    }
    for (const Image* image : layout.slices)
        if (image->slope != 1 || image->intercept != 0) layout.rescaled = true;
    layout.exactInt16 = layout.rescaled;
    for (const Image* image : layout.slices) layout.exactInt16 = layout.exactInt16 && rescalesToInt16(*image);
    return layout;
}

Volume readVolume(const Layout& layout) {
    const VolumeHeader& h = layout.header;
    const ScalarType outType = !layout.rescaled ? h.type : layout.exactInt16 ? ScalarType::Int16 : ScalarType::Float32;
    if (layout.rescaled) sampleBytes(h, outType);
    Volume native(h.dims, h.type, h.spacing, h.origin);
    native.setDirection(h.direction);
    const std::size_t sliceBytes = std::size_t(h.dims[0]) * std::size_t(h.dims[1]) * scalarTypeSize(h.type);
    std::size_t at = 0;
    for (const Image* image : layout.slices) {
        const std::size_t bytes = sliceBytes * std::size_t(image->frames);
        decodeInto(*image, native.bytes() + at, bytes);
        at += bytes;
    }
    if (!layout.rescaled) return native;
    Volume out(h.dims, outType, h.spacing, h.origin);
    out.setDirection(h.direction);
    const std::size_t sliceSamples = std::size_t(h.dims[0]) * std::size_t(h.dims[1]);
    std::size_t sample = 0;
    for (const Image* image : layout.slices) {
        const std::size_t n = sliceSamples * std::size_t(image->frames);
        visitSamples(native, [&](const auto* in) {
            if (outType == ScalarType::Int16)
                rescale(in + sample, n, image->slope, image->intercept, out.data<std::int16_t>() + sample);
            else
                rescale(in + sample, n, image->slope, image->intercept, out.data<float>() + sample);
        });
        sample += n;
    }
    return out;
}

std::size_t pick(const std::string& path, const std::vector<const std::vector<Image>*>& list,
                 const std::string& which) {
    for (std::size_t k = 0; k < list.size(); ++k)
        if (list[k]->front().seriesUid == which) return k;
    if (const auto n = parseInteger(which); n && *n >= 1 && std::size_t(*n) <= list.size()) return std::size_t(*n - 1);
    throw InputError(path + ": no series \"" + printable(which) + "\" (" + std::to_string(list.size()) +
                     " series: give a SeriesInstanceUID or 1.." + std::to_string(list.size()) +
                     "; isotrack info lists them)");
}

DicomContents contentsOf(const std::string& path, const Gathered& gathered) {
    DicomContents out;
    out.skipped = gathered.skipped;
    for (const auto* images : ordered(gathered.series)) {
        const Image& first = images->front();
        DicomSeries s;
        s.uid = first.seriesUid;
        s.description = first.description;
        s.modality = first.modality;
        s.images = images->size();
        s.dims = {first.columns, first.rows,
                  int(std::min<std::size_t>(sliceCount(*images), std::size_t(kMaxDimension)))};
        try {
            layoutOf(path, *images);  // headers only: nothing is decoded
            if (sliceCount(*images) == 1) s.problem = DicomProblem::SingleSlice;
        } catch (const NotAVolume& e) {
            s.problem = e.problem();
            s.detail = e.what();
        }
        // A file named directly is read as it is, even as one slice.
        if (!out.chosen && (s.formsVolume() || gathered.singleFile)) out.chosen = out.series.size();
        out.series.push_back(std::move(s));
    }
    return out;
}

std::string reasonOf(const std::string& message, const std::string& file) {
    const std::string prefix = file + ": ";
    return message.compare(0, prefix.size(), prefix) == 0 ? message.substr(prefix.size()) : message;
}

std::string noVolumeMessage(const std::string& path, const DicomContents& contents) {
    const std::size_t n = contents.skipped.size();
    const std::string skipped = std::to_string(n) + (n == 1 ? " file" : " files") + " skipped";
    // Every file skipped: the first one's reason is likely every one's.
    if (contents.series.empty())
        return path + ": no DICOM images found" +
               (n == 0 ? ""
                       : " (" + skipped + ", the first " + contents.skipped.front().file + ": " +
                             contents.skipped.front().why + ")");
    // One series: its own message says which file and what.
    if (contents.series.size() == 1 && !contents.series.front().detail.empty())
        return path + ": no series forms a volume: " + contents.series.front().detail + (n == 0 ? "" : "; " + skipped);
    std::string list;
    for (std::size_t k = 0; k < contents.series.size(); ++k) {
        const DicomSeries& s = contents.series[k];
        if (k) list += "; ";
        list += std::to_string(k + 1) + ": " + (s.modality.empty() ? "" : s.modality + " ") +
                std::to_string(s.dims[2]) + (s.dims[2] == 1 ? " slice of " : " slices of ") +
                std::to_string(s.dims[0]) + " x " + std::to_string(s.dims[1]) + ", " + dicomProblemText(s.problem);
    }
    return path + ": no series forms a volume (" + list + ")" + (n == 0 ? "" : "; " + skipped);
}

}  // namespace isotrack::detail::dicom

namespace isotrack {

const char* dicomProblemText(DicomProblem problem) {
    switch (problem) {
        case DicomProblem::None: return "forms a volume";
        case DicomProblem::SingleSlice: return "single slice";
        case DicomProblem::MixedSizes: return "mixed sizes";
        case DicomProblem::MixedSampleTypes: return "mixed sample types";
        case DicomProblem::MixedPixelSpacing: return "mixed pixel spacing";
        case DicomProblem::MultiFrameAmongOthers: return "multi-frame file among others";
        case DicomProblem::Unordered: return "no slice positions";
        case DicomProblem::BadOrientation: return "bad orientation";
        case DicomProblem::MixedOrientation: return "orientation differs per slice";
        case DicomProblem::DuplicateSlices: return "duplicate slices";
        case DicomProblem::UnevenSpacing: return "uneven spacing";
        case DicomProblem::GantryTilt: return "gantry tilt";
        case DicomProblem::TooLarge: return "too large";
        case DicomProblem::BadGeometry: return "bad geometry";
        case DicomProblem::PixelDataShort: return "pixel data missing or short";
    }
    return "unknown";
}

}  // namespace isotrack
