// The lookups that let the labelled exhaustive pass join a cell piece's
// vertices while looking up few of them (PieceUnions, derived from the
// continuation table), and the joining of surfaces across a seam between chunks.
#include "extract/marching_cubes/surface_labels.h"

#include "isotrack/continuation.h"
#include "isotrack/cube.h"
#include "isotrack/errors.h"

namespace isotrack::detail {
namespace {

PieceUnions pieceUnionsFor(TableKind kind) {
    const auto& table = continuationTable(kind);
    // Per low face (-x, -y, -z), its edges; and the x- and y-edges of the cell's
    // upper slice, placeholders in a seam slab, which stand in for a group only when alone.
    std::array<unsigned, 3> lowFace{};
    unsigned upperSlice = 0;
    for (int e = 0; e < cube::kEdgeCount; ++e) {
        for (int f = 0; f < 3; ++f) lowFace[std::size_t(f)] |= unsigned(cube::edgeOnFace(e, 2 * f)) << e;
        if (cube::edgeOrigin(e)[2] == 1 && cube::edgeAxis(e) != 2) upperSlice |= 1u << e;
    }
    const unsigned newEdges = ((1u << cube::kEdgeCount) - 1) & ~(lowFace[0] | lowFace[1] | lowFace[2]);
    PieceUnions out;
    auto onUpperSlice = [&](int e) { return (upperSlice >> e & 1) != 0; };
    for (int config = 0; config < 256; ++config) {
        const CaseContinuation& cased = table[std::size_t(config)];
        unsigned crossed = 0;
        for (int e = 0; e < cube::kEdgeCount; ++e) crossed |= unsigned(cased.pieceOfEdge[std::size_t(e)] >= 0) << e;
        for (int across = 0; across < 8; ++across) {
            for (int p = 0; p < cased.pieceCount; ++p) {
                const unsigned old = cased.pieces[p].edgeMask & ~newEdges;
                std::array<int, cube::kEdgeCount> group;
                for (int e = 0; e < cube::kEdgeCount; ++e) group[std::size_t(e)] = e;
                auto find = [&](int e) {
                    while (group[std::size_t(e)] != e) e = group[std::size_t(e)];
                    return e;
                };
                for (int f = 0; f < 3; ++f) {
                    const unsigned onFace = crossed & lowFace[std::size_t(f)];
                    if (!(across >> f & 1) || __builtin_popcount(onFace) != 2 || (onFace & old) != onFace) continue;
                    group[std::size_t(find(__builtin_ctz(onFace)))] = find(31 - __builtin_clz(onFace));
                }
                // Each group's stand-in: its first edge off the upper slice, else its only edge.
                std::array<int, cube::kEdgeCount> standIn;
                standIn.fill(-1);
                for (int e = 0; e < cube::kEdgeCount; ++e) {
                    if (!(old >> e & 1)) continue;
                    int& chosen = standIn[std::size_t(find(e))];
                    if (chosen < 0 || (onUpperSlice(chosen) && !onUpperSlice(e))) chosen = e;
                }
                unsigned lookups = cased.pieces[p].edgeMask & newEdges;
                for (int chosen : standIn) {
                    if (chosen >= 0) lookups |= 1u << chosen;
                }
                out.lookups[std::size_t(config)][std::size_t(across)][std::size_t(p)] =
                    static_cast<std::uint16_t>(lookups);
            }
        }
    }
    return out;
}

}  // namespace

const PieceUnions& pieceUnions(TableKind kind) {
    if (kind == TableKind::Trilinear) throw InputError(kTrilinearNoContinuationTable);
    if (kind == TableKind::Consistent) {
        static const PieceUnions consistent = pieceUnionsFor(kind);
        return consistent;
    }
    static const PieceUnions classic = pieceUnionsFor(kind);
    return classic;
}

void stitchSeam(const std::vector<std::size_t>& seamIndices, const Mesh& mesh, std::uint32_t* parent) {
    std::size_t joined = ~std::size_t(0);
    for (std::size_t at : seamIndices) {
        const std::size_t first = at - at % 3;
        if (first == joined) continue;
        joined = first;
        const std::uint32_t* triangle = &mesh.indices[first];
        std::uint32_t root = findRoot(parent, triangle[0]);
        for (int k = 1; k < 3; ++k) {
            const std::uint32_t other = findRoot(parent, triangle[k]);
            if (other != root) root = linkRoots(parent, root, other);
        }
    }
}

}  // namespace isotrack::detail
