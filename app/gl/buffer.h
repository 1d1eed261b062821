#pragma once
// A GL buffer object: vertex or index data in GPU memory.
//
// Data goes in and out through the copy-read/copy-write binding points, never
// GL_ELEMENT_ARRAY_BUFFER, because that binding belongs to whichever vertex
// array is bound: uploading an index buffer must not rewire some mesh's VAO.
#include <cstddef>

#include "gl/handle.h"

namespace isotrack::gl {

namespace detail {
void destroyBuffer(unsigned id);
}

enum class BufferUsage { Static, Dynamic };

class Buffer {
public:
    Buffer();  // a new, empty buffer object; needs a current context
    Buffer(Buffer&& other) noexcept;
    Buffer& operator=(Buffer&& other) noexcept;
    Buffer(const Buffer&) = delete;
    Buffer& operator=(const Buffer&) = delete;
    ~Buffer() = default;

    // Replaces the storage with `bytes` bytes, initialised from `data` if not null.
    void allocate(std::size_t bytes, const void* data, BufferUsage usage);
    // Overwrites [offset, offset + bytes) of the existing storage.
    void update(std::size_t offset, std::size_t bytes, const void* data);
    // GPU-side copy from another buffer, no round trip through the CPU.
    void copyFrom(const Buffer& source, std::size_t sourceOffset, std::size_t offset, std::size_t bytes);
    // Reads back [offset, offset + bytes); for tests and debugging.
    void read(std::size_t offset, std::size_t bytes, void* out) const;

    unsigned id() const { return handle_.id(); }
    std::size_t size() const { return size_; }

private:
    UniqueHandle<detail::destroyBuffer> handle_;
    std::size_t size_ = 0;
};

}  // namespace isotrack::gl
