// DICOM series through GDCM: see isotrack/dicom.h.
//
// Three steps. Gather: the files of a folder (recursively), of a DICOMDIR's
// image records, or the one file given. Headers: each file is read up to its
// pixel data, and the images are grouped by SeriesInstanceUID. Series: the
// chosen one is checked as a whole (sizes, orientation, positions, spacing) and
// sized against the volume limit and its files' bytes before anything is
// allocated; only then is each file's pixel data decoded into its slice.
#include "isotrack/dicom.h"

#include <gdcmDataElement.h>
#include <gdcmDataSet.h>
#include <gdcmDicts.h>
#include <gdcmGlobal.h>
#include <gdcmImage.h>
#include <gdcmImageReader.h>
#include <gdcmReader.h>
#include <gdcmSequenceOfFragments.h>
#include <gdcmSequenceOfItems.h>
#include <gdcmStringFilter.h>
#include <gdcmTag.h>
#include <gdcmTrace.h>
#include <gdcmVR.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "dicom_structure.h"
#include "io_common.h"
#include "isotrack/errors.h"
#include "isotrack/orientation.h"

namespace isotrack {

namespace {

namespace fs = std::filesystem;
using detail::numberText;
using detail::printable;

constexpr std::size_t kMaxFiles = 100000;
// Decoded bytes a file may claim per byte it holds (lossless JPEG of a flat image
// compresses about this far); beyond it a header is taken to be lying.
constexpr std::uint64_t kMaxDecodeRatio = 2000;
// Slices are even when each gap is within this share of the mean gap (DS values
// carry at most 16 characters).
constexpr double kSpacingTolerance = 0.01;

const gdcm::Tag kPixelData(0x7fe0, 0x0010);

struct Image {  // one file's header
    std::string path;
    std::string seriesUid, description, modality;
    int rows = 0, columns = 0, frames = 1;
    int bitsAllocated = 0, bitsStored = 0, pixelRepresentation = 0, samplesPerPixel = 1;
    std::optional<Vec3d> position;
    std::optional<std::array<double, 6>> orientation;
    std::array<double, 2> pixelSpacing{1, 1};  // between rows, between columns
    double slope = 1, intercept = 0;
    detail::DicomStructure structure;
};

void quietGdcm() {
    gdcm::Trace::SetDebug(false);
    gdcm::Trace::SetWarning(false);
    gdcm::Trace::SetError(false);
}

std::string trimmed(const std::string& s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos) return "";
    return s.substr(first, s.find_last_not_of(" \t\r\n\0") - first + 1);
}

// "a\b\c" as DICOM multi-valued strings hold numbers; nullopt unless exactly `count` finite ones.
std::optional<std::vector<double>> numbers(const std::string& text, std::size_t count) {
    std::vector<double> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find('\\', start), text.size());
        const auto v = detail::parseFinite(trimmed(text.substr(start, end - start)));
        if (!v) return std::nullopt;
        out.push_back(*v);
        start = end + 1;
    }
    if (out.size() != count) return std::nullopt;
    return out;
}

class HeaderFields {
public:
    HeaderFields(const gdcm::File& file, std::string path) : path_(std::move(path)) { filter_.SetFile(file); }

    std::string text(std::uint16_t group, std::uint16_t element) const {
        return trimmed(filter_.ToString(gdcm::Tag(group, element)));
    }
    bool has(std::uint16_t group, std::uint16_t element) const { return !text(group, element).empty(); }
    std::optional<std::vector<double>> values(std::uint16_t group, std::uint16_t element, const char* name,
                                              std::size_t count) const {
        const std::string t = text(group, element);
        if (t.empty()) return std::nullopt;
        auto v = numbers(t, count);
        if (!v)
            throw FormatError(path_ + ": field \"" + name + "\": expected " + std::to_string(count) + " numbers, got \"" +
                              printable(t) + "\"");
        return v;
    }
    int integer(std::uint16_t group, std::uint16_t element, const char* name, int otherwise, int lo, int hi) const {
        const auto v = values(group, element, name, 1);
        if (!v) return otherwise;
        const double x = (*v)[0];
        if (x != std::floor(x) || x < lo || x > hi)
            throw FormatError(path_ + ": field \"" + name + "\": expected a whole number in " + std::to_string(lo) + ".." +
                              std::to_string(hi) + ", got " + numberText(x));
        return int(x);
    }

private:
    gdcm::StringFilter filter_;
    std::string path_;
};

// GDCM asserts when a standard element it reads carries a VR the dictionary
// does not allow, so such a file is refused first.
void checkVrs(const std::string& path, const detail::DicomStructure& structure) {
    const gdcm::Dicts& dicts = gdcm::Global::GetInstance().GetDicts();
    for (const auto& [tagBits, spelled] : structure.explicitVrs) {
        const gdcm::Tag tag(std::uint16_t(tagBits >> 16), std::uint16_t(tagBits & 0xffff));
        if (tag.IsPrivate() || tag.GetElement() == 0) continue;
        const gdcm::VR expected = dicts.GetDictEntry(tag).GetVR();
        if (expected == gdcm::VR::INVALID) continue;
        const gdcm::VR found = gdcm::VR::GetVRType(spelled.c_str());
        if (found == gdcm::VR::INVALID || !expected.Compatible(found)) {
            char name[16];
            std::snprintf(name, sizeof name, "(%04X,%04X)", unsigned(tag.GetGroup()), unsigned(tag.GetElement()));
            throw FormatError(path + ": element " + name + " has VR " + printable(spelled) + ", the standard gives it " +
                              gdcm::VR::GetVRString(expected));
        }
    }
}

// The header of one file, up to its pixel data; nullopt for a file that is not
// DICOM, or holds no image, when `required` is false.
std::optional<Image> readImageHeader(const std::string& path, bool required) {
    const auto refuse = [&](const std::string& problem) -> std::optional<Image> {
        if (required) throw FormatError(path + ": " + problem);
        return std::nullopt;
    };
    Image image;
    image.path = path;
    // GDCM only ever sees files whose every length has been checked.
    try {
        image.structure = detail::checkDicomStructure(path);
    } catch (const FormatError& e) {
        if (detail::hasDicomMagic(path)) throw;
        if (!required) return std::nullopt;
        throw FormatError(path + ": not a DICOM file (no \"DICM\" after a 128-byte preamble, nor a dataset without one)");
    }
    checkVrs(path, image.structure);
    gdcm::Reader reader;
    reader.SetFileName(path.c_str());
    bool read = false;
    try {
        read = reader.ReadUpToTag(kPixelData, std::set<gdcm::Tag>());
    } catch (const std::exception&) {
        read = false;
    }
    // A file with the DICM preamble that GDCM cannot read is an error even in a
    // folder: skipping it could silently drop the first or last slice.
    if (!read && image.structure.hasMagic) throw FormatError(path + ": its DICOM header cannot be read");
    if (!read) return refuse("not a DICOM file, or its header is damaged or truncated");
    const HeaderFields f(reader.GetFile(), path);
    if (!f.has(0x0028, 0x0010) || !f.has(0x0028, 0x0011)) return refuse("holds no image (no Rows or Columns)");

    image.seriesUid = f.text(0x0020, 0x000e);
    image.description = f.text(0x0008, 0x103e);
    image.modality = f.text(0x0008, 0x0060);
    image.rows = f.integer(0x0028, 0x0010, "Rows", 0, 1, kMaxDimension);
    image.columns = f.integer(0x0028, 0x0011, "Columns", 0, 1, kMaxDimension);
    image.frames = f.integer(0x0028, 0x0008, "NumberOfFrames", 1, 1, kMaxDimension);
    image.bitsAllocated = f.integer(0x0028, 0x0100, "BitsAllocated", 0, 0, 64);
    image.bitsStored = f.integer(0x0028, 0x0101, "BitsStored", image.bitsAllocated, 1, 64);
    image.pixelRepresentation = f.integer(0x0028, 0x0103, "PixelRepresentation", 0, 0, 1);
    image.samplesPerPixel = f.integer(0x0028, 0x0002, "SamplesPerPixel", 1, 1, 4);
    if (const auto v = f.values(0x0020, 0x0032, "ImagePositionPatient", 3)) image.position = Vec3d{(*v)[0], (*v)[1], (*v)[2]};
    if (const auto v = f.values(0x0020, 0x0037, "ImageOrientationPatient", 6)) {
        std::array<double, 6> o{};
        std::copy(v->begin(), v->end(), o.begin());
        image.orientation = o;
    }
    if (const auto v = f.values(0x0028, 0x0030, "PixelSpacing", 2)) {
        if (!((*v)[0] > 0) || !((*v)[1] > 0))
            throw FormatError(path + ": field \"PixelSpacing\": expected 2 positive numbers, got \"" +
                              printable(f.text(0x0028, 0x0030)) + "\"");
        image.pixelSpacing = {(*v)[0], (*v)[1]};
    }
    if (const auto v = f.values(0x0028, 0x1053, "RescaleSlope", 1)) image.slope = (*v)[0];
    if (const auto v = f.values(0x0028, 0x1052, "RescaleIntercept", 1)) image.intercept = (*v)[0];
    if (f.has(0x0028, 0x1052) && !f.has(0x0028, 0x1053))  // GDCM would take the slope as 0
        throw FormatError(path + ": field \"RescaleSlope\": missing, though RescaleIntercept is given");
    if (image.slope == 0) throw FormatError(path + ": field \"RescaleSlope\": 0 would erase every sample");
    if (image.samplesPerPixel != 1)
        throw FormatError(path + ": field \"SamplesPerPixel\": " + std::to_string(image.samplesPerPixel) +
                          " (colour) is not supported, only 1");
    if (image.bitsAllocated != 8 && image.bitsAllocated != 16 && image.bitsAllocated != 32)
        throw FormatError(path + ": field \"BitsAllocated\": expected 8, 16 or 32, got " +
                          std::to_string(image.bitsAllocated));
    if (image.bitsStored > image.bitsAllocated)
        throw FormatError(path + ": field \"BitsStored\": " + std::to_string(image.bitsStored) + " exceeds BitsAllocated " +
                          std::to_string(image.bitsAllocated));
    return image;
}

// A string element's value, trimmed; empty when absent.
std::string stringValue(const gdcm::DataSet& ds, const gdcm::Tag& tag) {
    if (!ds.FindDataElement(tag)) return "";
    const gdcm::ByteValue* value = ds.GetDataElement(tag).GetByteValue();
    if (!value || !value->GetPointer()) return "";
    return trimmed(std::string(value->GetPointer(), value->GetLength()));
}

// The files a DICOMDIR's IMAGE records name, relative to its folder.
std::vector<std::string> dicomdirFiles(const std::string& path) {
    if (!detail::hasDicomMagic(path)) throw FormatError(path + ": not a DICOMDIR (no \"DICM\" after a 128-byte preamble)");
    checkVrs(path, detail::checkDicomStructure(path));
    gdcm::Reader reader;
    reader.SetFileName(path.c_str());
    bool read = false;
    try {
        read = reader.Read();
    } catch (const std::exception&) {
        read = false;
    }
    if (!read) throw FormatError(path + ": not a DICOMDIR, or it is damaged or truncated");
    const gdcm::DataSet& ds = reader.GetFile().GetDataSet();
    const gdcm::Tag recordsTag(0x0004, 0x1220);
    if (!ds.FindDataElement(recordsTag)) throw FormatError(path + ": DICOMDIR has no DirectoryRecordSequence");
    const gdcm::SmartPointer<gdcm::SequenceOfItems> records = ds.GetDataElement(recordsTag).GetValueAsSQ();
    if (!records) throw FormatError(path + ": DICOMDIR's DirectoryRecordSequence is not a sequence");
    const fs::path folder = fs::path(path).parent_path();
    std::vector<std::string> files;
    for (gdcm::SequenceOfItems::SizeType i = 1; i <= records->GetNumberOfItems(); ++i) {
        const gdcm::DataSet& item = records->GetItem(i).GetNestedDataSet();
        if (stringValue(item, gdcm::Tag(0x0004, 0x1430)) != "IMAGE") continue;
        const std::string id = stringValue(item, gdcm::Tag(0x0004, 0x1500));
        if (id.empty()) continue;
        fs::path file = folder;
        std::size_t start = 0;
        while (start <= id.size()) {
            const std::size_t end = std::min(id.find('\\', start), id.size());
            const std::string part = trimmed(id.substr(start, end - start));
            if (part == ".." || part == "." || part.find('/') != std::string::npos)
                throw FormatError(path + ": DICOMDIR record names \"" + printable(id) + "\", outside its folder");
            if (!part.empty()) file /= part;
            start = end + 1;
        }
        files.push_back(file.string());
        if (files.size() > kMaxFiles) throw FormatError(path + ": DICOMDIR lists more than " + std::to_string(kMaxFiles) + " images");
    }
    if (files.empty()) throw FormatError(path + ": DICOMDIR lists no images");
    return files;
}

bool isDicomdir(const std::string& path) { return detail::lowerCase(fs::path(path).filename().string()) == "dicomdir"; }

// Every image header at `path`, grouped by series.
std::map<std::string, std::vector<Image>> readSeries(const std::string& path) {
    quietGdcm();
    std::error_code ec;
    std::vector<std::string> files;
    bool required = true;  // a file named directly must be an image
    if (fs::is_directory(path, ec)) {
        required = false;
        fs::recursive_directory_iterator it(path, fs::directory_options::skip_permission_denied, ec), end;
        if (ec) throw FormatError(path + ": cannot read the folder: " + ec.message());
        for (; it != end; it.increment(ec)) {
            if (ec) throw FormatError(path + ": cannot read the folder: " + ec.message());
            if (!it->is_regular_file(ec) || isDicomdir(it->path().string())) continue;
            files.push_back(it->path().string());
            if (files.size() > kMaxFiles)
                throw FormatError(path + ": more than " + std::to_string(kMaxFiles) + " files in the folder");
        }
        std::sort(files.begin(), files.end());
    } else if (isDicomdir(path)) {
        detail::openForReading(path);  // names a missing file or a device plainly
        files = dicomdirFiles(path);
    } else {
        detail::openForReading(path);
        files.push_back(path);
    }
    std::map<std::string, std::vector<Image>> series;
    for (const std::string& file : files) {
        if (required) detail::openForReading(file);
        auto image = readImageHeader(file, required);
        if (image) series[image->seriesUid].push_back(std::move(*image));
    }
    if (series.empty()) throw FormatError(path + ": no DICOM images found");
    return series;
}

std::size_t sliceCount(const std::vector<Image>& images) {
    std::size_t n = 0;
    for (const Image& i : images) n += std::size_t(i.frames);
    return n;
}

// Largest first, ties by UID.
std::vector<const std::vector<Image>*> ordered(const std::map<std::string, std::vector<Image>>& series) {
    std::vector<const std::vector<Image>*> out;
    for (const auto& entry : series) out.push_back(&entry.second);
    std::stable_sort(out.begin(), out.end(), [](auto* a, auto* b) { return sliceCount(*a) > sliceCount(*b); });
    return out;
}

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

// A series checked as one volume: the slices in order and the geometry.
struct Layout {
    std::vector<const Image*> slices;  // one per slice, or one multi-frame file
    detail::VolumeHeader header;
    bool rescaled = false;
    bool exactInt16 = false;
};

[[noreturn]] void refuse(const Image& image, const std::string& problem) { throw FormatError(image.path + ": " + problem); }

void checkSameShape(const std::vector<Image>& images) {
    const Image& first = images.front();
    for (const Image& image : images) {
        if (image.rows != first.rows || image.columns != first.columns)
            refuse(image, "mixed sizes in one series: " + std::to_string(image.columns) + " x " + std::to_string(image.rows) +
                              " here, " + std::to_string(first.columns) + " x " + std::to_string(first.rows) + " in " +
                              first.path);
        if (image.bitsAllocated != first.bitsAllocated || image.pixelRepresentation != first.pixelRepresentation)
            refuse(image, "mixed sample types in one series (BitsAllocated/PixelRepresentation differ from " + first.path + ")");
        if (image.pixelSpacing != first.pixelSpacing)
            refuse(image, "mixed PixelSpacing in one series (differs from " + first.path + ")");
        if (images.size() > 1 && image.frames != 1)
            refuse(image, "a multi-frame file in a series of " + std::to_string(images.size()) +
                              " files is not supported (give the file itself)");
        if (images.size() > 1 && (!image.position || !image.orientation))
            refuse(image, "no ImagePositionPatient or ImageOrientationPatient, so the slices cannot be ordered");
    }
}

// Row, column and normal directions from ImageOrientationPatient.
Mat3d directionOf(const Image& image) {
    if (!image.orientation) return kIdentityDirection;
    const auto& o = *image.orientation;
    const Vec3d row{o[0], o[1], o[2]}, column{o[3], o[4], o[5]};
    const Vec3d normal{row[1] * column[2] - row[2] * column[1], row[2] * column[0] - row[0] * column[2],
                       row[0] * column[1] - row[1] * column[0]};
    const auto direction = directionFromAxes({row, column, normal});
    if (!direction || std::fabs(norm(row) - 1) > 1e-3 || std::fabs(norm(column) - 1) > 1e-3)
        refuse(image, "field \"ImageOrientationPatient\": expected two orthogonal unit vectors, got " + numberText(o[0]) + " " +
                          numberText(o[1]) + " " + numberText(o[2]) + " " + numberText(o[3]) + " " + numberText(o[4]) + " " +
                          numberText(o[5]));
    return *direction;
}

// Sorts the slices along the normal and measures the gap between them.
double orderSlices(Layout& layout, const Vec3d& normal) {
    std::vector<const Image*>& s = layout.slices;
    std::sort(s.begin(), s.end(), [&](const Image* a, const Image* b) { return dot(*a->position, normal) < dot(*b->position, normal); });
    const double first = dot(*s.front()->position, normal), last = dot(*s.back()->position, normal);
    const double mean = (last - first) / double(s.size() - 1);
    for (std::size_t k = 1; k < s.size(); ++k)
        if (!(dot(minus(*s[k]->position, *s[k - 1]->position), normal) > 1e-6 * std::max(1.0, std::fabs(mean))))
            refuse(*s[k], "at the same ImagePositionPatient as " + s[k - 1]->path + " (duplicate slice?)");
    for (std::size_t k = 1; k < s.size(); ++k) {
        const Vec3d step = minus(*s[k]->position, *s[k - 1]->position);
        const double gap = dot(step, normal);
        if (std::fabs(gap - mean) > kSpacingTolerance * mean)
            refuse(*s[k], "uneven slice spacing: " + numberText(gap) + " mm from " + s[k - 1]->path + ", " + numberText(mean) +
                              " mm on average (missing slice?)");
        const Vec3d across = minus(step, {gap * normal[0], gap * normal[1], gap * normal[2]});
        if (norm(across) > kSpacingTolerance * mean)
            refuse(*s[k], "slices are not stacked along their normal (gantry tilt of " +
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

Layout layoutOf(const std::string& path, const std::vector<Image>& images) {
    checkSameShape(images);
    const Image& first = images.front();
    Layout layout;
    for (const Image& image : images) layout.slices.push_back(&image);
    detail::VolumeHeader& h = layout.header;
    h.path = path;
    h.sizeField = "Rows/Columns";
    h.type = nativeType(first);
    h.direction = directionOf(first);
    h.spacing = {first.pixelSpacing[1], first.pixelSpacing[0], 1.0};
    if (first.position) h.origin = *first.position;
    h.dims = {first.columns, first.rows, int(std::min<std::size_t>(sliceCount(images), std::size_t(kMaxDimension) + 1))};
    if (sliceCount(images) > std::size_t(kMaxDimension))
        refuse(first, std::to_string(sliceCount(images)) + " slices, more than " + std::to_string(kMaxDimension));
    if (images.size() > 1) {
        for (const Image& image : images)
            if (directionOf(image) != h.direction) {
                const Mat3d d = directionOf(image);
                for (std::size_t a = 0; a < 3; ++a)
                    if (norm(minus(d[a], h.direction[a])) > 1e-4)
                        refuse(image, "mixed ImageOrientationPatient in one series (differs from " + first.path + ")");
            }
        h.spacing[2] = orderSlices(layout, h.direction[2]);
        h.origin = *layout.slices.front()->position;
    }
    detail::sampleBytes(h);  // the volume limit, before anything else
    detail::checkGeometry(h, "PixelSpacing", "ImagePositionPatient");
    for (const Image* image : layout.slices) {
        const std::uint64_t bytes = std::uint64_t(image->rows) * std::uint64_t(image->columns) *
                                    std::uint64_t(image->frames) * std::uint64_t(image->bitsAllocated / 8);
        const detail::DicomStructure& st = image->structure;
        const std::string samples = std::to_string(image->columns) + " x " + std::to_string(image->rows) + " x " +
                                    std::to_string(image->frames) + " samples need " + std::to_string(bytes) + " bytes";
        if (!st.hasPixelData) refuse(*image, "no pixel data");
        if (!st.encapsulated && st.pixelDataBytes < bytes)
            refuse(*image, samples + ", but its pixel data holds " + std::to_string(st.pixelDataBytes));
        if (st.encapsulated && bytes > st.pixelDataBytes * kMaxDecodeRatio + 4096)
            refuse(*image, samples + ", more than its " + std::to_string(st.pixelDataBytes) +
                               " compressed bytes can hold");
    }
    for (const Image* image : layout.slices)
        if (image->slope != 1 || image->intercept != 0) layout.rescaled = true;
    layout.exactInt16 = layout.rescaled;
    for (const Image* image : layout.slices) layout.exactInt16 = layout.exactInt16 && rescalesToInt16(*image);
    return layout;
}

// Reads a file through GDCM's image reader; false when it cannot (GDCM may throw on damaged files).
bool readImage(gdcm::ImageReader& reader, const Image& image) {
    reader.SetFileName(image.path.c_str());
    try {
        return reader.Read();
    } catch (const std::exception&) {
        return false;
    }
}

// Decodes one file's pixel data into `out`, which holds exactly its bytes.
void decodeInto(const Image& image, std::byte* out, std::size_t bytes) {
    gdcm::ImageReader reader;
    const bool read = readImage(reader, image);
    const gdcm::DataSet& ds = reader.GetFile().GetDataSet();
    if (!ds.FindDataElement(kPixelData)) refuse(image, "no pixel data");
    if (!read) refuse(image, "cannot read its pixel data (damaged or truncated?)");
    const gdcm::DataElement& pixels = ds.GetDataElement(kPixelData);
    if (const gdcm::ByteValue* raw = pixels.GetByteValue()) {
        if (raw->GetLength() < bytes)
            refuse(image, "pixel data holds " + std::to_string(raw->GetLength()) + " bytes, Rows x Columns need " +
                              std::to_string(bytes));
    } else if (!pixels.GetSequenceOfFragments()) {
        refuse(image, "no pixel data");
    }
    const gdcm::Image& decoded = reader.GetImage();
    if (decoded.GetColumns() != unsigned(image.columns) || decoded.GetRows() != unsigned(image.rows) ||
        decoded.GetBufferLength() != bytes)
        refuse(image, "its pixel data does not match its Rows, Columns and BitsAllocated");
    std::vector<char> buffer(bytes);
    if (!decoded.GetBuffer(buffer.data()))
        refuse(image, "cannot decode its pixel data (transfer syntax " +
                          std::string(gdcm::TransferSyntax::GetTSString(decoded.GetTransferSyntax())) + ")");
    std::memcpy(out, buffer.data(), bytes);
}

// A multi-frame file: GDCM reads its geometry (per-frame functional groups included).
void multiFrameGeometry(const Image& image, detail::VolumeHeader& h) {
    gdcm::ImageReader reader;
    if (!readImage(reader, image)) refuse(image, "cannot read its pixel data (damaged or truncated?)");
    const gdcm::Image& decoded = reader.GetImage();
    const double* o = decoded.GetOrigin();
    const double* c = decoded.GetDirectionCosines();
    const double* s = decoded.GetSpacing();
    h.origin = {o[0], o[1], o[2]};
    Image oriented = image;
    oriented.orientation = std::array<double, 6>{c[0], c[1], c[2], c[3], c[4], c[5]};
    h.direction = directionOf(oriented);
    h.spacing = {s[0], s[1], s[2] > 0 ? s[2] : 1.0};
    detail::checkGeometry(h, "PixelSpacing", "ImagePositionPatient");
}

template <class T, class Out>
void rescale(const T* in, std::size_t n, double slope, double intercept, Out* out) {
    for (std::size_t k = 0; k < n; ++k) out[k] = static_cast<Out>(slope * double(in[k]) + intercept);
}

Volume readVolume(const Layout& layout) {
    const detail::VolumeHeader& h = layout.header;
    const ScalarType outType = !layout.rescaled ? h.type : layout.exactInt16 ? ScalarType::Int16 : ScalarType::Float32;
    if (layout.rescaled) detail::sampleBytes(h, outType);
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

const std::vector<Image>& pick(const std::string& path, const std::map<std::string, std::vector<Image>>& series,
                               const std::string& which) {
    const auto list = ordered(series);
    if (which.empty()) return *list.front();
    if (const auto it = series.find(which); it != series.end()) return it->second;
    if (const auto n = detail::parseInteger(which); n && *n >= 1 && std::size_t(*n) <= list.size())
        return *list[std::size_t(*n - 1)];
    throw InputError(path + ": no series \"" + printable(which) + "\" (" + std::to_string(list.size()) +
                     " series: give a SeriesInstanceUID or 1.." + std::to_string(list.size()) + "; isotrack info lists them)");
}

}  // namespace

bool isDicomPath(const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) return true;
    if (isDicomdir(path)) return true;
    const std::string ext = detail::lowerExtension(path);
    return ext == ".dcm" || ext == ".dicom";
}

std::vector<DicomSeries> listDicomSeries(const std::string& path) {
    const auto series = readSeries(path);
    std::vector<DicomSeries> out;
    for (const auto* images : ordered(series)) {
        const Image& first = images->front();
        DicomSeries s;
        s.uid = first.seriesUid;
        s.description = first.description;
        s.modality = first.modality;
        s.images = images->size();
        s.dims = {first.columns, first.rows, int(std::min<std::size_t>(sliceCount(*images), std::size_t(kMaxDimension)))};
        out.push_back(s);
    }
    return out;
}

Volume loadDicom(const std::string& path, const std::string& series) {
    const auto all = readSeries(path);
    const std::vector<Image>& images = pick(path, all, series);
    Layout layout = layoutOf(path, images);
    if (images.size() == 1 && images.front().frames > 1) multiFrameGeometry(images.front(), layout.header);
    return readVolume(layout);
}

}  // namespace isotrack
