#include "gl/vertex_array.h"

#include <glad/gl.h>

#include <cstdint>
#include <vector>

#include "gl/buffer.h"
#include "gl/check.h"
#include "gl/make_handle.h"

namespace isotrack::gl {

void detail::destroyVertexArray(unsigned id) { glDeleteVertexArrays(1, &id); }

VertexArray::VertexArray() : handle_(makeHandle(glGenVertexArrays, "glGenVertexArrays", "vertex array")) {}

void VertexArray::setFloatAttribute(unsigned location, const Buffer& buffer, int components, std::size_t stride,
                                    std::size_t offset) {
    ISOTRACK_GL_CALL(glBindVertexArray(handle_.id()));
    ISOTRACK_GL_CALL(glBindBuffer(GL_ARRAY_BUFFER, buffer.id()));
    ISOTRACK_GL_CALL(glEnableVertexAttribArray(location));
    ISOTRACK_GL_CALL(glVertexAttribPointer(location, components, GL_FLOAT, GL_FALSE, static_cast<GLsizei>(stride),
                                           reinterpret_cast<const void*>(static_cast<std::uintptr_t>(offset))));
    ISOTRACK_GL_CALL(glBindVertexArray(0));
}

void VertexArray::setUintAttribute(unsigned location, const Buffer& buffer) {
    ISOTRACK_GL_CALL(glBindVertexArray(handle_.id()));
    ISOTRACK_GL_CALL(glBindBuffer(GL_ARRAY_BUFFER, buffer.id()));
    ISOTRACK_GL_CALL(glEnableVertexAttribArray(location));
    ISOTRACK_GL_CALL(glVertexAttribIPointer(location, 1, GL_UNSIGNED_INT, sizeof(std::uint32_t), nullptr));
    ISOTRACK_GL_CALL(glBindVertexArray(0));
}

void VertexArray::setIndexBuffer(const Buffer& buffer) {
    ISOTRACK_GL_CALL(glBindVertexArray(handle_.id()));
    ISOTRACK_GL_CALL(glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer.id()));
    ISOTRACK_GL_CALL(glBindVertexArray(0));
}

void VertexArray::drawTriangles(std::size_t indexCount) const {
    if (indexCount == 0) return;
    ISOTRACK_GL_CALL(glBindVertexArray(handle_.id()));
    ISOTRACK_GL_CALL(glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(indexCount), GL_UNSIGNED_INT, nullptr));
}

void VertexArray::drawLines(std::size_t vertexCount) const {
    if (vertexCount == 0) return;
    ISOTRACK_GL_CALL(glBindVertexArray(handle_.id()));
    ISOTRACK_GL_CALL(glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(vertexCount)));
}

void VertexArray::multiDrawTriangles(std::size_t draws, const int* counts, const std::size_t* firstIndices,
                                     const int* baseVertices) const {
    if (draws == 0) return;
    std::vector<const void*> offsets(draws);
    for (std::size_t i = 0; i < draws; ++i) {
        offsets[i] =
            reinterpret_cast<const void*>(static_cast<std::uintptr_t>(firstIndices[i] * sizeof(std::uint32_t)));
    }
    ISOTRACK_GL_CALL(glBindVertexArray(handle_.id()));
    ISOTRACK_GL_CALL(glMultiDrawElementsBaseVertex(GL_TRIANGLES, counts, GL_UNSIGNED_INT, offsets.data(),
                                                   static_cast<GLsizei>(draws), baseVertices));
}

}  // namespace isotrack::gl
