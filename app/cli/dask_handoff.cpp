#include "cli/dask_handoff.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "isotrack/errors.h"

namespace isotrack::cli {

namespace {

bool endsWith(const std::string& text, const std::string& tail) {
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

}  // namespace

bool wantsDask(const std::string& volume, const std::string& scheduler) {
    std::string path = volume;
    while (path.size() > 1 && path.back() == '/') path.pop_back();
    return !scheduler.empty() || endsWith(path, ".zarr");
}

void checkDaskRequest(const DaskRequest& request, TableKind table, WorldFrame frame, bool json, bool outFormat) {
    auto refuse = [](const std::string& what) {
        throw InputError("--scheduler (Dask): " + what + " is not supported there (docs/distributed.md)");
    };
    if (request.volume.empty()) refuse("--field");
    if (!request.iso) refuse("a default isovalue (it reads every sample first): give --iso");
    if (request.method == Method::Tree) refuse("--method tree");
    if (table != TableKind::Consistent) refuse(std::string("--table ") + tableKindName(table));
    if (frame != WorldFrame::Lps) refuse(std::string("--frame ") + worldFrameName(frame));
    if (json) refuse("--json");
    if (outFormat) refuse("--out-format");
    if (request.method == Method::All && !request.out.empty()) refuse("--out with --method all (use --out-dir)");
    if (request.method != Method::All && !request.outDir.empty()) refuse("--out-dir without --method all");
}

void runOnDask(const DaskRequest& request) {
#if defined(ISOTRACK_PYTHON) && defined(ISOTRACK_PYTHON_PATH)
    std::vector<std::string> args{ISOTRACK_PYTHON, "-m",
                                  "isotrack.dask", "--volume",
                                  request.volume,  "--iso=" + number(*request.iso),
                                  "--method",      methodName(request.method)};
    if (!request.scheduler.empty()) args.insert(args.end(), {"--scheduler", request.scheduler});
    if (request.seed.size() == 3)  // the module takes (z, y, x), as the array is indexed
        args.insert(args.end(), {"--seed", number(request.seed[2]) + "," + number(request.seed[1]) + "," +
                                               number(request.seed[0])});
    const std::string out = request.outDir.empty() ? request.out : request.outDir;
    if (!out.empty()) args.insert(args.end(), {"--out", out});
    // The module next to this executable's build, or where `cmake --install` put it.
    const char* existing = std::getenv("PYTHONPATH");
    const std::string path =
        std::string(ISOTRACK_PYTHON_PATH) + (existing && *existing ? ":" + std::string(existing) : "");
    setenv("PYTHONPATH", path.c_str(), 1);
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    std::fflush(stdout);
    execv(argv[0], argv.data());
    throw InputError(std::string("--scheduler: cannot start ") + ISOTRACK_PYTHON + ": " + std::strerror(errno));
#else
    (void)request;
    throw InputError("--scheduler: this build has no Python module (pybind11 and numpy), which runs on Dask");
#endif
}

}  // namespace isotrack::cli
