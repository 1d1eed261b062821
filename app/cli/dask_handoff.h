#pragma once
// `extract` on a Dask cluster: with --scheduler ADDRESS, or a zarr volume
// (FOLDER.zarr), the command hands the extraction to the Python module's
// front end, `python3 -m isotrack.dask` (docs/distributed.md), which runs one
// task per chunk on the scheduler and stitches the surfaces. The process is
// replaced by it, so its output and exit status are the command's.
#include <optional>
#include <string>
#include <vector>

#include "isotrack/extract.h"
#include "isotrack/orientation.h"
#include "isotrack/tables.h"

namespace isotrack::cli {

struct DaskRequest {
    std::string volume;     // a zarr folder or a volume file
    std::string scheduler;  // tcp://HOST:PORT, local:N, or empty: Dask's threaded scheduler
    std::optional<double> iso;
    Method method = Method::All;
    std::vector<double> seed;  // x, y, z in the array's coordinates (index * spacing)
    std::string out, outDir;
};

// Whether `extract` goes to Dask: a scheduler is given or the volume is zarr.
bool wantsDask(const std::string& volume, const std::string& scheduler);

// InputError naming what Dask cannot do (another table, frame, --json, tree...).
void checkDaskRequest(const DaskRequest& request, TableKind table, WorldFrame frame, bool json, bool outFormat);

// Replaces the process with the module's front end; returns only to throw
// InputError when this build has no Python module or it cannot be started.
[[noreturn]] void runOnDask(const DaskRequest& request);

}  // namespace isotrack::cli
