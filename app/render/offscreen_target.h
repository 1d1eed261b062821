#pragma once
// A single-sampled colour + depth framebuffer of a fixed size, for screenshots
// and tests (no multisampling, so pixels are reproducible).
#include <cstddef>

#include "gl/colour_depth_target.h"
#include "render/image.h"

namespace isotrack::render {

class OffscreenTarget {
public:
    OffscreenTarget(int width, int height);  // needs a current context

    void bind() const { target_.framebuffer().bind(); }
    // The pixels, top row first.
    Image read() const;
    // Copies the colour into the default framebuffer with its bottom-left
    // corner at (x, y), and binds the default framebuffer.
    void blitToDefault(int x, int y) const { target_.framebuffer().blitColourToDefault(width(), height(), x, y); }
    // Colour and depth/stencil, 4 bytes each per pixel.
    std::size_t bytes() const { return target_.bytes(); }

    int width() const { return target_.width(); }
    int height() const { return target_.height(); }

private:
    gl::ColourDepthTarget target_;
};

}  // namespace isotrack::render
