#include "render/surface_arena.h"

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace isotrack::render {
namespace {

constexpr std::size_t kVertexBytes = sizeof(Vertex);
constexpr std::size_t kSlotBytes = sizeof(std::uint32_t);
constexpr std::size_t kIndexBytes = sizeof(std::uint32_t);
constexpr std::size_t kFloatsPerSlot = SurfaceArena::kTexelsPerSlot * 4;
constexpr std::size_t kMinGrowVertices = 1024;
constexpr std::size_t kMinGrowIndices = 3 * 2048;
// Vertex numbers and pick ids travel through the table as floats: exact below 2^24.
constexpr std::size_t kMaxPageVertices = std::size_t(1) << 24;

static_assert(sizeof(Vertex) == 6 * sizeof(float), "Vertex must be tightly packed position + normal floats");

// GL objects live on one thread, so a plain counter will do.
std::size_t uploadedEverywhere = 0;

std::size_t grownCapacity(std::size_t count, std::size_t needed, std::size_t minimum) {
    return std::max({needed, 2 * count, minimum});
}

}  // namespace

std::size_t SurfaceArena::uploadedTotal() { return uploadedEverywhere; }

SurfaceArena::SurfaceArena(const ArenaOptions& options) : options_(options) {}

SurfaceArena::Slot& SurfaceArena::live(std::uint32_t slot) {
    if (slot >= slots_.size() || !slots_[slot].live) {
        throw std::invalid_argument("SurfaceArena: slot " + std::to_string(slot) + " is not in use");
    }
    return slots_[slot];
}

std::uint32_t SurfaceArena::create() {
    std::uint32_t slot = 0;
    if (!freeSlots_.empty()) {
        slot = freeSlots_.back();
        freeSlots_.pop_back();
    } else {
        slot = static_cast<std::uint32_t>(slots_.size());
        slots_.emplace_back();
        table_.resize(slots_.size() * kFloatsPerSlot, 0.0f);
    }
    slots_[slot] = Slot{};
    slots_[slot].live = true;
    writeEntry(slot);
    return slot;
}

void SurfaceArena::clear(std::uint32_t index) {
    Slot& slot = live(index);
    SlotPlace& place = slot.place;
    if (place.page >= 0) {
        Page& page = *pages_[static_cast<std::size_t>(place.page)];
        page.vertexSpace.release(place.firstVertex, place.vertexCapacity);
        page.indexSpace.release(place.firstIndex, place.indexCapacity);
        --page.surfaces;
    }
    place = SlotPlace{};
    writeEntry(index);
}

void SurfaceArena::release(std::uint32_t index) {
    clear(index);
    slots_[index].live = false;
    freeSlots_.push_back(index);
}

int SurfaceArena::makePage(std::size_t vertices, std::size_t indices) {
    const std::size_t vertexCapacity = std::max(vertices, options_.pageVertices);
    const std::size_t indexCapacity = std::max(indices, options_.pageVertices * options_.indicesPerVertex);
    if (vertexCapacity > kMaxPageVertices) {
        throw std::length_error("a surface of " + std::to_string(vertices) +
                                " vertices is more than one GPU page holds (" + std::to_string(kMaxPageVertices) + ")");
    }
    auto page = std::make_unique<Page>();
    page->vertices.allocate(vertexCapacity * kVertexBytes, nullptr, gl::BufferUsage::Dynamic);
    page->slots.allocate(vertexCapacity * kSlotBytes, nullptr, gl::BufferUsage::Dynamic);
    page->indices.allocate(indexCapacity * kIndexBytes, nullptr, gl::BufferUsage::Dynamic);
    page->array.setFloatAttribute(0, page->vertices, 3, kVertexBytes, offsetof(Vertex, position));
    page->array.setFloatAttribute(1, page->vertices, 3, kVertexBytes, offsetof(Vertex, normal));
    page->array.setUintAttribute(2, page->slots);
    page->array.setIndexBuffer(page->indices);
    page->vertexSpace = RangeAllocator(vertexCapacity);
    page->indexSpace = RangeAllocator(indexCapacity);
    for (std::size_t i = 0; i < pages_.size(); ++i) {
        if (!pages_[i]) {
            pages_[i] = std::move(page);
            return static_cast<int>(i);
        }
    }
    pages_.push_back(std::move(page));
    return static_cast<int>(pages_.size() - 1);
}

// First page (first fit) with room for both ranges; -1 if none.
int SurfaceArena::findSpace(std::size_t vertices, std::size_t indices, std::size_t& firstVertex,
                            std::size_t& firstIndex) {
    for (std::size_t i = 0; i < pages_.size(); ++i) {
        Page* page = pages_[i].get();
        if (page == nullptr || page->vertexSpace.largestFree() < vertices || page->indexSpace.largestFree() < indices) {
            continue;
        }
        firstVertex = *page->vertexSpace.allocate(vertices);
        firstIndex = *page->indexSpace.allocate(indices);
        return static_cast<int>(i);
    }
    return -1;
}

void SurfaceArena::prepare(std::size_t vertices, std::size_t indices) {
    for (const auto& page : pages_) {
        if (page && page->vertexSpace.largestFree() >= vertices && page->indexSpace.largestFree() >= indices) return;
    }
    makePage(vertices, indices);
}

void SurfaceArena::trim() {
    for (auto& page : pages_) {
        if (page && page->surfaces == 0) page.reset();
    }
    while (!pages_.empty() && !pages_.back()) pages_.pop_back();
}

// Copies the slot's contents GPU-side into the new ranges (already allocated)
// and frees the old ones.
void SurfaceArena::moveTo(Slot& slot, int pageIndex, std::size_t firstVertex, std::size_t firstIndex,
                          std::size_t vertexCapacity, std::size_t indexCapacity) {
    SlotPlace& place = slot.place;
    Page& to = *pages_[static_cast<std::size_t>(pageIndex)];
    if (place.page >= 0) {
        Page& from = *pages_[static_cast<std::size_t>(place.page)];
        to.vertices.copyFrom(from.vertices, place.firstVertex * kVertexBytes, firstVertex * kVertexBytes,
                             place.vertexCount * kVertexBytes);
        to.slots.copyFrom(from.slots, place.firstVertex * kSlotBytes, firstVertex * kSlotBytes,
                          place.vertexCount * kSlotBytes);
        to.indices.copyFrom(from.indices, place.firstIndex * kIndexBytes, firstIndex * kIndexBytes,
                            place.indexCount * kIndexBytes);
        from.vertexSpace.release(place.firstVertex, place.vertexCapacity);
        from.indexSpace.release(place.firstIndex, place.indexCapacity);
        --from.surfaces;
        if (place.vertexCount + place.indexCount > 0) {
            ++moves_;
            movedBytes_ += place.vertexCount * (kVertexBytes + kSlotBytes) + place.indexCount * kIndexBytes;
        }
    }
    ++to.surfaces;
    place.page = pageIndex;
    place.firstVertex = firstVertex;
    place.firstIndex = firstIndex;
    place.vertexCapacity = vertexCapacity;
    place.indexCapacity = indexCapacity;
}

// Grows the slot's ranges where they lie: to the wanted capacity, or as far as
// the free space right after each goes, as long as that holds what is needed.
bool SurfaceArena::growInPlace(Slot& slot, std::size_t vertices, std::size_t indices, std::size_t wantVertices,
                               std::size_t wantIndices) {
    SlotPlace& place = slot.place;
    if (place.page < 0) return false;
    Page& page = *pages_[static_cast<std::size_t>(place.page)];
    const std::size_t vertexRoom =
        place.vertexCapacity + page.vertexSpace.freeAt(place.firstVertex + place.vertexCapacity);
    const std::size_t indexRoom = place.indexCapacity + page.indexSpace.freeAt(place.firstIndex + place.indexCapacity);
    if (vertexRoom < vertices || indexRoom < indices) return false;
    const std::size_t newVertices = std::max(place.vertexCapacity, std::min(wantVertices, vertexRoom));
    const std::size_t newIndices = std::max(place.indexCapacity, std::min(wantIndices, indexRoom));
    page.vertexSpace.tryGrow(place.firstVertex, place.vertexCapacity, newVertices);
    page.indexSpace.tryGrow(place.firstIndex, place.indexCapacity, newIndices);
    place.vertexCapacity = newVertices;
    place.indexCapacity = newIndices;
    return true;
}

// Capacity for at least `vertices` and `indices`, ideally the wanted amounts: in
// place if the space after the ranges allows, else in a new place (this page or
// another, or a new page), the contents copied GPU-side.
void SurfaceArena::growTo(std::uint32_t index, std::size_t vertices, std::size_t indices, std::size_t wantVertices,
                          std::size_t wantIndices) {
    Slot& slot = slots_[index];
    SlotPlace& place = slot.place;
    // A range is never empty (a mesh of vertices and no indices still gets one index).
    vertices = std::max(vertices, std::size_t(1));
    indices = std::max(indices, std::size_t(1));
    if (vertices <= place.vertexCapacity && indices <= place.indexCapacity && place.page >= 0) return;
    if (growInPlace(slot, vertices, indices, wantVertices, wantIndices)) return;
    wantVertices = std::max({wantVertices, vertices, place.vertexCapacity});
    wantIndices = std::max({wantIndices, indices, place.indexCapacity});
    std::size_t firstVertex = 0, firstIndex = 0;
    int pageIndex = findSpace(wantVertices, wantIndices, firstVertex, firstIndex);
    if (pageIndex < 0) {
        pageIndex = makePage(wantVertices, wantIndices);
        firstVertex = *pages_[static_cast<std::size_t>(pageIndex)]->vertexSpace.allocate(wantVertices);
        firstIndex = *pages_[static_cast<std::size_t>(pageIndex)]->indexSpace.allocate(wantIndices);
    }
    moveTo(slot, pageIndex, firstVertex, firstIndex, wantVertices, wantIndices);
    writeEntry(index);
}

void SurfaceArena::reserve(std::uint32_t index, std::size_t vertices, std::size_t indices) {
    live(index);
    if (vertices > 0 || indices > 0) growTo(index, vertices, indices, vertices, indices);
}

void SurfaceArena::uploadSlotNumbers(std::uint32_t index, std::size_t first, std::size_t count) {
    const SlotPlace& place = slots_[index].place;
    slotNumbers_.assign(count, index);
    pages_[static_cast<std::size_t>(place.page)]->slots.update((place.firstVertex + first) * kSlotBytes,
                                                               count * kSlotBytes, slotNumbers_.data());
}

void SurfaceArena::append(std::uint32_t index, const Mesh& mesh, const MeshRange& range) {
    Slot& slot = live(index);
    SlotPlace& place = slot.place;
    if (range.firstVertex != place.vertexCount || range.firstIndex != place.indexCount ||
        range.firstVertex + range.vertexCount > mesh.vertices.size() ||
        range.firstIndex + range.indexCount > mesh.indices.size()) {
        throw std::invalid_argument("GpuMesh::append: range starting at vertex " + std::to_string(range.firstVertex) +
                                    ", index " + std::to_string(range.firstIndex) + " does not continue a mesh of " +
                                    std::to_string(place.vertexCount) + " vertices, " +
                                    std::to_string(place.indexCount) + " indices");
    }
    if (range.vertexCount == 0 && range.indexCount == 0) return;
    const std::size_t vertices = place.vertexCount + range.vertexCount, indices = place.indexCount + range.indexCount;
    if (vertices > place.vertexCapacity || indices > place.indexCapacity || place.page < 0) {
        growTo(index, vertices, indices, grownCapacity(place.vertexCount, vertices, kMinGrowVertices),
               grownCapacity(place.indexCount, indices, kMinGrowIndices));
    }
    Page& page = *pages_[static_cast<std::size_t>(place.page)];
    page.vertices.update((place.firstVertex + place.vertexCount) * kVertexBytes, range.vertexCount * kVertexBytes,
                         mesh.vertices.data() + range.firstVertex);
    uploadSlotNumbers(index, place.vertexCount, range.vertexCount);
    page.indices.update((place.firstIndex + place.indexCount) * kIndexBytes, range.indexCount * kIndexBytes,
                        mesh.indices.data() + range.firstIndex);
    place.vertexCount = vertices;
    place.indexCount = indices;
    const std::size_t bytes = range.vertexCount * (kVertexBytes + kSlotBytes) + range.indexCount * kIndexBytes;
    slot.uploaded += bytes;
    uploadedEverywhere += bytes;
}

void SurfaceArena::shrinkToFit(std::uint32_t index) {
    SlotPlace& place = live(index).place;
    if (place.page < 0) return;
    if (place.vertexCount == 0 || place.indexCount == 0) {
        clear(index);
        return;
    }
    Page& page = *pages_[static_cast<std::size_t>(place.page)];
    page.vertexSpace.shrink(place.firstVertex, place.vertexCapacity, place.vertexCount);
    page.indexSpace.shrink(place.firstIndex, place.indexCapacity, place.indexCount);
    place.vertexCapacity = place.vertexCount;
    place.indexCapacity = place.indexCount;
}

void SurfaceArena::setLook(std::uint32_t index, const SurfaceLook& look) {
    Slot& slot = live(index);
    const SurfaceLook& old = slot.look;
    if (old.colour == look.colour && old.highlight == look.highlight && old.offset == look.offset &&
        old.growthScale == look.growthScale && old.pickId == look.pickId) {
        return;
    }
    slot.look = look;
    writeEntry(index);
}

void SurfaceArena::writeEntry(std::uint32_t index) {
    const Slot& slot = slots_[index];
    const SurfaceLook& look = slot.look;
    float* entry = table_.data() + std::size_t(index) * kFloatsPerSlot;
    const float values[kFloatsPerSlot] = {look.colour.r,
                                          look.colour.g,
                                          look.colour.b,
                                          look.highlight,
                                          look.offset.x,
                                          look.offset.y,
                                          look.offset.z,
                                          look.growthScale,
                                          static_cast<float>(slot.place.firstVertex),
                                          static_cast<float>(look.pickId),
                                          0.0f,
                                          0.0f};
    std::copy(values, values + kFloatsPerSlot, entry);
    if (dirtyFirst_ == dirtyEnd_) {
        dirtyFirst_ = index;
        dirtyEnd_ = index + 1;
    } else {
        dirtyFirst_ = std::min<std::size_t>(dirtyFirst_, index);
        dirtyEnd_ = std::max<std::size_t>(dirtyEnd_, index + 1);
    }
}

void SurfaceArena::sync() {
    const std::size_t texels = slots_.size() * kTexelsPerSlot;
    if (tableTexture_.texels() < texels) {  // room for twice the slots, the whole table sent
        const std::size_t capacity = std::max<std::size_t>(2 * texels, 64 * kTexelsPerSlot);
        std::vector<float> grown(capacity * 4, 0.0f);
        std::copy(table_.begin(), table_.end(), grown.begin());
        const std::size_t most = gl::TextureBuffer::maxTexels() / kTexelsPerSlot * kTexelsPerSlot;
        tableTexture_.allocate(std::max(texels, std::min(capacity, most)), grown.data());
        uploadedEverywhere += tableTexture_.texels() * gl::TextureBuffer::kTexelBytes;
    } else if (dirtyFirst_ < dirtyEnd_) {
        const std::size_t first = dirtyFirst_ * kTexelsPerSlot, count = (dirtyEnd_ - dirtyFirst_) * kTexelsPerSlot;
        tableTexture_.update(first, count, table_.data() + first * 4);
        uploadedEverywhere += count * gl::TextureBuffer::kTexelBytes;
    }
    dirtyFirst_ = dirtyEnd_ = 0;
}

ArenaStats SurfaceArena::stats() const {
    ArenaStats stats;
    std::size_t largestPerPage = 0;
    for (const auto& page : pages_) {
        if (!page) continue;
        ++stats.pages;
        const RangeAllocator &v = page->vertexSpace, &i = page->indexSpace;
        stats.capacityBytes += v.capacity() * (kVertexBytes + kSlotBytes) + i.capacity() * kIndexBytes;
        stats.freeBytes += v.freeSize() * (kVertexBytes + kSlotBytes) + i.freeSize() * kIndexBytes;
        const std::size_t vertexFree = v.largestFree() * (kVertexBytes + kSlotBytes);
        const std::size_t indexFree = i.largestFree() * kIndexBytes;
        stats.largestFreeBytes = std::max({stats.largestFreeBytes, vertexFree, indexFree});
        largestPerPage += vertexFree + indexFree;
    }
    for (const Slot& slot : slots_) {
        if (!slot.live) continue;
        const SlotPlace& p = slot.place;
        stats.usedBytes += p.vertexCount * (kVertexBytes + kSlotBytes) + p.indexCount * kIndexBytes;
    }
    stats.reservedBytes = stats.capacityBytes - stats.freeBytes;
    if (stats.freeBytes > 0) {
        stats.fragmentation = 1.0 - static_cast<double>(largestPerPage) / static_cast<double>(stats.freeBytes);
    }
    stats.moves = moves_;
    stats.movedBytes = movedBytes_;
    return stats;
}

}  // namespace isotrack::render
