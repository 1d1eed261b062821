// Tracking one surface on several threads. Each thread walks the cells of its
// own tiles (a checkerboard of 64^3 to 8^3 samples, smaller as threads are
// more: SparseBlocks::ownerShift), with plain loads and stores: a piece
// continuing into another thread's tile is sent to that thread (Exchange),
// and only vertices on edges between tiles, which cells of several threads
// share, are claimed with a compare-and-swap. The threads' parts are then
// joined into one mesh, in parallel, and the triangles between tiles measured.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "extract/common/part_ids.h"
#include "extract/tracking/track_walker.h"
#include "extract/tracking/walk_exchange.h"
#include "support/huge_pages.h"
#include "support/parallel.h"

namespace isotrack::detail {
namespace {

// Sizes `buffer` to `size` and returns null where its capacity allows; otherwise
// sizes `fresh` instead (its pages possibly huge) and returns it, for the caller
// to fill with the buffer's contents too.
template <class T>
Buffer<T>* sizeWhole(Buffer<T>& buffer, std::size_t size, Buffer<T>& fresh) {
    if (size <= buffer.capacity()) {
        buffer.resize(size);
        return nullptr;
    }
    detail::resizeOnHugePages(fresh, size);
    return &fresh;
}

}  // namespace

Surface walkTogether(const Volume& volume, const TrackWorker& worker, const GridEdge& seed, TableKind table,
                     int threads, Clock::time_point start) {
    SparseBlocks blocks(volume.dims(), threads, SparseBlocks::VertexSlots::Lazy);
    std::vector<Walker> walkers(static_cast<std::size_t>(threads));
    const PartIds ids(threads);
    const int idShift = ids.shift;
    for (int t = 0; t < threads; ++t) {
        walkers[std::size_t(t)].thread = t;
        walkers[std::size_t(t)].idBase = ids.base(t);
        walkers[std::size_t(t)].indexMask = ids.indexMask();
        walkers[std::size_t(t)].tileMask = blocks.tileMask();
    }
    // The first cells are walked on this thread alone: a small surface is done
    // before more threads would pay for starting. What is left is handed to the
    // walkers of the queued pieces' tiles.
    queueSeed(volume, seed, worker, blocks, walkers[0]);
    worker.advance(blocks, nullptr, walkers[0], kPiecesAlone);
    if (walkers[0].queue.empty()) {
        Surface surface = finishedSurface(walkers[0], table);
        surface.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        return surface;
    }
    for (const Entry& entry : walkers[0].queue.drain()) walkers[std::size_t(entry.block->owner)].queue.push(entry);
    Exchange exchange(threads);
    detail::runTogether(
        threads, [&](int t) { worker.walkShared(blocks, walkers[std::size_t(t)], exchange); },
        [&] { exchange.stop(); });

    // The parts, in thread order, in the first walker's buffers; vertex ids become indices.
    std::vector<std::size_t> firstVertex(std::size_t(threads) + 1, 0), firstIndex(std::size_t(threads) + 1, 0);
    for (std::size_t t = 0; t < walkers.size(); ++t) {
        firstVertex[t + 1] = firstVertex[t] + walkers[t].mesh.vertices.size();
        firstIndex[t + 1] = firstIndex[t] + walkers[t].mesh.indices.size();
    }
    // The whole mesh goes in the first walker's buffers where they have room; a
    // buffer without is replaced by a new one (its pages possibly huge), which
    // takes the first walker's part too, copied in parallel with the others'.
    Mesh& mesh = walkers[0].mesh;
    Mesh grown;
    Buffer<Vertex>* const movedVertices = sizeWhole(mesh.vertices, firstVertex.back(), grown.vertices);
    Buffer<PackedGridEdge>* const movedEdges = sizeWhole(mesh.vertexEdges, firstVertex.back(), grown.vertexEdges);
    Buffer<std::uint32_t>* const movedIndices = sizeWhole(mesh.indices, firstIndex.back(), grown.indices);
    Vertex* const vertices = movedVertices ? movedVertices->data() : mesh.vertices.data();
    PackedGridEdge* const edges = movedEdges ? movedEdges->data() : mesh.vertexEdges.data();
    std::uint32_t* const indices = movedIndices ? movedIndices->data() : mesh.indices.data();
    const std::uint32_t indexMask = walkers[0].indexMask;
    auto finalIndex = [&](std::uint32_t id) {
        return static_cast<std::uint32_t>(firstVertex[id >> idShift] + (id & indexMask));
    };
    // Each part in `threads` slices, so that every thread has a share of the copying.
    // The first walker's ids are final but for the corners it took from other
    // walkers (its unmeasured triangles), set once every part is in place.
    const int slices = threads;
    detail::parallelFor(threads * slices, threads, [&](int task) {
        const std::size_t t = std::size_t(task / slices), slice = std::size_t(task % slices);
        const Mesh& part = walkers[t].mesh;
        const std::size_t vertexCount = firstVertex[t + 1] - firstVertex[t],
                          indexCount = firstIndex[t + 1] - firstIndex[t];
        const std::size_t vBegin = vertexCount * slice / std::size_t(slices),
                          vEnd = vertexCount * (slice + 1) / std::size_t(slices);
        const std::size_t iBegin = indexCount * slice / std::size_t(slices),
                          iEnd = indexCount * (slice + 1) / std::size_t(slices);
        if (t > 0 || movedVertices)
            std::copy(part.vertices.data() + vBegin, part.vertices.data() + vEnd, vertices + firstVertex[t] + vBegin);
        if (t > 0 || movedEdges)
            std::copy(part.vertexEdges.data() + vBegin, part.vertexEdges.data() + vEnd,
                      edges + firstVertex[t] + vBegin);
        if (t > 0) {
            for (std::size_t i = iBegin; i < iEnd; ++i) indices[firstIndex[t] + i] = finalIndex(part.indices[i]);
        } else if (movedIndices) {
            std::copy(part.indices.data() + iBegin, part.indices.data() + iEnd, indices + iBegin);
        }
    });
    if (movedVertices) mesh.vertices.swap(*movedVertices);
    if (movedEdges) mesh.vertexEdges.swap(*movedEdges);
    if (movedIndices) mesh.indices.swap(*movedIndices);
    for (const std::size_t first : walkers[0].unmeasured) {
        for (std::size_t k = first; k < first + 3; ++k) mesh.indices[k] = finalIndex(mesh.indices[k]);
    }

    // The first walker takes the others' figures, and measures the triangles
    // between tiles now that every corner is in place.
    Walker& whole = walkers[0];
    for (std::size_t t = 0; t < walkers.size(); ++t) {
        if (t > 0) {
            whole.measure.merge(walkers[t].measure);
            whole.cellsVisited += walkers[t].cellsVisited;
        }
        for (const std::size_t first : walkers[t].unmeasured) {
            const std::size_t k = firstIndex[t] + first;
            whole.measure.addTriangle(mesh.vertices.data(), mesh.indices[k], mesh.indices[k + 1], mesh.indices[k + 2]);
        }
    }
    Surface surface = finishedSurface(whole, table);
    surface.stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return surface;
}

}  // namespace isotrack::detail
