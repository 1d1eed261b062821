#pragma once
// The exhaustive pass with its connected surfaces labelled on the way, for
// extractAllSurfaces to split in parallel.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

// A chunk of slabs marched by one thread: its vertices and triangles are
// contiguous in the mesh. Its triangles may use vertices of the next chunk (on
// the slice between them), never of others.
struct MarchedChunk {
    std::size_t vertexBegin = 0, vertexEnd = 0;
    std::size_t triangleBegin = 0, triangleEnd = 0;
    std::vector<std::uint8_t> pieceStarts;  // one bit per triangle of the chunk (LSB first), set on each cell piece's first
};

struct LabelledMesh {
    Mesh mesh;
    std::vector<MarchedChunk> chunks;
    Buffer<std::uint32_t> root;             // per vertex, the smallest vertex id of its connected surface
};

LabelledMesh marchLabelled(const Volume& volume, double iso, TableKind table, int threads);

}  // namespace isotrack::detail
