#pragma once
// Off-screen render targets: textures, renderbuffers and the framebuffer
// objects that bind them together.
#include <cstdint>
#include <vector>

#include "gl/handle.h"

namespace isotrack::gl {

namespace detail {
void destroyTexture(unsigned id);
void destroyRenderbuffer(unsigned id);
void destroyFramebuffer(unsigned id);
}  // namespace detail

enum class PixelFormat {
    Rgba8,            // colour
    R32UI,            // one unsigned integer per pixel, e.g. surface ids for picking
    Depth24Stencil8,  // depth and stencil
};

// A 2D texture with nearest filtering and no mipmaps, for render targets.
class Texture {
public:
    Texture(int width, int height, PixelFormat format);
    Texture(Texture&&) noexcept = default;
    Texture& operator=(Texture&&) noexcept = default;
    Texture(const Texture&) = delete;
    Texture& operator=(const Texture&) = delete;
    ~Texture() = default;

    unsigned id() const { return handle_.id(); }

private:
    UniqueHandle<detail::destroyTexture> handle_;
};

// Single-sampled storage for a render target that is never sampled.
class Renderbuffer {
public:
    Renderbuffer(int width, int height, PixelFormat format);
    Renderbuffer(Renderbuffer&&) noexcept = default;
    Renderbuffer& operator=(Renderbuffer&&) noexcept = default;
    Renderbuffer(const Renderbuffer&) = delete;
    Renderbuffer& operator=(const Renderbuffer&) = delete;
    ~Renderbuffer() = default;

    unsigned id() const { return handle_.id(); }

private:
    UniqueHandle<detail::destroyRenderbuffer> handle_;
};

class Framebuffer {
public:
    Framebuffer();
    Framebuffer(Framebuffer&&) noexcept = default;
    Framebuffer& operator=(Framebuffer&&) noexcept = default;
    Framebuffer(const Framebuffer&) = delete;
    Framebuffer& operator=(const Framebuffer&) = delete;
    ~Framebuffer() = default;

    void attachColour(const Renderbuffer& buffer);
    void attachColour(const Texture& texture);
    void attachDepthStencil(const Renderbuffer& buffer);
    // Throws Error naming the status unless the attachments form a complete target.
    void checkComplete() const;

    // Subsequent draws render into this framebuffer.
    void bind() const;
    // Draws go to the context's own framebuffer again.
    static void bindDefault();

    // The colour attachment's RGBA bytes, bottom row first as GL stores them.
    std::vector<std::uint8_t> readRgba(int width, int height) const;

    // For id buffers (an R32UI colour attachment): glClear is undefined on
    // integer targets, so the colour is cleared to `value` with glClearBuffer,
    // and depth to 1. Binds this framebuffer.
    void clearIdAndDepth(std::uint32_t value) const;
    // One pixel (GL's origin: bottom-left) of the R32UI colour attachment, and
    // of the depth attachment as a window-space depth in [0, 1].
    std::uint32_t readUint(int x, int y) const;
    float readDepth(int x, int y) const;

    // Copies this framebuffer's colour [0, width) x [0, height) into the default
    // framebuffer at (x, y) (GL's bottom-left origin), pixel for pixel; leaves
    // the default framebuffer bound.
    void blitColourToDefault(int width, int height, int x, int y) const;

    // The RGBA bytes of the default framebuffer's back buffer (a window's
    // frame before it is swapped), bottom row first.
    static std::vector<std::uint8_t> readDefaultRgba(int width, int height);

    unsigned id() const { return handle_.id(); }

private:
    UniqueHandle<detail::destroyFramebuffer> handle_;
};

}  // namespace isotrack::gl
