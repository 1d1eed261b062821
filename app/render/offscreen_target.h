#pragma once
// A single-sampled colour + depth framebuffer of a fixed size, for screenshots
// and tests (no multisampling, so pixels are reproducible).
#include <cstddef>

#include "gl/framebuffer.h"
#include "render/image.h"

namespace isotrack::render {

class OffscreenTarget {
public:
    OffscreenTarget(int width, int height);  // needs a current context

    void bind() const { framebuffer_.bind(); }
    // The pixels, top row first.
    Image read() const;
    // Copies the colour into the default framebuffer with its bottom-left
    // corner at (x, y), and binds the default framebuffer.
    void blitToDefault(int x, int y) const { framebuffer_.blitColourToDefault(width_, height_, x, y); }
    // Colour and depth/stencil, 4 bytes each per pixel.
    std::size_t bytes() const { return std::size_t(width_) * std::size_t(height_) * 8; }

    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_, height_;
    gl::Renderbuffer colour_, depth_;
    gl::Framebuffer framebuffer_;
};

}  // namespace isotrack::render
