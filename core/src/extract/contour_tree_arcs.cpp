// The contour tree's arcs: the augmented tree (one edge per sample) compressed
// into arcs between its critical samples, each arc keeping its regular samples
// in ascending order; and the queries on the compressed tree.
//
// Passes of compressContourTree, all by rank (the position in the sorted
// order, as the merge leaves the tree), so that an arc's samples are near each
// other: countDegrees (arcs above and below each sample), chains (union-find
// over the edges between regular samples: each chain is an arc, numbered by
// its smallest sample index), the nodes (samples with other than one arc each
// way, numbered by sample index), endpoints (an edge from a chain to a node
// gives that arc its end; edges between two nodes are arcs of their own, in
// the order of the sample holding the edge), and the arcs' sample lists (the
// ranks in order, bucketed by arc, so each stays sorted). One array of 4 bytes
// a rank says which chain or node each is; with the edges and the order, 12
// bytes a sample besides the tree itself, 18 while the chains are found.
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "contour_tree_build.h"

namespace isotrack::detail {
namespace {

struct Degrees {
    Buffer<std::uint8_t> up, down;
    bool regular(std::uint32_t k) const { return up[k] == 1 && down[k] == 1; }
};

Degrees countDegrees(const AugmentedTree& tree) {
    const std::size_t n = tree.next.size();
    Degrees d{Buffer<std::uint8_t>(n, 0), Buffer<std::uint8_t>(n, 0)};
    for (std::uint32_t k = 0; k < n; ++k) {
        if (tree.next[k] == kNoSample) continue;
        const std::uint32_t t = tree.next[k] & AugmentedTree::kIndexMask;
        if (tree.next[k] & AugmentedTree::kDownBit) {
            ++d.down[k], ++d.up[t];
        } else {
            ++d.up[k], ++d.down[t];
        }
    }
    return d;
}

std::uint32_t chainRoot(Buffer<std::uint32_t>& forest, std::uint32_t k) {
    while (forest[k] != k) {
        forest[k] = forest[forest[k]];
        k = forest[k];
    }
    return k;
}

// Numbers the chains of regular samples by their smallest sample index:
// arcOf[k] for each regular rank; returns the number of chains.
std::uint32_t numberChains(const AugmentedTree& tree, const Degrees& d, Buffer<std::uint32_t>& arcOf) {
    const auto n = std::uint32_t(tree.next.size());
    Buffer<std::uint32_t> forest(n);
    for (std::uint32_t k = 0; k < n; ++k) forest[k] = k;
    for (std::uint32_t k = 0; k < n; ++k) {
        if (tree.next[k] == kNoSample || !d.regular(k)) continue;
        const std::uint32_t t = tree.next[k] & AugmentedTree::kIndexMask;
        if (d.regular(t)) forest[chainRoot(forest, k)] = chainRoot(forest, t);
    }
    // Provisional numbers in rank order, kept at each root; then renumbered.
    constexpr std::uint32_t kNumbered = 0x80000000u;
    std::vector<std::uint32_t> smallest;  // by provisional number
    arcOf.assign(n, kNoSample);
    auto numberedRoot = [&](std::uint32_t k) {  // chainRoot, where a numbered entry is a root too
        for (;;) {
            const std::uint32_t parent = forest[k];
            if (parent == k || (parent & kNumbered)) return k;
            const std::uint32_t grandparent = forest[parent];
            if (grandparent == parent || (grandparent & kNumbered)) return parent;
            forest[k] = grandparent;
            k = grandparent;
        }
    };
    for (std::uint32_t k = 0; k < n; ++k) {
        if (!d.regular(k)) continue;
        const std::uint32_t r = numberedRoot(k);
        if (!(forest[r] & kNumbered)) {
            forest[r] = std::uint32_t(smallest.size()) | kNumbered;
            smallest.push_back(tree.order[k]);
        }
        const std::uint32_t chain = forest[r] & ~kNumbered;
        smallest[chain] = std::min(smallest[chain], tree.order[k]);
        arcOf[k] = chain;
    }
    std::vector<std::uint32_t> byFirst(smallest.size());
    for (std::uint32_t c = 0; c < byFirst.size(); ++c) byFirst[c] = c;
    sortByKey(byFirst, [&](std::uint32_t c) { return smallest[c]; });
    std::vector<std::uint32_t>& renumber = smallest;  // reused: provisional -> final
    for (std::uint32_t c = 0; c < byFirst.size(); ++c) renumber[byFirst[c]] = c;
    for (std::uint32_t& a : arcOf) {
        if (a != kNoSample) a = renumber[a];
    }
    return std::uint32_t(byFirst.size());
}

// arcOf after numberNodes: a regular rank's chain, or a node's number with kNodeBit.
constexpr std::uint32_t kNodeBit = 0x80000000u;
bool isNode(std::uint32_t entry) { return (entry & kNodeBit) != 0; }

// The nodes, numbered by sample index, with their degrees; marked in arcOf.
void numberNodes(const Volume& volume, const AugmentedTree& tree, const Degrees& d, Buffer<std::uint32_t>& arcOf,
                 ContourTree& out) {
    const auto n = std::uint32_t(tree.next.size());
    std::vector<std::uint32_t> nodeRanks;  // by sample
    for (std::uint32_t k = 0; k < n; ++k) {
        if (!d.regular(k)) nodeRanks.push_back(k);
    }
    sortByKey(nodeRanks, [&](std::uint32_t k) { return tree.order[k]; });
    out.nodes.resize(nodeRanks.size());
    visitSamples(volume, [&](const auto* values) {
        for (std::uint32_t i = 0; i < nodeRanks.size(); ++i) {
            const std::uint32_t k = nodeRanks[i];
            ContourTree::Node& node = out.nodes[i];
            node.sample = tree.order[k];
            node.value = double(values[node.sample]);
            node.up = d.up[k], node.down = d.down[k];
            arcOf[k] = i | kNodeBit;
        }
    });
}

// Gives each arc its end nodes; an edge between two nodes is an arc of its own.
void linkArcs(const AugmentedTree& tree, const Buffer<std::uint32_t>& arcOf, ContourTree& out) {
    const auto n = std::uint32_t(tree.next.size());
    auto node = [&](std::uint32_t k) { return arcOf[k] & ~kNodeBit; };
    std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>> between;  // holder's sample, lower, upper
    for (std::uint32_t k = 0; k < n; ++k) {
        if (tree.next[k] == kNoSample) continue;
        const std::uint32_t t = tree.next[k] & AugmentedTree::kIndexMask;
        const bool rk = !isNode(arcOf[k]), rt = !isNode(arcOf[t]);
        if (rk && rt) continue;
        const std::uint32_t lo = std::min(k, t), hi = std::max(k, t);
        if (!rk && !rt) {
            between.emplace_back(tree.order[k], lo, hi);
            continue;
        }
        const std::uint32_t chain = arcOf[rk ? k : t], end = rk ? t : k;
        if (end == lo) {
            out.arcs[chain].lower = node(end);
        } else {
            out.arcs[chain].upper = node(end);
        }
    }
    std::sort(between.begin(), between.end());
    for (const auto& [holder, lo, hi] : between) {
        ContourTree::Arc arc;
        arc.lower = node(lo), arc.upper = node(hi);
        out.arcs.push_back(arc);
    }
}

// The arcs' regular samples, bucketed in ascending order.
void fillSamples(const AugmentedTree& tree, const Buffer<std::uint32_t>& arcOf, std::uint32_t chains,
                 ContourTree& out) {
    std::vector<std::size_t> start(std::size_t(chains) + 1, 0);
    for (const std::uint32_t a : arcOf) {
        if (!isNode(a)) ++start[a + 1];
    }
    for (std::size_t a = 0; a < chains; ++a) start[a + 1] += start[a];
    for (std::size_t a = 0; a < chains; ++a) out.arcs[a].begin = out.arcs[a].end = start[a];
    out.samples.resize(start[chains]);
    const auto n = std::uint32_t(arcOf.size());
    for (std::uint32_t k = 0; k < n; ++k) {
        const std::uint32_t a = arcOf[k];
        if (!isNode(a)) out.samples[out.arcs[a].end++] = tree.order[k];
    }
}

void indexNodeArcs(ContourTree& out) {
    out.nodeArcBegin.assign(out.nodes.size() + 1, 0);
    for (const ContourTree::Arc& arc : out.arcs) ++out.nodeArcBegin[arc.lower + 1], ++out.nodeArcBegin[arc.upper + 1];
    for (std::size_t n = 0; n < out.nodes.size(); ++n) out.nodeArcBegin[n + 1] += out.nodeArcBegin[n];
    out.nodeArcs.resize(out.nodeArcBegin.back());
    std::vector<std::uint32_t> fill(out.nodeArcBegin.begin(), out.nodeArcBegin.end() - 1);
    for (std::size_t a = 0; a < out.arcs.size(); ++a) {
        out.nodeArcs[fill[out.arcs[a].lower]++] = std::uint32_t(a);
        out.nodeArcs[fill[out.arcs[a].upper]++] = std::uint32_t(a);
    }
}

}  // namespace

ContourTree compressContourTree(const Volume& volume, AugmentedTree&& augmented) {
    ContourTree out;
    out.dims = volume.dims();
    Buffer<std::uint32_t> arcOf;
    std::uint32_t chains = 0;
    {
        const Degrees d = countDegrees(augmented);
        chains = numberChains(augmented, d, arcOf);
        numberNodes(volume, augmented, d, arcOf, out);
    }
    out.arcs.resize(chains);
    linkArcs(augmented, arcOf, out);
    Buffer<std::uint32_t>().swap(augmented.next);
    fillSamples(augmented, arcOf, chains, out);
    Buffer<std::uint32_t>().swap(arcOf), Buffer<std::uint32_t>().swap(augmented.order);
    indexNodeArcs(out);
    return out;
}

}  // namespace isotrack::detail

namespace isotrack {

std::size_t ContourTree::nodeAt(std::uint32_t sample) const {
    const auto it = std::lower_bound(nodes.begin(), nodes.end(), sample,
                                     [](const Node& node, std::uint32_t s) { return node.sample < s; });
    return it != nodes.end() && it->sample == sample ? std::size_t(it - nodes.begin()) : nodes.size();
}

std::vector<std::size_t> ContourTree::arcsAt(double v) const {
    std::vector<std::size_t> out;
    for (std::size_t a = 0; a < arcs.size(); ++a) {
        const Arc& arc = arcs[a];
        if (arc.pruned) continue;
        const double lo = nodes[arc.lower].value, hi = nodes[arc.upper].value;
        if ((std::isnan(lo) || lo < v) && hi >= v) out.push_back(a);
    }
    return out;
}

std::size_t followArc(const ContourTree& tree, std::size_t arc, double to) {
    auto crosses = [&](std::size_t a) {
        const double lo = tree.nodes[tree.arcs[a].lower].value, hi = tree.nodes[tree.arcs[a].upper].value;
        return (std::isnan(lo) || lo < to) && hi >= to;
    };
    if (crosses(arc)) return arc;
    const bool up = tree.nodes[tree.arcs[arc].upper].value < to;
    std::size_t node = up ? tree.arcs[arc].upper : tree.arcs[arc].lower;
    for (;;) {
        std::size_t next = tree.arcs.size();
        for (std::uint32_t k = tree.nodeArcBegin[node]; k < tree.nodeArcBegin[node + 1]; ++k) {
            const std::size_t a = tree.nodeArcs[k];
            const ContourTree::Arc& candidate = tree.arcs[a];
            if (candidate.pruned || (up ? candidate.lower : candidate.upper) != node) continue;
            if (next == tree.arcs.size() || candidate.size() > tree.arcs[next].size()) next = a;
        }
        if (next == tree.arcs.size() || crosses(next)) return next;
        node = up ? tree.arcs[next].upper : tree.arcs[next].lower;
    }
}

double ContourTree::persistence(std::size_t arc) const {
    const double lo = nodes[arcs[arc].lower].value, hi = nodes[arcs[arc].upper].value;
    if (std::isnan(lo) || std::isnan(hi)) return std::numeric_limits<double>::infinity();
    return hi - lo;
}

std::size_t ContourTree::byteSize() const {
    return nodes.size() * sizeof(Node) + arcs.size() * sizeof(Arc) +
           (samples.size() + nodeArcBegin.size() + nodeArcs.size()) * sizeof(std::uint32_t);
}

}  // namespace isotrack
