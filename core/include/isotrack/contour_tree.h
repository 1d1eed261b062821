#pragma once
// The contour tree of a volume: every connected isosurface of every isovalue,
// as the arcs of one tree (Carr, Snoeyink & Axen 2003).
//
// A point of an arc at isovalue v is one connected surface of the consistent
// table at v. The tree is built under the digital topology that table gives
// its surfaces: the samples at or above v ("above", as the table counts
// sample >= iso) are joined only across faces (6-connected), those below v
// across faces and face diagonals (18-connected), since the table keeps the
// above corners apart on an ambiguous face and never joins corners across a
// cube's diagonal. So the number of arcs crossing v equals the number of
// surfaces extractAllSurfaces finds at v. Equal samples are ordered by their
// index (simulation of simplicity); NaN is below everything.
//
// Each arc keeps its regular samples in ascending order, so a seed edge of its
// surface at any isovalue is found by a binary search, and tracking the seeds
// gives every surface without a scan of the volume.
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/surface.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack {

struct ContourTree {
    // A critical sample: an extremum, a saddle, or a sample joining or
    // splitting contours (a node with other than one arc above and one below).
    struct Node {
        std::uint32_t sample = 0;        // index into the volume
        double value = 0.0;              // NaN for a NaN sample
        std::uint32_t up = 0, down = 0;  // arcs above and below it
    };
    // One surface over the isovalues (lower's value, upper's value]: at v it
    // exists when lower < v <= upper (a NaN lower counts as below every v).
    struct Arc {
        std::uint32_t lower = 0, upper = 0;  // nodes
        // Its regular samples in samples[begin, end), ascending; 32 bits, as the
        // tree takes fewer than 2^31 samples (20 bytes an arc rather than 32).
        std::uint32_t begin = 0, end = 0;
        bool pruned = false;  // hidden by simplify()
        std::size_t size() const { return end - begin; }
    };
    Dims dims{0, 0, 0};
    std::vector<Node> nodes;  // by sample index
    std::vector<Arc> arcs;
    std::vector<std::uint32_t> samples;
    // The arcs at each node: nodeArcs[nodeArcBegin[n], nodeArcBegin[n + 1]).
    std::vector<std::uint32_t> nodeArcBegin, nodeArcs;

    // The node at a sample, or nodes.size() when that sample is regular.
    std::size_t nodeAt(std::uint32_t sample) const;
    // Arcs crossing v (not pruned), in arc order.
    std::vector<std::size_t> arcsAt(double v) const;
    // Persistence of an arc: upper value minus lower value (infinite with a NaN end).
    double persistence(std::size_t arc) const;
    // Bytes the tree holds.
    std::size_t byteSize() const;
};

// Flexible isosurfaces: the arc that the surface on `arc` is on at isovalue
// `to`, following the tree. The arc itself when it crosses `to`; else the walk
// leaves it at its end toward `to` and goes on through the nodes: where the
// surface meets others (a node with one arc on the far side) it becomes the
// merged surface; where it splits (several arcs on the far side) it keeps the
// branch that sweeps the most samples. Pruned arcs are not taken. Returns
// arcs.size() when the surface vanishes on the way (an extremum is passed).
std::size_t followArc(const ContourTree& tree, std::size_t arc, double to);

// How far a contour tree build has got, for another thread to show, and how it
// is stopped. The build moves through the phases in order; within sorting,
// sweeping and merging, done/total is the fraction of samples handled (total is
// 0 while unknown). Cancel is checked every 64Ki samples.
struct ContourTreeProgress {
    enum class Phase : std::uint8_t { Sorting, Sweeping, Merging, Arcs, Done };
    std::atomic<Phase> phase{Phase::Sorting};
    std::atomic<std::uint64_t> done{0}, total{0};
    const std::atomic<bool>* cancel = nullptr;  // when another thread sets it: Cancelled
    // Each phase's wall time in seconds (Sorting, Sweeping, Merging, Arcs),
    // written by the building thread as the phase ends: read it once the build
    // has returned.
    std::array<double, 4> seconds{};

    // The fraction of the whole build, from the phases' typical shares of its time.
    double fraction() const;
};
// "sorting the samples", "sweeping the join and split trees", "merging them", "building arcs", "done".
const char* contourTreePhaseName(ContourTreeProgress::Phase phase);

// Builds the contour tree on `threads` threads, core's kept ones (the sort and
// the class pass on all of them, the join and split trees at once on two, the
// arcs on up to four). Throws InputError for an empty volume or one of 2^31
// samples or more, and Cancelled (isotrack/errors.h) when progress->cancel is
// set meanwhile (on any thread: it stops every part and is thrown here).
ContourTree computeContourTree(const Volume& volume, int threads = 2, ContourTreeProgress* progress = nullptr);

// Hides noise: repeatedly prunes the leaf branch (a chain of arcs from an
// extremum to the saddle where it joins the rest) with the smallest measure,
// while that measure is below the threshold; `minPersistence` measures the
// branch's value range, `minSize` its number of samples. Pruned arcs get
// `pruned` and are left out of arcsAt; saddles left with one arc each way stay
// nodes. Never prunes the last branch at a saddle.
void simplifyContourTree(ContourTree& tree, double minPersistence, std::size_t minSize = 0);

// A seed of one arc's surface at v: a grid edge with one end above v in the
// arc's upper part and the other below v in its lower part. `certain` is false
// when no such pair was found (the sides were too large to enumerate) and the
// edge is only a crossed edge near the cut, whose surface may be another arc's.
struct ArcSeed {
    std::size_t arc = 0;
    GridEdge edge;
    bool certain = true;
};
// One seed for each arc crossing v (arcsAt's order), or for each of `arcs`
// (each must cross v). Throws InputError when the volume is not the tree's.
std::vector<ArcSeed> arcSeeds(const ContourTree& tree, const Volume& volume, double v);
std::vector<ArcSeed> arcSeeds(const ContourTree& tree, const Volume& volume, double v,
                              const std::vector<std::size_t>& arcs);

// The `count` arcs crossing v that sweep the most samples, most first.
std::vector<std::size_t> largestArcsAt(const ContourTree& tree, double v, std::size_t count);

// The surface of `arc` at v (which the arc must cross), tracked from its arcSeeds
// seed with the consistent table on `threads` threads, with the arc, its
// persistence and the surface's topology in its stats: one flexible isosurface.
Surface trackArc(const ContourTree& tree, const Volume& volume, std::size_t arc, double v, int threads = 1);

// The surfaces of the arcs crossing v, tracked from arcSeeds with the consistent
// table, on `threads` threads (a surface each), largest first, each with its arc in `arcs` (same order) and in its
// stats (with the arc's persistence and the surface's topology, measureTopology). Seeds that are
// not certain are tracked last and skipped when their edge is on a surface
// already tracked, so the surfaces are those of extractAllSurfaces at v. With
// `largest` > 0, only the surfaces of largestArcsAt(tree, v, largest). The
// arcs in `leaveOut` (flexible isosurfaces shown at their own isovalue) are
// left out of the result, and neither seeded nor tracked while every other
// seed is certain; otherwise they are tracked, as their surfaces may hold an
// uncertain seed, and dropped after.
std::vector<Surface> trackTreeSurfaces(const ContourTree& tree, const Volume& volume, double v, int threads = 1,
                                       std::vector<std::size_t>* arcs = nullptr, std::size_t largest = 0,
                                       const std::vector<std::size_t>& leaveOut = {});

}  // namespace isotrack
