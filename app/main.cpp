// isotrack: extract, track and explore isosurfaces.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <new>
#include <utility>
#include <vector>

#include "cli/commands.h"
#include "viewer/viewer_options.h"

namespace {

// Meshes are re-extracted again and again (the viewer's isovalue slider,
// extract --repeat): memory a mesh frees is kept for the next one instead of
// going back to the kernel, which would hand out fresh pages, each zeroed on
// first touch. glibc otherwise maps big blocks on their own and unmaps them on
// free.
void keepFreedMemoryForReuse() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace

int main(int argc, char** argv) {
    keepFreedMemoryForReuse();
    CLI::App app{"isotrack: extract and track isosurfaces of 3D scalar volumes, one connected surface at a time",
                 "isotrack"};
    app.set_version_flag("--version", "isotrack 0.1.0");
    std::vector<std::pair<CLI::App*, isotrack::cli::RunCommand>> commands;
    auto add = [&](isotrack::cli::RunCommand (*addCommand)(CLI::App&)) {
        const std::size_t before = app.get_subcommands({}).size();
        auto run = addCommand(app);
        commands.emplace_back(app.get_subcommands({})[before], std::move(run));
    };
    add(isotrack::cli::addExtractCommand);
    add(isotrack::cli::addFieldCommand);
    add(isotrack::cli::addRenderCommand);
    add(isotrack::cli::addInfoCommand);
    add(isotrack::cli::addBenchCommand);
    add(isotrack::cli::addTreeCommand);
    app.require_subcommand(0, 1);
    // No subcommand: the interactive viewer, with its own top-level options.
    const isotrack::viewer::ViewerCommandLine viewer = isotrack::viewer::addViewerOptions(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForAllHelp& e) {
        return app.exit(e);
    } catch (const CLI::CallForVersion& e) {
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "isotrack: %s (see isotrack --help)\n", e.what());
        return 2;
    }

    try {
        for (auto& [command, run] : commands) {
            if (command->parsed()) return run();
        }
        return isotrack::viewer::runViewerCommand(viewer);
    } catch (const std::bad_alloc&) {
        std::fprintf(stderr, "isotrack: out of memory\n");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "isotrack: %s\n", e.what());
    }
    return 1;
}
