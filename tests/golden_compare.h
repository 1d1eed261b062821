#pragma once
// The golden-image comparison shared by the GL tests (tests/gl/gl_test_support.h)
// and the viewer's window screenshots (tests/viewer/viewer_check.cpp): a pixel
// differs when any of its R, G, B channels differs from the baseline by more
// than a tolerance; the diff image shows differing pixels in red and the rest
// as a dimmed copy of the baseline.
#include <cstddef>
#include <string>

#include "render/image.h"

namespace isotrack::test {

struct ImageDifference {
    std::size_t differentPixels = 0;
    int largestChannelDelta = 0;
    render::Image diff;
};

// `expected` and `actual` have the same size.
ImageDifference compareImages(const render::Image& expected, const render::Image& actual, int channelTolerance);

// True when ISOTRACK_UPDATE_GOLDEN=1: write baselines instead of comparing.
bool updateRequested();

// The golden policy both kinds of golden test follow. With ISOTRACK_UPDATE_GOLDEN=1
// the baseline is written (look at it before committing). A missing baseline or one
// of another size fails and writes ACTUAL; otherwise more than `maxDifferentFraction`
// of pixels differing by more than `channelTolerance` fails and writes ACTUAL and
// DIFF, and a pass removes what an earlier failure left there.
struct GoldenPolicy {
    std::string baseline;    // tests/golden/NAME.png
    std::string actualPath;  // where the image goes when it fails
    std::string diffPath;    // where the diff image goes when it fails
    int channelTolerance = 0;
    double maxDifferentFraction = 0.0;
};

struct GoldenVerdict {
    bool passed = false;
    bool updated = false;        // the baseline was written
    std::string message;         // what happened, with the paths to look at; one line when passing
    ImageDifference difference;  // when compared
};

GoldenVerdict checkGoldenImage(const render::Image& actual, const std::string& name, const GoldenPolicy& policy);

}  // namespace isotrack::test
