#pragma once
// Surface colours: distinct, deterministic, for any number of surfaces.
#include <cstddef>

#include <glm/vec3.hpp>

namespace isotrack::render {

// The colour of the surface at `rank` (0 = the largest surface): neighbours in
// rank differ strongly in hue, and no two of the first few hundred come close
// (a low-discrepancy sequence in hue, saturation and value). Rank 0 is a warm
// sand tone. Pure function of the rank: the same on every run and platform.
glm::vec3 surfaceColour(std::size_t rank);

}  // namespace isotrack::render
