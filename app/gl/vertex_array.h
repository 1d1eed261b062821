#pragma once
// A vertex array object: which buffers feed which shader inputs, and the index
// buffer. Draw calls go through it, so the caller never binds anything itself.
#include <cstddef>

#include "gl/handle.h"

namespace isotrack::gl {

class Buffer;

namespace detail {
void destroyVertexArray(unsigned id);
}

class VertexArray {
public:
    VertexArray();  // needs a current context
    VertexArray(VertexArray&&) noexcept = default;
    VertexArray& operator=(VertexArray&&) noexcept = default;
    VertexArray(const VertexArray&) = delete;
    VertexArray& operator=(const VertexArray&) = delete;
    ~VertexArray() = default;

    // Shader input `location` reads `components` floats per vertex from `buffer`,
    // starting at byte `offset`, `stride` bytes apart. The VAO remembers the
    // buffer object, so call this again after replacing the buffer.
    void setFloatAttribute(unsigned location, const Buffer& buffer, int components, std::size_t stride,
                           std::size_t offset);
    // Shader input `location` reads one unsigned int per vertex from `buffer`
    // (an integer attribute, `in uint` in GLSL), tightly packed from byte 0.
    void setUintAttribute(unsigned location, const Buffer& buffer);
    // Indices are 32-bit unsigned.
    void setIndexBuffer(const Buffer& buffer);

    void drawTriangles(std::size_t indexCount) const;  // indexed, from index 0
    void drawLines(std::size_t vertexCount) const;     // not indexed, pairs of vertices
    // Triangles of `draws` index ranges in one call (glMultiDrawElementsBaseVertex):
    // range i is counts[i] indices from index firstIndices[i], each index plus
    // baseVertices[i]. Drawn as edges when the polygon mode says lines.
    void multiDrawTriangles(std::size_t draws, const int* counts, const std::size_t* firstIndices,
                            const int* baseVertices) const;

    unsigned id() const { return handle_.id(); }

private:
    UniqueHandle<detail::destroyVertexArray> handle_;
};

}  // namespace isotrack::gl
