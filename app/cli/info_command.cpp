// isotrack info: what a volume file holds, before extracting anything from it.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/dicom_report.h"
#include "cli/source.h"
#include "isotrack/dicom.h"
#include "isotrack/io.h"
#include "isotrack/isovalue.h"
#include "isotrack/orientation.h"
#include "isotrack/time_series.h"
#include "isotrack/volume.h"

namespace isotrack::cli {
namespace {

constexpr int kBarWidth = 40;

struct InfoOptions {
    std::string path;
    command_line::RawOptions raw;
    int bins = 16;
    bool json = false;
    bool values = false;  // read the samples of a mapped volume of any size
};

// A mapped volume up to this size has its values read (range, histogram, the
// suggested isovalue); a bigger one only with --values, so that info on a volume
// larger than memory reads its header alone.
constexpr std::uint64_t kMappedValueBytes = std::uint64_t(1) << 30;

// Counts of finite samples in equal bins over [min, max]; NaN and infinities counted apart.
struct Histogram {
    double min = 0.0, max = 0.0;
    std::vector<std::uint64_t> counts;
    std::uint64_t nonFinite = 0;
    bool read = true;  // false: the samples were not read (a big mapped volume)
    bool empty() const { return counts.empty(); }
    double binWidth() const { return counts.empty() ? 0.0 : (max - min) / double(counts.size()); }
};

Histogram histogram(const Volume& volume, int bins) {
    Histogram h;
    const auto range = volume.range();
    const std::size_t n = volume.sampleCount();
    if (!std::isfinite(range[0])) {
        h.nonFinite = n;
        return h;
    }
    h.min = range[0];
    h.max = range[1];
    h.counts = sampleHistogram(volume, range, std::size_t(bins));
    h.nonFinite = n - std::accumulate(h.counts.begin(), h.counts.end(), std::uint64_t(0));
    return h;
}

std::string formatBytes(std::uint64_t bytes) {
    const char* units[] = {"bytes", "KiB", "MiB", "GiB"};
    double v = double(bytes);
    int unit = 0;
    while (v >= 1024.0 && unit < 3) v /= 1024.0, ++unit;
    char buf[64];
    std::snprintf(buf, sizeof buf, unit == 0 ? "%.0f %s" : "%.1f %s", v, units[unit]);
    return buf;
}

std::string formatName(const std::string& path, const command_line::RawOptions& raw) {
    if (!raw.dims.empty()) return std::string("raw (") + raw.endian + " endian)";
    const auto format = volumeFormatOf(path);
    return format ? volumeFormatName(*format) : "unknown";
}

bool isDicom(const InfoOptions& options) {
    return options.raw.dims.empty() && volumeFormatOf(options.path) == VolumeFormat::Dicom;
}

nlohmann::json infoJson(const InfoOptions& options, const Volume& volume, const Histogram& h) {
    const Dims& d = volume.dims();
    nlohmann::json j{
        {"file", options.path},
        {"format", formatName(options.path, options.raw)},
        {"dims", {d[0], d[1], d[2]}},
        {"samples", volume.sampleCount()},
        {"scalar_type", scalarTypeName(volume.type())},
        {"spacing", volume.spacing()},
        {"origin", volume.origin()},
        {"extent",
         {(d[0] - 1) * volume.spacing()[0], (d[1] - 1) * volume.spacing()[1], (d[2] - 1) * volume.spacing()[2]}},
        {"frame", worldFrameName(WorldFrame::Lps)},
        {"direction", volume.direction()},  // the index axes' unit vectors
        {"orientation", orientationCode(volume.direction())},
        {"world_bounds", worldBounds(volume)},
        {"memory_bytes", volume.byteSize()},
        {"mapped", volume.mappedFile() != nullptr},
        {"values_read", h.read},
        {"non_finite", h.read ? nlohmann::json(h.nonFinite) : nlohmann::json(nullptr)},
    };
    if (h.empty()) {
        j["range"] = nullptr;
        j["histogram"] = nullptr;
    } else {
        j["range"] = {h.min, h.max};
        j["histogram"] = {{"min", h.min}, {"max", h.max}, {"bin_width", h.binWidth()}, {"counts", h.counts}};
    }
    return j;
}

void printInfo(const InfoOptions& options, const Volume& volume, const Histogram& h) {
    const Dims& d = volume.dims();
    const Vec3d& s = volume.spacing();
    const Vec3d& o = volume.origin();
    std::printf("%s\n", options.path.c_str());
    std::printf("  format    %s\n", formatName(options.path, options.raw).c_str());
    std::printf("  dims      %d x %d x %d (%zu samples)\n", d[0], d[1], d[2], volume.sampleCount());
    std::printf("  type      %s\n", scalarTypeName(volume.type()));
    std::printf("  spacing   %.10g %.10g %.10g\n", s[0], s[1], s[2]);
    std::printf("  origin    %.10g %.10g %.10g\n", o[0], o[1], o[2]);
    std::printf("  extent    %g x %g x %g\n", (d[0] - 1) * s[0], (d[1] - 1) * s[1], (d[2] - 1) * s[2]);
    // World frame LPS; each row is an index axis's unit vector, as NRRD's space directions.
    const Mat3d& m = volume.direction();
    for (std::size_t a = 0; a < 3; ++a)
        std::printf("  %-9s %.10g %.10g %.10g (%c axis)\n", a == 0 ? "direction" : "", m[a][0], m[a][1], m[a][2],
                    "ijk"[a]);
    std::printf("  orient    %s (world frame LPS)\n", orientationCode(m).c_str());
    const auto box = worldBounds(volume);
    std::printf("  world box %.10g %.10g %.10g .. %.10g %.10g %.10g\n", box[0][0], box[0][1], box[0][2], box[1][0],
                box[1][1], box[1][2]);
    if (!h.read)
        std::printf("  values    not read: %s mapped (--values reads every sample)\n",
                    formatBytes(volume.byteSize()).c_str());
    else if (h.empty())
        std::printf("  range     none: no finite samples\n");
    else
        std::printf("  range     %g .. %g\n", h.min, h.max);
    if (h.nonFinite) std::printf("  nan/inf   %llu samples\n", static_cast<unsigned long long>(h.nonFinite));
    const char* where = volume.mappedFile() ? "mapped from the file, read where used" : "in memory";
    if (volume.byteSize() < 1024)
        std::printf("  samples   %zu bytes, %s\n", volume.byteSize(), where);
    else
        std::printf("  samples   %s (%zu bytes), %s\n", formatBytes(volume.byteSize()).c_str(), volume.byteSize(),
                    where);
    if (h.empty()) return;

    std::printf("  histogram %zu bins of width %g\n", h.counts.size(), h.binWidth());
    const std::uint64_t peak = *std::max_element(h.counts.begin(), h.counts.end());
    for (std::size_t b = 0; b < h.counts.size(); ++b) {
        const std::uint64_t c = h.counts[b];
        int bar = peak ? int(std::llround(double(c) / double(peak) * kBarWidth)) : 0;
        if (c > 0 && bar == 0) bar = 1;  // a bin that holds anything shows
        std::printf("  %12.6g  %-*s %llu\n", h.min + double(b) * h.binWidth(), kBarWidth,
                    std::string(std::size_t(bar), '#').c_str(), static_cast<unsigned long long>(c));
    }
}

// The isovalue extract, render, tree, bench and the viewer open the file at
// without --iso (core's suggestIsovalue), and the step of the rule that chose it.
void addSuggestedIsovalue(const std::optional<IsovalueSuggestion>& suggestion, nlohmann::json& j) {
    j["suggested_isovalue"] = suggestion ? nlohmann::json(suggestion->value) : nlohmann::json(nullptr);
    j["suggested_isovalue_rule"] =
        suggestion ? nlohmann::json(isovalueRuleName(suggestion->rule)) : nlohmann::json(nullptr);
}

void printSuggestedIsovalue(const std::optional<IsovalueSuggestion>& suggestion) {
    if (suggestion)
        std::printf("  suggested isovalue: %.10g (%s)\n", suggestion->value, isovalueRuleName(suggestion->rule));
}

// A .pvd collection, a 4D NIfTI or numbered files: its steps; nothing for one volume.
std::optional<TimeSeries> timeSeries(const InfoOptions& options) {
    if (!options.raw.dims.empty()) return std::nullopt;
    const auto format = volumeFormatOf(options.path);
    if (format == VolumeFormat::Dicom) return std::nullopt;
    TimeSeries series = readTimeSeries(options.path);
    const bool numbered = series.steps.front().file != options.path;
    if (format != VolumeFormat::VtkCollection && !numbered && series.steps.size() == 1) return std::nullopt;
    return series;
}

void addStepsJson(const TimeSeries& series, std::size_t shown, nlohmann::json& j) {
    nlohmann::json steps = nlohmann::json::array();
    for (std::size_t i = 0; i < series.steps.size(); ++i)
        steps.push_back({{"index", i}, {"time", series.steps[i].time}, {"file", series.steps[i].file}});
    j["steps"] = steps;
    j["time_step"] = shown;
}

void printSteps(const TimeSeries& series, std::size_t shown) {
    std::printf("  steps     %zu time steps (shown: step %zu; --time STEP reads another)\n", series.steps.size(),
                shown);
    for (std::size_t i = 0; i < series.steps.size(); ++i)
        std::printf("  %6zu    time %.10g  %s\n", i, series.steps[i].time, series.steps[i].file.c_str());
}

int runInfo(const InfoOptions& options) {
    Volume volume;
    std::optional<DicomVolume> dicom;
    if (isDicom(options)) {
        try {
            dicom = readDicom(options.path, options.raw.series);
        } catch (const DicomNoVolume& e) {
            warnSkipped(e.contents());
            printNoVolume(options.path, e.contents());
            return 1;
        }
        warnSkipped(dicom->contents);
        volume = std::move(dicom->volume);
    } else {
        volume = loadVolumeFile(options.path, options.raw);
    }
    const std::optional<TimeSeries> series = timeSeries(options);
    const bool readValues = options.values || !volume.mappedFile() || volume.byteSize() <= kMappedValueBytes;
    Histogram h;
    if (readValues)
        h = histogram(volume, options.bins);
    else
        h.read = false;
    std::optional<IsovalueSuggestion> suggestion;
    if (!h.empty()) suggestion = isovalueSuggestion(volume, {h.min, h.max});
    if (options.json) {
        nlohmann::json j = infoJson(options, volume, h);
        addSuggestedIsovalue(suggestion, j);
        if (dicom) {
            j["series"] = seriesJson(dicom->contents, dicom->series);
            addSkippedJson(j, dicom->contents);
        }
        if (series) addStepsJson(*series, options.raw.time, j);
        std::printf("%s\n", j.dump().c_str());
    } else {
        printInfo(options, volume, h);
        printSuggestedIsovalue(suggestion);
        if (dicom) printSeries(dicom->contents, dicom->series);
        if (series) printSteps(*series, options.raw.time);
    }
    return 0;
}

}  // namespace

RunCommand addInfoCommand(CLI::App& app) {
    auto options = std::make_shared<InfoOptions>();
    CLI::App* command = app.add_subcommand("info", "Describe a volume file: format, size, type, geometry, values");
    auto* volume = command
                       ->add_option("--volume", options->path,
                                    "Volume file (.nrrd .nhdr .nii .nii.gz .mhd .mha .vtk .vti .pvd .dcm, a DICOM "
                                    "folder or "
                                    "DICOMDIR; raw with --dims)")
                       ->required();
    command_line::addRawOptions(*command, options->raw, volume);
    command->add_option("--bins", options->bins, "Histogram bins (default 16)")->check(CLI::Range(1, 256));
    command->add_flag("--json", options->json, "Print one JSON object on stdout");
    command->add_flag("--values", options->values,
                      "Read every sample of a mapped volume over 1 GiB too (range, histogram, suggested isovalue)");
    return [options] { return runInfo(*options); };
}

}  // namespace isotrack::cli
