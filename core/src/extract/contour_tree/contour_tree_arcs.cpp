// The contour tree's arcs: the merge's chains and edges between nodes made
// into arcs between the critical samples (nodes), each arc keeping its regular
// samples in ascending order; and the queries on the compressed tree.
//
// The nodes (the ranks on no chain) come from the merge's start with their
// degrees, and are numbered by sample index beside the merge (numberNodes).
// Passes of compressContourTree, by rank (the position in the sorted order,
// as the merge leaves the tree): the nodes' records are written and their
// numbers marked in arcOf; one pass counts each chain's samples; the arcs are
// numbered (the chains by their smallest sample index, then the edges between
// two nodes in the order of the sample the merge peeled them from); a second
// pass buckets the ranks by chain, in order, so each arc's samples stay
// sorted. Besides the tree itself: the order and arcOf, 8 bytes a sample.
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "extract/contour_tree/contour_tree_build.h"
#include "support/huge_pages.h"
#include "support/parallel.h"

namespace isotrack::detail {
namespace {

// arcOf after numberNodes: a regular rank's chain, or a node's number with kNodeBit.
constexpr std::uint32_t kNodeBit = 0x80000000u;
bool isNode(std::uint32_t entry) { return (entry & kNodeBit) != 0; }

// The count of each piece's samples in each part of the ranks (the nodes
// marked in arcOf).
void countPieces(const AugmentedTree& tree, std::vector<Buffer<std::uint32_t>>& sizes, const BuildProgress& progress) {
    inRanges(std::uint32_t(tree.arcOf.size()), sizes.size(),
             [&](std::size_t p, std::uint32_t begin, std::uint32_t end) {
                 sizes[p].assign(tree.pieces.size(), 0);
                 progress.inStrides(begin, end, [&](std::uint32_t from, std::uint32_t to) {
                     for (std::uint32_t k = from; k < to; ++k) {
                         const std::uint32_t piece = tree.arcOf[k];
                         if (!isNode(piece)) ++sizes[p][piece];
                     }
                 });
             });
}

// A set of sample indices as bits, with a count of the members before each
// word: a member's position among the members in index order, found without
// sorting them (the nodes and the arcs, a million of each on the CT).
class IndexRanks {
public:
    explicit IndexRanks(std::uint32_t n) : words_(std::size_t(n) / 64 + 1, 0), before_(words_.size() + 1, 0) {}
    void add(std::uint32_t s) { words_[s >> 6] |= std::uint64_t(1) << (s & 63u); }
    // Once every member is added.
    void count() {
        for (std::size_t w = 0; w < words_.size(); ++w) {
            before_[w + 1] = before_[w] + std::uint32_t(__builtin_popcountll(words_[w]));
        }
    }
    std::uint32_t rankOf(std::uint32_t s) const {
        const std::uint64_t below = words_[s >> 6] & ((std::uint64_t(1) << (s & 63u)) - 1);
        return before_[s >> 6] + std::uint32_t(__builtin_popcountll(below));
    }

private:
    Buffer<std::uint64_t> words_;
    Buffer<std::uint32_t> before_;
};

// The nodes' records, numbered by sample index, and each node's number marked
// in arcOf, in parts of the nodes on `parts` threads.
void placeNodes(const Volume& volume, AugmentedTree& tree, std::size_t parts, ContourTree& out) {
    resizeOnHugePages(out.nodes, tree.nodeRanks.size());
    visitSamples(volume, [&](const auto* values) {
        inRanges(std::uint32_t(tree.nodeRanks.size()), parts, [&](std::size_t, std::uint32_t begin, std::uint32_t end) {
            for (std::uint32_t j = begin; j < end; ++j) {
                const std::uint32_t k = tree.nodeRanks[j], sample = tree.order[k], i = tree.nodeNumbers[j];
                ContourTree::Node& node = out.nodes[i];
                node.sample = sample;
                node.value = double(values[sample]);
                node.up = tree.nodeDegrees[j] & 7u, node.down = tree.nodeDegrees[j] >> 3;
                tree.arcOf[k] = i | kNodeBit;
            }
        });
    });
    Buffer<std::uint32_t>().swap(tree.nodeRanks), Buffer<std::uint32_t>().swap(tree.nodeNumbers);
    Buffer<std::uint8_t>().swap(tree.nodeDegrees);
}

// The arcs: chains first, by their smallest sample, then the edges between
// two nodes, by the sample peeled (the pieces by key; both kinds of key are
// unique), and each node's degrees counted; each piece's arc found on
// `parts` threads. Returns the piece of each arc.
Buffer<std::uint32_t> numberArcs(AugmentedTree& tree, std::size_t parts, ContourTree& out) {
    const auto count = std::uint32_t(tree.pieces.size());
    const auto n = std::uint32_t(tree.order.size());
    IndexRanks chains(n), edges(n);
    for (const AugmentedTree::Piece& piece : tree.pieces) {
        if (piece.key & AugmentedTree::kEdgeBit) {
            edges.add(piece.key & AugmentedTree::kIndexMask);
        } else {
            chains.add(piece.key);
        }
    }
    chains.count(), edges.count();
    auto node = [&](std::uint32_t k) { return tree.arcOf[k] & ~kNodeBit; };
    Buffer<std::uint32_t> pieceOfArc(count);
    resizeOnHugePages(out.arcs, count);
    inRanges(count, parts, [&](std::size_t, std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t p = begin; p < end; ++p) {
            const AugmentedTree::Piece& piece = tree.pieces[p];
            const std::uint32_t a = (piece.key & AugmentedTree::kEdgeBit)
                                        ? tree.chains + edges.rankOf(piece.key & AugmentedTree::kIndexMask)
                                        : chains.rankOf(piece.key);
            const std::uint32_t lower = node(piece.lower), upper = node(piece.upper);
            pieceOfArc[a] = p;
            out.arcs[a].lower = lower, out.arcs[a].upper = upper;
        }
    });
    Buffer<AugmentedTree::Piece>().swap(tree.pieces);
    return pieceOfArc;
}

// The arcs' regular samples, bucketed by piece in ascending order; the
// buckets lie in arc order, and each part of the ranks fills its own share of
// each bucket, after the shares of the parts before it. `sizes` (by part and
// piece) become the shares' ends; they move in lists of 4 bytes a piece,
// small enough to stay in cache, rather than in the arcs' records (samples
// < 2^31, so they fit).
void fillSamples(const AugmentedTree& tree, std::uint32_t chains, Buffer<std::uint32_t>&& pieceOfArc,
                 std::vector<Buffer<std::uint32_t>>& sizes, ContourTree& out, const BuildProgress& progress) {
    std::uint32_t sum = 0;
    for (std::uint32_t a = 0; a < chains; ++a) {  // the chains are the first arcs; edges hold no samples
        out.arcs[a].begin = sum;
        for (Buffer<std::uint32_t>& part : sizes) sum += std::exchange(part[pieceOfArc[a]], sum);
        out.arcs[a].end = sum;
    }
    Buffer<std::uint32_t>().swap(pieceOfArc);  // gone before the samples come
    resizeOnHugePages(out.samples, sum);
    inRanges(std::uint32_t(tree.arcOf.size()), sizes.size(),
             [&](std::size_t p, std::uint32_t begin, std::uint32_t end) {
                 std::uint32_t* at = sizes[p].data();
                 progress.inStrides(begin, end, [&](std::uint32_t from, std::uint32_t to) {
                     for (std::uint32_t k = from; k < to; ++k) {
                         const std::uint32_t piece = tree.arcOf[k];
                         if (!isNode(piece)) out.samples[at[piece]++] = tree.order[k];
                     }
                 });
             });
}

void indexNodeArcs(ContourTree& out) {
    resizeOnHugePages(out.nodeArcBegin, out.nodes.size() + 1);  // zeros: out is new
    for (std::size_t n = 0; n < out.nodes.size(); ++n)
        out.nodeArcBegin[n + 1] = out.nodeArcBegin[n] + out.nodes[n].up + out.nodes[n].down;
    resizeOnHugePages(out.nodeArcs, out.nodeArcBegin.back());
    Buffer<std::uint32_t> fill(out.nodeArcBegin.begin(), out.nodeArcBegin.end() - 1);
    for (std::size_t a = 0; a < out.arcs.size(); ++a) {
        out.nodeArcs[fill[out.arcs[a].lower]++] = std::uint32_t(a);
        out.nodeArcs[fill[out.arcs[a].upper]++] = std::uint32_t(a);
    }
}

}  // namespace

void numberNodes(AugmentedTree& tree) {
    IndexRanks number(std::uint32_t(tree.order.size()));
    for (const std::uint32_t k : tree.nodeRanks) number.add(tree.order[k]);
    number.count();
    tree.nodeNumbers.resize(tree.nodeRanks.size());
    for (std::size_t j = 0; j < tree.nodeRanks.size(); ++j)
        tree.nodeNumbers[j] = number.rankOf(tree.order[tree.nodeRanks[j]]);
}

ContourTree compressContourTree(const Volume& volume, AugmentedTree&& augmented, int threads,
                                const BuildProgress& progress) {
    ContourTree out;
    out.dims = volume.dims();
    const std::uint32_t chains = augmented.chains;
    const bool large = augmented.arcOf.size() >= (std::size_t(1) << 16);
    std::vector<Buffer<std::uint32_t>> sizes(large ? std::size_t(std::clamp(threads, 1, 4)) : 1);
    placeNodes(volume, augmented, sizes.size(), out);
    countPieces(augmented, sizes, progress);
    fillSamples(augmented, chains, numberArcs(augmented, sizes.size(), out), sizes, out, progress);
    augmented.arcOf = {}, augmented.order = {};
    augmented.sorted.shrink(0), augmented.spare.shrink(0);
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
    // The upper node's value first (below v, the lower one is not read), and
    // requested a few arcs ahead: the arcs are read in sequence, their nodes
    // anywhere. On the CT's million arcs 11-12 ms a call before, 6-7 now.
    std::vector<std::size_t> out;
    constexpr std::size_t kAhead = 16;
    for (std::size_t a = 0; a < arcs.size(); ++a) {
        if (a + kAhead < arcs.size()) __builtin_prefetch(&nodes[arcs[a + kAhead].upper]);
        const Arc& arc = arcs[a];
        if (arc.pruned) continue;
        const double hi = nodes[arc.upper].value;
        if (!(hi >= v)) continue;
        const double lo = nodes[arc.lower].value;
        if (std::isnan(lo) || lo < v) out.push_back(a);
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
