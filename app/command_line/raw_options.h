#pragma once
// How a volume file is read when its name alone does not say: --dims, --type,
// --spacing and --endian for raw samples, --series for a DICOM folder, --array
// for a .vti, --time for a time series. The subcommands and the viewer's own
// options take the same words; reading the file is core's (isotrack/source.h).
#include <cstddef>
#include <string>
#include <vector>

#include "isotrack/io.h"

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace isotrack::command_line {

// --dims NX,NY,NZ --type T [--spacing SX,SY,SZ] [--endian little|big]; and for a
// DICOM folder or DICOMDIR, --series UID|N.
struct RawOptions {
    std::vector<int> dims;  // empty: the file has a header, the extension picks the loader
    std::string type;
    std::vector<double> spacing;
    std::string endian = "little";
    std::string series;    // DICOM: --series UID|N, empty for the largest that forms a volume
    std::string array;     // .vti: --array NAME, empty for the first one-component PointData array
    std::size_t time = 0;  // .pvd, 4D NIfTI: --time STEP, the step's index
};

// Adds the raw layout options; they need `volume` (the --volume option).
void addRawOptions(CLI::App& command, RawOptions& raw, CLI::Option* volume);

// The layout --dims, --type, --spacing and --endian give (raw.dims set); InputError
// for a --type that is not one of core's sample type names (parseScalarType).
RawLayout rawLayout(const RawOptions& raw);

}  // namespace isotrack::command_line
