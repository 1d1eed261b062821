#pragma once
// The volume a command works on: a file (--volume) or a built-in field (--field),
// and the isovalue (--iso, defaulting per field, or to the middle of a file's range).
#include <optional>
#include <string>

#include "isotrack/volume.h"

namespace CLI {
class App;
}

namespace isotrack::cli {

struct SourceOptions {
    std::string volumePath;
    std::string fieldSpec;
    std::optional<double> iso;
};

// Adds --volume, --field (exactly one required) and --iso to `command`.
void addSourceOptions(CLI::App& command, SourceOptions& options);

struct Source {
    Volume volume;
    std::string name;  // the file path or the field spec
    double iso = 0.0;
};

// Loads the file or builds the field. Throws isotrack's typed errors.
Source loadSource(const SourceOptions& options);

}  // namespace isotrack::cli
