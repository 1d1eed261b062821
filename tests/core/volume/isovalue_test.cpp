// The opening isovalue from a histogram (isotrack/isovalue.h).
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>
#include <string>

#include "isotrack/io.h"
#include "isotrack/isovalue.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"

using namespace isotrack;

TEST_CASE("the valley above the tallest interior peak", "[isovalue]") {
    // Padding in the first bin, a tall peak at 30, a valley at 45, a second hump at 60.
    std::vector<std::uint64_t> counts(128, 100);
    counts[0] = 1000000;
    for (int i = 20; i < 41; ++i) counts[std::size_t(i)] = 100000 - 8000 * std::uint64_t(std::abs(i - 30));
    for (int i = 41; i < 50; ++i) counts[std::size_t(i)] = 5000;
    counts[45] = 2000;
    for (int i = 50; i < 70; ++i) counts[std::size_t(i)] = 20000;
    const double iso = suggestIsovalue(counts, 0.0, 128.0);
    CHECK(iso > 42.0);
    CHECK(iso < 50.0);
    const IsovalueSuggestion suggestion = isovalueSuggestion(counts, 0.0, 128.0);
    CHECK(suggestion.value == iso);
    CHECK(suggestion.rule == IsovalueRule::HistogramValley);
}

TEST_CASE("two-valued data falls back to Otsu's threshold between the values", "[isovalue]") {
    Volume mask({16, 16, 16}, ScalarType::UInt8);
    for (int z = 4; z < 12; ++z)
        for (int y = 4; y < 12; ++y)
            for (int x = 4; x < 12; ++x) mask.setValue(x, y, z, 200.0);
    const double iso = suggestIsovalue(mask);
    CHECK(iso > 0.0);
    CHECK(iso < 200.0);
    CHECK(marchingCubes(mask, iso).triangleCount() > 0);
    CHECK(isovalueSuggestion(mask).rule == IsovalueRule::Otsu);
    // A constant volume gives its value.
    Volume flat({8, 8, 8}, ScalarType::Float32);
    CHECK(suggestIsovalue(flat) == 0.0);
    CHECK(isovalueSuggestion(flat).rule == IsovalueRule::Constant);
}

TEST_CASE("each step of the rule has a name of its own", "[isovalue]") {
    const std::set<std::string> names{isovalueRuleName(IsovalueRule::HistogramValley),
                                      isovalueRuleName(IsovalueRule::Otsu), isovalueRuleName(IsovalueRule::Constant)};
    CHECK(names.size() == 3);
    CHECK(std::string(isovalueRuleName(IsovalueRule::HistogramValley)) == "histogram valley");
}

TEST_CASE("the CT opens between soft tissue and bone, on the whole skull", "[isovalue][ct]") {
    const std::string path = std::string(ISOTRACK_SOURCE_DIR) + "/assets/ct/cranium.nrrd";
    if (!std::filesystem::exists(path)) {
        WARN("skipped: " << path << " is missing (scripts/get_ct.sh makes it)");
        return;
    }
    const Volume ct = loadVolume(path);
    const double iso = suggestIsovalue(ct);
    CHECK(isovalueSuggestion(ct).rule == IsovalueRule::HistogramValley);
    CHECK(iso > 250.0);  // above soft tissue (about 0..100 HU)
    CHECK(iso < 600.0);  // and well below the range's middle (981), where the skull is full of holes
    const std::vector<Surface> surfaces = extractAllSurfaces(ct, iso);
    REQUIRE_FALSE(surfaces.empty());
    CHECK(surfaces.front().stats.triangles > 500000);  // the skull, in one piece
}
