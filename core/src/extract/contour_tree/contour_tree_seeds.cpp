// Seeds from the contour tree, and the surfaces they track.
//
// At isovalue v an arc's surface is the one contour between two components:
// A, the samples at or above v joined to the arc's upper part, and B, the
// samples below v joined to its lower part. The arc's samples at or above v
// and its upper node are in A; those below v and its lower node are in B. Any
// grid edge from A to B crosses v on that surface, so two 18-adjacent samples,
// one from each list, give a seed: their edge when they share one, else on the
// face they share, the edge from the corner that is not on the other's side.
// Membership of a sample in A is cheap near the arc: the upper node, or a
// sample at or above v on an arc at the upper node (the tree joins them without
// going below v); a binary search in that arc's sorted samples. The search
// starts at the arc's samples nearest v and looks at a bounded number of them.
// When none pairs up (an arc between two saddles, its samples far from its
// surface), both sides are enumerated through the tree (every arc reached from
// the end node without crossing v, capped) and searched for a pair: exact, and
// complete when the sides fit in the cap. Only if that fails too is the seed a
// crossed edge at the nearest sample below v, marked as not certain.
#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_set>

#include "extract/contour_tree/contour_tree_build.h"
#include "isotrack/errors.h"
#include "isotrack/tracking.h"
#include "support/parallel.h"

namespace isotrack {
namespace {

constexpr int kSearchSamples = 64;  // each way from v along the arc

template <class T>
struct ArcView {
    const ContourTree& tree;
    const ContourTree::Arc& arc;
    const T* values;
    double v;

    bool belowV(std::uint32_t s) const { return !(double(values[s]) >= v); }  // NaN is below
    std::uint32_t lowerNode() const { return tree.nodes[arc.lower].sample; }
    std::uint32_t upperNode() const { return tree.nodes[arc.upper].sample; }
    bool onArc(const ContourTree::Arc& other, std::uint32_t s) const {
        const detail::SampleOrder<T> cmp{values};
        const auto first = tree.samples.begin() + std::ptrdiff_t(other.begin);
        const auto last = tree.samples.begin() + std::ptrdiff_t(other.end);
        const auto it =
            std::lower_bound(first, last, s, [&](std::uint32_t a, std::uint32_t b) { return cmp.below(a, b); });
        return it != last && *it == s;
    }
    // Whether s is on an arc at `node` or at the other end of one: with s on the
    // same side of v as the node, the tree joins them without crossing v.
    bool nearNode(std::uint32_t node, std::uint32_t s) const {
        if (tree.nodes[node].sample == s) return true;
        for (std::uint32_t k = tree.nodeArcBegin[node]; k < tree.nodeArcBegin[node + 1]; ++k) {
            const ContourTree::Arc& other = tree.arcs[tree.nodeArcs[k]];
            const std::uint32_t end = other.lower == node ? other.upper : other.lower;
            if (tree.nodes[end].sample == s || onArc(other, s)) return true;
        }
        return false;
    }
    // B: below v and joined to the arc's lower node under v.
    bool inLowerPart(std::uint32_t s) const { return belowV(s) && nearNode(arc.lower, s); }
    // A: at or above v and joined to the upper node above v.
    bool inUpperPart(std::uint32_t s) const { return !belowV(s) && nearNode(arc.upper, s); }
    // Position of the first of the arc's samples at or above v.
    std::size_t split() const {
        const auto first = tree.samples.begin() + std::ptrdiff_t(arc.begin);
        const auto last = tree.samples.begin() + std::ptrdiff_t(arc.end);
        return std::size_t(std::partition_point(first, last, [&](std::uint32_t s) { return belowV(s); }) -
                           tree.samples.begin());
    }
};

GridEdge edgeBetween(const Dims& dims, std::uint32_t a, std::uint32_t b) {
    const std::uint32_t nx = std::uint32_t(dims[0]), ny = std::uint32_t(dims[1]);
    const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
    const std::uint32_t d = hi - lo;
    const int axis = d == 1 ? 0 : d == nx ? 1 : 2;
    return GridEdge{int(lo % nx), int((lo / nx) % ny), int(lo / (nx * ny)), axis};
}

// The crossed edge between `below` (in B) and `above` (in A), 18-adjacent.
template <class T>
GridEdge seedEdge(const ArcView<T>& view, std::uint32_t below, std::uint32_t above) {
    const Dims& dims = view.tree.dims;
    const std::int64_t stride[3] = {1, dims[0], std::int64_t(dims[0]) * dims[1]};
    const std::int64_t nx = dims[0], ny = dims[1];
    auto coords = [&](std::int64_t s) { return std::array<std::int64_t, 3>{s % nx, (s / nx) % ny, s / (nx * ny)}; };
    const auto p = coords(below), q = coords(above);
    int differing = -1;
    for (int a = 0; a < 3; ++a) {
        if (p[std::size_t(a)] != q[std::size_t(a)]) {
            if (differing >= 0) {
                // A face diagonal: the corner one step from `below` along the first axis.
                const auto corner = std::uint32_t(
                    std::int64_t(below) + (q[std::size_t(differing)] - p[std::size_t(differing)]) * stride[differing]);
                return view.belowV(corner) ? edgeBetween(dims, corner, above) : edgeBetween(dims, below, corner);
            }
            differing = a;
        }
    }
    return edgeBetween(dims, below, above);
}

// The samples of one side of the cut on arc `a` at v (A when `upper`, else B)
// that the tree reaches from the arc's end on that side without crossing v,
// up to `cap` of them, in the order reached (each once: every arc and node is
// visited once); `complete` tells whether that is all of the side.
template <class T>
std::vector<std::uint32_t> sideSamples(const ArcView<T>& view, std::size_t a, bool upper, std::size_t cap,
                                       bool& complete) {
    const ContourTree& tree = view.tree;
    std::vector<std::uint32_t> out;
    std::vector<bool> nodesSeen(tree.nodes.size()), arcsSeen(tree.arcs.size());  // a bit each, cheaper than sets
    arcsSeen[a] = true;
    auto onSide = [&](std::uint32_t s) { return view.belowV(s) != upper; };
    for (std::size_t k = view.arc.begin; k < view.arc.end; ++k) {
        if (onSide(tree.samples[k])) out.push_back(tree.samples[k]);
    }
    std::vector<std::uint32_t> queue{upper ? view.arc.upper : view.arc.lower};
    nodesSeen[queue.front()] = true;
    complete = true;
    while (!queue.empty()) {
        if (out.size() >= cap) return complete = false, out;
        const std::uint32_t node = queue.back();
        queue.pop_back();
        out.push_back(tree.nodes[node].sample);
        for (std::uint32_t k = tree.nodeArcBegin[node]; k < tree.nodeArcBegin[node + 1]; ++k) {
            const std::uint32_t b = tree.nodeArcs[k];
            if (arcsSeen[b]) continue;
            arcsSeen[b] = true;
            const ContourTree::Arc& other = tree.arcs[b];
            for (std::size_t j = other.begin; j < other.end; ++j) {
                if (onSide(tree.samples[j])) out.push_back(tree.samples[j]);
            }
            const std::uint32_t end = other.lower == node ? other.upper : other.lower;
            if (onSide(tree.nodes[end].sample) && !nodesSeen[end]) nodesSeen[end] = true, queue.push_back(end);
        }
    }
    return out;
}

// A seed from the two sides enumerated through the tree: exact, and found
// whenever the sides fit in the cap (the two sides always touch somewhere).
// The smaller side is walked in the order reached, the larger one sorted for
// lookups (lists, a radix sort and bits per arc and node, not hash sets: on the
// CT a side of 2^17 samples took 25-30 ms in a std::unordered_set).
template <class T>
bool sideSeed(const ArcView<T>& view, std::size_t a, GridEdge& edge) {
    constexpr std::size_t kCap = std::size_t(1) << 17;
    bool completeA = false, completeB = false;
    std::vector<std::uint32_t> sideA = sideSamples(view, a, true, kCap, completeA),
                               sideB = sideSamples(view, a, false, kCap, completeB);
    const bool fromB = sideB.size() <= sideA.size();
    const std::vector<std::uint32_t>& from = fromB ? sideB : sideA;
    std::vector<std::uint32_t>& to = fromB ? sideA : sideB;
    detail::sortByKey(to, [](std::uint32_t s) { return s; });
    const detail::Neighbours neighbours{view.tree.dims};
    for (const std::uint32_t s : from) {
        std::uint32_t found = detail::kNoSample;
        // Only a neighbour on the other side of v may be on the other side of
        // the cut: its value first, then the search.
        neighbours.forEach<18>(s, [&](std::uint32_t m) {
            if (found == detail::kNoSample && view.belowV(m) != fromB && std::binary_search(to.begin(), to.end(), m))
                found = m;
        });
        if (found != detail::kNoSample) {
            edge = fromB ? seedEdge(view, s, found) : seedEdge(view, found, s);
            return true;
        }
    }
    return false;
}

template <class T>
ArcSeed seedOf(const ContourTree& tree, std::size_t a, const T* values, double v) {
    const ArcView<T> view{tree, tree.arcs[a], values, v};
    const detail::Neighbours neighbours{tree.dims};
    const std::size_t split = view.split(), begin = view.arc.begin, end = view.arc.end;
    for (std::size_t k = 0; k <= std::size_t(kSearchSamples); ++k) {
        // Below v: the arc's k-th sample down from v, or its lower node just past them.
        if (k <= split - begin) {
            const std::uint32_t s = k < split - begin ? tree.samples[split - 1 - k] : view.lowerNode();
            std::uint32_t found = detail::kNoSample;
            neighbours.forEach<18>(s, [&](std::uint32_t m) {
                if (found == detail::kNoSample && view.inUpperPart(m)) found = m;
            });
            if (found != detail::kNoSample) return ArcSeed{a, seedEdge(view, s, found), true};
        }
        if (k <= end - split) {
            const std::uint32_t s = k < end - split ? tree.samples[split + k] : view.upperNode();
            std::uint32_t found = detail::kNoSample;
            neighbours.forEach<18>(s, [&](std::uint32_t m) {
                if (found == detail::kNoSample && view.inLowerPart(m)) found = m;
            });
            if (found != detail::kNoSample) return ArcSeed{a, seedEdge(view, found, s), true};
        }
    }
    GridEdge edge;
    if (sideSeed(view, a, edge)) return ArcSeed{a, edge, true};
    // No pair found: any crossed edge at the nearest sample below v.
    const std::uint32_t below = split > begin ? tree.samples[split - 1] : view.lowerNode();
    std::uint32_t above = detail::kNoSample;
    neighbours.forEach<6>(below, [&](std::uint32_t m) {
        if (above == detail::kNoSample && !view.belowV(m)) above = m;
    });
    if (above != detail::kNoSample) return ArcSeed{a, edgeBetween(tree.dims, below, above), false};
    return ArcSeed{a, GridEdge{}, false};  // not crossed: trackTreeSurfaces skips it
}

std::uint64_t edgeKey(const GridEdge& e, const Dims& dims) {
    return (std::uint64_t(e.x) +
            std::uint64_t(dims[0]) * (std::uint64_t(e.y) + std::uint64_t(dims[1]) * std::uint64_t(e.z))) *
               3 +
           std::uint64_t(e.axis);
}

}  // namespace

std::vector<ArcSeed> arcSeeds(const ContourTree& tree, const Volume& volume, double v) {
    return arcSeeds(tree, volume, v, tree.arcsAt(v));
}

std::vector<ArcSeed> arcSeeds(const ContourTree& tree, const Volume& volume, double v,
                              const std::vector<std::size_t>& arcs) {
    if (volume.dims() != tree.dims) throw InputError("the contour tree is not this volume's (its dimensions differ)");
    std::vector<ArcSeed> seeds;
    visitSamples(volume, [&](const auto* values) {
        for (const std::size_t a : arcs) seeds.push_back(seedOf(tree, a, values, v));
    });
    return seeds;
}

std::vector<std::size_t> largestArcsAt(const ContourTree& tree, double v, std::size_t count) {
    std::vector<std::size_t> arcs = tree.arcsAt(v);
    auto larger = [&](std::size_t a, std::size_t b) { return tree.arcs[a].size() > tree.arcs[b].size(); };
    if (arcs.size() > count) {
        std::nth_element(arcs.begin(), arcs.begin() + std::ptrdiff_t(count), arcs.end(), larger);
        arcs.resize(count);
    }
    std::stable_sort(arcs.begin(), arcs.end(), larger);
    return arcs;
}

namespace {

// A surface tracked from `arc`'s seed, with what the tree knows of it.
void describeArcSurface(const ContourTree& tree, std::size_t arc, Surface& surface) {
    surface.stats.arc = arc;
    surface.stats.persistence = tree.persistence(arc);
    measureTopology(surface);
}

}  // namespace

Surface trackArc(const ContourTree& tree, const Volume& volume, std::size_t arc, double v, int threads) {
    const ArcSeed seed = arcSeeds(tree, volume, v, {arc}).front();
    Surface surface = trackSurface(volume, v, seed.edge, TableKind::Consistent, threads);
    describeArcSurface(tree, arc, surface);
    return surface;
}

std::vector<Surface> trackTreeSurfaces(const ContourTree& tree, const Volume& volume, double v, int threads,
                                       std::vector<std::size_t>* arcs, std::size_t largest,
                                       const std::vector<std::size_t>& leaveOut) {
    const std::vector<std::size_t> crossing = largest > 0 ? largestArcsAt(tree, v, largest) : tree.arcsAt(v);
    const std::unordered_set<std::size_t> left(leaveOut.begin(), leaveOut.end());
    std::vector<std::size_t> kept, leftOut;
    for (const std::size_t a : crossing) (left.count(a) ? leftOut : kept).push_back(a);
    std::vector<ArcSeed> seeds = arcSeeds(tree, volume, v, kept);
    const bool anyUncertain = std::any_of(seeds.begin(), seeds.end(), [](const ArcSeed& s) { return !s.certain; });
    // An uncertain seed may lie on a left-out arc's surface, which must then
    // cover it: every arc's seed, as without leaveOut (rare: an uncertain seed
    // takes an arc whose two sides both exceed 2^17 samples).
    if (anyUncertain && !leftOut.empty()) seeds = arcSeeds(tree, volume, v, crossing);
    const auto firstUncertain =
        std::stable_partition(seeds.begin(), seeds.end(), [](const ArcSeed& s) { return s.certain; });
    const auto certain = std::size_t(firstUncertain - seeds.begin());
    // Certain seeds are distinct surfaces: tracked at once, one surface per thread.
    std::vector<std::pair<Surface, std::size_t>> tracked(certain);
    detail::parallelFor(int(certain), std::max(1, threads), [&](int i) {
        const ArcSeed& seed = seeds[std::size_t(i)];
        tracked[std::size_t(i)] = {trackSurface(volume, v, seed.edge, TableKind::Consistent, 1), seed.arc};
    });
    std::unordered_set<std::uint64_t> covered;  // the edges of the surfaces tracked, once a seed is not certain
    if (certain < seeds.size()) {
        for (const auto& [surface, arc] : tracked) {
            for (const GridEdge e : surface.mesh.vertexEdges) covered.insert(edgeKey(e, tree.dims));
        }
    }
    for (std::size_t k = certain; k < seeds.size(); ++k) {
        const ArcSeed& seed = seeds[k];
        if (!edgeIsCrossed(volume, v, seed.edge) || covered.count(edgeKey(seed.edge, tree.dims))) continue;
        Surface surface = trackSurface(volume, v, seed.edge, TableKind::Consistent, 1);
        for (const GridEdge e : surface.mesh.vertexEdges) covered.insert(edgeKey(e, tree.dims));
        tracked.emplace_back(std::move(surface), seed.arc);
    }
    std::stable_sort(tracked.begin(), tracked.end(),
                     [](const auto& a, const auto& b) { return a.first.stats.triangles > b.first.stats.triangles; });
    std::vector<Surface> out;
    if (arcs) arcs->clear();
    for (auto& [surface, arc] : tracked) {
        if (left.count(arc)) continue;
        describeArcSurface(tree, arc, surface);
        out.push_back(std::move(surface));
        if (arcs) arcs->push_back(arc);
    }
    return out;
}

}  // namespace isotrack
