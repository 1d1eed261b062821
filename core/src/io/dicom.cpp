// DICOM series through GDCM: see isotrack/dicom.h.
//
// Three steps. Gather: the files of a folder (recursively), of a DICOMDIR's
// image records, or the one file given. Headers: each file is read up to its
// pixel data, and the images are grouped by SeriesInstanceUID
// (dicom_gdcm.cpp). Series: the chosen one is checked as a whole and only then
// decoded, slice by slice (dicom_series.cpp).
//
// Debian's GDCM aborts or crashes on some damaged files, so all three steps run
// in a forked child (support/isolated.h): the volume, or the list of series,
// comes back through a pipe; an error comes back with its type and message; a
// crash inside GDCM becomes a LibraryFailure naming the file it was reading.
#include "isotrack/dicom.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <type_traits>

#include "dicom_internal.h"
#include "io_common.h"
#include "isotrack/errors.h"
#include "isotrack/mapped_file.h"
#include "support/isolated.h"

namespace isotrack {

namespace {

namespace fs = std::filesystem;
using namespace detail::dicom;

constexpr const char* kLibrary = "the DICOM library";
constexpr std::uint64_t kMaxText = 1 << 20;           // one string in a reply
constexpr std::uint64_t kMaxListBytes = 64ull << 20;  // a reply listing series

template <class T>
void put(detail::ReplyWriter& out, const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    out.write(&value, sizeof value);
}

void putText(detail::ReplyWriter& out, const std::string& text) {
    put(out, std::uint64_t(text.size()));
    out.write(text.data(), text.size());
}

template <class T>
T get(detail::ReplyReader& in) {
    static_assert(std::is_trivially_copyable_v<T>);
    T value;
    in.read(&value, sizeof value);
    return value;
}

std::string getText(detail::ReplyReader& in, const std::string& path) {
    const auto size = get<std::uint64_t>(in);
    if (size > kMaxText)
        throw FormatError(path + ": " + kLibrary + ": a reply string of " + std::to_string(size) + " bytes");
    std::string text(std::size_t(size), '\0');
    in.read(text.data(), text.size());
    return text;
}

// A volume's geometry as it crosses the pipe, its samples after it.
struct VolumeHead {
    Dims dims;
    ScalarType type;
    Vec3d spacing, origin;
    Mat3d direction;
    std::uint64_t bytes;
};

detail::IsolatedRun isolatedRun(const std::string& path, std::uint64_t maxReplyBytes) {
    detail::dicom::prepareGdcm();  // before the fork: the child inherits the loaded dictionaries
    return {kLibrary, path, maxReplyBytes};
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
    const auto work = [&](detail::ReplyWriter& out) {
        const SeriesMap series = readSeries(path);
        const auto list = ordered(series);
        put(out, std::uint64_t(list.size()));
        for (const auto* images : list) {
            const Image& first = images->front();
            putText(out, first.seriesUid);
            putText(out, first.description);
            putText(out, first.modality);
            put(out, std::uint64_t(images->size()));
            put(out, Dims{first.columns, first.rows,
                          int(std::min<std::size_t>(sliceCount(*images), std::size_t(kMaxDimension)))});
        }
    };
    std::vector<DicomSeries> out;
    const auto read = [&](detail::ReplyReader& in) {
        const auto count = get<std::uint64_t>(in);
        for (std::uint64_t k = 0; k < count; ++k) {
            DicomSeries s;
            s.uid = getText(in, path);
            s.description = getText(in, path);
            s.modality = getText(in, path);
            s.images = std::size_t(get<std::uint64_t>(in));
            s.dims = get<Dims>(in);
            out.push_back(std::move(s));
        }
    };
    detail::runIsolated(isolatedRun(path, kMaxListBytes), work, read);
    return out;
}

Volume loadDicom(const std::string& path, const std::string& series) {
    const auto work = [&](detail::ReplyWriter& out) {
        const SeriesMap all = readSeries(path);
        const std::vector<Image>& images = pick(path, all, series);
        Layout layout = layoutOf(path, images);
        if (images.size() == 1 && images.front().frames > 1) multiFrameGeometry(images.front(), layout.header);
        const Volume volume = readVolume(layout);
        put(out, VolumeHead{volume.dims(), volume.type(), volume.spacing(), volume.origin(), volume.direction(),
                            volume.byteSize()});
        out.write(volume.bytes(), volume.byteSize());
    };
    Volume volume;
    const auto read = [&](detail::ReplyReader& in) {
        const auto head = get<VolumeHead>(in);
        detail::VolumeHeader h;
        h.path = path;
        h.dims = head.dims;
        h.type = head.type;
        if (h.type > ScalarType::Float64 || detail::sampleBytes(h) != head.bytes)
            throw FormatError(path + ": " + kLibrary + ": the volume that came back does not match its size");
        volume = Volume(head.dims, head.type, head.spacing, head.origin);
        volume.setDirection(head.direction);
        in.read(volume.bytes(), volume.byteSize());
    };
    detail::runIsolated(isolatedRun(path, std::min(kMaxVolumeBytes, availableMemoryBytes()) + 4096), work, read);
    return volume;
}

}  // namespace isotrack
