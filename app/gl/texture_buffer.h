#pragma once
// A buffer texture: a Buffer read by shaders through texelFetch on a
// samplerBuffer, four 32-bit floats per texel (GL_RGBA32F). Core since GL 3.1;
// GL 3.3 guarantees only 65,536 texels (maxTexels() says what this one allows).
#include <cstddef>

#include "gl/buffer.h"
#include "gl/handle.h"

namespace isotrack::gl {

namespace detail {
void destroyTexture(unsigned id);
}

class TextureBuffer {
public:
    TextureBuffer();  // empty; needs a current context
    TextureBuffer(TextureBuffer&&) noexcept = default;
    TextureBuffer& operator=(TextureBuffer&&) noexcept = default;
    TextureBuffer(const TextureBuffer&) = delete;
    TextureBuffer& operator=(const TextureBuffer&) = delete;
    ~TextureBuffer() = default;

    // New storage of `texels` texels, initialised from `data` (4 floats a texel)
    // if not null. Throws Error past maxTexels().
    void allocate(std::size_t texels, const float* data);
    // Overwrites texels [first, first + count).
    void update(std::size_t first, std::size_t count, const float* data);
    std::size_t texels() const { return buffer_.size() / kTexelBytes; }
    // Binds the texture to texture unit `unit` for the next draws.
    void bind(int unit) const;

    static std::size_t maxTexels();  // GL_MAX_TEXTURE_BUFFER_SIZE
    static constexpr std::size_t kTexelBytes = 4 * sizeof(float);

private:
    Buffer buffer_;
    UniqueHandle<detail::destroyTexture> handle_;
};

}  // namespace isotrack::gl
