#include "golden_compare.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>

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

bool updateRequested() {
    const char* env = std::getenv("ISOTRACK_UPDATE_GOLDEN");
    return env != nullptr && std::strcmp(env, "1") == 0;
}

}  // namespace isotrack::test
