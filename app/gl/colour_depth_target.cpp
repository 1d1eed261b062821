#include "gl/colour_depth_target.h"

namespace isotrack::gl {

ColourDepthTarget::ColourDepthTarget(int width, int height, PixelFormat colour, ColourStorage storage)
    : width_(width), height_(height), depth_(width, height, PixelFormat::Depth24Stencil8) {
    if (storage == ColourStorage::Texture) {
        colourTexture_.emplace(width, height, colour);
        framebuffer_.attachColour(*colourTexture_);
    } else {
        colourBuffer_.emplace(width, height, colour);
        framebuffer_.attachColour(*colourBuffer_);
    }
    framebuffer_.attachDepthStencil(depth_);
    framebuffer_.checkComplete();
}

}  // namespace isotrack::gl
