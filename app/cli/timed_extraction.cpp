#include "cli/timed_extraction.h"

#include <algorithm>
#include <string>

#include "isotrack/errors.h"

namespace isotrack::cli {

void checkMethodSeed(Method method, const std::vector<double>& seed) {
    if (method == Method::Track && seed.size() != 3)
        throw InputError("--method track needs --seed X,Y,Z, the point whose surface is tracked");
    if (method != Method::Track && !seed.empty())
        throw InputError(std::string("--seed is used by --method track only, not ") + methodName(method));
}

ExtractRequest extractRequest(Method method, double iso, TableKind table, int threads,
                              const std::vector<double>& seed) {
    if (method == Method::Track && seed.size() != 3)
        throw InputError("--method track needs --seed X,Y,Z, the point whose surface is tracked");
    ExtractRequest request;
    request.method = method;
    request.iso = iso;
    request.table = table;
    request.threads = threads;
    if (method == Method::Track) request.seeds.push_back({seed[0], seed[1], seed[2]});
    return request;
}

TimedExtraction extractTimed(const Volume& volume, const ExtractRequest& request) {
    TimedExtraction out;
    out.seconds = secondsOf([&] { out.surfaces = extract(volume, request); });
    return out;
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2.0;
}

}  // namespace isotrack::cli
