// Global names of grid edges across a volume's chunks; see isotrack/chunks.h.
#include <string>

#include "extract/measure/surface_measure.h"
#include "isotrack/chunks.h"
#include "isotrack/errors.h"

namespace isotrack {

std::uint64_t globalEdgeId(const GridEdge& edge, const Dims& volumeDims) { return detail::edgeOrder(edge, volumeDims); }

GridEdge edgeOfGlobalId(std::uint64_t id, const Dims& volumeDims) {
    const auto nx = std::uint64_t(volumeDims[0]), ny = std::uint64_t(volumeDims[1]);
    const std::uint64_t sample = id / 3;
    return GridEdge{int(sample % nx), int(sample / nx % ny), int(sample / (nx * ny)), int(id % 3)};
}

namespace {

std::string dimsText(const Dims& d) {
    return "(" + std::to_string(d[0]) + ", " + std::to_string(d[1]) + ", " + std::to_string(d[2]) + ")";
}

}  // namespace

ChunkEdges chunkEdges(const Mesh& mesh, const Dims& offset, const Dims& chunkDims, const Dims& volumeDims) {
    for (std::size_t k = 0; k < 3; ++k) {
        if (offset[k] < 0 || chunkDims[k] < 2 || offset[k] + chunkDims[k] > volumeDims[k])
            throw InputError("chunk: samples from " + dimsText(offset) + " spanning " + dimsText(chunkDims) +
                             " do not fit in a volume of " + dimsText(volumeDims));
    }
    // A face is shared when a chunk with cells lies beyond it: below, any chunk
    // not at the volume's start; above, one that starts at the chunk's last sample
    // and still has a cell, that is, this chunk's samples end before the volume's.
    int sharedLow[3], sharedHigh[3];
    for (std::size_t k = 0; k < 3; ++k) {
        sharedLow[k] = offset[k] > 0 ? 0 : -1;
        sharedHigh[k] = offset[k] + chunkDims[k] < volumeDims[k] ? chunkDims[k] - 1 : -1;
    }
    ChunkEdges out;
    const std::size_t count = mesh.vertexEdges.size();
    out.ids.resize(count);
    out.shared.resize(count);
    out.onBorder.resize(count);
    for (std::size_t v = 0; v < count; ++v) {
        const GridEdge local = mesh.vertexEdges[v];
        if (local.axis == kCellInterior)
            throw InputError("chunk: a vertex inside a cell (the trilinear table's) cannot join chunks");
        const int p[3] = {local.x, local.y, local.z};
        bool shared = false;
        for (int k = 0; k < 3; ++k) {
            if (k == local.axis) continue;
            shared = shared || p[k] == sharedLow[k] || p[k] == sharedHigh[k];
        }
        const GridEdge global{local.x + offset[0], local.y + offset[1], local.z + offset[2], local.axis};
        out.ids[v] = globalEdgeId(global, volumeDims);
        out.shared[v] = shared;
        out.onBorder[v] = detail::edgeOnVolumeBorder(global, volumeDims);
    }
    return out;
}

}  // namespace isotrack
