#include "cli/source.h"

#include <CLI/CLI.hpp>
#include <cmath>

#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"

namespace isotrack::cli {

void addSourceOptions(CLI::App& command, SourceOptions& options) {
    std::string names;
    for (const FieldInfo& field : builtinFields()) names += std::string(names.empty() ? "" : ", ") + field.name;
    auto* volume = command.add_option("--volume", options.volumePath, "Volume file (.nrrd, .nhdr)");
    auto* field = command.add_option("--field", options.fieldSpec, "Built-in field NAME[:N] (" + names + ")");
    volume->excludes(field);
    field->excludes(volume);
    command.add_option("--iso", options.iso, "Isovalue (default: the field's own, or the middle of the data range)");
}

Source loadSource(const SourceOptions& options) {
    if (options.volumePath.empty() == options.fieldSpec.empty()) {
        throw InputError("give exactly one of --volume FILE or --field NAME[:N]");
    }
    Source source;
    if (!options.fieldSpec.empty()) {
        const FieldSpec spec = parseFieldSpec(options.fieldSpec);
        source.volume = makeField(spec);
        source.name = spec.name + ":" + std::to_string(spec.size);
        source.iso = options.iso.value_or(fieldDefaultIso(spec.name));
    } else {
        source.volume = loadVolume(options.volumePath);
        source.name = options.volumePath;
        if (options.iso) {
            source.iso = *options.iso;
        } else {
            const auto range = source.volume.range();
            if (!std::isfinite(range[0])) throw InputError(options.volumePath + ": no finite samples, give --iso");
            source.iso = (range[0] + range[1]) / 2.0;
        }
    }
    if (!std::isfinite(source.iso)) throw InputError("--iso: must be a finite number");
    return source;
}

}  // namespace isotrack::cli
