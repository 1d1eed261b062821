// Tracking one surface with the trilinear table on several threads, as the
// consistent table's walkTogether does (track_together.cpp): each thread walks
// the cells of its own tiles (SparseBlocks::ownerShift), sends a cell in
// another thread's tile to that thread (Exchange), and claims vertices on
// edges between tiles with a compare-and-swap. The threads' parts are then
// joined into one mesh, in parallel; the surface is measured once it is whole
// (trackTrilinear), as on one thread.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "extract/trilinear/trilinear_walker.h"
#include "support/parallel.h"

namespace isotrack::detail {
namespace {

// Pieces a walk on several threads first walks on one, as the consistent
// table's: a small surface is done before more threads would pay for starting.
constexpr std::size_t kPiecesAlone = 8192;

// The parts' meshes in one, in thread order, vertex ids made indices; in parallel.
Mesh joinParts(std::vector<TrilinearPart>& parts, int idShift, int threads) {
    std::vector<std::size_t> firstVertex(parts.size() + 1, 0), firstIndex(parts.size() + 1, 0);
    for (std::size_t t = 0; t < parts.size(); ++t) {
        firstVertex[t + 1] = firstVertex[t] + parts[t].mesh.vertices.size();
        firstIndex[t + 1] = firstIndex[t] + parts[t].mesh.indices.size();
    }
    Mesh mesh;
    mesh.vertices.resize(firstVertex.back());
    mesh.vertexEdges.resize(firstVertex.back());
    mesh.indices.resize(firstIndex.back());
    const std::uint32_t indexMask = parts[0].indexMask;
    // Each part in `threads` slices, so that every thread has a share of the copying.
    const int slices = threads;
    parallelFor(int(parts.size()) * slices, threads, [&](int task) {
        const std::size_t t = std::size_t(task / slices), slice = std::size_t(task % slices);
        const Mesh& part = parts[t].mesh;
        const std::size_t vertexCount = part.vertices.size(), indexCount = part.indices.size();
        const std::size_t vBegin = vertexCount * slice / std::size_t(slices),
                          vEnd = vertexCount * (slice + 1) / std::size_t(slices);
        // Whole triangles to a slice.
        const std::size_t iBegin = indexCount / 3 * slice / std::size_t(slices) * 3,
                          iEnd = indexCount / 3 * (slice + 1) / std::size_t(slices) * 3;
        std::copy(part.vertices.begin() + std::ptrdiff_t(vBegin), part.vertices.begin() + std::ptrdiff_t(vEnd),
                  mesh.vertices.begin() + std::ptrdiff_t(firstVertex[t] + vBegin));
        std::copy(part.vertexEdges.begin() + std::ptrdiff_t(vBegin), part.vertexEdges.begin() + std::ptrdiff_t(vEnd),
                  mesh.vertexEdges.begin() + std::ptrdiff_t(firstVertex[t] + vBegin));
        for (std::size_t i = iBegin; i < iEnd; ++i) {
            const std::uint32_t id = part.indices[i];
            mesh.indices[firstIndex[t] + i] = static_cast<std::uint32_t>(firstVertex[id >> idShift] + (id & indexMask));
        }
    });
    return mesh;
}

}  // namespace

Mesh walkTrilinearTogether(const Volume& volume, const TrilinearWalker& walker, const GridEdge& seed, int threads,
                           std::vector<std::size_t>& piecesByThread) {
    SparseBlocks blocks(volume.dims(), threads);
    std::vector<TrilinearPart> parts(static_cast<std::size_t>(threads));
    int tagBits = 0;
    while ((1 << tagBits) < threads) ++tagBits;
    const int idShift = 32 - tagBits;
    for (int t = 0; t < threads; ++t) {
        TrilinearPart& part = parts[std::size_t(t)];
        part.thread = t;
        part.idBase = static_cast<std::uint32_t>(std::uint64_t(t) << idShift);
        part.indexMask = static_cast<std::uint32_t>((std::uint64_t(1) << idShift) - 1);
        part.shared = true;
        part.tileMask = blocks.tileMask();
    }
    // The first pieces are walked on this thread alone; what is left is handed
    // to the parts of the queued cells' tiles.
    walker.queueSeed(blocks, parts[0], seed);
    walker.advance(blocks, parts[0], kPiecesAlone);
    if (!parts[0].queue.empty()) {
        std::vector<TrilinearEntry> left;
        while (!parts[0].queue.empty()) left.push_back(parts[0].queue.pop());
        for (const TrilinearEntry& entry : left) parts[std::size_t(entry.block->owner)].queue.push(entry);
        Exchange exchange(threads);
        runTogether(
            threads, [&](int t) { walker.walkShared(blocks, parts[std::size_t(t)], exchange); },
            [&] { exchange.stop(); });
    }
    piecesByThread.clear();
    for (const TrilinearPart& part : parts) piecesByThread.push_back(part.piecesVisited);
    return joinParts(parts, idShift, threads);
}

}  // namespace isotrack::detail
