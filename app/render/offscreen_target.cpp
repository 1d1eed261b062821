#include "render/offscreen_target.h"

namespace isotrack::render {

OffscreenTarget::OffscreenTarget(int width, int height)
    : width_(width),
      height_(height),
      colour_(width, height, gl::PixelFormat::Rgba8),
      depth_(width, height, gl::PixelFormat::Depth24Stencil8) {
    framebuffer_.attachColour(colour_);
    framebuffer_.attachDepthStencil(depth_);
    framebuffer_.checkComplete();
}

Image OffscreenTarget::read() const {
    return imageFromBottomUp(width_, height_, framebuffer_.readRgba(width_, height_));
}

}  // namespace isotrack::render
