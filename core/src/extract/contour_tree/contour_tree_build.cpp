// The contour tree, built as Carr, Snoeyink & Axen (2003) build it: sort the
// samples, sweep them from the top to grow the join tree (how the components
// of the superlevel sets merge, 6-connected) and from the bottom to grow the
// split tree (sublevel sets, 18-connected), on two threads at once, then merge
// the two by peeling leaves: a sample that is a leaf above in the join tree
// and has one arc down in the split tree (or the mirror) is a leaf of the
// contour tree, whose one edge goes to its neighbour in the join (split) tree.
//
// Passes: sortSamples (stable radix sort on the native values, so ties stay in
// index order), classifySamples (in grid order: which samples meet exactly one
// component in each sweep, and through which neighbour), the two sweeps
// (union-find with randomized linking and path halving, each root keeping the
// rank of its component's newest sample; only candidates look up more than
// one neighbour, one of each group the class pass noted in their forest slot;
// each sweep ends in a trunk once one component is left and no extremum is to
// come), countLinks (each rank's arcs above in the join tree and below
// in the split tree, from the links; on two threads each sweep's thread counts
// its own tree when done), startMerge (the nodes and leaves, in parts) and
// mergeTrees, beside which the nodes are numbered. The sweeps write the
// trees by rank, the position in the order: the merge walks each arc in value
// order, and where arcs do not interleave the next sample of an arc is the
// next rank, so it reads memory in sequence instead of anywhere in the grid.
// The threaded passes (sort, classes, sweeps, arcs) run on core's kept threads
// (support/parallel.h); a part's exception, Cancelled included (each part
// checks for a cancel at least once a stride), is rethrown on the calling thread.
//
// Memory: the order, the two trees and their two union-find forests, 4 bytes
// each per sample, and the class byte: 21 bytes per sample at the peak (17 on
// one thread, where the split sweep reuses the join sweep's forest). The
// order, the join tree and the forests live in the sort's two blocks (Pages),
// so the kernel zeroes only the split tree's and the classes' pages afresh.
// The forests and classes are gone by the merge, which puts each rank's arc
// (4 bytes) and state (a byte) where the forests were, and adds its stack of
// leaves (at most 4 bytes), a 12-byte piece per arc and 9 bytes a node (rank,
// number, degrees).
#include <algorithm>
#include <cassert>
#include <iterator>
#include <utility>

#include <unistd.h>

#include "extract/contour_tree/contour_tree_build.h"
#include "isotrack/errors.h"
#include "support/working_memory.h"

namespace isotrack::detail {
namespace {

// The union-find forest of a sweep, 4 bytes a sample: a sample's entry is its
// parent, or for a root, kRootBit and its component's newest sample (the one
// its tree link hangs from), so no array of those is needed. Roots are linked
// by a hash of their index (randomized linking: as fast as union by rank with
// path halving, without storing ranks).
constexpr std::uint32_t kRootBit = 0x80000000u;

std::uint32_t findRoot(const Slice<std::uint32_t>& forest, std::uint32_t s) {
    for (;;) {
        const std::uint32_t parent = forest[s];
        if (parent & kRootBit) return s;
        const std::uint32_t grandparent = forest[parent];
        if (grandparent & kRootBit) return parent;
        forest[s] = grandparent;
        s = grandparent;
    }
}

std::uint32_t linkPriority(std::uint32_t s) {
    s ^= s >> 16, s *= 0x7feb352du, s ^= s >> 15, s *= 0x846ca68bu, s ^= s >> 16;
    return s;
}

// The sweeps visit the samples in value order, a random order in space (the
// shells of a sphere), so each sample's lines are requested this many samples
// ahead, and its class twice as far ahead, to have many misses in flight at once.
constexpr std::uint32_t kPrefetchDistance = 16;

// One sweep: the join tree when Up (from the top, 6 neighbours), the split tree
// otherwise (from the bottom, 18 neighbours), both by rank (k, the position in
// the order). When the sample of rank k meets a component, the rank of the
// component's newest sample gets link = k, where the merge reads it, with no
// renumbering after. A sample of one class (classifySamples) meets the
// component of the one neighbour its class names, or none; only candidates
// read their whole neighbourhood. The forest (by sample) needs no start: each
// sample's entry is written when the sweep reaches it, before it is read.
//
// The trunk (Gueunet et al.'s FTM): once the sweep has met its last extremum
// (lastExtremum, the last sample of class 0 in its order) and all it has swept
// is one component, every later sample joins that component and nothing else,
// so each rank links to the next one swept, and the rest of the sweep is a
// write in sequence, without the forest or the samples' neighbours.
template <bool Up, class T>
void sweep(const T* values, const Dims& dims, const Slice<std::uint32_t>& order, const Buffer<std::uint8_t>& classes,
           std::uint32_t lastExtremum, const Slice<std::uint32_t>& forest, bool groupsInForest,
           const Slice<std::uint32_t>& link, const BuildProgress& progress) {
    const auto n = std::uint32_t(order.size());
    const SampleOrder<T> cmp{values};
    const Neighbours neighbours{dims};
    constexpr std::uint8_t kCandidate = Up ? kJoinCandidate : kSplitCandidate;
    // A class c names position c - 1 of the 6 (join) or 18 (split) neighbours,
    // whose index offset is offset[c]; classes between those and kCandidate
    // never occur. A candidate's groups name positions p: offset[p + 1].
    std::int64_t offset[kNeighbourPositions + 1] = {};
    for (std::uint8_t p = 0; p < kNeighbourPositions; ++p) offset[p + 1] = neighbourOffset(dims, p);
    auto classOf = [&](std::uint32_t s) { return std::uint8_t(Up ? classes[s] & 7u : classes[s] >> 3); };
    auto rankAt = [&](std::uint32_t step) { return Up ? n - 1 - step : step; };
    // Each rank but the last gets its link from the next sample that meets its
    // component (all of them are one component in the end), so link needs no start.
    link[rankAt(n - 1)] = kNoSample;
    std::uint32_t components = 0;  // roots of the forest so far
    bool extremaMet = lastExtremum == kNoSample;
    auto meet = [&](std::uint32_t k, std::uint32_t& root, std::uint32_t r) {
        --components;
        link[forest[r] & ~kRootBit] = k;
        const bool keep = linkPriority(root) > linkPriority(r);
        const std::uint32_t winner = keep ? root : r;
        forest[keep ? r : root] = winner;
        forest[winner] = k | kRootBit;
        root = winner;
    };
    for (std::uint32_t step = 0; step < n; ++step) {
        progress.step(step);  // throws Cancelled when asked to stop
        if (step + 3 * kPrefetchDistance < n) __builtin_prefetch(&classes[order[rankAt(step + 3 * kPrefetchDistance)]]);
        if (step + 2 * kPrefetchDistance < n)
            __builtin_prefetch(&forest[order[rankAt(step + 2 * kPrefetchDistance)]], 1);
        if (step + kPrefetchDistance < n) {
            // The neighbours it will look up: the one its class names, or a
            // candidate's groups', noted in its forest slot (requested above).
            const std::uint32_t later = order[rankAt(step + kPrefetchDistance)];
            const std::uint8_t c = classOf(later);
            if (c == kCandidate && groupsInForest) {
                for (std::uint32_t left = forest[later]; left; left &= left - 1)
                    __builtin_prefetch(&forest[std::int64_t(later) + offset[1 + __builtin_ctz(left)]]);
            } else if (c != 0 && c != kCandidate) {
                __builtin_prefetch(&forest[std::int64_t(later) + offset[c]]);
            }
        }
        const std::uint32_t k = rankAt(step), s = order[k];
        const std::uint8_t c = classOf(s);
        const std::uint32_t groups = groupsInForest && c == kCandidate ? forest[s] : 0;
        forest[s] = k | kRootBit;
        ++components;
        extremaMet = extremaMet || s == lastExtremum;
        std::uint32_t root = s;
        if (c == kCandidate && groupsInForest) {  // one neighbour of each group (CandidateGroups)
            for (std::uint32_t left = groups; left; left &= left - 1) {
                const auto m = std::uint32_t(std::int64_t(s) + offset[1 + __builtin_ctz(left)]);
                const std::uint32_t r = findRoot(forest, m);
                if (r != root) meet(k, root, r);
            }
        } else if (c == kCandidate) {
            neighbours.forEach<Up ? 6 : 18>(s, [&](std::uint32_t m) {
                if (Up ? !cmp.below(s, m) : !cmp.below(m, s)) return;  // not swept yet
                const std::uint32_t r = findRoot(forest, m);
                if (r == root) return;
                meet(k, root, r);
            });
        } else if (c != 0) {
            meet(k, root, findRoot(forest, std::uint32_t(std::int64_t(s) + offset[c])));
        }
        if (extremaMet && components == 1) {  // the trunk: rank k is the one component's newest
            for (++step; step < n; ++step) {
                progress.step(step);
                link[rankAt(step - 1)] = rankAt(step);
            }
            return;
        }
    }
}

// The sample each sweep meets last among its extrema (class 0): the lowest in
// the order with no face neighbour above (join), the highest with none of its
// 18 below (split); kNoSample for a sweep with none. A scan of the classes in
// parts on `threads` threads, the extrema's values compared in the order.
template <class T>
std::pair<std::uint32_t, std::uint32_t> lastExtrema(const T* values, const Buffer<std::uint8_t>& classes, int threads) {
    const auto n = std::uint32_t(classes.size());
    const SampleOrder<T> cmp{values};
    const int parts = int(std::clamp<std::uint32_t>(n >> 20, 1, std::uint32_t(std::max(threads, 1))));
    std::vector<std::pair<std::uint32_t, std::uint32_t>> found(std::size_t(parts), {kNoSample, kNoSample});
    parallelFor(parts, parts, [&](int part) {
        auto& [join, split] = found[std::size_t(part)];
        const std::uint32_t begin = std::uint32_t(std::uint64_t(n) * part / parts);
        const std::uint32_t end = std::uint32_t(std::uint64_t(n) * (part + 1) / parts);
        for (std::uint32_t s = begin; s < end; ++s) {
            const std::uint8_t c = classes[s];
            if ((c & 7u) == 0 && (join == kNoSample || cmp.below(s, join))) join = s;
            if ((c >> 3) == 0 && (split == kNoSample || cmp.below(split, s))) split = s;
        }
    });
    std::pair<std::uint32_t, std::uint32_t> last{kNoSample, kNoSample};
    for (const auto& [join, split] : found) {
        if (join != kNoSample && (last.first == kNoSample || cmp.below(join, last.first))) last.first = join;
        if (split != kNoSample && (last.second == kNoSample || cmp.below(last.second, split))) last.second = split;
    }
    return last;
}

// first() and second() at once, each on a kept thread, when `together` (an
// exception of either, Cancelled included, is rethrown here); else in turn.
template <class First, class Second>
void inTurnOrTogether(bool together, First&& first, Second&& second) {
    if (!together) {
        first();
        second();
        return;
    }
    parallelFor(2, 2, [&](int which) {
        if (which == 0) {
            first();
        } else {
            second();
        }
    });
}

// The merge's state of a sample, a byte: the join tree's arcs above it (at
// most 6) in the low 3 bits, the split tree's below it (at most 18) above
// them, and kGone once it is peeled off.
constexpr std::uint8_t kGone = 0xff, kOneBelow = 8;
bool isGone(std::uint8_t state) { return (state & 7u) == 7u; }
bool isLeaf(std::uint8_t state) { return !isGone(state) && (state & 7u) + (state >> 3) == 1; }

// Follows link past removed samples, shortening the path on the way.
std::uint32_t liveLink(const Slice<std::uint32_t>& link, const Slice<std::uint8_t>& state, std::uint32_t s) {
    const std::uint32_t next = link[s];
    if (next == kNoSample || !isGone(state[next])) return next;  // most often: nothing to skip or shorten
    std::uint32_t t = link[next];
    while (t != kNoSample && isGone(state[t])) t = link[t];
    for (std::uint32_t u = s; u != t;) u = std::exchange(link[u], t);  // the whole path points past them now
    return t;
}

// Carr's merge: peels the leaves of the join and split trees, whose arcs are
// counted in state. The peel walks each chain of regular samples sample after
// sample, a miss for each where arcs interleave; the link of the next one is
// requested as soon as the sample is known, beside its state. A sample is a
// node of the contour tree when it is one of either tree (Carr et al.: the
// contour tree's up-degree is the join tree's, its down-degree the split
// tree's), so the regular ones are known before the merge.
constexpr std::uint8_t kRegular = 1 + kOneBelow;    // one arc above, one below
constexpr std::uint32_t kUnpeeled = kNoSample - 1;  // arcOf of a regular rank the merge has not reached

// The merge's start, in parts of the ranks on up to 4 threads: with `up` (the
// join tree's counts, when the sweeps counted their trees apart), state gets
// them added; then each rank's arcOf is kUnpeeled when regular and kNoSample
// for a node, tree.nodeRanks lists the nodes' ranks in ascending order (and
// nodeDegrees their states, which hold their degrees in the contour tree), and
// the leaves are returned in the order of their samples (each part sorts its
// own, then they are merged: samples are unique keys). The lists are counted
// before they are filled: a list grown as it is filled writes its pages twice,
// and this machine's first write to a page is its costliest.
Buffer<std::uint32_t> startMerge(const Slice<std::uint8_t>& state, const std::uint8_t* up, AugmentedTree& tree,
                                 int threads) {
    const auto n = std::uint32_t(state.size());
    const std::size_t parts = n >= (std::uint32_t(1) << 16) ? std::size_t(std::clamp(threads, 1, 4)) : 1;
    std::vector<std::uint32_t> nodeCount(parts + 1), leafCount(parts);
    // up lies where arcOf goes: added before arcOf is written. Locals
    // throughout: a byte written may alias anything, so the loops would read
    // their bounds and pointers again after every write.
    inRanges(n, parts, [&](std::size_t p, std::uint32_t begin, std::uint32_t end) {
        std::uint8_t* const states = state.begin();
        std::uint32_t nodes = 0, leaves = 0;
        if (up) {
            for (std::uint32_t k = begin; k < end; ++k) states[k] = std::uint8_t(states[k] + up[k]);
        }
        for (std::uint32_t k = begin; k < end; ++k) {
            const std::uint8_t here = states[k];
            nodes += here != kRegular;
            leaves += isLeaf(here);
        }
        nodeCount[p + 1] = nodes, leafCount[p] = leaves;
    });
    for (std::size_t p = 0; p < parts; ++p) nodeCount[p + 1] += nodeCount[p];
    tree.nodeRanks.resize(nodeCount.back());
    tree.nodeDegrees.resize(nodeCount.back());
    std::vector<Buffer<std::uint32_t>> leaves(parts);
    auto sample = [&](std::uint32_t k) { return tree.order[k]; };
    inRanges(n, parts, [&](std::size_t p, std::uint32_t begin, std::uint32_t end) {
        Buffer<std::uint32_t>& partLeaves = leaves[p];
        partLeaves.resize(leafCount[p]);
        std::uint32_t* node = tree.nodeRanks.data() + nodeCount[p];
        std::uint8_t* degrees = tree.nodeDegrees.data() + nodeCount[p];
        std::uint32_t* leaf = partLeaves.data();
        std::uint32_t* const arcOf = tree.arcOf.begin();
        const std::uint8_t* const states = state.begin();
        for (std::uint32_t k = begin; k < end; ++k) {
            const std::uint8_t here = states[k];
            arcOf[k] = here == kRegular ? kUnpeeled : kNoSample;
            if (here != kRegular) *node++ = k, *degrees++ = here;
            if (isLeaf(here)) *leaf++ = k;
        }
        sortByKey(partLeaves, sample);
    });
    Buffer<std::uint32_t> sorted = std::move(leaves[0]);
    for (std::size_t p = 1; p < leaves.size(); ++p) {
        Buffer<std::uint32_t> both(sorted.size() + leaves[p].size());
        std::merge(sorted.begin(), sorted.end(), leaves[p].begin(), leaves[p].end(), both.begin(),
                   [&](std::uint32_t a, std::uint32_t b) { return sample(a) < sample(b); });
        sorted.swap(both);
    }
    return sorted;
}

// The peel, from the leaves startMerge found (popped from the back: the
// largest sample first).
void mergeTrees(const Slice<std::uint32_t>& joinDown, const Slice<std::uint32_t>& splitUp,
                const Slice<std::uint8_t>& state, Buffer<std::uint32_t>&& leaves, AugmentedTree& tree,
                const BuildProgress& progress) {
    const auto n = std::uint32_t(state.size());
    tree.pieces.reserve(tree.nodeRanks.size() - 1);      // a tree: one arc fewer than nodes
    auto edge = [&](std::uint32_t s, std::uint32_t t) {  // peeled s, its edge to t
        const bool regularS = tree.arcOf[s] != kNoSample, regularT = tree.arcOf[t] != kNoSample;
        if (!regularS && !regularT) {
            tree.pieces.push_back({std::min(s, t), std::max(s, t), tree.order[s] | AugmentedTree::kEdgeBit});
            return;
        }
        if (!regularS) {  // a walk from node s enters a chain
            tree.arcOf[t] = std::uint32_t(tree.pieces.size());
            tree.pieces.push_back({});
            ++tree.chains;
            (s < t ? tree.pieces.back().lower : tree.pieces.back().upper) = s;
        }
        assert(!regularS || tree.arcOf[s] != kUnpeeled);  // a regular sample is peeled only after the walk entered it
        AugmentedTree::Piece& chain = tree.pieces[tree.arcOf[regularS ? s : t]];
        if (regularT) {
            tree.arcOf[t] = tree.arcOf[regularS ? s : t];
            chain.key = std::min(chain.key, tree.order[t]);
        } else {  // and leaves it at node t
            (t < s ? chain.lower : chain.upper) = t;
        }
    };
    std::uint32_t remaining = n;
    // A regular sample peeled leaves the next one on its chain a leaf, which
    // the stack would give back at once: the walk goes on along the chain
    // here, sample after sample, until it reaches a node or a sample that is
    // no leaf, as the stack would have, without it.
    // Most often a chain's next sample is the next rank (down the join tree,
    // up the split tree: `step`), regular and not yet reached; a run of those
    // goes without following links, so that the next ranks' lines are read
    // while this one's are written, rather than each after the last.
    auto walkChain = [&](std::uint32_t s, const Slice<std::uint32_t>& link, std::uint32_t step, std::uint8_t unit,
                         std::uint8_t leafState) {
        AugmentedTree::Piece& chain = tree.pieces[tree.arcOf[s]];
        const std::uint32_t piece = tree.arcOf[s];
        std::uint32_t key = chain.key;
        for (;;) {
            for (std::uint32_t t = s + step; remaining > 1 && t < n && link[s] == t && tree.arcOf[t] == kUnpeeled;
                 t = s + step) {
                state[t] = leafState;  // an unreached regular sample's state is kRegular, less this arc
                state[s] = kGone;
                --remaining;
                progress.step(n - remaining);
                tree.arcOf[t] = piece;
                key = std::min(key, tree.order[t]);
                s = t;
            }
            if (remaining <= 1) {
                chain.key = key;
                return s;
            }
            const std::uint32_t t = liveLink(link, state, s);
            __builtin_prefetch(&link[t]);
            state[t] = std::uint8_t(state[t] - unit);
            state[s] = kGone;
            --remaining;
            progress.step(n - remaining);
            if (tree.arcOf[t] == kNoSample) {  // a node: the chain ends there
                (t < s ? chain.lower : chain.upper) = t;
                chain.key = key;
                return t;
            }
            tree.arcOf[t] = piece;
            key = std::min(key, tree.order[t]);
            if (state[t] != leafState || remaining <= 1) {
                chain.key = key;
                return t;
            }
            s = t;
        }
    };
    while (!leaves.empty() && remaining > 1) {
        const std::uint32_t s = leaves.back();
        leaves.pop_back();
        const std::uint8_t here = state[s];
        if (tree.arcOf[s] != kNoSample && (here == kOneBelow || here == 1)) {  // on a chain
            const std::uint32_t t =
                here == kOneBelow ? walkChain(s, joinDown, ~0u, 1, kOneBelow) : walkChain(s, splitUp, 1, kOneBelow, 1);
            if (isLeaf(state[t])) leaves.push_back(t);
            continue;
        }
        std::uint32_t t;
        if (here == kOneBelow) {  // a maximum of what is left: its edge goes down the join tree
            t = liveLink(joinDown, state, s);
            __builtin_prefetch(&joinDown[t]);
            --state[t];
        } else if (here == 1) {  // a minimum: up the split tree
            t = liveLink(splitUp, state, s);
            __builtin_prefetch(&splitUp[t]);
            state[t] = std::uint8_t(state[t] - kOneBelow);
        } else {
            continue;
        }
        edge(s, t);
        state[s] = kGone;
        --remaining;
        progress.step(n - remaining);
        if (isLeaf(state[t])) leaves.push_back(t);
    }
}

// The merge's state from the links: a rank's arcs above it in the join tree
// are the ranks whose join link is it, and below it in the split tree those
// whose split link is it; each adds `unit` to out there.
void countLinks(const Slice<std::uint32_t>& link, const Slice<std::uint8_t>& out, std::uint8_t unit) {
    for (const std::uint32_t to : link) {
        if (to != kNoSample) out[to] = std::uint8_t(out[to] + unit);
    }
}

}  // namespace

Pages::Pages(std::size_t bytes) : bytes_(bytes) {
    if (bytes == 0) return;
    base_ = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (base_ == MAP_FAILED) {
        base_ = nullptr, bytes_ = 0;
        throw std::bad_alloc();
    }
#if defined(MADV_HUGEPAGE)
    madvise(base_, bytes, MADV_HUGEPAGE);  // fewer faults and TLB misses; only a hint
#endif
}

Pages::Pages(Pages&& other) noexcept
    : base_(std::exchange(other.base_, nullptr)), bytes_(std::exchange(other.bytes_, 0)) {}

Pages& Pages::operator=(Pages&& other) noexcept {
    if (this != &other) {
        shrink(0);
        base_ = std::exchange(other.base_, nullptr), bytes_ = std::exchange(other.bytes_, 0);
    }
    return *this;
}

void Pages::shrink(std::size_t bytes) {
    if (!base_ || bytes >= bytes_) return;
    const auto page = std::size_t(sysconf(_SC_PAGESIZE));
    auto pages = [&](std::size_t b) { return (b + page - 1) / page * page; };
    if (pages(bytes) < pages(bytes_)) munmap(at<char>(pages(bytes)), pages(bytes_) - pages(bytes));
    bytes_ = bytes;
    if (bytes == 0) base_ = nullptr;
}

AugmentedTree augmentedContourTree(const Volume& volume, int threads, const BuildProgress& progress) {
    const Dims& dims = volume.dims();
    if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2) {
        throw InputError("the contour tree needs at least 2 samples along each axis (a volume with cells)");
    }
    if (volume.sampleCount() >= std::size_t(AugmentedTree::kIndexMask)) {
        throw InputError("the contour tree takes volumes of fewer than 2^31 samples");
    }
    AugmentedTree tree;
    const auto n = std::uint32_t(volume.sampleCount());
    progress.start(ContourTreeProgress::Phase::Sorting, 0);
    // The sort's blocks, 8 bytes a sample each, hold the rest: sorted the
    // order and the join links, spare the two forests, then the merge's
    // arcOf and state.
    SortedSamples sorted = sortSamples(volume, threads, progress);
    const std::size_t half = 4 * std::size_t(n);
    tree.order = sorted.order();
    const Slice<std::uint32_t> joinDown = sliceOf<std::uint32_t>(sorted.sorted, half, n);
    const Pages splitPages(half);
    const Slice<std::uint32_t> splitUp = sliceOf<std::uint32_t>(splitPages, 0, n);
    const bool together = threads > 1;  // the two sweeps at once, each with a forest of its own
    if (!together) sorted.spare.shrink(half);
    // The split tree's pages are the sweeps' only fresh ones: the kernel zeroes
    // each page when it is first written, which takes as long here as the
    // split sweep's own work on a smooth field, so on several threads they are
    // written now, on all of them, rather than on the split sweep's alone.
    const int touchParts = together ? std::min(threads, int(n >> 20) + 1) : 0;
    parallelFor(touchParts, touchParts, [&](int part) {
        const std::size_t begin = std::size_t(n) * std::size_t(part) / std::size_t(touchParts);
        const std::size_t end = std::size_t(n) * std::size_t(part + 1) / std::size_t(touchParts);
        std::fill(splitUp.begin() + begin, splitUp.begin() + end, kNoSample);
    });
    progress.start(ContourTreeProgress::Phase::Sweeping, 2 * std::uint64_t(n));  // both sweeps count
    // Each candidate's groups of swept neighbours wait in its sweep's forest
    // slot until the sweep reaches it; on one thread the split sweep reuses the
    // join sweep's forest, and finds its candidates' groups itself.
    CandidateGroups groups;
    groups.join = sorted.spare.at<std::uint32_t>(0);
    if (together) groups.split = sorted.spare.at<std::uint32_t>(half);
    Buffer<std::uint8_t> classes = classifySamples(volume, threads, progress, groups);
    visitSamples(volume, [&](const auto* values) {
        const std::pair<std::uint32_t, std::uint32_t> last = lastExtrema(values, classes, threads);
        // Together, each thread counts its tree's arcs where its forest was: the
        // join tree's in the first n bytes of spare, the split tree's at half.
        auto count = [&](const Slice<std::uint32_t>& link, std::size_t at, std::uint8_t unit) {
            if (!together) return;
            const Slice<std::uint8_t> counts = sliceOf<std::uint8_t>(sorted.spare, at, n);
            std::fill(counts.begin(), counts.end(), std::uint8_t(0));
            countLinks(link, counts, unit);
        };
        auto join = [&] {
            sweep<true>(values, dims, tree.order, classes, last.first, sliceOf<std::uint32_t>(sorted.spare, 0, n), true,
                        joinDown, progress);
            count(joinDown, 0, 1);
        };
        auto split = [&] {  // on one thread, in the join forest's place after it
            sweep<false>(values, dims, tree.order, classes, last.second,
                         sliceOf<std::uint32_t>(sorted.spare, together ? half : 0, n), together, splitUp, progress);
            count(splitUp, half, kOneBelow);
        };
        inTurnOrTogether(together, join, split);
    });
    Buffer<std::uint8_t>().swap(classes);
    progress.check();
    progress.start(ContourTreeProgress::Phase::Merging, n);
    sorted.spare.shrink(half + n);  // the rest of the split forest
    Pages statePages(together ? 0 : n);
    const Slice<std::uint8_t> state =
        sliceOf<std::uint8_t>(together ? sorted.spare : statePages, together ? half : 0, n);
    if (!together) {
        std::fill(state.begin(), state.end(), std::uint8_t(0));
        countLinks(joinDown, state, 1);
        countLinks(splitUp, state, kOneBelow);
    }
    tree.arcOf = sliceOf<std::uint32_t>(sorted.spare, 0, n);
    Buffer<std::uint32_t> leaves =
        startMerge(state, together ? sorted.spare.at<std::uint8_t>(0) : nullptr, tree, threads);
    // The nodes are known before the peel, so on two threads they are numbered
    // beside it, on the second thread, idle otherwise.
    inTurnOrTogether(
        together, [&] { mergeTrees(joinDown, splitUp, state, std::move(leaves), tree, progress); },
        [&] { numberNodes(tree); });
    sorted.sorted.shrink(half), sorted.spare.shrink(half);  // the links and state are done with
    tree.sorted = std::move(sorted.sorted), tree.spare = std::move(sorted.spare);
    return tree;
}

ContourTree computeContourTreeImpl(const Volume& volume, int threads, ContourTreeProgress* progress) {
    const BuildProgress build(progress);
    AugmentedTree augmented = augmentedContourTree(volume, threads, build);
    build.start(ContourTreeProgress::Phase::Arcs, 0);
    ContourTree tree = compressContourTree(volume, std::move(augmented), threads, build);
    build.start(ContourTreeProgress::Phase::Done, 0);
    return tree;
}

}  // namespace isotrack::detail

namespace isotrack {

const char* contourTreePhaseName(ContourTreeProgress::Phase phase) {
    switch (phase) {
        case ContourTreeProgress::Phase::Sorting: return "sorting the samples";
        case ContourTreeProgress::Phase::Sweeping: return "sweeping the join and split trees";
        case ContourTreeProgress::Phase::Merging: return "merging them";
        case ContourTreeProgress::Phase::Arcs: return "building arcs";
        case ContourTreeProgress::Phase::Done: break;
    }
    return "done";
}

double ContourTreeProgress::fraction() const {
    // Shares of the build's time (sphere:256 and CT profiles, one thread): sort
    // 15%, classes and sweeps 55%, merge 15%, arcs 15%.
    constexpr double kStart[] = {0.0, 0.15, 0.70, 0.85, 1.0};
    const auto p = std::size_t(phase.load(std::memory_order_relaxed));
    if (p + 1 >= std::size(kStart)) return 1.0;
    const std::uint64_t t = total.load(std::memory_order_relaxed);
    const double within = t ? std::min(1.0, double(done.load(std::memory_order_relaxed)) / double(t)) : 0.0;
    return kStart[p] + within * (kStart[p + 1] - kStart[p]);
}

ContourTree computeContourTree(const Volume& volume, int threads, ContourTreeProgress* progress) {
    // The build's peak beyond the volume (docs/performance.md): 22-24 bytes a sample.
    detail::requireWorkingMemory(volume, 24, "the contour tree's build");
    ContourTree tree = detail::computeContourTreeImpl(volume, threads, progress);
    volume.throwIfDamaged();  // a mapped file that shrank meanwhile read as zeros
    return tree;
}

}  // namespace isotrack
