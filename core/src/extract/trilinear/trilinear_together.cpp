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

#include "extract/common/part_ids.h"
#include "extract/trilinear/trilinear_walker.h"
#include "support/parallel.h"

namespace isotrack::detail {

Mesh walkTrilinearTogether(const Volume& volume, const TrilinearWalker& walker, const GridEdge& seed, int threads,
                           std::vector<std::size_t>& piecesByThread) {
    SparseBlocks blocks(volume.dims(), threads);
    std::vector<TrilinearPart> parts(static_cast<std::size_t>(threads));
    const PartIds ids(threads);
    const int idShift = ids.shift;
    for (int t = 0; t < threads; ++t) {
        TrilinearPart& part = parts[std::size_t(t)];
        part.thread = t;
        part.idBase = ids.base(t);
        part.indexMask = ids.indexMask();
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
