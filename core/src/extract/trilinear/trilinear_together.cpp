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
    return joinWalkParts(parts, idShift, threads);
}

}  // namespace isotrack::detail
