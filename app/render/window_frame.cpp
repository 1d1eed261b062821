#include "render/window_frame.h"

#include <glm/vec4.hpp>

#include "gl/framebuffer.h"
#include "gl/state.h"

namespace isotrack::render {

void beginWindowFrame(int width, int height, const glm::vec3& background) {
    gl::Framebuffer::bindDefault();
    gl::setViewport(0, 0, width, height);
    gl::clear(glm::vec4(background, 1.0f));
}

Image readWindowImage(int width, int height) {
    return imageFromBottomUp(width, height, gl::Framebuffer::readDefaultRgba(width, height));
}

}  // namespace isotrack::render
