#include "gl_test_support.h"

#include <catch2/catch.hpp>
#include <filesystem>
#include <memory>

#include "gl/check.h"
#include "headless/headless_context.h"

namespace isotrack::test {
namespace {

std::string outputPath(const std::string& name, const char* suffix) {
    std::filesystem::create_directories(ISOTRACK_GOLDEN_OUT);
    return std::string(ISOTRACK_GOLDEN_OUT) + "/" + name + suffix;
}

}  // namespace

void useHeadlessGl() {
    static const headless::HeadlessContext context;
    gl::setErrorChecks(true);
}

void checkGolden(const std::string& name, const render::Image& actual, const GoldenTolerance& tolerance) {
    const std::string golden = std::string(ISOTRACK_GOLDEN_DIR) + "/" + name + ".png";
    if (updateRequested()) {
        render::writePng(actual, golden);
        WARN("ISOTRACK_UPDATE_GOLDEN=1: wrote " << golden << " (look at it before committing)");
        return;
    }
    if (!std::filesystem::exists(golden)) {
        const std::string actualPath = outputPath(name, ".actual.png");
        render::writePng(actual, actualPath);
        FAIL("no golden image " << golden << "\n  actual: " << actualPath
                                << "\n  look at it, then rerun with ISOTRACK_UPDATE_GOLDEN=1 to make it the baseline");
    }
    const render::Image expected = render::readPng(golden);
    if (expected.width != actual.width || expected.height != actual.height) {
        const std::string actualPath = outputPath(name, ".actual.png");
        render::writePng(actual, actualPath);
        FAIL(name << ": golden is " << expected.width << "x" << expected.height << ", actual is " << actual.width << "x"
                  << actual.height << "\n  actual: " << actualPath);
    }
    const ImageDifference difference = compareImages(expected, actual, tolerance.channelTolerance);
    const std::size_t pixels = std::size_t(actual.width) * std::size_t(actual.height);
    const double fraction = double(difference.differentPixels) / double(pixels);
    if (fraction <= tolerance.maxDifferentFraction) {
        // Passing now: drop what an earlier failure left, so golden_out/ holds only current failures.
        std::filesystem::remove(std::string(ISOTRACK_GOLDEN_OUT) + "/" + name + ".actual.png");
        std::filesystem::remove(std::string(ISOTRACK_GOLDEN_OUT) + "/" + name + ".diff.png");
    } else {
        const std::string actualPath = outputPath(name, ".actual.png");
        const std::string diffPath = outputPath(name, ".diff.png");
        render::writePng(actual, actualPath);
        render::writePng(difference.diff, diffPath);
        FAIL(name << ": " << difference.differentPixels << " of " << pixels << " pixels (" << fraction * 100.0
                  << "%) differ by more than " << tolerance.channelTolerance << " in a channel (largest "
                  << difference.largestChannelDelta << "); allowed " << tolerance.maxDifferentFraction * 100.0
                  << "%\n  golden: " << golden << "\n  actual: " << actualPath << "\n  diff:   " << diffPath);
    }
}

render::Image renderForGolden(const std::vector<const Mesh*>& surfaces, const Volume& volume,
                              render::SnapshotOptions options) {
    options.width = 320;
    options.height = 240;
    return render::renderSnapshot(surfaces, render::volumeBounds(volume), options).image;
}

}  // namespace isotrack::test
