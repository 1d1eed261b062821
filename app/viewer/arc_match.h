#pragma once
// Identity across isovalues with the contour tree: a surface is its arc.
//
// A new surface (at the new isovalue, on arc b) continues the old surface (at
// the old isovalue) on the arc that b leads back to at the old isovalue, by
// core's followArc. So on the same arc it is the same surface; after a split
// every part leads back to the surface that split; after a merge the merged
// surface leads back to the branch sweeping the most samples, and the other
// surfaces that joined it end there; a surface born on the way (a new extremum
// passed) leads back to none and continues nothing.
#include <cstddef>
#include <optional>
#include <vector>

#include "isotrack/contour_tree.h"

namespace isotrack::viewer {

// For each new surface, the index of the old surface it continues, or -1.
// `oldArcs` are the old surfaces' arcs at `oldIso`, `newArcs` the new ones'.
// nullopt when a surface has no arc (it came from another method): then the
// caller matches another way.
std::optional<std::vector<int>> matchByArc(const ContourTree& tree, double oldIso,
                                           const std::vector<std::optional<std::size_t>>& oldArcs,
                                           const std::vector<std::optional<std::size_t>>& newArcs);

}  // namespace isotrack::viewer
