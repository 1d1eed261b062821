#pragma once
// The golden-image comparison shared by the GL tests (tests/gl/gl_test_support.h)
// and the viewer's window screenshots (tests/viewer/viewer_check.cpp): a pixel
// differs when any of its R, G, B channels differs from the baseline by more
// than a tolerance; the diff image shows differing pixels in red and the rest
// as a dimmed copy of the baseline.
#include <cstddef>

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

}  // namespace isotrack::test
