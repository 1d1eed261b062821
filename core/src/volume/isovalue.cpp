// Choosing a volume's opening isovalue from its histogram (see isovalue.h).
#include "isotrack/isovalue.h"

#include <algorithm>
#include <cstddef>

namespace isotrack {
namespace {

constexpr std::size_t kBins = 128;
constexpr std::size_t kSmoothRadius = 2;  // five bins

double binCentre(std::size_t bin, std::size_t bins, double lo, double hi) {
    return lo + (hi - lo) * (double(bin) + 0.5) / double(bins);
}

std::vector<double> smoothed(const std::vector<std::uint64_t>& counts) {
    const std::size_t n = counts.size();
    std::vector<double> out(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t from = i >= kSmoothRadius ? i - kSmoothRadius : 0;
        const std::size_t to = std::min(n - 1, i + kSmoothRadius);
        double sum = 0.0;
        for (std::size_t j = from; j <= to; ++j) sum += double(counts[j]);
        out[i] = sum / double(to - from + 1);
    }
    return out;
}

}  // namespace

double otsuThreshold(const std::vector<std::uint64_t>& counts, double lo, double hi) {
    const std::size_t n = counts.size();
    double total = 0.0, weightedTotal = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        total += double(counts[i]);
        weightedTotal += double(i) * double(counts[i]);
    }
    if (n < 2 || total <= 0.0) return 0.5 * (lo + hi);
    double below = 0.0, weightedBelow = 0.0, bestVariance = -1.0;
    std::size_t bestSplit = n / 2;  // the threshold lies between bin split-1 and bin split
    for (std::size_t split = 1; split < n; ++split) {
        below += double(counts[split - 1]);
        weightedBelow += double(split - 1) * double(counts[split - 1]);
        const double above = total - below;
        if (below <= 0.0 || above <= 0.0) continue;
        const double meanBelow = weightedBelow / below;
        const double meanAbove = (weightedTotal - weightedBelow) / above;
        const double variance = below * above * (meanBelow - meanAbove) * (meanBelow - meanAbove);
        if (variance > bestVariance) {
            bestVariance = variance;
            bestSplit = split;
        }
    }
    return lo + (hi - lo) * double(bestSplit) / double(n);
}

const char* isovalueRuleName(IsovalueRule rule) {
    switch (rule) {
        case IsovalueRule::HistogramValley: return "histogram valley";
        case IsovalueRule::Otsu: return "Otsu threshold";
        case IsovalueRule::Constant: break;
    }
    return "constant volume";
}

IsovalueSuggestion isovalueSuggestion(const std::vector<std::uint64_t>& counts, double lo, double hi) {
    const std::size_t n = counts.size();
    if (!(hi > lo) || n == 0) return {0.5 * (lo + hi), IsovalueRule::Constant};
    if (n < 8) return {otsuThreshold(counts, lo, hi), IsovalueRule::Otsu};
    std::vector<std::uint64_t> interior = counts;
    interior.front() = 0;
    interior.back() = 0;
    const std::vector<double> smooth = smoothed(interior);
    std::size_t peak = 1;
    for (std::size_t i = 1; i + 1 < n; ++i) {
        if (interior[i] > interior[peak]) peak = i;
    }
    // Walk up from the peak while the smoothed counts fall; stop where they rise again.
    std::size_t valley = peak;
    while (valley + 2 < n && smooth[valley + 1] <= smooth[valley]) ++valley;
    const bool found = valley + 2 < n && valley > peak && smooth[valley] < 0.5 * smooth[peak];
    if (!found) return {otsuThreshold(counts, lo, hi), IsovalueRule::Otsu};
    return {binCentre(valley, n, lo, hi), IsovalueRule::HistogramValley};
}

IsovalueSuggestion isovalueSuggestion(const Volume& volume) { return isovalueSuggestion(volume, volume.range()); }

IsovalueSuggestion isovalueSuggestion(const Volume& volume, const std::array<double, 2>& range) {
    if (!(range[1] > range[0])) return {range[0], IsovalueRule::Constant};
    return isovalueSuggestion(sampleHistogram(volume, range, kBins), range[0], range[1]);
}

double suggestIsovalue(const Volume& volume) { return isovalueSuggestion(volume).value; }

double suggestIsovalue(const Volume& volume, const std::array<double, 2>& range) {
    return isovalueSuggestion(volume, range).value;
}

double suggestIsovalue(const std::vector<std::uint64_t>& counts, double lo, double hi) {
    return isovalueSuggestion(counts, lo, hi).value;
}

}  // namespace isotrack
