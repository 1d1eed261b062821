#pragma once
// The DICOM loader's parts (see isotrack/dicom.h): dicom_gdcm.cpp is the GDCM
// glue (headers, DICOMDIR records, pixel decoding), dicom_series.cpp assembles a
// series into a volume without GDCM, and dicom.cpp runs both in a child process
// (support/isolated.h) and carries the result back.
#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dicom_structure.h"
#include "io_common.h"
#include "isotrack/dicom.h"
#include "isotrack/volume.h"

namespace isotrack::detail::dicom {

struct Image {  // one file's header
    std::string path;
    std::string seriesUid, description, modality;
    int rows = 0, columns = 0, frames = 1;
    int bitsAllocated = 0, bitsStored = 0, pixelRepresentation = 0, samplesPerPixel = 1;
    std::optional<Vec3d> position;
    std::optional<std::array<double, 6>> orientation;
    std::array<double, 2> pixelSpacing{1, 1};  // between rows, between columns
    double slope = 1, intercept = 0;
    DicomStructure structure;
};

using SeriesMap = std::map<std::string, std::vector<Image>>;  // by SeriesInstanceUID

// What a path holds: its images by series and, for a folder or DICOMDIR, the
// files left out.
struct Gathered {
    SeriesMap series;
    std::vector<DicomSkipped> skipped;
    bool singleFile = false;
};

// A series that does not form a volume: the message names a file.
class NotAVolume : public FormatError {
public:
    NotAVolume(DicomProblem problem, const std::string& message) : FormatError(message), problem_(problem) {}
    DicomProblem problem() const { return problem_; }

private:
    DicomProblem problem_;
};

// A series checked as one volume: the slices in order and the geometry.
struct Layout {
    std::vector<const Image*> slices;  // one per slice, or one multi-frame file
    VolumeHeader header;
    bool rescaled = false;
    bool exactInt16 = false;
};

// dicom_gdcm.cpp

// Loads GDCM's dictionaries and silences its messages; once per process, in the
// parent, before any child is forked.
void prepareGdcm();
bool isDicomdir(const std::string& path);
// Every image header at `path` (a folder, a DICOMDIR or a file), grouped by
// series. In a folder or DICOMDIR a file that cannot be read is skipped, as are
// the files in `exclude` (with the reason given there).
Gathered readSeries(const std::string& path, const std::vector<DicomSkipped>& exclude);
// Decodes one file's pixel data into `out`, which holds exactly its bytes.
void decodeInto(const Image& image, std::byte* out, std::size_t bytes);
// A multi-frame file: GDCM reads its geometry (per-frame functional groups included).
void multiFrameGeometry(const Image& image, VolumeHeader& h);

// dicom_series.cpp

[[noreturn]] void refuse(const Image& image, const std::string& problem);
// The series cannot form a volume: NotAVolume.
[[noreturn]] void refuse(const Image& image, DicomProblem why, const std::string& problem);
std::size_t sliceCount(const std::vector<Image>& images);
// Largest first, ties by UID.
std::vector<const std::vector<Image>*> ordered(const SeriesMap& series);
// `which`: a SeriesInstanceUID, or a 1-based number in `list`; InputError for another.
std::size_t pick(const std::string& path, const std::vector<const std::vector<Image>*>& list, const std::string& which);
// Each series of `gathered`, in ordered()'s order, checked as a volume; and the default.
DicomContents contentsOf(const std::string& path, const Gathered& gathered);
// A message about `file` without its leading "FILE: ", as DicomSkipped::why.
std::string reasonOf(const std::string& message, const std::string& file);
// The one-line message of DicomNoVolume.
std::string noVolumeMessage(const std::string& path, const DicomContents& contents);
// Row, column and normal directions from ImageOrientationPatient.
Mat3d directionOf(const Image& image);
Layout layoutOf(const std::string& path, const std::vector<Image>& images);
Volume readVolume(const Layout& layout);

}  // namespace isotrack::detail::dicom
