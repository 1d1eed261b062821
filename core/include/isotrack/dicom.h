#pragma once
// DICOM volumes, read through GDCM: a folder of slices (searched recursively),
// a DICOMDIR (the images it lists), or a single file (one slice or multi-frame).
//
// Slices of a series are sorted by ImagePositionPatient along the slice normal
// (the cross product of ImageOrientationPatient's row and column directions);
// the slice spacing comes from those positions, never from SliceThickness.
// Uneven spacing, a gantry tilt (positions off the normal), mixed sizes or
// orientations, and duplicate positions are FormatErrors naming a file. Samples
// get RescaleSlope/RescaleIntercept: they stay int16 when the result is exactly
// an int16 for every sample the header allows, else they become float32. The
// direction is DICOM's own LPS. Compressed transfer syntaxes are whatever GDCM
// decodes (JPEG, JPEG-LS, JPEG 2000, RLE, deflate).
#include <cstddef>
#include <string>
#include <vector>

#include "isotrack/volume.h"

namespace isotrack {

struct DicomSeries {
    std::string uid;          // SeriesInstanceUID
    std::string description;  // SeriesDescription, may be empty
    std::string modality;
    std::size_t images = 0;  // files; the frames of a multi-frame file count as its slices
    Dims dims{0, 0, 0};      // columns, rows, slices
};

// True for a folder, a file named DICOMDIR, or a .dcm/.dicom file.
bool isDicomPath(const std::string& path);

// The series at `path`, largest (most slices) first, ties by UID.
std::vector<DicomSeries> listDicomSeries(const std::string& path);

// One series: `series` empty picks the largest, else a SeriesInstanceUID or its
// 1-based number in listDicomSeries' order.
Volume loadDicom(const std::string& path, const std::string& series = "");

}  // namespace isotrack
