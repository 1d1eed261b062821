#pragma once
// The isovalue a volume opens on when the user has not chosen one.
//
// Rule: the valley above the tallest peak of the histogram. The values are
// counted in 128 bins across the volume's range; the two end bins are left out
// (padding, air clamped to the scanner's minimum and saturated samples gather
// there), the counts are smoothed over five bins, and from the tallest
// remaining peak the walk goes up in value while the counts fall; where they
// stop falling is the valley, and its bin's centre the isovalue. On a CT the
// tallest peak is soft tissue and the valley above it lies between tissue and
// bone (401.43 HU on the Cranium sample, a closed skull). When there is no
// such valley (the counts fall to the last bin, or two-valued data), Otsu's
// threshold over the same bins is used instead.
//
// Every front end opens a file at this value: `isotrack extract` and the other
// commands without --iso, the viewer, Python; `isotrack info` prints it.
#include <array>
#include <cstdint>
#include <vector>

#include "isotrack/volume.h"

namespace isotrack {

// Which step of the rule gave the value.
enum class IsovalueRule : std::uint8_t {
    HistogramValley,  // the valley above the tallest peak
    Otsu,             // no such valley: Otsu's threshold
    Constant,         // one value only (or no bins): the middle of the range
};
// "histogram valley", "Otsu threshold", "constant volume".
const char* isovalueRuleName(IsovalueRule rule);

struct IsovalueSuggestion {
    double value = 0.0;
    IsovalueRule rule = IsovalueRule::Constant;
};

// The suggested isovalue and the step that chose it.
IsovalueSuggestion isovalueSuggestion(const Volume& volume);
// The same, for a caller that has the volume's range() already: one pass fewer
// over the samples (each is a full read of a mapped file).
IsovalueSuggestion isovalueSuggestion(const Volume& volume, const std::array<double, 2>& range);
// The same rule on a histogram already counted: `counts` in equal bins across [lo, hi].
IsovalueSuggestion isovalueSuggestion(const std::vector<std::uint64_t>& counts, double lo, double hi);

// isovalueSuggestion's value.
double suggestIsovalue(const Volume& volume);
double suggestIsovalue(const Volume& volume, const std::array<double, 2>& range);
double suggestIsovalue(const std::vector<std::uint64_t>& counts, double lo, double hi);

// Otsu's threshold: the bin boundary that maximises the between-class variance.
double otsuThreshold(const std::vector<std::uint64_t>& counts, double lo, double hi);

}  // namespace isotrack
