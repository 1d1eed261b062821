#pragma once
// The contour tree as a plot: isovalue upwards, one column per branch of a
// branch decomposition, each arc a vertical segment in its branch's column.
// Plain numbers only (no GL, no ImGui): the viewer's panel and `isotrack tree
// --out FILE.svg` draw the same layout.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "isotrack/contour_tree.h"

namespace isotrack {

struct TreeLayout {
    // One arc of the tree: a vertical segment at x from value `lower` to
    // `upper` (a NaN end is drawn at `lo`).
    struct Segment {
        std::uint32_t arc = 0;
        std::uint32_t branch = 0;  // 0: the root branch; branches are numbered most persistent first
        float x = 0.0f;            // its branch's column, in (0, 1)
        double lower = 0.0, upper = 0.0;
    };
    // Where a branch meets its parent: a horizontal line at `value` from the
    // parent's column x0 to the branch's column x1.
    struct Link {
        float x0 = 0.0f, x1 = 0.0f;
        double value = 0.0;
    };
    // A branch drawn whole: its column and value range, and its number of arcs.
    // A plot draws these, and only the arcs it colours one by one, so its cost
    // is that of the branches, however many arcs they hold.
    struct BranchLine {
        float x = 0.0f;
        double lower = 0.0, upper = 0.0;
        std::size_t arcs = 0;
    };
    std::vector<Segment> segments;        // sorted by arc
    std::vector<BranchLine> branchLines;  // by branch
    std::vector<Link> links;
    std::size_t branches = 0;
    double lo = 0.0, hi = 1.0;         // the finite node values' range (hi > lo)
    std::size_t hiddenArcs = 0;        // kept arcs on branches left out (maxBranches)
    std::size_t prunedArcs = 0;        // arcs simplifyContourTree pruned
    double minShownPersistence = 0.0;  // the least persistent branch drawn

    // The segment of `arc`, or nullptr when the arc is not drawn.
    const Segment* segmentOf(std::size_t arc) const;
    // The segment nearest to the point (x, value) within `xTolerance`
    // horizontally whose values hold `value` (within `valueTolerance`), or
    // nullptr. For picking an arc in the plot.
    const Segment* pick(float x, double value, float xTolerance, double valueTolerance) const;
};

// Lays out the tree's arcs that are not pruned as a branch decomposition: the
// root branch climbs monotonically from the lowest node, always by the arc
// that reaches highest; every other arc at a node on a branch starts a branch
// of its own, climbing (or descending) monotonically by the arc that reaches
// furthest. A branch's persistence is its value range. The `maxBranches` most
// persistent branches are drawn (a branch only with its parent), each in its
// own column, children after their parent (depth first); the arcs of the rest
// are counted in hiddenArcs. Deterministic: ties go to the lower arc index.
TreeLayout layoutContourTree(const ContourTree& tree, std::size_t maxBranches = SIZE_MAX);

}  // namespace isotrack
