#pragma once
// One surface's mesh on the GPU: vertex and index buffers and the vertex array
// that ties them to the surface shaders.
//
// Built from a core Mesh, never the reverse. A surface that is still being
// tracked grows: append() uploads only the vertices and indices added since the
// last call, into buffers whose capacity doubles when full (the old contents
// move GPU-side, nothing is sent twice). A finished mesh uploaded in one go gets
// buffers of exactly its size.
#include <cstddef>

#include "gl/buffer.h"
#include "gl/vertex_array.h"
#include "isotrack/mesh.h"
#include "isotrack/tracking.h"

namespace isotrack::render {

// Vertices [firstVertex, firstVertex + vertexCount) and indices likewise, as a
// SurfaceTracker::Step reports them.
struct MeshRange {
    std::size_t firstVertex = 0, vertexCount = 0;
    std::size_t firstIndex = 0, indexCount = 0;
};

struct GpuMeshBytes {
    std::size_t vertexBytes = 0;    // in use
    std::size_t indexBytes = 0;     // in use
    std::size_t capacityBytes = 0;  // allocated, both buffers
};

class GpuMesh {
public:
    // An empty mesh, ready to grow. Needs a current GL context, as do all members.
    GpuMesh();
    // The whole of `mesh`, in buffers of exactly its size.
    explicit GpuMesh(const Mesh& mesh);

    // Uploads `range` of `mesh`, which must start where the uploaded data ends
    // (throws std::invalid_argument otherwise: a step was skipped or repeated).
    void append(const Mesh& mesh, const MeshRange& range);
    void append(const Mesh& mesh, const SurfaceTracker::Step& step);
    // Uploads whatever `mesh` holds beyond what is already uploaded.
    void appendNew(const Mesh& mesh);
    // Once a grown mesh is complete: buffers of exactly its size, the contents
    // copied GPU-side (nothing is sent again), the spare capacity freed.
    void shrinkToFit();

    std::size_t vertexCount() const { return vertexCount_; }
    std::size_t indexCount() const { return indexCount_; }
    GpuMeshBytes bytes() const;
    // Bytes sent from the CPU since construction (GPU-side copies excluded).
    std::size_t uploadedBytes() const { return uploadedBytes_; }
    // Bytes every GpuMesh has sent from the CPU since the program started (the
    // viewer takes the difference across a frame).
    static std::size_t uploadedTotal();

    const gl::VertexArray& vertexArray() const { return vertexArray_; }
    // For tests: the buffers themselves.
    const gl::Buffer& vertexBuffer() const { return vertices_; }
    const gl::Buffer& indexBuffer() const { return indices_; }

    void draw() const { vertexArray_.drawTriangles(indexCount_); }

private:
    void reserve(std::size_t vertexCapacity, std::size_t indexCapacity);
    void bindAttributes();

    gl::Buffer vertices_, indices_;
    gl::VertexArray vertexArray_;
    std::size_t vertexCount_ = 0, indexCount_ = 0;
    std::size_t uploadedBytes_ = 0;
};

}  // namespace isotrack::render
