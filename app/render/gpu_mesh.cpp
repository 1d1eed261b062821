#include "render/gpu_mesh.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace isotrack::render {
namespace {

constexpr std::size_t kVertexBytes = sizeof(Vertex);
constexpr std::size_t kIndexBytes = sizeof(std::uint32_t);
constexpr std::size_t kMinGrowVertices = 1024;
constexpr std::size_t kMinGrowIndices = 3 * 2048;

static_assert(sizeof(Vertex) == 6 * sizeof(float), "Vertex must be tightly packed position + normal floats");

std::size_t grownCapacity(std::size_t capacity, std::size_t needed, std::size_t minimum) {
    return std::max({needed, 2 * capacity, minimum});
}

// A buffer of `bytes` holding the first `keep` bytes of `old`, copied GPU-side.
gl::Buffer regrow(const gl::Buffer& old, std::size_t bytes, std::size_t keep) {
    gl::Buffer buffer;
    buffer.allocate(bytes, nullptr, gl::BufferUsage::Dynamic);
    buffer.copyFrom(old, 0, 0, keep);
    return buffer;
}

// GL objects live on one thread, so a plain counter will do.
std::size_t uploadedEverywhere = 0;

}  // namespace

std::size_t GpuMesh::uploadedTotal() { return uploadedEverywhere; }

GpuMesh::GpuMesh() { bindAttributes(); }

GpuMesh::GpuMesh(const Mesh& mesh) {
    vertexCount_ = mesh.vertices.size();
    indexCount_ = mesh.indices.size();
    vertices_.allocate(vertexCount_ * kVertexBytes, mesh.vertices.data(), gl::BufferUsage::Static);
    indices_.allocate(indexCount_ * kIndexBytes, mesh.indices.data(), gl::BufferUsage::Static);
    uploadedBytes_ = mesh.drawByteSize();
    uploadedEverywhere += uploadedBytes_;
    bindAttributes();
}

void GpuMesh::bindAttributes() {
    vertexArray_.setFloatAttribute(0, vertices_, 3, kVertexBytes, offsetof(Vertex, position));
    vertexArray_.setFloatAttribute(1, vertices_, 3, kVertexBytes, offsetof(Vertex, normal));
    vertexArray_.setIndexBuffer(indices_);
}

void GpuMesh::reserve(std::size_t vertexCapacity, std::size_t indexCapacity) {
    bool replaced = false;
    if (vertexCapacity * kVertexBytes > vertices_.size()) {
        const std::size_t count = grownCapacity(vertices_.size() / kVertexBytes, vertexCapacity, kMinGrowVertices);
        vertices_ = regrow(vertices_, count * kVertexBytes, vertexCount_ * kVertexBytes);
        replaced = true;
    }
    if (indexCapacity * kIndexBytes > indices_.size()) {
        const std::size_t count = grownCapacity(indices_.size() / kIndexBytes, indexCapacity, kMinGrowIndices);
        indices_ = regrow(indices_, count * kIndexBytes, indexCount_ * kIndexBytes);
        replaced = true;
    }
    if (replaced) bindAttributes();
}

void GpuMesh::append(const Mesh& mesh, const MeshRange& range) {
    if (range.firstVertex != vertexCount_ || range.firstIndex != indexCount_ ||
        range.firstVertex + range.vertexCount > mesh.vertices.size() ||
        range.firstIndex + range.indexCount > mesh.indices.size()) {
        throw std::invalid_argument("GpuMesh::append: range starting at vertex " + std::to_string(range.firstVertex) +
                                    ", index " + std::to_string(range.firstIndex) + " does not continue a mesh of " +
                                    std::to_string(vertexCount_) + " vertices, " + std::to_string(indexCount_) +
                                    " indices");
    }
    reserve(vertexCount_ + range.vertexCount, indexCount_ + range.indexCount);
    vertices_.update(vertexCount_ * kVertexBytes, range.vertexCount * kVertexBytes,
                     mesh.vertices.data() + range.firstVertex);
    indices_.update(indexCount_ * kIndexBytes, range.indexCount * kIndexBytes, mesh.indices.data() + range.firstIndex);
    vertexCount_ += range.vertexCount;
    indexCount_ += range.indexCount;
    uploadedBytes_ += range.vertexCount * kVertexBytes + range.indexCount * kIndexBytes;
    uploadedEverywhere += range.vertexCount * kVertexBytes + range.indexCount * kIndexBytes;
}

void GpuMesh::append(const Mesh& mesh, const SurfaceTracker::Step& step) {
    append(mesh, MeshRange{step.firstVertex, step.vertexCount, step.firstIndex, step.indexCount});
}

void GpuMesh::appendNew(const Mesh& mesh) {
    append(mesh, MeshRange{vertexCount_, mesh.vertices.size() - std::min(vertexCount_, mesh.vertices.size()),
                           indexCount_, mesh.indices.size() - std::min(indexCount_, mesh.indices.size())});
}

void GpuMesh::shrinkToFit() {
    const std::size_t vertexBytes = vertexCount_ * kVertexBytes, indexBytes = indexCount_ * kIndexBytes;
    bool replaced = false;
    if (vertices_.size() > vertexBytes) {
        vertices_ = regrow(vertices_, vertexBytes, vertexBytes);
        replaced = true;
    }
    if (indices_.size() > indexBytes) {
        indices_ = regrow(indices_, indexBytes, indexBytes);
        replaced = true;
    }
    if (replaced) bindAttributes();
}

GpuMeshBytes GpuMesh::bytes() const {
    return {vertexCount_ * kVertexBytes, indexCount_ * kIndexBytes, vertices_.size() + indices_.size()};
}

}  // namespace isotrack::render
