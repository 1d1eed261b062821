// The DICOM loader's GDCM glue (see dicom_internal.h): each file's header up to
// its pixel data, a DICOMDIR's image records, and a file's decoded pixels. This
// code runs in the child process of dicom.cpp; every call into GDCM is a
// LibraryCall and names its file first (noteSubject), so that a crash inside
// GDCM becomes a one-line error naming the file.
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
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>

#include "dicom_internal.h"
#include "isotrack/errors.h"
#include "support/isolated.h"

namespace isotrack::detail::dicom {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kMaxFiles = 100000;

const gdcm::Tag kPixelData(0x7fe0, 0x0010);

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
        const auto v = parseFinite(trimmed(text.substr(start, end - start)));
        if (!v) return std::nullopt;
        out.push_back(*v);
        start = end + 1;
    }
    if (out.size() != count) return std::nullopt;
    return out;
}

// The header elements isotrack reads.
constexpr std::array<std::uint32_t, 15> kHeaderTags{0x00080060, 0x0008103e, 0x0020000e, 0x00200032, 0x00200037,
                                                    0x00280002, 0x00280008, 0x00280010, 0x00280011, 0x00280030,
                                                    0x00280100, 0x00280101, 0x00280103, 0x00281052, 0x00281053};

// Their values as text, as GDCM reads them up to the pixel data; nullopt when
// GDCM cannot read the header.
std::optional<std::map<std::uint32_t, std::string>> headerTexts(const std::string& path) {
    noteSubject(path);
    const LibraryCall gdcmCall;
    gdcm::Reader reader;
    reader.SetFileName(path.c_str());
    try {
        if (!reader.ReadUpToTag(kPixelData, std::set<gdcm::Tag>())) return std::nullopt;
    } catch (const std::exception&) {
        return std::nullopt;
    }
    gdcm::StringFilter filter;
    filter.SetFile(reader.GetFile());
    std::map<std::uint32_t, std::string> texts;
    for (const std::uint32_t tag : kHeaderTags)
        texts[tag] = trimmed(filter.ToString(gdcm::Tag(std::uint16_t(tag >> 16), std::uint16_t(tag & 0xffff))));
    return texts;
}

class HeaderFields {
public:
    HeaderFields(std::map<std::uint32_t, std::string> texts, std::string path)
        : texts_(std::move(texts)), path_(std::move(path)) {}

    std::string text(std::uint16_t group, std::uint16_t element) const {
        return texts_.at(std::uint32_t(group) << 16 | element);
    }
    bool has(std::uint16_t group, std::uint16_t element) const { return !text(group, element).empty(); }
    std::optional<std::vector<double>> values(std::uint16_t group, std::uint16_t element, const char* name,
                                              std::size_t count) const {
        const std::string t = text(group, element);
        if (t.empty()) return std::nullopt;
        auto v = numbers(t, count);
        if (!v)
            throw FormatError(path_ + ": field \"" + name + "\": expected " + std::to_string(count) +
                              " numbers, got \"" + printable(t) + "\"");
        return v;
    }
    int integer(std::uint16_t group, std::uint16_t element, const char* name, int otherwise, int lo, int hi) const {
        const auto v = values(group, element, name, 1);
        if (!v) return otherwise;
        const double x = (*v)[0];
        if (x != std::floor(x) || x < lo || x > hi)
            throw FormatError(path_ + ": field \"" + name + "\": expected a whole number in " + std::to_string(lo) +
                              ".." + std::to_string(hi) + ", got " + numberText(x));
        return int(x);
    }

private:
    std::map<std::uint32_t, std::string> texts_;
    std::string path_;
};

// GDCM asserts when a standard element it reads carries a VR the dictionary
// does not allow, so such a file is refused first.
void checkVrs(const std::string& path, const DicomStructure& structure) {
    noteSubject(path);
    const LibraryCall gdcmCall;
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
            throw FormatError(path + ": element " + name + " has VR " + printable(spelled) +
                              ", the standard gives it " + gdcm::VR::GetVRString(expected));
        }
    }
}

// The header of one file, up to its pixel data; a FormatError naming the file
// for one that is not DICOM, holds no image, or cannot be read.
Image readImageHeader(const std::string& path) {
    Image image;
    image.path = path;
    // GDCM only ever sees files whose every length has been checked.
    try {
        image.structure = checkDicomStructure(path);
    } catch (const FormatError& e) {
        if (hasDicomMagic(path)) throw;
        throw FormatError(path +
                          ": not a DICOM file (no \"DICM\" after a 128-byte preamble, nor a dataset without one)");
    }
    checkVrs(path, image.structure);
    auto texts = headerTexts(path);
    if (!texts && image.structure.hasMagic) throw FormatError(path + ": its DICOM header cannot be read");
    if (!texts) throw FormatError(path + ": not a DICOM file, or its header is damaged or truncated");
    const HeaderFields f(std::move(*texts), path);
    if (!f.has(0x0028, 0x0010) || !f.has(0x0028, 0x0011))
        throw FormatError(path + ": holds no image (no Rows or Columns)");

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
    if (const auto v = f.values(0x0020, 0x0032, "ImagePositionPatient", 3))
        image.position = Vec3d{(*v)[0], (*v)[1], (*v)[2]};
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
        throw FormatError(path + ": field \"BitsStored\": " + std::to_string(image.bitsStored) +
                          " exceeds BitsAllocated " + std::to_string(image.bitsAllocated));
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
    if (!hasDicomMagic(path)) throw FormatError(path + ": not a DICOMDIR (no \"DICM\" after a 128-byte preamble)");
    checkVrs(path, checkDicomStructure(path));
    noteSubject(path);
    const LibraryCall gdcmCall;  // the records are walked through GDCM
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
        if (files.size() > kMaxFiles)
            throw FormatError(path + ": DICOMDIR lists more than " + std::to_string(kMaxFiles) + " images");
    }
    if (files.empty()) throw FormatError(path + ": DICOMDIR lists no images");
    return files;
}

}  // namespace

void prepareGdcm() {
    static std::once_flag once;
    std::call_once(once, [] {
        gdcm::Trace::SetDebug(false);
        gdcm::Trace::SetWarning(false);
        gdcm::Trace::SetError(false);
        gdcm::Global::GetInstance().GetDicts();  // children inherit them, loaded
    });
}

bool isDicomdir(const std::string& path) { return lowerCase(fs::path(path).filename().string()) == "dicomdir"; }

Gathered readSeries(const std::string& path, const std::vector<DicomSkipped>& exclude) {
    std::error_code ec;
    std::vector<std::string> files;
    Gathered out;
    if (fs::is_directory(path, ec)) {
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
        openForReading(path);  // names a missing file or a device plainly
        files = dicomdirFiles(path);
    } else {
        openForReading(path);
        Image image = readImageHeader(path);  // a file named directly must be an image
        out.series[image.seriesUid].push_back(std::move(image));
        out.singleFile = true;
        return out;
    }
    std::map<std::string, std::string> excluded;
    for (const DicomSkipped& s : exclude) excluded[s.file] = s.why;
    for (const std::string& file : files) {
        if (const auto it = excluded.find(file); it != excluded.end()) {
            out.skipped.push_back({file, it->second});
            continue;
        }
        // A file left out is reported, never dropped silently: it may have
        // been a slice of the series the user wants.
        try {
            Image image = readImageHeader(file);
            out.series[image.seriesUid].push_back(std::move(image));
        } catch (const FormatError& e) {
            out.skipped.push_back({file, reasonOf(e.what(), file)});
        }
    }
    return out;
}

namespace {

// Reads a file through GDCM's image reader; false when it cannot (GDCM may throw on damaged files).
bool readImage(gdcm::ImageReader& reader, const Image& image) {
    noteSubject(image.path);
    reader.SetFileName(image.path.c_str());
    try {
        return reader.Read();
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace

void decodeInto(const Image& image, std::byte* out, std::size_t bytes) {
    const LibraryCall gdcmCall;
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
    if (!decoded.GetBuffer(reinterpret_cast<char*>(out)))  // exactly `bytes`, checked above
        refuse(image, "cannot decode its pixel data (transfer syntax " +
                          std::string(gdcm::TransferSyntax::GetTSString(decoded.GetTransferSyntax())) + ")");
}

void multiFrameGeometry(const Image& image, VolumeHeader& h) {
    std::array<double, 3> o{}, s{};
    std::array<double, 6> c{};
    {
        const LibraryCall gdcmCall;
        gdcm::ImageReader reader;
        if (!readImage(reader, image)) refuse(image, "cannot read its pixel data (damaged or truncated?)");
        const gdcm::Image& decoded = reader.GetImage();
        std::copy_n(decoded.GetOrigin(), 3, o.begin());
        std::copy_n(decoded.GetDirectionCosines(), 6, c.begin());
        std::copy_n(decoded.GetSpacing(), 3, s.begin());
    }
    h.origin = {o[0], o[1], o[2]};
    Image oriented = image;
    oriented.orientation = c;
    h.direction = directionOf(oriented);
    h.spacing = {s[0], s[1], s[2] > 0 ? s[2] : 1.0};
    checkGeometry(h, "PixelSpacing", "ImagePositionPatient");
}

}  // namespace isotrack::detail::dicom
