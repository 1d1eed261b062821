#pragma once
// A single-sampled colour + depth framebuffer of a fixed size, for screenshots
// and tests (no multisampling, so pixels are reproducible).
#include "gl/framebuffer.h"
#include "render/image.h"

namespace isotrack::render {

class OffscreenTarget {
public:
    OffscreenTarget(int width, int height);  // needs a current context

    void bind() const { framebuffer_.bind(); }
    // The pixels, top row first.
    Image read() const;

    int width() const { return width_; }
    int height() const { return height_; }

private:
    int width_, height_;
    gl::Renderbuffer colour_, depth_;
    gl::Framebuffer framebuffer_;
};

}  // namespace isotrack::render
