#pragma once
// What the contour-tree plot in the panel (method tree) shows: the tree's
// layout (isotrack/tree_layout.h, built once per tree by the viewer's worker)
// and the surfaces on its arcs. Plain values, as the rest of PanelState.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "isotrack/tree_layout.h"

namespace isotrack::ui {

struct TreePlotSurface {
    std::uint32_t id = 0;  // the surface's id
    std::size_t arc = 0;
    std::array<float, 3> colour{};
    double iso = 0.0;  // its own isovalue: a mark on its arc
};

struct TreePlotState {
    std::shared_ptr<const TreeLayout> layout;  // null until the tree is built
    std::vector<TreePlotSurface> surfaces;
    // How long the tree's build took (0 when not known): in all, with the
    // plot's layout, and each phase (sort, sweeps, merge, arcs).
    double buildSeconds = 0.0;
    std::array<double, 4> buildPhaseSeconds{};
};

}  // namespace isotrack::ui
