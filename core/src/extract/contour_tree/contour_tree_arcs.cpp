// The contour tree's arcs: the augmented tree (one edge per sample) compressed
// into arcs between its critical samples, each arc keeping its regular samples
// in ascending order; and the queries on the compressed tree.
//
// Passes of compressContourTree: countDegrees (arcs above and below each
// sample), the nodes (samples with other than one arc each way), chains
// (union-find over the edges between regular samples: each chain is an arc),
// endpoints (an edge from a chain to a node gives that arc its end), and the
// arcs' sample lists (the sorted order bucketed by arc, so each stays sorted).
#include <algorithm>
#include <cmath>
#include <limits>

#include "extract/contour_tree/contour_tree_build.h"

namespace isotrack::detail {
namespace {

struct Degrees {
    std::vector<std::uint8_t> up, down;
    bool regular(std::uint32_t s) const { return up[s] == 1 && down[s] == 1; }
};

Degrees countDegrees(const AugmentedTree& tree) {
    const std::size_t n = tree.next.size();
    Degrees d{std::vector<std::uint8_t>(n, 0), std::vector<std::uint8_t>(n, 0)};
    for (std::uint32_t s = 0; s < n; ++s) {
        if (tree.next[s] == kNoSample) continue;
        const std::uint32_t t = tree.next[s] & AugmentedTree::kIndexMask;
        if (tree.next[s] & AugmentedTree::kDownBit) {
            ++d.down[s], ++d.up[t];
        } else {
            ++d.up[s], ++d.down[t];
        }
    }
    return d;
}

std::uint32_t chainRoot(std::vector<std::uint32_t>& forest, std::uint32_t s) {
    while (forest[s] != s) {
        forest[s] = forest[forest[s]];
        s = forest[s];
    }
    return s;
}

// Numbers the chains of regular samples: arcOf[s] for each regular sample;
// returns the number of chains.
std::uint32_t numberChains(const AugmentedTree& tree, const Degrees& d, std::vector<std::uint32_t>& arcOf) {
    const auto n = std::uint32_t(tree.next.size());
    std::vector<std::uint32_t> forest(n);
    for (std::uint32_t s = 0; s < n; ++s) forest[s] = s;
    for (std::uint32_t s = 0; s < n; ++s) {
        if (tree.next[s] == kNoSample || !d.regular(s)) continue;
        const std::uint32_t t = tree.next[s] & AugmentedTree::kIndexMask;
        if (d.regular(t)) forest[chainRoot(forest, s)] = chainRoot(forest, t);
    }
    arcOf.assign(n, kNoSample);
    std::uint32_t chains = 0;
    for (std::uint32_t s = 0; s < n; ++s) {
        if (!d.regular(s)) continue;
        const std::uint32_t r = chainRoot(forest, s);
        if (arcOf[r] == kNoSample) arcOf[r] = chains++;
        arcOf[s] = arcOf[r];
    }
    return chains;
}

// Gives each arc its end nodes; an edge between two nodes is an arc of its own.
template <class T>
void linkArcs(const AugmentedTree& tree, const Degrees& d, const std::vector<std::uint32_t>& arcOf, ContourTree& out,
              const T* values) {
    const SampleOrder<T> cmp{values};
    const auto n = std::uint32_t(tree.next.size());
    auto node = [&](std::uint32_t s) { return std::uint32_t(out.nodeAt(s)); };
    for (std::uint32_t s = 0; s < n; ++s) {
        if (tree.next[s] == kNoSample) continue;
        const std::uint32_t t = tree.next[s] & AugmentedTree::kIndexMask;
        const bool rs = d.regular(s), rt = d.regular(t);
        if (rs && rt) continue;
        const std::uint32_t lo = cmp.below(s, t) ? s : t, hi = lo == s ? t : s;
        if (!rs && !rt) {
            ContourTree::Arc arc;
            arc.lower = node(lo), arc.upper = node(hi);
            out.arcs.push_back(arc);
            continue;
        }
        const std::uint32_t chain = arcOf[rs ? s : t], end = rs ? t : s;
        if (end == lo) {
            out.arcs[chain].lower = node(end);
        } else {
            out.arcs[chain].upper = node(end);
        }
    }
}

// The arcs' regular samples, bucketed in ascending order.
void fillSamples(const AugmentedTree& tree, const std::vector<std::uint32_t>& arcOf, std::uint32_t chains,
                 ContourTree& out) {
    std::vector<std::size_t> start(std::size_t(chains) + 1, 0);
    for (const std::uint32_t a : arcOf) {
        if (a != kNoSample) ++start[a + 1];
    }
    for (std::size_t a = 0; a < chains; ++a) start[a + 1] += start[a];
    for (std::size_t a = 0; a < chains; ++a) out.arcs[a].begin = out.arcs[a].end = start[a];
    out.samples.resize(start[chains]);
    for (const std::uint32_t s : tree.order) {
        const std::uint32_t a = arcOf[s];
        if (a != kNoSample) out.samples[out.arcs[a].end++] = s;
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
    std::vector<std::uint32_t> arcOf;
    std::uint32_t chains = 0;
    {
        const Degrees d = countDegrees(augmented);
        const auto n = std::uint32_t(augmented.next.size());
        for (std::uint32_t s = 0; s < n; ++s) {
            if (d.regular(s)) continue;
            ContourTree::Node node;
            node.sample = s;
            node.value = visitSamples(volume, [&](const auto* values) { return double(values[s]); });
            node.up = d.up[s], node.down = d.down[s];
            out.nodes.push_back(node);
        }
        chains = numberChains(augmented, d, arcOf);
        out.arcs.resize(chains);
        visitSamples(volume, [&](const auto* values) { linkArcs(augmented, d, arcOf, out, values); });
    }
    std::vector<std::uint32_t>().swap(augmented.next);
    fillSamples(augmented, arcOf, chains, out);
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
