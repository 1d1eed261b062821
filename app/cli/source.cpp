#include "cli/source.h"

#include <CLI/CLI.hpp>
#include <cmath>
#include <map>
#include <utility>

#include "cli/dicom_report.h"
#include "isotrack/dicom.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/source.h"
#include "isotrack/time_series.h"

namespace isotrack::cli {

namespace {

// --type takes the names info and extract --json print (scalarTypeName).
const std::map<std::string, ScalarType> kRawTypes = [] {
    std::map<std::string, ScalarType> types;
    for (ScalarType t : {ScalarType::UInt8, ScalarType::Int8, ScalarType::UInt16, ScalarType::Int16, ScalarType::UInt32,
                         ScalarType::Int32, ScalarType::Float32, ScalarType::Float64}) {
        types[scalarTypeName(t)] = t;
    }
    return types;
}();

}  // namespace

ScalarType rawScalarType(const std::string& name) {
    const auto type = kRawTypes.find(name);
    if (type == kRawTypes.end()) throw InputError("--type: unknown sample type \"" + name + "\"");
    return type->second;
}

void addRawOptions(CLI::App& command, RawOptions& raw, CLI::Option* volume) {
    std::vector<std::string> typeNames;
    for (const auto& entry : kRawTypes) typeNames.push_back(entry.first);
    auto* dims = command.add_option("--dims", raw.dims, "Read --volume as raw samples, x fastest: NX,NY,NZ")
                     ->delimiter(',')
                     ->expected(3)
                     ->check(CLI::PositiveNumber);
    auto* type =
        command.add_option("--type", raw.type, "Raw sample type (with --dims)")->check(CLI::IsMember(typeNames));
    auto* spacing = command.add_option("--spacing", raw.spacing, "Raw sample spacing SX,SY,SZ (default 1,1,1)")
                        ->delimiter(',')
                        ->expected(3)
                        ->check(CLI::PositiveNumber);
    auto* endian = command.add_option("--endian", raw.endian, "Raw byte order: little (default) or big")
                       ->check(CLI::IsMember({"little", "big"}));
    command
        .add_option("--series", raw.series,
                    "DICOM folder or DICOMDIR: the series to read, by SeriesInstanceUID or number in `info` (default: "
                    "the largest that forms a volume)")
        ->needs(volume)
        ->excludes(dims);
    command
        .add_option("--array", raw.array,
                    "VTK XML ImageData (.vti): the PointData array to read, by Name (default: the first with one "
                    "component)")
        ->needs(volume)
        ->excludes(dims);
    command
        .add_option("--time", raw.time,
                    "A time series (.pvd collection, 4D NIfTI): the step to read, by its index in `info` (default 0)")
        ->needs(volume)
        ->excludes(dims);
    dims->needs(volume);
    dims->needs(type);
    type->needs(dims);
    spacing->needs(dims);
    endian->needs(dims);
}

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
    addRawOptions(command, options.raw, volume);
}

namespace {

// The layout --dims, --type, --spacing and --endian give.
RawLayout rawLayout(const RawOptions& raw) {
    RawLayout layout;
    for (std::size_t a = 0; a < 3; ++a) layout.dims[a] = raw.dims.at(a);
    layout.type = rawScalarType(raw.type);
    if (!raw.spacing.empty()) layout.spacing = {raw.spacing.at(0), raw.spacing.at(1), raw.spacing.at(2)};
    layout.bigEndian = raw.endian == "big";
    return layout;
}

}  // namespace

Volume loadVolumeFile(const std::string& path, const RawOptions& raw) {
    if (!raw.series.empty()) return loadDicom(path, raw.series);
    if (raw.dims.empty()) return loadTimeStep(readTimeSeries(path), raw.time, raw.array);
    return loadRaw(path, rawLayout(raw));
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
        if (!options.raw.dims.empty()) spec.raw = rawLayout(options.raw);
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
