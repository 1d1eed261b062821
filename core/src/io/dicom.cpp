// DICOM series through GDCM: see isotrack/dicom.h.
//
// Three steps. Gather: the files of a folder (recursively), of a DICOMDIR's
// image records, or the one file given. Headers: each file is read up to its
// pixel data (a file of a folder that cannot be is skipped), and the images
// are grouped by SeriesInstanceUID (dicom_gdcm.cpp). Series: each is checked
// as a volume from its headers; the chosen one is then decoded, slice by slice
// (dicom_series.cpp).
//
// Debian's GDCM aborts or crashes on some damaged files, so all three steps run
// in a forked child (support/isolated.h): the contents (series and skipped
// files) come back through a pipe, then the volume; an error comes back with
// its type and message; a crash inside GDCM becomes a LibraryFailure naming the
// file it was reading. When that happens while the headers of a folder are
// read, the parent skips that file and forks again.
#include "isotrack/dicom.h"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
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

void putContents(detail::ReplyWriter& out, const DicomContents& contents) {
    put(out, std::uint64_t(contents.series.size()));
    for (const DicomSeries& s : contents.series) {
        putText(out, s.uid);
        putText(out, s.description);
        putText(out, s.modality);
        put(out, std::uint64_t(s.images));
        put(out, s.dims);
        put(out, s.problem);
        putText(out, s.detail);
    }
    put(out, std::uint64_t(contents.skipped.size()));
    for (const DicomSkipped& s : contents.skipped) {
        putText(out, s.file);
        putText(out, s.why);
    }
    put(out, std::uint64_t(contents.chosen ? *contents.chosen + 1 : 0));
}

DicomContents getContents(detail::ReplyReader& in, const std::string& path) {
    DicomContents contents;
    const auto count = get<std::uint64_t>(in);
    for (std::uint64_t k = 0; k < count; ++k) {
        DicomSeries s;
        s.uid = getText(in, path);
        s.description = getText(in, path);
        s.modality = getText(in, path);
        s.images = std::size_t(get<std::uint64_t>(in));
        s.dims = get<Dims>(in);
        s.problem = get<DicomProblem>(in);
        if (int(s.problem) < 0 || s.problem > DicomProblem::PixelDataShort)
            throw FormatError(path + ": " + kLibrary + ": a series problem of " + std::to_string(int(s.problem)));
        s.detail = getText(in, path);
        contents.series.push_back(std::move(s));
    }
    const auto skipped = get<std::uint64_t>(in);
    for (std::uint64_t k = 0; k < skipped; ++k) {
        DicomSkipped s;
        s.file = getText(in, path);
        s.why = getText(in, path);
        contents.skipped.push_back(std::move(s));
    }
    const auto chosen = get<std::uint64_t>(in);
    if (chosen > contents.series.size())
        throw FormatError(path + ": " + kLibrary + ": series " + std::to_string(chosen) + " of " +
                          std::to_string(contents.series.size()) + " chosen");
    if (chosen) contents.chosen = std::size_t(chosen - 1);
    return contents;
}

// A file GDCM crashes on while the headers are read is skipped, and the headers
// read again without it, up to this many files; a crash while decoding the
// chosen series stays an error.
constexpr std::size_t kMaxCrashingFiles = 16;

// Runs `work` (headers, then whatever it sends after the contents) in a child,
// again without each file GDCM crashed on while reading the headers of a folder
// or DICOMDIR. `read` gets the contents, then reads the rest.
void runScan(const std::string& path, std::uint64_t maxReplyBytes,
             const std::function<void(detail::ReplyWriter&, const Gathered&)>& work,
             const std::function<void(detail::ReplyReader&, DicomContents)>& read) {
    std::error_code ec;
    const bool many = fs::is_directory(path, ec) || isDicomdir(path);
    std::vector<DicomSkipped> crashed;
    while (true) {
        bool scanned = false;
        try {
            detail::runIsolated(
                isolatedRun(path, maxReplyBytes),
                [&](detail::ReplyWriter& out) { work(out, readSeries(path, crashed)); },
                [&](detail::ReplyReader& in) {
                    DicomContents contents = getContents(in, path);
                    scanned = true;
                    read(in, std::move(contents));
                });
            return;
        } catch (const LibraryFailure& e) {
            if (scanned || !many || e.file().empty() || e.file() == path || crashed.size() >= kMaxCrashingFiles) throw;
            crashed.push_back({e.file(), reasonOf(e.what(), e.file())});
        }
    }
}

}  // namespace

bool isDicomPath(const std::string& path) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) return true;
    if (isDicomdir(path)) return true;
    const std::string ext = detail::lowerExtension(path);
    return ext == ".dcm" || ext == ".dicom";
}

DicomContents scanDicom(const std::string& path) {
    DicomContents contents;
    runScan(
        path, kMaxListBytes,
        [&](detail::ReplyWriter& out, const Gathered& gathered) { putContents(out, contentsOf(path, gathered)); },
        [&](detail::ReplyReader&, DicomContents read) { contents = std::move(read); });
    return contents;
}

DicomVolume readDicom(const std::string& path, const std::string& series) {
    const auto work = [&](detail::ReplyWriter& out, const Gathered& gathered) {
        const DicomContents contents = contentsOf(path, gathered);
        putContents(out, contents);
        const auto list = ordered(gathered.series);
        std::optional<std::size_t> index = contents.chosen;
        if (!series.empty() && !list.empty()) index = pick(path, list, series);
        put(out, std::uint64_t(index ? *index + 1 : 0));
        if (!index) return;
        const std::vector<Image>& images = *list[*index];
        Layout layout = layoutOf(path, images);
        if (images.size() == 1 && images.front().frames > 1) multiFrameGeometry(images.front(), layout.header);
        const Volume volume = readVolume(layout);
        put(out, VolumeHead{volume.dims(), volume.type(), volume.spacing(), volume.origin(), volume.direction(),
                            volume.byteSize()});
        out.write(volume.bytes(), volume.byteSize());
    };
    DicomVolume result;
    const auto read = [&](detail::ReplyReader& in, DicomContents contents) {
        result.contents = std::move(contents);
        const auto index = get<std::uint64_t>(in);
        if (index > result.contents.series.size())
            throw FormatError(path + ": " + kLibrary + ": series " + std::to_string(index) + " read of " +
                              std::to_string(result.contents.series.size()));
        if (index == 0) throw DicomNoVolume(noVolumeMessage(path, result.contents), result.contents);
        result.series = std::size_t(index - 1);
        const auto head = get<VolumeHead>(in);
        detail::VolumeHeader h;
        h.path = path;
        h.dims = head.dims;
        h.type = head.type;
        if (h.type > ScalarType::Float64 || detail::sampleBytes(h) != head.bytes)
            throw FormatError(path + ": " + kLibrary + ": the volume that came back does not match its size");
        result.volume = Volume(head.dims, head.type, head.spacing, head.origin);
        result.volume.setDirection(head.direction);
        in.read(result.volume.bytes(), result.volume.byteSize());
    };
    runScan(path, kMaxListBytes + std::min(kMaxVolumeBytes, availableMemoryBytes()) + 4096, work, read);
    return result;
}

Volume loadDicom(const std::string& path, const std::string& series) { return readDicom(path, series).volume; }

}  // namespace isotrack
