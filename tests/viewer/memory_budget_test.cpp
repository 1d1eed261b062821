// A mapped volume over the viewer's memory budget: loadForView leaves its
// samples unread (no range, histogram or default isovalue) and needs an
// isovalue; under the budget it reads them as for any volume, with core's
// default isovalue.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <string>

#include "core/io/io_test_files.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/source.h"
#include "viewer/extraction_worker.h"

using namespace isotrack;
using namespace isotrack::viewer;
using isotrack::testing::TempDir;
using isotrack::testing::writeFile;

namespace {

// The blobs field as float32 raw samples, read back as a mapped volume.
VolumeSource blobsRaw(const TempDir& dir) {
    const Volume field = makeField({"blobs", 24});
    std::string bytes(field.sampleCount() * sizeof(float), '\0');
    const Dims& n = field.dims();
    for (int z = 0; z < n[2]; ++z) {
        for (int y = 0; y < n[1]; ++y) {
            for (int x = 0; x < n[0]; ++x) {
                const float value = static_cast<float>(field.value(x, y, z));
                std::memcpy(&bytes[field.index(x, y, z) * sizeof(float)], &value, sizeof(float));
            }
        }
    }
    writeFile(dir.file("blobs.raw"), bytes);
    RawLayout layout;
    layout.dims = field.dims();
    layout.type = ScalarType::Float32;
    return VolumeSource::file(dir.file("blobs.raw"), layout);
}

constexpr std::uint64_t kSampleBytes = 24 * 24 * 24 * sizeof(float);

}  // namespace

TEST_CASE("a mapped volume under the budget is read as any volume", "[viewer][memory]") {
    TempDir dir;
    const VolumeSource source = blobsRaw(dir);
    const std::shared_ptr<LoadedVolume> loaded = loadForView(source, false, kSampleBytes);
    REQUIRE(loaded->mapped != nullptr);
    CHECK(loaded->mappedBytes == kSampleBytes);
    CHECK_FALSE(loaded->overBudget);
    CHECK(loaded->valuesRead);
    CHECK(loaded->range == loaded->volume.range());
    CHECK(loaded->histogram.size() == kHistogramBins);
    const LoadedSource reference = loadSource(source);  // core's default isovalue, as the CLI has it
    REQUIRE(reference.defaultIso);
    CHECK(loaded->defaultIso == *reference.defaultIso);
}

TEST_CASE("a mapped volume over the budget is left unread and needs an isovalue", "[viewer][memory]") {
    TempDir dir;
    const VolumeSource source = blobsRaw(dir);
    const std::string budget = "over the memory budget";
    CHECK_THROWS_AS(loadForView(source, false, kSampleBytes - 1), InputError);
    CHECK_THROWS_WITH(loadForView(source, false, kSampleBytes - 1),
                      Catch::Contains(budget) && Catch::Contains("--iso") && Catch::Contains(source.text));
    const std::shared_ptr<LoadedVolume> loaded = loadForView(source, true, kSampleBytes - 1);
    REQUIRE(loaded->mapped != nullptr);
    CHECK(loaded->overBudget);
    CHECK_FALSE(loaded->valuesRead);
    CHECK(loaded->histogram.empty());
    CHECK(std::isnan(loaded->defaultIso));
}

TEST_CASE("a field is never over the budget", "[viewer][memory]") {
    const std::shared_ptr<LoadedVolume> loaded = loadForView(VolumeSource::field("blobs:16"), false, 1);
    CHECK(loaded->mapped == nullptr);
    CHECK_FALSE(loaded->overBudget);
    CHECK(loaded->valuesRead);
    CHECK(loaded->defaultIso == fieldDefaultIso("blobs"));
}
