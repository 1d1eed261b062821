#pragma once
// Every surface's mesh in a few shared GPU buffers, so that all of them draw in
// a handful of calls.
//
// The arena holds *pages*; a page is a vertex buffer, a parallel buffer of one
// surface slot number per vertex, an index buffer and the vertex array that
// binds them. A surface is a *slot*: one vertex range and one index range in
// one page. Its indices stay local to its own vertices (0 is its first), the
// draw adds the range's first vertex as base vertex, so a core Mesh uploads as
// it is. Ranges come from a RangeAllocator per buffer (first fit, coalescing),
// so deleting and re-extracting surfaces reuses the freed space.
//
// What differs per surface when drawing (colour, offset, selection highlight,
// growth colouring, pick id, first vertex) is the *surface table*: three RGBA32F
// texels per slot in a buffer texture, which the shaders read with the slot
// number of each vertex. It is re-sent only where it changed.
//
// Growth: appending past a slot's capacity reserves about twice what it holds,
// growing in place while the space after it is free, else moving the slot with
// glCopyBufferSubData (never a re-upload from the CPU). Pages are made when
// needed and kept until trim(); prepare() makes room for a batch of surfaces
// up front, so a whole extraction lands in one page.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "gl/buffer.h"
#include "gl/texture_buffer.h"
#include "gl/vertex_array.h"
#include "isotrack/mesh.h"
#include "render/range_allocator.h"

namespace isotrack::render {

// Vertices [firstVertex, firstVertex + vertexCount) and indices likewise, as a
// SurfaceTracker::Step reports them.
struct MeshRange {
    std::size_t firstVertex = 0, vertexCount = 0;
    std::size_t firstIndex = 0, indexCount = 0;
};

// One slot's entry in the surface table.
struct SurfaceLook {
    glm::vec3 colour{0.8f};
    float highlight = 0.0f;  // 1 for the selection
    glm::vec3 offset{0.0f};
    float growthScale = 0.0f;  // 1 / vertex count to colour by growth order, else 0
    std::uint32_t pickId = 0;
};

// Where a slot's data lies. page < 0: nothing allocated yet.
struct SlotPlace {
    int page = -1;
    std::size_t firstVertex = 0, vertexCount = 0, vertexCapacity = 0;
    std::size_t firstIndex = 0, indexCount = 0, indexCapacity = 0;
};

struct ArenaStats {
    std::size_t pages = 0;
    std::size_t capacityBytes = 0;     // every page's buffers
    std::size_t reservedBytes = 0;     // held by surfaces, spare capacity included
    std::size_t usedBytes = 0;         // holding surface data
    std::size_t freeBytes = 0;         // capacity - reserved
    std::size_t largestFreeBytes = 0;  // the largest free vertex or index range
    // 1 - (each page's largest free vertex range + largest free index range) /
    // all free bytes: 0 while every page's free space is one range per buffer.
    double fragmentation = 0.0;
    std::size_t moves = 0, movedBytes = 0;  // slots moved to a bigger range, GPU-side
};

struct ArenaOptions {
    // A new page holds at least this many vertices (and indicesPerVertex times as
    // many indices), more when a batch or a surface needs more. Making a buffer
    // costs time in proportion to its size on llvmpipe, so pages start modest.
    std::size_t pageVertices = std::size_t(1) << 18;
    std::size_t indicesPerVertex = 6;  // its index capacity, per vertex
};

class SurfaceArena {
public:
    struct Page {
        gl::Buffer vertices, slots, indices;
        gl::VertexArray array;
        RangeAllocator vertexSpace, indexSpace;
        std::size_t surfaces = 0;
    };

    explicit SurfaceArena(const ArenaOptions& options = {});  // needs a current GL context
    SurfaceArena(const SurfaceArena&) = delete;
    SurfaceArena& operator=(const SurfaceArena&) = delete;

    // A new empty slot / gives a slot and its ranges back.
    std::uint32_t create();
    void release(std::uint32_t slot);
    // Empties a slot, freeing its ranges (it stays valid).
    void clear(std::uint32_t slot);

    // Capacity for at least this many vertices and indices (exactly this many
    // when the slot must be (re)allocated), keeping its contents.
    void reserve(std::uint32_t slot, std::size_t vertices, std::size_t indices);
    // Uploads `range` of `mesh`, which must continue the slot's data
    // (std::invalid_argument otherwise). Grows capacity ahead as described above.
    void append(std::uint32_t slot, const Mesh& mesh, const MeshRange& range);
    // Capacity down to the contents (the tail given back in place).
    void shrinkToFit(std::uint32_t slot);
    // Makes sure some page has one free vertex range and one free index range of
    // at least these sizes, making a page for them if none has.
    void prepare(std::size_t vertices, std::size_t indices);
    // Frees pages that hold no surface.
    void trim();

    const SlotPlace& place(std::uint32_t slot) const { return slots_.at(slot).place; }
    const SurfaceLook& look(std::uint32_t slot) const { return slots_.at(slot).look; }
    std::size_t uploadedBytes(std::uint32_t slot) const { return slots_.at(slot).uploaded; }
    const Page* page(int index) const { return pages_.at(static_cast<std::size_t>(index)).get(); }
    std::size_t pageCount() const { return pages_.size(); }  // some may be null after trim()

    // The surface table: set a slot's entry; sync() sends what changed (call
    // before drawing), bindTable() binds it to a texture unit.
    void setLook(std::uint32_t slot, const SurfaceLook& look);
    void sync();
    void bindTable(int unit) const { tableTexture_.bind(unit); }

    ArenaStats stats() const;
    // Bytes every arena has sent from the CPU (meshes, slot numbers, table) since
    // the program started; GPU-side copies excluded.
    static std::size_t uploadedTotal();

    static constexpr std::size_t kTexelsPerSlot = 3;

private:
    struct Slot {
        SlotPlace place;
        SurfaceLook look;
        std::size_t uploaded = 0;
        bool live = false;
    };

    Slot& live(std::uint32_t slot);
    int findSpace(std::size_t vertices, std::size_t indices, std::size_t& firstVertex, std::size_t& firstIndex);
    int makePage(std::size_t vertices, std::size_t indices);
    void moveTo(Slot& slot, int page, std::size_t firstVertex, std::size_t firstIndex, std::size_t vertexCapacity,
                std::size_t indexCapacity);
    bool growInPlace(Slot& slot, std::size_t vertices, std::size_t indices, std::size_t wantVertices,
                     std::size_t wantIndices);
    void growTo(std::uint32_t slot, std::size_t vertices, std::size_t indices, std::size_t wantVertices,
                std::size_t wantIndices);
    void writeEntry(std::uint32_t slot);
    void uploadSlotNumbers(std::uint32_t slot, std::size_t first, std::size_t count);

    ArenaOptions options_;
    std::vector<std::unique_ptr<Page>> pages_;
    std::vector<Slot> slots_;
    std::vector<std::uint32_t> freeSlots_;
    std::vector<float> table_;  // kTexelsPerSlot * 4 floats per slot, as sent
    gl::TextureBuffer tableTexture_;
    std::size_t dirtyFirst_ = 0, dirtyEnd_ = 0;  // slots whose entries changed since sync()
    std::size_t moves_ = 0, movedBytes_ = 0;
    std::vector<std::uint32_t> slotNumbers_;  // scratch for uploads
};

}  // namespace isotrack::render
