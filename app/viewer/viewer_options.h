#pragma once
// The viewer's command line: top-level options of `isotrack`, used when no
// subcommand is given (`isotrack` alone opens the window on a built-in field).
#include <memory>
#include <string>

namespace CLI {
class App;
}
namespace isotrack::cli {
struct RawOptions;
}

namespace isotrack::viewer {

struct ViewerOptions;

struct ViewerCommandLine {
    std::shared_ptr<ViewerOptions> options;
    std::shared_ptr<std::string> size;     // WIDTHxHEIGHT, parsed by run()
    std::shared_ptr<cli::RawOptions> raw;  // --dims --type --spacing --endian
};

// Adds --volume, --field, --iso, --table, --method, --frame, --script, --json,
// --profile, --deterministic, --size and --threads to `app`, in a "Viewer" group.
ViewerCommandLine addViewerOptions(CLI::App& app);

// Opens the viewer with the parsed options; returns the exit status. Throws
// isotrack's errors (bad options, a script error) for main to print.
int runViewerCommand(const ViewerCommandLine& commandLine);

}  // namespace isotrack::viewer
