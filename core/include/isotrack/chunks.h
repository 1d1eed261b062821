#pragma once
// A volume cut into chunks, each extracted on its own (isotrack.dask): one name
// for every grid edge across the chunks, and which of a chunk's edges it shares
// with other chunks, so that the chunks' pieces of surface join exactly.
//
// A chunk owns the cells [lo, hi) along each axis and reads the samples
// [lo, hi], one more on each high side, where the next chunk starts. With the
// consistent table a cell's triangles depend only on its eight samples, so the
// chunks' triangles are exactly the whole volume's; and a crossed edge on a
// face two chunks share is the same edge, and the same vertex, for both. Pieces
// sharing such an edge are one surface (as dask-image joins labels across
// chunk faces, but with no slab to relabel: the edge's name is global).
#include <cstdint>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/volume.h"

namespace isotrack {

// An edge's name in the whole volume: its place in memory order, the order in
// which surfaces of equal size are sorted ((z * ny + y) * nx + x) * 3 + axis.
std::uint64_t globalEdgeId(const GridEdge& edge, const Dims& volumeDims);
// The edge a global id names.
GridEdge edgeOfGlobalId(std::uint64_t id, const Dims& volumeDims);

// Per vertex of a chunk's mesh (its edges in the chunk's own indices; the
// chunk's samples start at `offset` and span `chunkDims` in a volume of
// `volumeDims`): the global id of its edge, whether that edge lies on a face the
// chunk shares with another chunk, and whether it lies on the volume's border
// (where a surface is cut open). Throws InputError when the chunk does not fit
// in the volume or a vertex lies inside a cell (the trilinear table's vertices,
// whose pieces do not join by edges).
struct ChunkEdges {
    std::vector<std::uint64_t> ids;
    std::vector<std::uint8_t> shared;
    std::vector<std::uint8_t> onBorder;
};
ChunkEdges chunkEdges(const Mesh& mesh, const Dims& offset, const Dims& chunkDims, const Dims& volumeDims);

}  // namespace isotrack
