#include "command_line/raw_options.h"

#include <CLI/CLI.hpp>
#include <set>
#include <string>
#include <vector>

#include "isotrack/volume.h"

namespace isotrack::command_line {

void addRawOptions(CLI::App& command, RawOptions& raw, CLI::Option* volume) {
    // --type takes the names info and extract --json print (scalarTypeName), sorted for --help.
    std::set<std::string> typeNames;
    for (ScalarType type : kScalarTypes) typeNames.insert(scalarTypeName(type));
    auto* dims = command.add_option("--dims", raw.dims, "Read --volume as raw samples, x fastest: NX,NY,NZ")
                     ->delimiter(',')
                     ->expected(3)
                     ->check(CLI::PositiveNumber);
    auto* type = command.add_option("--type", raw.type, "Raw sample type (with --dims)")
                     ->check(CLI::IsMember(std::vector<std::string>(typeNames.begin(), typeNames.end())));
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

RawLayout rawLayout(const RawOptions& raw) {
    RawLayout layout;
    for (std::size_t a = 0; a < 3; ++a) layout.dims[a] = raw.dims.at(a);
    layout.type = parseScalarType(raw.type);
    if (!raw.spacing.empty()) layout.spacing = {raw.spacing.at(0), raw.spacing.at(1), raw.spacing.at(2)};
    layout.bigEndian = raw.endian == "big";
    return layout;
}

}  // namespace isotrack::command_line
