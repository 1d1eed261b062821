#include "render/palette.h"

#include <cmath>

namespace isotrack::render {
namespace {

constexpr double kGoldenFraction = 0.3819660112501051;  // 1 - 1/phi: the golden angle as a fraction of a turn
constexpr double kFirstHue = 0.09;                      // sand
// 1/g^2 and 1/g^3 for g = 1.2207440846..., the real root of g^3 = g + 1.
constexpr double kR3Second = 0.6710436067037893;
constexpr double kR3Third = 0.5497004779019703;

// HSV with all three in [0, 1].
glm::vec3 hsvToRgb(float h, float s, float v) {
    const float sector = h * 6.0f;
    const auto base = static_cast<int>(std::floor(sector)) % 6;
    const float f = sector - std::floor(sector);
    const float p = v * (1.0f - s), q = v * (1.0f - s * f), t = v * (1.0f - s * (1.0f - f));
    switch (base) {
        case 0: return {v, t, p};
        case 1: return {q, v, p};
        case 2: return {p, v, t};
        case 3: return {p, q, v};
        case 4: return {t, p, v};
        default: return {v, p, q};
    }
}

}  // namespace

glm::vec3 surfaceColour(std::size_t rank) {
    // Hue steps by the golden angle; saturation and value follow the other two
    // coordinates of Roberts' R3 sequence, so (hue, saturation, value) stays
    // evenly spread however many surfaces there are.
    const auto r = static_cast<double>(rank % 65536);
    const auto hue = static_cast<float>(std::fmod(kFirstHue + r * kGoldenFraction, 1.0));
    const auto saturation = static_cast<float>(std::fmod(0.5 + r * kR3Second, 1.0));
    const auto value = static_cast<float>(std::fmod(0.5 + r * kR3Third, 1.0));
    return hsvToRgb(hue, 0.40f + 0.35f * saturation, 0.68f + 0.27f * value);
}

}  // namespace isotrack::render
