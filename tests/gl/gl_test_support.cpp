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
void report(const std::string& name, const std::string& baseline, const render::Image& actual,
            const ImageDifference& difference, int channelTolerance) {
    const char* env = std::getenv("ISOTRACK_GOLDEN_REPORT");
    if (env == nullptr || std::string(env) != "1") return;
    const render::Image expected = render::readPng(baseline);
    const std::size_t any = compareImages(expected, actual, 0).differentPixels;
    const double pixels = double(actual.width) * double(actual.height);
    std::fprintf(
        stderr,
        "golden %s: %zu pixels differ at all (%.3f%%), largest channel delta %d; %zu (%.3f%%) by more than %d\n",
        name.c_str(), any, 100.0 * double(any) / pixels, difference.largestChannelDelta, difference.differentPixels,
        100.0 * double(difference.differentPixels) / pixels, channelTolerance);
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
    GoldenPolicy policy;
    policy.baseline = std::string(ISOTRACK_GOLDEN_DIR) + "/" + name + ".png";
    policy.actualPath = std::string(ISOTRACK_GOLDEN_OUT) + "/" + name + ".actual.png";
    policy.diffPath = std::string(ISOTRACK_GOLDEN_OUT) + "/" + name + ".diff.png";
    policy.channelTolerance = tolerance.channelTolerance;
    policy.maxDifferentFraction = tolerance.maxDifferentFraction;
    const GoldenVerdict verdict = checkGoldenImage(actual, name, policy);
    if (verdict.updated) WARN("ISOTRACK_UPDATE_GOLDEN=1: " << verdict.message);
    if (verdict.difference.diff.width > 0) {
        report(name, policy.baseline, actual, verdict.difference, tolerance.channelTolerance);
    }
    if (!verdict.passed) FAIL(verdict.message);
}

render::Image renderForGolden(const std::vector<const Mesh*>& surfaces, const Volume& volume,
                              render::SnapshotOptions options) {
    options.width = 320;
    options.height = 240;
    return render::renderSnapshot(surfaces, render::volumeBounds(volume), options).image;
}

}  // namespace isotrack::test
