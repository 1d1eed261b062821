#include "viewer/viewer_options.h"

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>

#include "command_line/raw_options.h"
#include "command_line/vocabulary.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "viewer/viewer.h"

namespace isotrack::viewer {
namespace {

constexpr int kMinSide = 400, kMaxSide = 8192;

int parseSide(const std::string& text, const std::string& whole) {
    int value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || ptr != end || value < kMinSide || value > kMaxSide) {
        throw InputError("--size \"" + whole + "\": each side must be an integer in " + std::to_string(kMinSide) +
                         ".." + std::to_string(kMaxSide));
    }
    return value;
}

}  // namespace

ViewerCommandLine addViewerOptions(CLI::App& app) {
    ViewerCommandLine commandLine{std::make_shared<ViewerOptions>(), std::make_shared<std::string>(),
                                  std::make_shared<command_line::RawOptions>()};
    ViewerOptions& o = *commandLine.options;
    CLI::Option_group* group =
        app.add_option_group("Viewer", "With no subcommand, isotrack opens the interactive viewer (needs a display)");
    CLI::Option* volume = group->add_option("--volume", o.volumePath, "Open this volume file in the viewer");
    CLI::Option* field = group->add_option(
        "--field", o.fieldSpec, std::string("Open a built-in field NAME[:N] (default ") + kDefaultField + ")");
    volume->excludes(field);
    command_line::addRawOptions(*group, *commandLine.raw, volume);
    group->add_option("--iso", o.iso,
                      "Isovalue (default: the field's own, or a file's suggested isovalue, as `isotrack info` "
                      "prints it)");
    command_line::addTableOption(*group, o.table);
    commandLine.method =
        command_line::addMethodOption(*group, o.method,
                                      "mc: exhaustive; track: surfaces you click; all: every surface (default); "
                                      "tree: every surface from the contour tree");
    command_line::addFrameOption(
        *group, o.frame, "Frame of exported meshes: lps (default, world), ras or voxel; the view stays in the grid");
    group->add_option("--script", o.script, "Run the commands in FILE, one per line, in the window");
    group->add_flag("--json", o.json, "On exit, print a JSON summary (surfaces, CPU and GPU bytes, frames)");
    group->add_option("--profile", o.profile, "Write a Chrome trace of every frame to FILE.json (opens in Perfetto)");
    group->add_flag("--deterministic", o.deterministic,
                    "Freeze the timings the panel shows and grow a fixed number of cells per frame, for "
                    "reproducible screenshots");
    group->add_flag("--no-vsync", o.noVsync, "Do not wait for the display's refresh between frames");
    group->add_option("--size", *commandLine.size, "Window size WIDTHxHEIGHT (default 1280x800)");
    group
        ->add_option("--memory-budget", o.memoryBudgetGiB,
                     "GiB a mapped volume may take before the viewer asks: bigger ones open without reading their "
                     "samples (give --iso), and mc, all and tree ask before they read them (default: half the "
                     "memory available)")
        ->check(CLI::PositiveNumber);
    group->add_option("--threads", o.threads, "Extraction threads (default: one fewer than the hardware threads)")
        ->check(CLI::Range(1, 256));
    return commandLine;
}

int runViewerCommand(const ViewerCommandLine& commandLine) {
    ViewerOptions options = *commandLine.options;
    if (options.iso && !std::isfinite(*options.iso)) throw InputError("--iso: must be a finite number");
    options.methodGiven = commandLine.method != nullptr && commandLine.method->count() > 0;
    if (!options.fieldSpec.empty()) parseFieldSpec(options.fieldSpec);
    const std::string& size = *commandLine.size;
    if (!size.empty()) {
        const std::size_t x = size.find('x');
        if (x == std::string::npos) throw InputError("--size \"" + size + "\": expected WIDTHxHEIGHT, e.g. 960x600");
        options.width = parseSide(size.substr(0, x), size);
        options.height = parseSide(size.substr(x + 1), size);
    }
    const command_line::RawOptions& raw = *commandLine.raw;
    options.series = raw.series;
    options.array = raw.array;
    options.time = raw.time;
    if (!raw.dims.empty()) options.raw = command_line::rawLayout(raw);
    return runViewer(options);
}

}  // namespace isotrack::viewer
