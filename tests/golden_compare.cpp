#include "golden_compare.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace isotrack::test {

ImageDifference compareImages(const render::Image& expected, const render::Image& actual, int channelTolerance) {
    ImageDifference result;
    result.diff = render::Image(actual.width, actual.height);
    for (int y = 0; y < actual.height; ++y) {
        for (int x = 0; x < actual.width; ++x) {
            const std::uint8_t* e = expected.pixel(x, y);
            const std::uint8_t* a = actual.pixel(x, y);
            int delta = 0;
            for (int c = 0; c < 3; ++c) delta = std::max(delta, std::abs(int(e[c]) - int(a[c])));
            result.largestChannelDelta = std::max(result.largestChannelDelta, delta);
            std::uint8_t* d = result.diff.pixel(x, y);
            if (delta > channelTolerance) {
                ++result.differentPixels;
                d[0] = static_cast<std::uint8_t>(128 + delta / 2);
                d[1] = d[2] = 0;
            } else {
                const int grey = (int(e[0]) + int(e[1]) + int(e[2])) / 9;
                d[0] = d[1] = d[2] = static_cast<std::uint8_t>(grey);
            }
            d[3] = 255;
        }
    }
    return result;
}

GoldenVerdict checkGoldenImage(const render::Image& actual, const std::string& name, const GoldenPolicy& policy) {
    GoldenVerdict verdict;
    if (updateRequested()) {
        render::writePng(actual, policy.baseline);
        verdict.passed = verdict.updated = true;
        verdict.message = "wrote " + policy.baseline + " (look at it before committing)";
        return verdict;
    }
    const auto failWithActual = [&](const std::string& what) {
        std::filesystem::create_directories(std::filesystem::path(policy.actualPath).parent_path());
        render::writePng(actual, policy.actualPath);
        verdict.message = what + "\n  actual: " + policy.actualPath;
        return verdict;
    };
    if (!std::filesystem::exists(policy.baseline)) {
        return failWithActual("no golden image " + policy.baseline +
                              "; look at the actual image, then rerun with ISOTRACK_UPDATE_GOLDEN=1 to make it "
                              "the baseline");
    }
    const render::Image expected = render::readPng(policy.baseline);
    if (expected.width != actual.width || expected.height != actual.height) {
        return failWithActual(name + ": golden is " + std::to_string(expected.width) + "x" +
                              std::to_string(expected.height) + ", actual is " + std::to_string(actual.width) + "x" +
                              std::to_string(actual.height));
    }
    verdict.difference = compareImages(expected, actual, policy.channelTolerance);
    const std::size_t pixels = std::size_t(actual.width) * std::size_t(actual.height);
    const double fraction = double(verdict.difference.differentPixels) / double(pixels);
    std::ostringstream line;
    line << name << ": " << verdict.difference.differentPixels << " of " << pixels << " pixels (" << fraction * 100.0
         << "%) differ by more than " << policy.channelTolerance << " in a channel (largest "
         << verdict.difference.largestChannelDelta << "); allowed " << policy.maxDifferentFraction * 100.0 << "%";
    verdict.passed = fraction <= policy.maxDifferentFraction;
    if (verdict.passed) {  // golden output folders hold only current failures
        std::filesystem::remove(policy.actualPath);
        std::filesystem::remove(policy.diffPath);
        verdict.message = line.str();
        return verdict;
    }
    failWithActual(line.str() + "\n  golden: " + policy.baseline);
    render::writePng(verdict.difference.diff, policy.diffPath);
    verdict.message += "\n  diff:   " + policy.diffPath;
    return verdict;
}

bool updateRequested() {
    const char* env = std::getenv("ISOTRACK_UPDATE_GOLDEN");
    return env != nullptr && std::strcmp(env, "1") == 0;
}

}  // namespace isotrack::test
