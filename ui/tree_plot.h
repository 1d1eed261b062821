#pragma once
// The contour-tree plot in the panel: what a click on an arc asks for.
#include <cstddef>
#include <optional>

#include "ui/actions.h"
#include "ui/tree_plot_state.h"

namespace isotrack::ui {

inline constexpr std::size_t kTreePlotBranches = 400;  // the most persistent branches drawn

// The action a click at (x, value) in the layout's coordinates asks for:
// selecting the surface on the arc nearest the point (within xTolerance of its
// column and valueTolerance of its values), or nothing when no arc is there or
// the arc has no surface.
std::optional<Action> treePlotClick(const TreePlotState& plot, float x, double value, float xTolerance,
                                    double valueTolerance);

}  // namespace isotrack::ui
