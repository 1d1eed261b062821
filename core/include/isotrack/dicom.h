#pragma once
// DICOM volumes, read through GDCM: a folder of slices (searched recursively),
// a DICOMDIR (the images it lists), or a single file (one slice or multi-frame).
//
// A folder or DICOMDIR is taken as it comes: each file is read on its own, and
// one that is not a DICOM image, or cannot be read (truncated, damaged, a
// header isotrack refuses, a file GDCM crashes on), is skipped and listed with
// why. The images left are grouped by SeriesInstanceUID, and each series is
// checked as a volume without decoding it; the default is the largest series
// that forms one. A file named directly is read as it is: any problem is an
// error.
//
// Slices of a series are sorted by ImagePositionPatient along the slice normal
// (the cross product of ImageOrientationPatient's row and column directions);
// the slice spacing comes from those positions, never from SliceThickness.
// Uneven spacing, a gantry tilt (positions off the normal), mixed sizes or
// orientations, and duplicate positions keep a series from forming a volume
// (DicomProblem), and reading it is a FormatError naming a file. Samples get
// RescaleSlope/RescaleIntercept: they stay int16 when the result is exactly an
// int16 for every sample the header allows, else they become float32. The
// direction is DICOM's own LPS. Compressed transfer syntaxes are whatever GDCM
// decodes (JPEG, JPEG-LS, JPEG 2000, RLE, deflate).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "isotrack/errors.h"
#include "isotrack/volume.h"

namespace isotrack {

// Why a series does not form a volume.
enum class DicomProblem {
    None,
    SingleSlice,        // one single-frame image: readable, but not a volume to extract from
    MixedSizes,         // Rows or Columns differ between files
    MixedSampleTypes,   // BitsAllocated or PixelRepresentation differ
    MixedPixelSpacing,  // PixelSpacing differs
    MultiFrameAmongOthers,
    Unordered,         // no ImagePositionPatient or ImageOrientationPatient to order slices by
    BadOrientation,    // ImageOrientationPatient is not two orthogonal unit vectors
    MixedOrientation,  // ImageOrientationPatient differs per slice (radial, localizers)
    DuplicateSlices,   // two slices at one position
    UnevenSpacing,     // a missing slice, or slices of two stacks
    GantryTilt,        // positions drift across the normal
    TooLarge,          // more slices or samples than isotrack reads
    BadGeometry,       // spacing or positions not finite, or out of range
    PixelDataShort,    // a file holds less pixel data than its header says
};

// A short stable text for each: "single slice", "orientation differs per slice", ...
const char* dicomProblemText(DicomProblem problem);

struct DicomSeries {
    std::string uid;          // SeriesInstanceUID
    std::string description;  // SeriesDescription, may be empty
    std::string modality;
    std::size_t images = 0;  // files; the frames of a multi-frame file count as its slices
    Dims dims{0, 0, 0};      // columns, rows, slices
    DicomProblem problem = DicomProblem::None;
    std::string detail;  // the problem as one line naming a file; empty with no problem or a single slice
    bool formsVolume() const { return problem == DicomProblem::None; }
};

// A file of a folder or DICOMDIR left out, and why (without the file's name).
struct DicomSkipped {
    std::string file;
    std::string why;
};

struct DicomContents {
    std::vector<DicomSeries> series;    // largest (most slices) first, ties by UID: --series N counts here
    std::vector<DicomSkipped> skipped;  // in path order
    // The series read when none is named: the largest that forms a volume, or
    // a single file's own; none when no series forms a volume.
    std::optional<std::size_t> chosen;
};

// No series at a folder or DICOMDIR forms a volume (or it holds no image): the
// message lists the series in one line; contents() has them, and the skipped files.
class DicomNoVolume : public FormatError {
public:
    DicomNoVolume(const std::string& message, DicomContents contents)
        : FormatError(message), contents_(std::move(contents)) {}
    const DicomContents& contents() const { return contents_; }

private:
    DicomContents contents_;
};

// True for a folder, a file named DICOMDIR, or a .dcm/.dicom file.
bool isDicomPath(const std::string& path);

// What `path` holds, without decoding any pixel data.
DicomContents scanDicom(const std::string& path);

struct DicomVolume {
    Volume volume;
    DicomContents contents;
    std::size_t series = 0;  // the index of the series read, in contents.series
};

// One series: `series` empty picks contents.chosen (DicomNoVolume when there is
// none), else a SeriesInstanceUID or its 1-based number in contents.series.
DicomVolume readDicom(const std::string& path, const std::string& series = "");
Volume loadDicom(const std::string& path, const std::string& series = "");

}  // namespace isotrack
