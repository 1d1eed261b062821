#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include "isotrack/contour_tree.h"
#include "isotrack/fields.h"
#include "isotrack/tree_layout.h"

using namespace isotrack;

namespace {

std::vector<double> isovalues(const Volume& volume, int count) {
    const auto [lo, hi] = volume.range();
    std::vector<double> out;
    for (int k = 1; k <= count; ++k) out.push_back(lo + (hi - lo) * k / (count + 1));
    return out;
}

// Every arc alive at v is a segment whose values hold v.
void requireAliveArcsCrossTheirHeight(const ContourTree& tree, const TreeLayout& layout, const Volume& volume) {
    for (const double v : isovalues(volume, 40)) {
        for (const std::size_t a : tree.arcsAt(v)) {
            INFO("iso " << v << ", arc " << a);
            const TreeLayout::Segment* s = layout.segmentOf(a);
            REQUIRE(s != nullptr);
            REQUIRE(s->lower < v);
            REQUIRE(s->upper >= v);
        }
    }
}

// One column per branch, and the segments in a column never overlap in value.
void requireBranchesApart(const TreeLayout& layout) {
    std::map<std::uint32_t, float> columnOf;
    std::map<float, std::vector<const TreeLayout::Segment*>> inColumn;
    for (const TreeLayout::Segment& s : layout.segments) {
        REQUIRE(s.x > 0.0f);
        REQUIRE(s.x < 1.0f);
        REQUIRE(s.lower <= s.upper);
        const auto [at, fresh] = columnOf.emplace(s.branch, s.x);
        REQUIRE(at->second == s.x);  // a branch keeps its column
        inColumn[s.x].push_back(&s);
    }
    REQUIRE(columnOf.size() == layout.branches);
    REQUIRE(inColumn.size() == layout.branches);  // no two branches share a column
    for (auto& [x, segments] : inColumn) {
        std::sort(segments.begin(), segments.end(),
                  [](auto* a, auto* b) { return a->lower != b->lower ? a->lower < b->lower : a->upper < b->upper; });
        for (std::size_t k = 1; k < segments.size(); ++k) REQUIRE(segments[k - 1]->upper <= segments[k]->lower);
    }
    REQUIRE(layout.links.size() + 1 == layout.branches);
    // Each branch's line covers its arcs' segments.
    REQUIRE(layout.branchLines.size() == layout.branches);
    std::vector<std::size_t> arcsOn(layout.branches, 0);
    for (const TreeLayout::Segment& s : layout.segments) {
        const TreeLayout::BranchLine& line = layout.branchLines[s.branch];
        REQUIRE(line.x == s.x);
        REQUIRE(line.lower <= s.lower);
        REQUIRE(line.upper >= s.upper);
        ++arcsOn[s.branch];
    }
    for (std::size_t b = 0; b < layout.branches; ++b) REQUIRE(layout.branchLines[b].arcs == arcsOn[b]);
}

}  // namespace

TEST_CASE("the tree's layout draws every arc alive at v across v's height", "[core][tree]") {
    for (const FieldSpec& spec : {FieldSpec{"blobs", 40}, FieldSpec{"noise", 24}, FieldSpec{"gyroid", 24}}) {
        INFO(spec.name);
        const Volume volume = makeField(spec);
        const ContourTree tree = computeContourTree(volume, 2);
        const TreeLayout layout = layoutContourTree(tree);
        REQUIRE(layout.segments.size() == tree.arcs.size());
        REQUIRE(layout.hiddenArcs == 0);
        requireAliveArcsCrossTheirHeight(tree, layout, volume);
        requireBranchesApart(layout);
    }
}

TEST_CASE("the tree's layout draws a simplified tree and the most persistent branches", "[core][tree]") {
    const Volume volume = makeField({"noise", 24});
    ContourTree tree = computeContourTree(volume, 2);
    simplifyContourTree(tree, 0.05);
    std::size_t kept = 0;
    for (const ContourTree::Arc& arc : tree.arcs) kept += arc.pruned ? 0 : 1;
    REQUIRE(kept < tree.arcs.size());
    const TreeLayout whole = layoutContourTree(tree);
    REQUIRE(whole.segments.size() == kept);
    REQUIRE(whole.prunedArcs == tree.arcs.size() - kept);
    for (const TreeLayout::Segment& s : whole.segments) REQUIRE_FALSE(tree.arcs[s.arc].pruned);
    requireAliveArcsCrossTheirHeight(tree, whole, volume);
    requireBranchesApart(whole);

    const TreeLayout few = layoutContourTree(tree, 5);
    REQUIRE(few.branches == 5);
    REQUIRE(few.segments.size() + few.hiddenArcs == kept);
    requireBranchesApart(few);
    // The branches drawn are the most persistent: none left out is more persistent than the least drawn.
    REQUIRE(few.minShownPersistence >= whole.minShownPersistence);
    // The root branch is drawn alike in both.
    for (const TreeLayout::Segment& s : few.segments) {
        if (s.branch == 0) REQUIRE(whole.segmentOf(s.arc)->branch == 0);
    }
}

TEST_CASE("the tree's layout is deterministic and picks the arc under the pointer", "[core][tree]") {
    const Volume volume = makeField({"blobs", 40});
    const ContourTree tree = computeContourTree(volume, 2);
    const TreeLayout a = layoutContourTree(tree, 50), b = layoutContourTree(computeContourTree(volume, 1), 50);
    REQUIRE(a.segments.size() == b.segments.size());
    for (std::size_t k = 0; k < a.segments.size(); ++k) {
        REQUIRE(a.segments[k].arc == b.segments[k].arc);
        REQUIRE(a.segments[k].branch == b.segments[k].branch);
        REQUIRE(a.segments[k].x == b.segments[k].x);
    }
    for (const TreeLayout::Segment& s : a.segments) {
        if (!(s.upper > s.lower)) continue;
        const TreeLayout::Segment* picked =
            a.pick(s.x + 0.1f / float(a.branches), (s.lower + s.upper) / 2, 0.4f / float(a.branches), 0.0);
        REQUIRE(picked != nullptr);
        REQUIRE(picked->arc == s.arc);
    }
    REQUIRE(a.pick(2.0f, (a.lo + a.hi) / 2, 0.01f, 0.0) == nullptr);
}

TEST_CASE("the tree's layout of an empty tree and of a constant volume", "[core][tree]") {
    const TreeLayout none = layoutContourTree(ContourTree{});
    REQUIRE(none.segments.empty());
    REQUIRE(none.branches == 0);
    REQUIRE(none.hi > none.lo);
    REQUIRE(none.pick(0.5f, 0.5, 1.0f, 1.0) == nullptr);

    Volume flat({4, 4, 4}, ScalarType::Float32);  // zeros: the tree orders them by index
    const ContourTree tree = computeContourTree(flat, 1);
    const TreeLayout layout = layoutContourTree(tree);
    REQUIRE(layout.segments.size() == tree.arcs.size());
    REQUIRE(layout.lo == 0.0);
    REQUIRE(layout.hi == 1.0);
    requireBranchesApart(layout);
    REQUIRE(layoutContourTree(tree, 0).segments.empty());
}
