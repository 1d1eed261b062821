#include "cli/dicom_report.h"

#include <cstdio>

namespace isotrack::cli {
namespace {

std::string plural(std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// MODALITY "DESCRIPTION", N slices of COLUMNS x ROWS
std::string seriesSummary(const DicomSeries& s) {
    std::string text = s.modality.empty() ? "" : s.modality + " ";
    if (!s.description.empty()) text += "\"" + s.description + "\", ";
    return text + plural(std::size_t(s.dims[2]), "slice", "slices") + " of " + std::to_string(s.dims[0]) + " x " +
           std::to_string(s.dims[1]);
}

std::string volumeText(const DicomSeries& s) {
    return s.formsVolume() ? "a volume" : std::string("not a volume: ") + dicomProblemText(s.problem);
}

}  // namespace

void warnSkipped(const DicomContents& contents) {
    for (const DicomSkipped& s : contents.skipped)
        std::fprintf(stderr, "isotrack: %s: skipped: %s\n", s.file.c_str(), s.why.c_str());
}

void addSkippedJson(nlohmann::json& report, const DicomContents& contents) {
    nlohmann::json files = nlohmann::json::array();
    for (const DicomSkipped& s : contents.skipped) files.push_back({{"file", s.file}, {"why", s.why}});
    report["dicom_skipped"] = contents.skipped.size();
    report["dicom_skipped_files"] = files;
}

nlohmann::json seriesJson(const DicomContents& contents, std::optional<std::size_t> read) {
    nlohmann::json out = nlohmann::json::array();
    for (std::size_t k = 0; k < contents.series.size(); ++k) {
        const DicomSeries& s = contents.series[k];
        out.push_back({{"number", k + 1},
                       {"uid", s.uid},
                       {"description", s.description},
                       {"modality", s.modality},
                       {"images", s.images},
                       {"dims", {s.dims[0], s.dims[1], s.dims[2]}},
                       {"volume", s.formsVolume()},
                       {"problem", s.formsVolume() ? nlohmann::json(nullptr) : dicomProblemText(s.problem)},
                       {"detail", s.detail.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.detail)},
                       {"read", read == k}});
    }
    return out;
}

void printSeries(const DicomContents& contents, std::optional<std::size_t> read) {
    for (std::size_t k = 0; k < contents.series.size(); ++k) {
        const DicomSeries& s = contents.series[k];
        std::printf("  %-9s %zu: %s, %s%s\n", k == 0 ? "series" : "", k + 1, seriesSummary(s).c_str(),
                    volumeText(s).c_str(), read == k ? " (read)" : "");
        std::printf("  %-9s %*s  uid %s\n", "", int(std::to_string(k + 1).size()), "", s.uid.c_str());
    }
    if (!contents.skipped.empty())
        std::printf("  %-9s %s (warnings on stderr)\n", "skipped",
                    plural(contents.skipped.size(), "file", "files").c_str());
}

void printNoVolume(const std::string& path, const DicomContents& contents) {
    if (contents.series.empty()) {
        std::fprintf(stderr, "isotrack: %s: no DICOM images found%s\n", path.c_str(),
                     contents.skipped.empty() ? "" : " (every file was skipped)");
        return;
    }
    std::fprintf(stderr, "isotrack: %s: no series forms a volume:\n", path.c_str());
    for (std::size_t k = 0; k < contents.series.size(); ++k) {
        const DicomSeries& s = contents.series[k];
        std::fprintf(stderr, "  %zu: %s, %s (uid %s)\n", k + 1, seriesSummary(s).c_str(), volumeText(s).c_str(),
                     s.uid.c_str());
        if (!s.detail.empty()) std::fprintf(stderr, "     %s\n", s.detail.c_str());
    }
}

}  // namespace isotrack::cli
