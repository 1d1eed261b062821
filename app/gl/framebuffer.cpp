#include "gl/framebuffer.h"

#include <glad/gl.h>

#include <string>

#include "gl/check.h"
#include "gl/make_handle.h"

namespace isotrack::gl {

void detail::destroyTexture(unsigned id) { glDeleteTextures(1, &id); }
void detail::destroyRenderbuffer(unsigned id) { glDeleteRenderbuffers(1, &id); }
void detail::destroyFramebuffer(unsigned id) { glDeleteFramebuffers(1, &id); }

namespace {

GLenum internalFormat(PixelFormat format) {
    switch (format) {
        case PixelFormat::Rgba8: return GL_RGBA8;
        case PixelFormat::R32UI: return GL_R32UI;
        case PixelFormat::Depth24Stencil8: return GL_DEPTH24_STENCIL8;
    }
    return GL_RGBA8;
}

// The client-side layout glTexImage2D wants even when no data is passed.
void transferFormat(PixelFormat format, GLenum& layout, GLenum& type) {
    switch (format) {
        case PixelFormat::Rgba8: layout = GL_RGBA, type = GL_UNSIGNED_BYTE; return;
        case PixelFormat::R32UI: layout = GL_RED_INTEGER, type = GL_UNSIGNED_INT; return;
        case PixelFormat::Depth24Stencil8: layout = GL_DEPTH_STENCIL, type = GL_UNSIGNED_INT_24_8; return;
    }
}

void checkSize(const char* what, int width, int height) {
    GLint limit = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &limit);
    if (width < 1 || height < 1 || width > limit || height > limit) {
        throw Error(std::string(what) + ": size " + std::to_string(width) + "x" + std::to_string(height) +
                    " is outside 1.." + std::to_string(limit));
    }
}

GLuint createTexture(int width, int height, PixelFormat format) {
    checkSize("gl::Texture", width, height);
    const GLuint id = makeHandle(glGenTextures, "glGenTextures", "texture");
    GLenum layout = GL_RGBA, type = GL_UNSIGNED_BYTE;
    transferFormat(format, layout, type);
    ISOTRACK_GL_CALL(glBindTexture(GL_TEXTURE_2D, id));
    ISOTRACK_GL_CALL(glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(internalFormat(format)), width, height, 0,
                                  layout, type, nullptr));
    ISOTRACK_GL_CALL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST));
    ISOTRACK_GL_CALL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST));
    ISOTRACK_GL_CALL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0));
    ISOTRACK_GL_CALL(glBindTexture(GL_TEXTURE_2D, 0));
    return id;
}

GLuint createRenderbuffer(int width, int height, PixelFormat format) {
    checkSize("gl::Renderbuffer", width, height);
    const GLuint id = makeHandle(glGenRenderbuffers, "glGenRenderbuffers", "renderbuffer");
    ISOTRACK_GL_CALL(glBindRenderbuffer(GL_RENDERBUFFER, id));
    ISOTRACK_GL_CALL(glRenderbufferStorage(GL_RENDERBUFFER, internalFormat(format), width, height));
    ISOTRACK_GL_CALL(glBindRenderbuffer(GL_RENDERBUFFER, 0));
    return id;
}

const char* statusName(GLenum status) {
    switch (status) {
        case GL_FRAMEBUFFER_UNDEFINED: return "GL_FRAMEBUFFER_UNDEFINED";
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
        case GL_FRAMEBUFFER_UNSUPPORTED: return "GL_FRAMEBUFFER_UNSUPPORTED";
        case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
        default: return "an unknown framebuffer status";
    }
}

}  // namespace

Texture::Texture(int width, int height, PixelFormat format) : handle_(createTexture(width, height, format)) {}

Renderbuffer::Renderbuffer(int width, int height, PixelFormat format)
    : handle_(createRenderbuffer(width, height, format)) {}

Framebuffer::Framebuffer() : handle_(makeHandle(glGenFramebuffers, "glGenFramebuffers", "framebuffer")) {}

void Framebuffer::attachColour(const Renderbuffer& buffer) {
    bind();
    ISOTRACK_GL_CALL(glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, buffer.id()));
}

void Framebuffer::attachColour(const Texture& texture) {
    bind();
    ISOTRACK_GL_CALL(glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture.id(), 0));
}

void Framebuffer::attachDepthStencil(const Renderbuffer& buffer) {
    bind();
    ISOTRACK_GL_CALL(
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, buffer.id()));
}

void Framebuffer::checkComplete() const {
    bind();
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) throw Error(std::string("framebuffer is incomplete: ") + statusName(status));
}

void Framebuffer::bind() const { ISOTRACK_GL_CALL(glBindFramebuffer(GL_FRAMEBUFFER, handle_.id())); }

void Framebuffer::bindDefault() { ISOTRACK_GL_CALL(glBindFramebuffer(GL_FRAMEBUFFER, 0)); }

std::vector<std::uint8_t> Framebuffer::readRgba(int width, int height) const {
    std::vector<std::uint8_t> pixels(std::size_t(width) * std::size_t(height) * 4);
    ISOTRACK_GL_CALL(glBindFramebuffer(GL_READ_FRAMEBUFFER, handle_.id()));
    ISOTRACK_GL_CALL(glReadBuffer(GL_COLOR_ATTACHMENT0));
    ISOTRACK_GL_CALL(glPixelStorei(GL_PACK_ALIGNMENT, 1));
    ISOTRACK_GL_CALL(glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data()));
    return pixels;
}

void Framebuffer::clearIdAndDepth(std::uint32_t value) const {
    bind();
    const GLuint id[4] = {value, 0, 0, 0};
    ISOTRACK_GL_CALL(glClearBufferuiv(GL_COLOR, 0, id));
    ISOTRACK_GL_CALL(glClearBufferfi(GL_DEPTH_STENCIL, 0, 1.0f, 0));
}

std::uint32_t Framebuffer::readUint(int x, int y) const {
    GLuint value = 0;
    ISOTRACK_GL_CALL(glBindFramebuffer(GL_READ_FRAMEBUFFER, handle_.id()));
    ISOTRACK_GL_CALL(glReadBuffer(GL_COLOR_ATTACHMENT0));
    ISOTRACK_GL_CALL(glPixelStorei(GL_PACK_ALIGNMENT, 1));
    ISOTRACK_GL_CALL(glReadPixels(x, y, 1, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, &value));
    return value;
}

float Framebuffer::readDepth(int x, int y) const {
    GLfloat depth = 1.0f;
    ISOTRACK_GL_CALL(glBindFramebuffer(GL_READ_FRAMEBUFFER, handle_.id()));
    ISOTRACK_GL_CALL(glPixelStorei(GL_PACK_ALIGNMENT, 1));
    ISOTRACK_GL_CALL(glReadPixels(x, y, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth));
    return depth;
}

void Framebuffer::blitColourToDefault(int width, int height, int x, int y) const {
    ISOTRACK_GL_CALL(glBindFramebuffer(GL_READ_FRAMEBUFFER, handle_.id()));
    ISOTRACK_GL_CALL(glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0));
    ISOTRACK_GL_CALL(
        glBlitFramebuffer(0, 0, width, height, x, y, x + width, y + height, GL_COLOR_BUFFER_BIT, GL_NEAREST));
    ISOTRACK_GL_CALL(glBindFramebuffer(GL_FRAMEBUFFER, 0));
}

std::vector<std::uint8_t> Framebuffer::readDefaultRgba(int width, int height) {
    std::vector<std::uint8_t> pixels(std::size_t(width) * std::size_t(height) * 4);
    ISOTRACK_GL_CALL(glBindFramebuffer(GL_READ_FRAMEBUFFER, 0));
    ISOTRACK_GL_CALL(glReadBuffer(GL_BACK));
    ISOTRACK_GL_CALL(glPixelStorei(GL_PACK_ALIGNMENT, 1));
    ISOTRACK_GL_CALL(glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data()));
    return pixels;
}

}  // namespace isotrack::gl
