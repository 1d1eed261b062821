#include "cli/source.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <utility>

#include "cli/dicom_report.h"
#include "isotrack/dicom.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/source.h"
#include "isotrack/time_series.h"

namespace isotrack::cli {

void addSourceOptions(CLI::App& command, SourceOptions& options) {
    std::string names;
    for (const FieldInfo& field : builtinFields()) names += std::string(names.empty() ? "" : ", ") + field.name;
    auto* volume = command.add_option("--volume", options.volumePath,
                                      "Volume file (.nrrd .nhdr .nii .nii.gz .mhd .mha .vtk .vti .pvd .dcm, a DICOM "
                                      "folder or DICOMDIR; raw with --dims)");
    auto* field = command.add_option("--field", options.fieldSpec, "Built-in field NAME[:N] (" + names + ")");
    volume->excludes(field);
    field->excludes(volume);
    command.add_option("--iso", options.iso,
                       "Isovalue (default: the field's own, or a file's suggested isovalue, as `isotrack info` "
                       "prints it)");
    command_line::addRawOptions(command, options.raw, volume);
}

Volume loadVolumeFile(const std::string& path, const command_line::RawOptions& raw) {
    if (!raw.series.empty()) return loadDicom(path, raw.series);
    if (raw.dims.empty()) return loadTimeStep(readTimeSeries(path), raw.time, raw.array);
    return loadRaw(path, command_line::rawLayout(raw));
}

void checkSourceOptions(const SourceOptions& options) {
    if (options.volumePath.empty() == options.fieldSpec.empty()) {
        throw InputError("give exactly one of --volume FILE or --field NAME[:N]");
    }
    if (!options.fieldSpec.empty()) parseFieldSpec(options.fieldSpec);
    if (options.iso && !std::isfinite(*options.iso)) throw InputError("--iso: must be a finite number");
}

Source loadSource(const SourceOptions& options) {
    checkSourceOptions(options);
    VolumeSource spec;
    if (!options.fieldSpec.empty()) {
        spec.text = options.fieldSpec;
    } else {
        spec.kind = VolumeSource::Kind::File;
        spec.text = options.volumePath;
        if (!options.raw.dims.empty()) spec.raw = command_line::rawLayout(options.raw);
        spec.series = options.raw.series;
        spec.array = options.raw.array;
        spec.time = options.raw.time;
    }
    LoadedSource loaded;
    try {
        // With --iso given, nothing reads the samples yet: a mapped file is read only where extraction goes.
        loaded = isotrack::loadSource(spec, options.iso ? DefaultIso::Skip : DefaultIso::Suggest);
    } catch (const DicomNoVolume& e) {
        warnSkipped(e.contents());
        throw;
    }
    if (loaded.dicom) warnSkipped(*loaded.dicom);
    Source source;
    source.volume = std::move(loaded.volume);
    source.name = std::move(loaded.name);
    source.dicom = std::move(loaded.dicom);
    source.dicomSeries = loaded.dicomSeries;
    if (options.iso) {
        source.iso = *options.iso;
    } else if (loaded.defaultIso) {
        source.iso = *loaded.defaultIso;
    } else {
        throw InputError(options.volumePath + ": no finite samples, give --iso");
    }
    return source;
}

std::vector<double> seedInGrid(const Volume& volume, const std::vector<double>& seed, WorldFrame frame) {
    const FrameTransform transform = gridToFrame(volume, frame);
    if (seed.size() != 3 || transform.identity()) return seed;
    const Vec3d grid = transform.toGrid({seed[0], seed[1], seed[2]});
    return {grid[0], grid[1], grid[2]};
}

}  // namespace isotrack::cli
