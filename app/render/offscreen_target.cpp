#include "render/offscreen_target.h"

namespace isotrack::render {

OffscreenTarget::OffscreenTarget(int width, int height)
    : target_(width, height, gl::PixelFormat::Rgba8, gl::ColourStorage::Renderbuffer) {}

Image OffscreenTarget::read() const {
    return imageFromBottomUp(width(), height(), target_.framebuffer().readRgba(width(), height()));
}

}  // namespace isotrack::render
