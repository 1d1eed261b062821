#include "gl/texture_buffer.h"

#include <glad/gl.h>

#include <string>

#include "gl/check.h"
#include "gl/make_handle.h"

namespace isotrack::gl {

TextureBuffer::TextureBuffer() : handle_(makeHandle(glGenTextures, "glGenTextures", "texture")) {}

std::size_t TextureBuffer::maxTexels() {
    GLint texels = 0;
    ISOTRACK_GL_CALL(glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &texels));
    return static_cast<std::size_t>(texels);
}

void TextureBuffer::allocate(std::size_t texels, const float* data) {
    const std::size_t most = maxTexels();
    if (texels > most) {
        throw Error("a texture buffer of " + std::to_string(texels) + " texels is more than this GL allows (" +
                    std::to_string(most) + ", GL_MAX_TEXTURE_BUFFER_SIZE)");
    }
    buffer_.allocate(texels * kTexelBytes, data, BufferUsage::Dynamic);
    ISOTRACK_GL_CALL(glBindTexture(GL_TEXTURE_BUFFER, handle_.id()));
    ISOTRACK_GL_CALL(glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32F, buffer_.id()));
    ISOTRACK_GL_CALL(glBindTexture(GL_TEXTURE_BUFFER, 0));
}

void TextureBuffer::update(std::size_t first, std::size_t count, const float* data) {
    buffer_.update(first * kTexelBytes, count * kTexelBytes, data);
}

void TextureBuffer::bind(int unit) const {
    ISOTRACK_GL_CALL(glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit)));
    ISOTRACK_GL_CALL(glBindTexture(GL_TEXTURE_BUFFER, handle_.id()));
    ISOTRACK_GL_CALL(glActiveTexture(GL_TEXTURE0));
}

}  // namespace isotrack::gl
