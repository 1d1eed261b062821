#pragma once
// Where a volume comes from: a built-in field or a file, with the isovalue to
// use when none is given.
#include <optional>
#include <string>

#include "isotrack/io.h"
#include "isotrack/volume.h"

namespace isotrack {

struct VolumeSource {
    enum class Kind { Field, File };
    Kind kind = Kind::Field;
    std::string text;              // Field: "NAME[:N]" (parseFieldSpec); File: its path
    std::optional<RawLayout> raw;  // File: read as raw samples in this layout, not by its extension
    std::string series;            // File: the DICOM series to read (UID or number), not the largest
};

struct LoadedSource {
    Volume volume;
    std::string name;  // Field: "NAME:N", the canonical name; File: its path
    // Field: the field's own isovalue. File: suggestIsovalue's (isotrack/isovalue.h,
    // the valley above the histogram's tallest peak), none when it has no finite sample.
    std::optional<double> defaultIso;
};

// Builds the field or reads the file. Throws InputError and FormatError as
// parseFieldSpec, makeField, loadVolume, loadRaw and loadDicom do.
LoadedSource loadSource(const VolumeSource& source);

}  // namespace isotrack
