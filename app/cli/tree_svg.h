#pragma once
// The contour tree's plot as SVG: the layout the viewer's panel draws
// (isotrack/tree_layout.h), arcs coloured as their surfaces.
#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "isotrack/tree_layout.h"

namespace isotrack::cli {

// A surface on the plot: its arc, its colour and its own isovalue (a mark).
struct PlottedSurface {
    std::size_t arc = 0;
    std::array<float, 3> colour{};
    double iso = 0.0;
};

// One <line class="branch"> per branch of the layout (data-arcs: how many
// arcs it draws, grey), over it one <line class="arc"> per surface on a drawn
// arc (data-arc, data-surface: its index in `surfaces`, in its colour), one
// <line class="link"> per link, the isovalue `at` as a dashed line and each
// surface's isovalue as a <circle class="surface">.
std::string treeSvg(const TreeLayout& layout, const std::vector<PlottedSurface>& surfaces, double at);

}  // namespace isotrack::cli
