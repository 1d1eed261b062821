#pragma once
// isotrack's subcommands. Each add*Command registers its options on `app` and
// returns the function that runs it once the command line has been parsed.
#include <functional>

namespace CLI {
class App;
}

namespace isotrack::cli {

using RunCommand = std::function<int()>;

RunCommand addExtractCommand(CLI::App& app);
RunCommand addFieldCommand(CLI::App& app);
RunCommand addRenderCommand(CLI::App& app);
RunCommand addInfoCommand(CLI::App& app);
RunCommand addBenchCommand(CLI::App& app);
RunCommand addTreeCommand(CLI::App& app);

}  // namespace isotrack::cli
