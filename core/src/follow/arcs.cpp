// Identity by the contour tree: a surface is its arc (isotrack/follow.h).
#include <map>

#include "isotrack/follow.h"

namespace isotrack {

std::optional<std::vector<int>> matchSurfacesByArc(const ContourTree& tree, double oldIso,
                                                   const std::vector<std::optional<std::size_t>>& oldArcs,
                                                   const std::vector<std::optional<std::size_t>>& newArcs) {
    std::map<std::size_t, int> oldOfArc;
    for (std::size_t i = 0; i < oldArcs.size(); ++i) {
        if (!oldArcs[i]) return std::nullopt;
        oldOfArc.emplace(*oldArcs[i], static_cast<int>(i));
    }
    std::vector<int> match(newArcs.size(), -1);
    for (std::size_t k = 0; k < newArcs.size(); ++k) {
        if (!newArcs[k]) return std::nullopt;
        const auto found = oldOfArc.find(followArc(tree, *newArcs[k], oldIso));
        if (found != oldOfArc.end()) match[k] = found->second;
    }
    return match;
}

std::optional<Surface> surfaceAtOwnIsovalue(const ContourTree& tree, const Volume& volume, std::size_t arc, double iso,
                                            int threads) {
    const std::size_t followed = followArc(tree, arc, iso);
    if (followed >= tree.arcs.size()) return std::nullopt;
    return trackArc(tree, volume, followed, iso, threads);
}

}  // namespace isotrack
