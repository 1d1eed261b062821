#pragma once
// The viewer's command line: top-level options of `isotrack`, used when no
// subcommand is given (`isotrack` alone opens the window on a built-in field).
#include <memory>
#include <string>

namespace CLI {
class App;
class Option;
}  // namespace CLI
namespace isotrack::command_line {
struct RawOptions;
}

namespace isotrack::viewer {

struct ViewerOptions;

struct ViewerCommandLine {
    std::shared_ptr<ViewerOptions> options;
    std::shared_ptr<std::string> size;              // WIDTHxHEIGHT, parsed by run()
    std::shared_ptr<command_line::RawOptions> raw;  // --dims --type --spacing --endian, --series
    CLI::Option* method = nullptr;                  // --method, to tell a method given from the default
};

// Adds --volume, --field, --iso, --table, --method, --frame, --script, --json,
// --profile, --deterministic, --size, --threads and --memory-budget to `app`, in a "Viewer" group.
ViewerCommandLine addViewerOptions(CLI::App& app);

// Opens the viewer with the parsed options; returns the exit status. Throws
// isotrack's errors (bad options, a script error) for main to print.
int runViewerCommand(const ViewerCommandLine& commandLine);

}  // namespace isotrack::viewer
