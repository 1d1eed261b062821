#include "gl_test_support.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "gl/check.h"
#include "headless/egl_context.h"
#include "headless/headless_context.h"

namespace isotrack::test {
namespace {

std::string outputPath(const std::string& name, const char* suffix) {
    std::filesystem::create_directories(ISOTRACK_GOLDEN_OUT);
    return std::string(ISOTRACK_GOLDEN_OUT) + "/" + name + suffix;
}

headless::Backend requestedBackend() {
    const char* env = std::getenv("ISOTRACK_TEST_GL");
    return env != nullptr && *env != '\0' ? headless::parseBackend(env) : headless::Backend::OSMesa;
}

std::unique_ptr<headless::HeadlessContext> makeContext() {
    try {
        auto context = std::make_unique<headless::HeadlessContext>(requestedBackend());
        std::fprintf(stderr, "gl_tests: %s, %s: %s, OpenGL %s\n", headless::backendName(context->backend()),
                     context->platform().c_str(), context->info().renderer.c_str(), context->info().version.c_str());
        return context;
    } catch (const headless::EglUnavailable& error) {
        // Nothing to test on this machine: ctest counts exit status 77 as skipped.
        std::fprintf(stderr, "gl_tests: skipped, %s\n", error.what());
        std::exit(77);
    }
}

const headless::HeadlessContext& sharedContext() {
    static const std::unique_ptr<headless::HeadlessContext> context = makeContext();
    return *context;
}

// ISOTRACK_GOLDEN_REPORT=1: one line per comparison, passing or not, to measure a backend.
void report(const std::string& name, const render::Image& expected, const render::Image& actual,
            const ImageDifference& difference, int channelTolerance) {
    const char* env = std::getenv("ISOTRACK_GOLDEN_REPORT");
    if (env == nullptr || std::string(env) != "1") return;
    const std::size_t any = compareImages(expected, actual, 0).differentPixels;
    const double pixels = double(actual.width) * double(actual.height);
    std::fprintf(stderr, "golden %s: %zu pixels differ at all (%.3f%%), largest channel delta %d; %zu (%.3f%%) by more than %d\n",
                 name.c_str(), any, 100.0 * double(any) / pixels, difference.largestChannelDelta,
                 difference.differentPixels, 100.0 * double(difference.differentPixels) / pixels, channelTolerance);
}

}  // namespace

void useHeadlessGl() {
    sharedContext();
    gl::setErrorChecks(true);
}

GoldenTolerance forCurrentBackend(GoldenTolerance tolerance) {
    const headless::HeadlessContext& context = sharedContext();
    if (context.backend() == headless::Backend::OSMesa || headless::isSoftwareRenderer(context.info().renderer)) {
        return tolerance;
    }
    tolerance.channelTolerance = std::max(tolerance.channelTolerance, kGpuChannelTolerance);
    tolerance.maxDifferentFraction = std::max(tolerance.maxDifferentFraction, kGpuDifferentFraction);
    return tolerance;
}

void checkGolden(const std::string& name, const render::Image& actual, const GoldenTolerance& requested) {
    const GoldenTolerance tolerance = forCurrentBackend(requested);
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
    report(name, expected, actual, difference, tolerance.channelTolerance);
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
