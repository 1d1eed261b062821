// isotrack field: write a built-in field as NRRD, to open it in other tools.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <memory>

#include "cli/commands.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"

namespace isotrack::cli {
namespace {

struct FieldOptions {
    std::string spec;
    std::string out;
};

int runField(const FieldOptions& options) {
    const FieldSpec spec = parseFieldSpec(options.spec);
    const Volume volume = makeField(spec);
    writeNrrd(volume, options.out);
    std::printf("%s:%d (default iso %g) -> %s\n", spec.name.c_str(), spec.size, fieldDefaultIso(spec.name),
                options.out.c_str());
    return 0;
}

}  // namespace

RunCommand addFieldCommand(CLI::App& app) {
    auto options = std::make_shared<FieldOptions>();
    CLI::App* command = app.add_subcommand("field", "Write a built-in field as an NRRD volume");
    command->add_option("spec", options->spec, "NAME[:N], e.g. blobs:256")->required();
    command->add_option("--out", options->out, "Output FILE.nrrd")->required();
    return [options] { return runField(*options); };
}

}  // namespace isotrack::cli
