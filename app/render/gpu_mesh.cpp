#include "render/gpu_mesh.h"

#include <algorithm>
#include <utility>

namespace isotrack::render {

GpuMesh::GpuMesh(SurfaceArena& arena) : arena_(&arena), slot_(arena.create()) {}

GpuMesh::GpuMesh(SurfaceArena& arena, const Mesh& mesh) : GpuMesh(arena) {
    arena.reserve(slot_, mesh.vertices.size(), mesh.indices.size());
    appendNew(mesh);
}

GpuMesh::GpuMesh(GpuMesh&& other) noexcept
    : arena_(std::exchange(other.arena_, nullptr)), slot_(std::exchange(other.slot_, 0u)) {}

GpuMesh& GpuMesh::operator=(GpuMesh&& other) noexcept {
    if (this != &other) {
        if (arena_ != nullptr) arena_->release(slot_);
        arena_ = std::exchange(other.arena_, nullptr);
        slot_ = std::exchange(other.slot_, 0u);
    }
    return *this;
}

GpuMesh::~GpuMesh() {
    if (arena_ != nullptr) arena_->release(slot_);
}

void GpuMesh::append(const Mesh& mesh, const MeshRange& range) { arena_->append(slot_, mesh, range); }

void GpuMesh::append(const Mesh& mesh, const SurfaceTracker::Step& step) {
    append(mesh, MeshRange{step.firstVertex, step.vertexCount, step.firstIndex, step.indexCount});
}

void GpuMesh::appendNew(const Mesh& mesh) {
    const std::size_t vertices = vertexCount(), indices = indexCount();
    append(mesh, MeshRange{vertices, mesh.vertices.size() - std::min(vertices, mesh.vertices.size()), indices,
                           mesh.indices.size() - std::min(indices, mesh.indices.size())});
}

void GpuMesh::shrinkToFit() { arena_->shrinkToFit(slot_); }

void GpuMesh::clear() { arena_->clear(slot_); }

GpuMeshBytes GpuMesh::bytes() const {
    const SlotPlace& p = place();
    return {p.vertexCount * sizeof(Vertex), p.indexCount * sizeof(std::uint32_t),
            p.vertexCapacity * (sizeof(Vertex) + sizeof(std::uint32_t)) + p.indexCapacity * sizeof(std::uint32_t)};
}

std::vector<Vertex> GpuMesh::readVertices() const {
    const SlotPlace& p = place();
    std::vector<Vertex> vertices(p.vertexCount);
    if (p.page >= 0)
        arena_->page(p.page)->vertices.read(p.firstVertex * sizeof(Vertex), p.vertexCount * sizeof(Vertex),
                                            vertices.data());
    return vertices;
}

std::vector<std::uint32_t> GpuMesh::readIndices() const {
    const SlotPlace& p = place();
    std::vector<std::uint32_t> indices(p.indexCount);
    if (p.page >= 0) arena_->page(p.page)->indices.read(p.firstIndex * 4, p.indexCount * 4, indices.data());
    return indices;
}

std::vector<std::uint32_t> GpuMesh::readSlotNumbers() const {
    const SlotPlace& p = place();
    std::vector<std::uint32_t> slots(p.vertexCount);
    if (p.page >= 0) arena_->page(p.page)->slots.read(p.firstVertex * 4, p.vertexCount * 4, slots.data());
    return slots;
}

}  // namespace isotrack::render
