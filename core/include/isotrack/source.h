#pragma once
// Where a volume comes from: a built-in field or a file, with the isovalue to
// use when none is given.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>

#include "isotrack/dicom.h"
#include "isotrack/io.h"
#include "isotrack/volume.h"

namespace isotrack {

struct VolumeSource {
    enum class Kind { Field, File };
    Kind kind = Kind::Field;
    std::string text;              // Field: "NAME[:N]" (parseFieldSpec); File: its path
    std::optional<RawLayout> raw;  // File: read as raw samples in this layout, not by its extension
    std::string series;            // File: the DICOM series to read (UID or number), not the largest
    std::string array;             // File (.vti): the PointData array to read, not the first scalar one
    std::size_t time = 0;          // File (.pvd, 4D NIfTI): the time step to read (isotrack/time_series.h)

    static VolumeSource field(std::string spec) {
        return VolumeSource{Kind::Field, std::move(spec), std::nullopt, "", "", 0};
    }
    static VolumeSource file(std::string path, std::optional<RawLayout> raw = std::nullopt) {
        return VolumeSource{Kind::File, std::move(path), std::move(raw), "", "", 0};
    }
    // The same data: kind, text, series, array, time, and whether (not how) it is read as raw samples.
    friend bool operator==(const VolumeSource& a, const VolumeSource& b) {
        return a.kind == b.kind && a.text == b.text && a.raw.has_value() == b.raw.has_value() && a.series == b.series &&
               a.array == b.array && a.time == b.time;
    }
    friend bool operator!=(const VolumeSource& a, const VolumeSource& b) { return !(a == b); }
};

struct LoadedSource {
    Volume volume;
    std::string name;  // Field: "NAME:N", the canonical name; File: its path
    // Field: the field's own isovalue. File: isovalueSuggestion's (isotrack/isovalue.h:
    // the valley above the histogram's tallest peak, else Otsu's threshold), none when
    // it has no finite sample.
    std::optional<double> defaultIso;
    // A DICOM file, folder or DICOMDIR: its series, the one read (dicomSeries)
    // and the files skipped, for the front end to report.
    std::optional<DicomContents> dicom;
    std::size_t dicomSeries = 0;
};

// Whether loadSource works out a file's default isovalue: Suggest reads every
// sample (the histogram); Skip leaves defaultIso empty, so that a mapped file's
// samples are read only where an extraction goes (isotrack/mapped_file.h).
enum class DefaultIso { Suggest, Skip };

// Builds the field or reads the file. Throws InputError and FormatError as
// parseFieldSpec, makeField, loadVolume, loadRaw and readDicom do (DicomNoVolume
// for a DICOM folder where no series forms a volume).
LoadedSource loadSource(const VolumeSource& source, DefaultIso defaultIso = DefaultIso::Suggest);

}  // namespace isotrack
