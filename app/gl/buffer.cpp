#include "gl/buffer.h"

#include <glad/gl.h>

#include <stdexcept>
#include <string>

#include "gl/check.h"
#include "gl/make_handle.h"

namespace isotrack::gl {

void detail::destroyBuffer(unsigned id) { glDeleteBuffers(1, &id); }

namespace {

void checkRange(const char* what, std::size_t offset, std::size_t bytes, std::size_t size) {
    if (offset > size || bytes > size - offset) {
        throw std::out_of_range(std::string("gl::Buffer::") + what + ": range [" + std::to_string(offset) + ", " +
                                std::to_string(offset + bytes) + ") outside a buffer of " + std::to_string(size) +
                                " bytes");
    }
}

}  // namespace

Buffer::Buffer() : handle_(makeHandle(glGenBuffers, "glGenBuffers", "buffer")) {}

Buffer::Buffer(Buffer&& other) noexcept : handle_(std::move(other.handle_)), size_(std::exchange(other.size_, 0)) {}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    handle_ = std::move(other.handle_);
    size_ = std::exchange(other.size_, 0);
    return *this;
}

void Buffer::allocate(std::size_t bytes, const void* data, BufferUsage usage) {
    ISOTRACK_GL_CALL(glBindBuffer(GL_COPY_WRITE_BUFFER, handle_.id()));
    ISOTRACK_GL_CALL(glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(bytes), data,
                                  usage == BufferUsage::Static ? GL_STATIC_DRAW : GL_DYNAMIC_DRAW));
    size_ = bytes;
}

void Buffer::update(std::size_t offset, std::size_t bytes, const void* data) {
    checkRange("update", offset, bytes, size_);
    if (bytes == 0) return;
    ISOTRACK_GL_CALL(glBindBuffer(GL_COPY_WRITE_BUFFER, handle_.id()));
    ISOTRACK_GL_CALL(
        glBufferSubData(GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), data));
}

void Buffer::copyFrom(const Buffer& source, std::size_t sourceOffset, std::size_t offset, std::size_t bytes) {
    checkRange("copyFrom (source)", sourceOffset, bytes, source.size_);
    checkRange("copyFrom", offset, bytes, size_);
    if (bytes == 0) return;
    ISOTRACK_GL_CALL(glBindBuffer(GL_COPY_READ_BUFFER, source.id()));
    ISOTRACK_GL_CALL(glBindBuffer(GL_COPY_WRITE_BUFFER, handle_.id()));
    ISOTRACK_GL_CALL(glCopyBufferSubData(GL_COPY_READ_BUFFER, GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(sourceOffset),
                                         static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes)));
}

void Buffer::read(std::size_t offset, std::size_t bytes, void* out) const {
    checkRange("read", offset, bytes, size_);
    if (bytes == 0) return;
    ISOTRACK_GL_CALL(glBindBuffer(GL_COPY_READ_BUFFER, handle_.id()));
    ISOTRACK_GL_CALL(
        glGetBufferSubData(GL_COPY_READ_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(bytes), out));
}

}  // namespace isotrack::gl
