#pragma once
// Room extract/contour_tree: the contour tree (isotrack/contour_tree.h) and
// its plot (isotrack/tree_layout.h): building it (contour_tree_build.cpp:
// the samples sorted in contour_tree_sort.cpp and classified by their
// neighbourhoods in contour_tree_classify.cpp, then swept and merged),
// its arcs and their queries (contour_tree_arcs.cpp), simplifying it
// (contour_tree_simplify.cpp), seeds and the surfaces of its arcs
// (contour_tree_seeds.cpp, tracked through isotrack/tracking.h) and its layout
// (contour_tree_layout.cpp). Uses support/ and the public headers only.
//
// The passes of computeContourTree, shared by its files.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include <sys/mman.h>

#include "isotrack/contour_tree.h"
#include "isotrack/errors.h"
#include "support/parallel.h"  // the passes' parts run on kept threads

namespace isotrack::detail {

constexpr std::uint32_t kNoSample = ~std::uint32_t(0);

// The build's arrays of a few bytes per sample live in pages of their own,
// handed back to the kernel when freed. The executable asks glibc to keep
// freed memory for reuse (app/main.cpp), which would keep every array the
// build has freed resident, while the next one may not fit where it was.
template <class T>
struct MappedAllocator {
    using value_type = T;
    static constexpr std::size_t kMapped = std::size_t(1) << 20;  // smaller blocks: operator new
    MappedAllocator() = default;
    template <class U>
    MappedAllocator(const MappedAllocator<U>&) {}
    T* allocate(std::size_t count) {
        const std::size_t bytes = count * sizeof(T);
        if (bytes < kMapped) return static_cast<T*>(::operator new(bytes));
        void* pages = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (pages == MAP_FAILED) throw std::bad_alloc();
#if defined(MADV_HUGEPAGE)
        madvise(pages, bytes, MADV_HUGEPAGE);  // fewer faults and TLB misses; only a hint
#endif
        return static_cast<T*>(pages);
    }
    void deallocate(T* block, std::size_t count) {
        const std::size_t bytes = count * sizeof(T);
        if (bytes < kMapped) {
            ::operator delete(block);
        } else {
            munmap(block, bytes);
        }
    }
    template <class U>
    bool operator==(const MappedAllocator<U>&) const {
        return true;
    }
    template <class U>
    bool operator!=(const MappedAllocator<U>&) const {
        return false;
    }
};
template <class T>
using Buffer = std::vector<T, MappedAllocator<T>>;

// A block of pages of its own (mapped, advised for huge pages), which the
// build's passes use one after another: the sort's two 8-byte-a-sample blocks
// hold the order, the links and the forests after it, and the merge's state
// after those, so the kernel zeroes each page once. Contents start undefined
// on reuse (zero when fresh); each user writes before it reads.
class Pages {
public:
    Pages() = default;
    explicit Pages(std::size_t bytes);
    Pages(const Pages&) = delete;
    Pages& operator=(const Pages&) = delete;
    Pages(Pages&& other) noexcept;
    Pages& operator=(Pages&& other) noexcept;
    ~Pages() { shrink(0); }
    template <class T>
    T* at(std::size_t byteOffset) const {
        return reinterpret_cast<T*>(static_cast<char*>(base_) + byteOffset);
    }
    std::size_t bytes() const { return bytes_; }
    // Hands the pages from `bytes` on back to the kernel.
    void shrink(std::size_t bytes);

private:
    void* base_ = nullptr;
    std::size_t bytes_ = 0;
};

// Count items of T at some place in Pages.
template <class T>
struct Slice {
    T* items = nullptr;
    std::size_t count = 0;
    T& operator[](std::size_t i) const { return items[i]; }
    T* begin() const { return items; }
    T* end() const { return items + count; }
    std::size_t size() const { return count; }
};
template <class T>
Slice<T> sliceOf(const Pages& pages, std::size_t byteOffset, std::size_t count) {
    return {pages.at<T>(byteOffset), count};
}

// The total order of the samples: by value, NaN lowest, ties by index.
template <class T>
struct SampleOrder {
    const T* values;
    bool below(std::uint32_t a, std::uint32_t b) const {
        const T x = values[a], y = values[b];
        if constexpr (std::is_floating_point_v<T>) {
            const bool nx = std::isnan(x), ny = std::isnan(y);
            if (nx || ny) return nx != ny ? nx : a < b;
        }
        return x < y || (x == y && a < b);
    }
};

// The six face neighbours, and the twelve face-diagonal ones, of a sample.
struct Neighbours {
    Dims dims;
    // Calls fn(neighbour) for the face (6) or face and face-diagonal (18) neighbours.
    template <int Count, class Fn>
    void forEach(std::uint32_t s, Fn&& fn) const {
        const std::uint32_t nx = std::uint32_t(dims[0]), ny = std::uint32_t(dims[1]);
        const std::uint32_t x = s % nx, y = (s / nx) % ny, z = s / (nx * ny);
        const std::uint32_t n[3] = {nx, ny, std::uint32_t(dims[2])};
        const std::int64_t stride[3] = {1, std::int64_t(nx), std::int64_t(nx) * ny};
        const std::uint32_t p[3] = {x, y, z};
        for (int a = 0; a < 3; ++a) {
            if (p[a] > 0) fn(std::uint32_t(s - stride[a]));
            if (p[a] + 1 < n[a]) fn(std::uint32_t(s + stride[a]));
        }
        if constexpr (Count == 18) {
            for (int a = 0; a < 3; ++a) {
                const int b = (a + 1) % 3;
                for (int da = -1; da <= 1; da += 2) {
                    if ((da < 0 && p[a] == 0) || (da > 0 && p[a] + 1 == n[a])) continue;
                    for (int db = -1; db <= 1; db += 2) {
                        if ((db < 0 && p[b] == 0) || (db > 0 && p[b] + 1 == n[b])) continue;
                        fn(std::uint32_t(std::int64_t(s) + da * stride[a] + db * stride[b]));
                    }
                }
            }
        }
    }
};

// The build's lists of a few bytes a node or sample are Buffers too, not on
// the heap: the executable's heap is never trimmed (app/main.cpp), so what the
// build put there would stay resident beside the tree it leaves.
//
// The contour tree as the merge leaves it, by rank (the position in order):
// each rank's arc, and the arcs as pieces. The merge peels each arc in one
// walk from a node, sample after sample, so it numbers the chains of regular
// samples as it goes (in the order it peels them) and notes their end nodes;
// an edge between two nodes is an arc of its own, noted with the sample that
// the merge peeled it from. Both are pieces of 12 bytes in one list, which
// holds one per arc (the nodes less one), so it is reserved once.
struct AugmentedTree {
    static constexpr std::uint32_t kIndexMask = 0x7fffffffu;  // ranks and samples fit below it
    static constexpr std::uint32_t kEdgeBit = ~kIndexMask;
    struct Piece {
        std::uint32_t lower = kNoSample, upper = kNoSample;  // the ranks of its end nodes
        // A chain's smallest sample index, or kEdgeBit and the sample peeled for
        // an edge between two nodes: the arcs' order (chains by their smallest
        // sample, then the edges by the sample peeled) is the order of keys.
        std::uint32_t key = kNoSample;
    };
    Pages sorted, spare;         // the sort's blocks (SortedSamples), holding the two below
    Slice<std::uint32_t> order;  // the samples, ascending
    Slice<std::uint32_t> arcOf;  // by rank: a regular sample's piece; kNoSample for a node
    Buffer<Piece> pieces;
    std::uint32_t chains = 0;  // the pieces that are chains
    // The nodes' ranks, ascending, and each one's number among the nodes in
    // sample order (numberNodes, beside the merge).
    Buffer<std::uint32_t> nodeRanks, nodeNumbers;
    // Each node's state as the merge began (by its place in nodeRanks): the
    // join tree's arcs above it in the low 3 bits, the split tree's below it
    // above them, which are its arcs above and below in the contour tree
    // (Carr et al.).
    Buffer<std::uint8_t> nodeDegrees;
};

// Reports progress to a ContourTreeProgress, if any, every kStride samples,
// and throws Cancelled there when asked to stop.
class BuildProgress {
public:
    static constexpr std::uint32_t kStride = 1u << 16;
    explicit BuildProgress(ContourTreeProgress* progress) : progress_(progress) {}
    // Moves to `phase`, noting how long the one before took (on the building
    // thread only).
    void start(ContourTreeProgress::Phase phase, std::uint64_t total) const {
        if (!progress_) return;
        const auto now = std::chrono::steady_clock::now();
        const auto before = std::size_t(progress_->phase.load(std::memory_order_relaxed));
        if (phaseStarted_ != std::chrono::steady_clock::time_point{} && before < progress_->seconds.size()) {
            progress_->seconds[before] = std::chrono::duration<double>(now - phaseStarted_).count();
        }
        phaseStarted_ = now;
        progress_->total.store(0, std::memory_order_relaxed);
        progress_->done.store(0, std::memory_order_relaxed);
        progress_->phase.store(phase, std::memory_order_relaxed);
        progress_->total.store(total, std::memory_order_relaxed);
        check();
    }
    // Called with each sample count k; counts a stride when k is a multiple of it,
    // and then throws Cancelled when asked to stop. On a thread of a parallel
    // step (support/parallel.h) the step rethrows it on the calling thread.
    void step(std::uint32_t k) const {
        if (progress_ && (k & (kStride - 1)) == 0 && k != 0) countStride();
    }
    bool cancelled() const { return progress_ && progress_->cancel && progress_->cancel->load(); }
    void check() const {
        if (cancelled()) throw Cancelled{};
    }
    // Runs fn(b, e) over [begin, end) a stride at a time, check() before each:
    // the loops of a pass that reports no progress of its own, stopped within a
    // stride; with `counted`, each stride's samples count as done.
    template <class Fn>
    void inStrides(std::uint32_t begin, std::uint32_t end, Fn&& fn, bool counted = false) const {
        while (begin < end) {
            check();
            const std::uint32_t next = end - begin > kStride ? begin + kStride : end;
            fn(begin, next);
            if (counted) count(next - begin);
            begin = next;
        }
    }
    // A phase whose total is known only once it has started (the sort's passes).
    void setTotal(std::uint64_t total) const {
        if (progress_) progress_->total.store(total, std::memory_order_relaxed);
    }
    void count(std::uint64_t samples) const {
        if (progress_) progress_->done.fetch_add(samples, std::memory_order_relaxed);
    }

private:
    // step()'s rare part, a call of its own so that step() stays inlined in
    // the sweeps' and the merge's loops (the throw would make it too large).
    [[gnu::noinline]] void countStride() const {
        progress_->done.fetch_add(kStride, std::memory_order_relaxed);
        check();
    }

    ContourTreeProgress* progress_;
    mutable std::chrono::steady_clock::time_point phaseStarted_{};
};

// The ranks [0, n) in `parts` parts, one a thread (kept threads, parallel.h):
// fn(part, begin, end). The first exception of a part (Cancelled, from
// progress.inStrides in its loop) is rethrown on the calling thread.
template <class Fn>
void inRanges(std::uint32_t n, std::size_t parts, Fn&& fn) {
    auto bound = [&](std::size_t p) { return std::uint32_t(std::uint64_t(n) * p / parts); };
    parallelFor(int(parts), int(parts),
                [&](int p) { fn(std::size_t(p), bound(std::size_t(p)), bound(std::size_t(p) + 1)); });
}

// Sorts items by key(item), a 32-bit key each, read once, stably (equal keys
// keep their items' order): (key, item) pairs sorted by key, in place of
// comparisons that would read the keys anywhere in memory. Large lists go by
// an LSD radix sort (11-bit digits, passes where one digit holds every key
// skipped), small ones by std::sort.
template <class Items, class Key>
void sortByKey(Items& items, Key&& key) {
    const std::size_t n = items.size();
    Buffer<std::uint64_t> pairs(n);
    for (std::size_t i = 0; i < n; ++i) pairs[i] = std::uint64_t(key(items[i])) << 32 | i;
    constexpr int kDigitBits = 11, kPasses = 3;
    constexpr std::size_t kBuckets = std::size_t(1) << kDigitBits;
    if (n < 4 * kBuckets) {
        std::sort(pairs.begin(), pairs.end());  // the index below the key keeps it stable
    } else {
        std::vector<std::uint32_t> count(kPasses * kBuckets);
        auto digit = [](std::uint64_t pair, int pass) {
            return std::size_t(pair >> (32 + kDigitBits * pass)) & (kBuckets - 1);
        };
        for (const std::uint64_t pair : pairs) {
            for (int pass = 0; pass < kPasses; ++pass) ++count[std::size_t(pass) * kBuckets + digit(pair, pass)];
        }
        Buffer<std::uint64_t> spare(n);
        for (int pass = 0; pass < kPasses; ++pass) {
            std::uint32_t* c = &count[std::size_t(pass) * kBuckets];
            if (std::find(c, c + kBuckets, std::uint32_t(n)) != c + kBuckets) continue;  // nothing moves
            std::uint32_t sum = 0;
            for (std::size_t b = 0; b < kBuckets; ++b) sum += std::exchange(c[b], sum);
            for (const std::uint64_t pair : pairs) spare[c[digit(pair, pass)]++] = pair;
            pairs.swap(spare);
        }
    }
    Items sorted(n);
    for (std::size_t i = 0; i < n; ++i) sorted[i] = items[std::uint32_t(pairs[i])];
    items.swap(sorted);
}

// Each sample's class for the two sweeps (contour_tree_classify.cpp): the join
// sweep's in the low 3 bits, the split sweep's above them. 0 is an extremum of
// that sweep, kJoinCandidate or kSplitCandidate a sample whose swept
// neighbours may be apart (the sweep reads them all), and any other c a sample
// joining exactly the component of its neighbour at position c - 1
// (neighbourOffset).
constexpr std::uint8_t kJoinCandidate = 7, kSplitCandidate = 31;
// The neighbour positions a class may name: the 6 faces, then the 12 edges.
constexpr std::uint8_t kNeighbourPositions = 18;
// Where the class pass also notes, for each candidate (by sample), one
// neighbour position of each group of its swept neighbours that are connected
// inside its neighbourhood (a mask of the 18 positions; the join sweep's are
// faces): the sweep looks up only those in its forest. Either may be null.
struct CandidateGroups {
    std::uint32_t* join = nullptr;
    std::uint32_t* split = nullptr;
};
Buffer<std::uint8_t> classifySamples(const Volume& volume, int threads, const BuildProgress& progress,
                                     const CandidateGroups& groups = {});
// The index offset of neighbour position p (0-5 the faces -x +x -y +y -z +z, then the edges).
std::int64_t neighbourOffset(const Dims& dims, std::uint8_t position);

// Samples sorted ascending in the order above (a stable radix sort, on up to
// `threads` threads): the order in the first half of `sorted` (8 bytes a
// sample), and `spare`, 8 bytes a sample more that the sort used and left.
struct SortedSamples {
    Pages sorted, spare;
    std::uint32_t count = 0;
    Slice<std::uint32_t> order() const { return sliceOf<std::uint32_t>(sorted, 0, count); }
};
SortedSamples sortSamples(const Volume& volume, int threads, const BuildProgress& progress);
// Join tree, split tree and their merge (Carr et al.'s algorithm).
AugmentedTree augmentedContourTree(const Volume& volume, int threads,
                                   const BuildProgress& progress = BuildProgress{nullptr});
// Numbers the nodes by sample index, tree.nodeNumbers from tree.nodeRanks
// (contour_tree_arcs.cpp). Reads only the order and nodeRanks, so it runs
// beside the merge.
void numberNodes(AugmentedTree& tree);
// Chains of regular samples into arcs between the critical ones (the passes
// over the ranks on up to 4 of `threads`).
ContourTree compressContourTree(const Volume& volume, AugmentedTree&& augmented, int threads,
                                const BuildProgress& progress);

}  // namespace isotrack::detail
