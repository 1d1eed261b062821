// Simplifying the contour tree by pruning leaf branches (Carr, Snoeyink & van
// de Panne 2004, "Simplifying flexible isosurfaces using local geometric
// measures").
//
// A leaf branch runs from an extremum through nodes left with one arc each way
// to the first node with more: a maximum's branch may be pruned where it ends
// at a node with two or more arcs above (so the rest stays connected), a
// minimum's at a node with two or more below. Branches are pruned smallest
// first, from a heap; pruning makes others longer, so a branch popped is
// measured again and pushed back when it has grown (measures only grow).
#include <cmath>
#include <functional>
#include <queue>
#include <utility>

#include "isotrack/contour_tree.h"

namespace isotrack {
namespace {

struct Branch {
    std::vector<std::size_t> arcs;
    std::size_t end = 0;  // the node it joins the rest at
    bool prunable = false;
    double persistence = 0.0;
    double size = 0.0;  // samples it sweeps
};

class Pruner {
public:
    explicit Pruner(ContourTree& tree)
        : tree_(tree), up_(tree.nodes.size()), down_(tree.nodes.size()), start_(tree.nodes.size() + 1, 0) {
        for (const ContourTree::Arc& arc : tree.arcs) {
            if (arc.pruned) continue;
            ++up_[arc.lower], ++down_[arc.upper];
            ++start_[arc.lower + 1], ++start_[arc.upper + 1];
        }
        for (std::size_t n = 0; n < tree.nodes.size(); ++n) start_[n + 1] += start_[n];
        incident_.resize(start_.back());
        std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
        for (std::size_t a = 0; a < tree.arcs.size(); ++a) {
            if (tree.arcs[a].pruned) continue;
            incident_[fill[tree.arcs[a].lower]++] = a;
            incident_[fill[tree.arcs[a].upper]++] = a;
        }
    }

    bool leaf(std::size_t n) const { return up_[n] + down_[n] == 1; }

    Branch branch(std::size_t leafNode) const {
        Branch b;
        const bool fromMax = up_[leafNode] == 0;
        std::size_t node = leafNode;
        do {
            const std::size_t arc = liveArc(node, !fromMax);
            b.arcs.push_back(arc);
            b.size += double(tree_.arcs[arc].size()) + 1.0;
            node = fromMax ? tree_.arcs[arc].lower : tree_.arcs[arc].upper;
        } while (up_[node] == 1 && down_[node] == 1);
        b.end = node;
        b.prunable = fromMax ? up_[node] >= 2 : down_[node] >= 2;
        const double lo = tree_.nodes[fromMax ? node : leafNode].value,
                     hi = tree_.nodes[fromMax ? leafNode : node].value;
        b.persistence = std::isnan(lo) || std::isnan(hi) ? INFINITY : hi - lo;
        return b;
    }

    void prune(const Branch& b) {
        for (const std::size_t arc : b.arcs) {
            tree_.arcs[arc].pruned = true;
            --up_[tree_.arcs[arc].lower], --down_[tree_.arcs[arc].upper];
        }
    }

    // The leaves whose branches pass through `node` once it has one arc each way
    // (a branch that was not prunable there may be now).
    std::vector<std::size_t> leavesThrough(std::size_t node) const {
        std::vector<std::size_t> out;
        if (up_[node] != 1 || down_[node] != 1) return out;
        for (const bool goingUp : {true, false}) {
            std::size_t n = node;
            do {
                const std::size_t arc = liveArc(n, goingUp);
                n = goingUp ? tree_.arcs[arc].upper : tree_.arcs[arc].lower;
            } while (up_[n] == 1 && down_[n] == 1);
            if (leaf(n)) out.push_back(n);
        }
        return out;
    }

private:
    // The one arc below (down) or above a node that is not pruned.
    std::size_t liveArc(std::size_t node, bool goingUp) const {
        for (std::size_t k = start_[node]; k < start_[node + 1]; ++k) {
            const ContourTree::Arc& arc = tree_.arcs[incident_[k]];
            if (!arc.pruned && (goingUp ? arc.lower : arc.upper) == node) return incident_[k];
        }
        return incident_[start_[node]];
    }

    ContourTree& tree_;
    std::vector<std::uint32_t> up_, down_;
    std::vector<std::size_t> start_, incident_;
};

void pruneBy(ContourTree& tree, double threshold, const std::function<double(const Branch&)>& measure) {
    Pruner pruner(tree);
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
    for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
        if (pruner.leaf(n)) heap.push({measure(pruner.branch(n)), n});
    }
    while (!heap.empty() && heap.top().first < threshold) {
        const auto [popped, n] = heap.top();
        heap.pop();
        if (!pruner.leaf(n)) continue;
        const Branch b = pruner.branch(n);
        const double m = measure(b);
        if (m > popped) {
            heap.push({m, n});
        } else if (b.prunable) {
            pruner.prune(b);
            for (const std::size_t other : pruner.leavesThrough(b.end))
                heap.push({measure(pruner.branch(other)), other});
        }
    }
}

}  // namespace

void simplifyContourTree(ContourTree& tree, double minPersistence, std::size_t minSize) {
    if (minPersistence > 0) pruneBy(tree, minPersistence, [](const Branch& b) { return b.persistence; });
    if (minSize > 0) pruneBy(tree, double(minSize), [](const Branch& b) { return b.size; });
}

}  // namespace isotrack
