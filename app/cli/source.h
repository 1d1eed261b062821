#pragma once
// The volume a command works on: a file (--volume) or a built-in field (--field),
// and the isovalue (--iso, defaulting to the field's own, or to a file's suggested
// isovalue: core's isovalueSuggestion, isotrack/isovalue.h, the valley above the
// histogram's tallest peak, else Otsu's threshold). Loading is core's
// (isotrack/source.h); a headerless file is read as raw samples when its layout
// is given with --dims (command_line/raw_options.h).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "command_line/raw_options.h"
#include "isotrack/dicom.h"
#include "isotrack/errors.h"
#include "isotrack/orientation.h"
#include "isotrack/volume.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace isotrack::cli {

struct SourceOptions {
    std::string volumePath;
    std::string fieldSpec;
    std::optional<double> iso;
    command_line::RawOptions raw;
};

// Adds --volume, --field (exactly one required), --iso and the raw layout options to `command`.
void addSourceOptions(CLI::App& command, SourceOptions& options);

// Reads the file: as raw samples when raw.dims is set, else by its extension.
Volume loadVolumeFile(const std::string& path, const command_line::RawOptions& raw);

struct Source {
    Volume volume;
    std::string name;  // the file path or the field spec
    double iso = 0.0;
    std::optional<DicomContents> dicom;  // DICOM: the series, the one read and the files skipped
    std::size_t dicomSeries = 0;
};

// Runs work() on the source's volume; a WorkingMemoryError from core (work
// too large for the memory available) comes out naming the file or field.
template <class Work>
decltype(auto) namingSource(const Source& source, Work&& work) {
    try {
        return work();
    } catch (const WorkingMemoryError& e) {
        throw WorkingMemoryError(source.name + ": " + e.what());
    }
}

// What can be checked before anything is read: one of --volume and --field,
// a well-formed field spec, a finite --iso. Throws InputError.
void checkSourceOptions(const SourceOptions& options);

// Loads the file or builds the field, after checkSourceOptions; warns on stderr of
// each DICOM file skipped. Throws isotrack's typed errors.
Source loadSource(const SourceOptions& options);

// A --seed point given in `frame` (the LPS world unless --frame says otherwise)
// in the grid coordinates the extractors work in; an empty seed stays empty.
std::vector<double> seedInGrid(const Volume& volume, const std::vector<double>& seed, WorldFrame frame);

}  // namespace isotrack::cli
