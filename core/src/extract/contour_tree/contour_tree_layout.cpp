// The contour tree laid out for a plot: a branch decomposition (Pascucci, Cole-
// McLaughlin & Scorzelli 2004, "Multi-resolution computation and presentation
// of contour trees") drawn with isovalue upwards and a column per branch.
//
// Passes:
//   1. incidence: each node's kept arcs above and below it (pruned arcs left out);
//   2. order: the nodes in a topological order of the arcs (lower before upper),
//      so equal values and NaN need no comparisons;
//   3. reach: for each node, the highest value a monotone climb from it
//      reaches and the lowest a monotone descent reaches, with the arc each
//      starts by;
//   4. branches: from a heap, most persistent first: the root branch climbs from
//      the lowest node; walking a branch pushes every other arc at its nodes as
//      a branch of its own, measured by its reach, until maxBranches are out;
//   5. columns: the branches depth first from the root, children in the order
//      they came out, one column each; a link joins a branch to its parent at
//      the node it starts from.
// Every arc is on exactly one branch: a walk takes one arc into a node and one
// out, and hands every other arc there to a new branch. A branch is monotone,
// so the segments in one column never overlap.
#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "isotrack/tree_layout.h"

namespace isotrack {
namespace {

constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

double keyOf(double value) { return std::isnan(value) ? -std::numeric_limits<double>::infinity() : value; }

// Pass 1: kept arcs per node, above (the node is their lower end) and below.
struct Incidence {
    std::vector<std::size_t> upBegin, up, downBegin, down;

    explicit Incidence(const ContourTree& tree) {
        const std::size_t n = tree.nodes.size();
        upBegin.assign(n + 1, 0), downBegin.assign(n + 1, 0);
        for (const ContourTree::Arc& arc : tree.arcs) {
            if (arc.pruned) continue;
            ++upBegin[arc.lower + 1], ++downBegin[arc.upper + 1];
        }
        for (std::size_t k = 0; k < n; ++k) upBegin[k + 1] += upBegin[k], downBegin[k + 1] += downBegin[k];
        up.resize(upBegin.back()), down.resize(downBegin.back());
        std::vector<std::size_t> upFill(upBegin.begin(), upBegin.end() - 1);
        std::vector<std::size_t> downFill(downBegin.begin(), downBegin.end() - 1);
        for (std::size_t a = 0; a < tree.arcs.size(); ++a) {
            const ContourTree::Arc& arc = tree.arcs[a];
            if (arc.pruned) continue;
            up[upFill[arc.lower]++] = a, down[downFill[arc.upper]++] = a;
        }
    }
    std::size_t ups(std::size_t node) const { return upBegin[node + 1] - upBegin[node]; }
    std::size_t downs(std::size_t node) const { return downBegin[node + 1] - downBegin[node]; }
};

// Passes 2 and 3: each node's monotone reach upwards and downwards.
struct Reach {
    std::vector<double> highest, lowest;
    std::vector<std::size_t> climbBy, descendBy;  // the arc reaching furthest, or kNone

    Reach(const ContourTree& tree, const Incidence& in) {
        const std::size_t n = tree.nodes.size();
        std::vector<std::size_t> order, waiting(n);
        order.reserve(n);
        for (std::size_t k = 0; k < n; ++k) {
            waiting[k] = in.downs(k);
            if (waiting[k] == 0) order.push_back(k);
        }
        for (std::size_t i = 0; i < order.size(); ++i) {
            for (std::size_t j = in.upBegin[order[i]]; j < in.upBegin[order[i] + 1]; ++j) {
                const std::size_t upper = tree.arcs[in.up[j]].upper;
                if (--waiting[upper] == 0) order.push_back(upper);
            }
        }
        highest.resize(n), lowest.resize(n), climbBy.assign(n, kNone), descendBy.assign(n, kNone);
        for (std::size_t i = order.size(); i-- > 0;) {
            const std::size_t node = order[i];
            highest[node] = keyOf(tree.nodes[node].value);
            for (std::size_t j = in.upBegin[node]; j < in.upBegin[node + 1]; ++j) {
                const std::size_t a = in.up[j];
                if (climbBy[node] == kNone || highest[tree.arcs[a].upper] > highest[node]) {
                    highest[node] = highest[tree.arcs[a].upper], climbBy[node] = a;
                }
            }
        }
        for (const std::size_t node : order) {
            lowest[node] = keyOf(tree.nodes[node].value);
            for (std::size_t j = in.downBegin[node]; j < in.downBegin[node + 1]; ++j) {
                const std::size_t a = in.down[j];
                if (descendBy[node] == kNone || lowest[tree.arcs[a].lower] < lowest[node]) {
                    lowest[node] = lowest[tree.arcs[a].lower], descendBy[node] = a;
                }
            }
        }
    }
};

struct PendingBranch {
    double persistence = 0.0;
    std::size_t firstArc = 0, start = 0, parent = 0;
    bool up = true;
    bool operator<(const PendingBranch& other) const {  // the heap's top: most persistent, then lowest arc
        if (persistence != other.persistence) return persistence < other.persistence;
        return firstArc > other.firstArc;
    }
};

struct Branch {
    std::size_t start = 0, parent = 0;
    std::vector<std::size_t> arcs;
};

// Pass 4: the branches, most persistent first, at most maxBranches.
class Decomposer {
public:
    Decomposer(const ContourTree& tree, const Incidence& in, const Reach& reach)
        : tree_(tree), in_(in), reach_(reach) {}

    std::vector<Branch> run(std::size_t maxBranches, double& minPersistence) {
        std::vector<Branch> branches;
        const std::size_t root = lowestNode();
        if (root == kNone) return branches;
        if (maxBranches == 0) return branches;
        pushOthers(root, kNone, reach_.climbBy[root], 0);
        minPersistence = std::numeric_limits<double>::infinity();
        branches.push_back(walk({minPersistence, reach_.climbBy[root], root, 0, true}, 0));
        while (!heap_.empty() && branches.size() < maxBranches) {
            const PendingBranch next = heap_.top();
            heap_.pop();
            minPersistence = next.persistence;
            branches.push_back(walk(next, branches.size()));
        }
        return branches;
    }

private:
    std::size_t lowestNode() const {
        std::size_t best = kNone;
        for (std::size_t k = 0; k < tree_.nodes.size(); ++k) {
            if (in_.downs(k) != 0 || in_.ups(k) == 0) continue;
            if (best == kNone || keyOf(tree_.nodes[k].value) < keyOf(tree_.nodes[best].value)) best = k;
        }
        return best;
    }

    // Every arc at `node` but the two a branch takes there becomes a pending branch.
    void pushOthers(std::size_t node, std::size_t in, std::size_t out, std::size_t parent) {
        const double here = keyOf(tree_.nodes[node].value);
        for (std::size_t j = in_.upBegin[node]; j < in_.upBegin[node + 1]; ++j) {
            const std::size_t a = in_.up[j];
            if (a != in && a != out) push(reach_.highest[tree_.arcs[a].upper] - here, a, node, parent, true);
        }
        for (std::size_t j = in_.downBegin[node]; j < in_.downBegin[node + 1]; ++j) {
            const std::size_t a = in_.down[j];
            if (a != in && a != out) push(here - reach_.lowest[tree_.arcs[a].lower], a, node, parent, false);
        }
    }
    void push(double persistence, std::size_t arc, std::size_t node, std::size_t parent, bool up) {
        heap_.push({std::isnan(persistence) ? 0.0 : persistence, arc, node, parent, up});
    }

    Branch walk(const PendingBranch& pending, std::size_t id) {
        Branch branch{pending.start, pending.parent, {}};
        for (std::size_t arc = pending.firstArc; arc != kNone;) {
            branch.arcs.push_back(arc);
            const std::size_t node = pending.up ? tree_.arcs[arc].upper : tree_.arcs[arc].lower;
            const std::size_t next = pending.up ? reach_.climbBy[node] : reach_.descendBy[node];
            pushOthers(node, arc, next, id);
            arc = next;
        }
        return branch;
    }

    const ContourTree& tree_;
    const Incidence& in_;
    const Reach& reach_;
    std::priority_queue<PendingBranch> heap_;
};

// Pass 5: a column per branch, depth first from the root.
std::vector<float> branchColumns(const std::vector<Branch>& branches) {
    const std::size_t count = branches.size();
    if (count == 0) return {};
    std::vector<std::vector<std::size_t>> children(count);
    for (std::size_t b = 1; b < count; ++b) children[branches[b].parent].push_back(b);
    std::vector<float> x(count, 0.0f);
    std::vector<std::size_t> stack{0};
    for (std::size_t column = 0; !stack.empty(); ++column) {
        const std::size_t b = stack.back();
        stack.pop_back();
        x[b] = static_cast<float>((double(column) + 0.5) / double(count));
        stack.insert(stack.end(), children[b].rbegin(), children[b].rend());
    }
    return x;
}

}  // namespace

TreeLayout layoutContourTree(const ContourTree& tree, std::size_t maxBranches) {
    TreeLayout layout;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const ContourTree::Node& node : tree.nodes) {
        if (std::isfinite(node.value)) lo = std::min(lo, node.value), hi = std::max(hi, node.value);
    }
    if (!std::isfinite(lo)) lo = 0.0, hi = 1.0;
    if (!(hi > lo)) hi = lo + 1.0;
    layout.lo = lo, layout.hi = hi;
    const Incidence incidence(tree);
    const Reach reach(tree, incidence);
    double minPersistence = 0.0;
    const std::vector<Branch> branches = Decomposer(tree, incidence, reach).run(maxBranches, minPersistence);
    layout.branches = branches.size();
    layout.minShownPersistence = minPersistence;
    const std::vector<float> x = branchColumns(branches);
    auto valueAt = [&](std::size_t node) {
        const double v = tree.nodes[node].value;
        return std::isnan(v) ? lo : v;
    };
    std::size_t kept = 0;
    for (const ContourTree::Arc& arc : tree.arcs) kept += arc.pruned ? 0 : 1;
    layout.prunedArcs = tree.arcs.size() - kept;
    for (std::size_t b = 0; b < branches.size(); ++b) {
        TreeLayout::BranchLine line{x[b], std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(), branches[b].arcs.size()};
        for (const std::size_t a : branches[b].arcs) {
            const ContourTree::Arc& arc = tree.arcs[a];
            layout.segments.push_back(
                {std::uint32_t(a), std::uint32_t(b), x[b], valueAt(arc.lower), valueAt(arc.upper)});
            line.lower = std::min(line.lower, layout.segments.back().lower);
            line.upper = std::max(line.upper, layout.segments.back().upper);
        }
        layout.branchLines.push_back(line);
        if (b > 0) layout.links.push_back({x[branches[b].parent], x[b], valueAt(branches[b].start)});
    }
    layout.hiddenArcs = kept - layout.segments.size();
    std::sort(layout.segments.begin(), layout.segments.end(),
              [](const TreeLayout::Segment& a, const TreeLayout::Segment& b) { return a.arc < b.arc; });
    return layout;
}

const TreeLayout::Segment* TreeLayout::segmentOf(std::size_t arc) const {
    const auto at = std::lower_bound(segments.begin(), segments.end(), arc,
                                     [](const Segment& s, std::size_t a) { return s.arc < a; });
    return at != segments.end() && at->arc == arc ? &*at : nullptr;
}

const TreeLayout::Segment* TreeLayout::pick(float x, double value, float xTolerance, double valueTolerance) const {
    const Segment* best = nullptr;
    float bestDistance = xTolerance;
    for (const Segment& s : segments) {
        const float distance = std::abs(s.x - x);
        if (distance > bestDistance || value < s.lower - valueTolerance || value > s.upper + valueTolerance) continue;
        if (best && distance == bestDistance && s.arc > best->arc) continue;
        best = &s, bestDistance = distance;
    }
    return best;
}

}  // namespace isotrack
