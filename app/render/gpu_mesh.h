#pragma once
// One surface's mesh on the GPU: a slot of a SurfaceArena (a vertex range and
// an index range in one of its shared pages), freed when the GpuMesh goes.
//
// Built from a core Mesh, never the reverse. A surface that is still being
// tracked grows: append() uploads only the vertices and indices added since the
// last call; the arena reserves capacity ahead and, when the slot must move,
// copies it GPU-side (nothing is sent twice). A finished mesh uploaded in one go
// gets ranges of exactly its size.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/tracking.h"
#include "render/surface_arena.h"

namespace isotrack::render {

struct GpuMeshBytes {
    std::size_t vertexBytes = 0;    // in use (positions and normals)
    std::size_t indexBytes = 0;     // in use
    std::size_t capacityBytes = 0;  // reserved: vertices, their slot numbers and indices
};

class GpuMesh {
public:
    // An empty mesh in `arena`, ready to grow. `arena` must outlive it.
    explicit GpuMesh(SurfaceArena& arena);
    // The whole of `mesh`, in ranges of exactly its size.
    GpuMesh(SurfaceArena& arena, const Mesh& mesh);
    GpuMesh(GpuMesh&& other) noexcept;
    GpuMesh& operator=(GpuMesh&& other) noexcept;
    GpuMesh(const GpuMesh&) = delete;
    GpuMesh& operator=(const GpuMesh&) = delete;
    ~GpuMesh();

    // Uploads `range` of `mesh`, which must start where the uploaded data ends
    // (throws std::invalid_argument otherwise: a step was skipped or repeated).
    void append(const Mesh& mesh, const MeshRange& range);
    void append(const Mesh& mesh, const SurfaceTracker::Step& step);
    // Uploads whatever `mesh` holds beyond what is already uploaded.
    void appendNew(const Mesh& mesh);
    // Once a grown mesh is complete: its ranges cut to its size, in place.
    void shrinkToFit();
    // Empties it (its ranges freed), keeping the slot.
    void clear();

    std::size_t vertexCount() const { return place().vertexCount; }
    std::size_t indexCount() const { return place().indexCount; }
    GpuMeshBytes bytes() const;
    // Bytes sent from the CPU since construction (GPU-side copies excluded).
    std::size_t uploadedBytes() const { return arena_->uploadedBytes(slot_); }
    // Bytes every GpuMesh has sent from the CPU since the program started (the
    // viewer takes the difference across a frame).
    static std::size_t uploadedTotal() { return SurfaceArena::uploadedTotal(); }

    SurfaceArena& arena() const { return *arena_; }
    std::uint32_t slot() const { return slot_; }
    const SlotPlace& place() const { return arena_->place(slot_); }
    // For tests: the contents, read back from the GPU.
    std::vector<Vertex> readVertices() const;
    std::vector<std::uint32_t> readIndices() const;
    std::vector<std::uint32_t> readSlotNumbers() const;

private:
    SurfaceArena* arena_;
    std::uint32_t slot_;
};

}  // namespace isotrack::render
