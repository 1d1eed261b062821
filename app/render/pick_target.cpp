#include "render/pick_target.h"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/vec4.hpp>

namespace isotrack::render {

PickTarget::PickTarget(int width, int height)
    : target_(width, height, gl::PixelFormat::R32UI, gl::ColourStorage::Texture) {
    gl::Framebuffer::bindDefault();
}

void PickTarget::bindAndClear() const { target_.framebuffer().clearIdAndDepth(0); }

void PickTarget::unbind() { gl::Framebuffer::bindDefault(); }

std::uint32_t PickTarget::idAt(int x, int y) const {
    if (x < 0 || y < 0 || x >= width() || y >= height()) return 0;
    return target_.framebuffer().readUint(x, height() - 1 - y);
}

float PickTarget::depthAt(int x, int y) const {
    if (x < 0 || y < 0 || x >= width() || y >= height()) return 1.0f;
    return target_.framebuffer().readDepth(x, height() - 1 - y);
}

glm::vec3 unproject(const FrameView& frame, float x, float y, float depth) {
    const glm::vec4 ndc{2.0f * x / static_cast<float>(frame.width) - 1.0f,
                        1.0f - 2.0f * y / static_cast<float>(frame.height), 2.0f * depth - 1.0f, 1.0f};
    const glm::vec4 world = glm::inverse(frame.viewProjection()) * ndc;
    return glm::vec3(world) / world.w;
}

void pixelRay(const FrameView& frame, float x, float y, glm::vec3& origin, glm::vec3& direction) {
    origin = unproject(frame, x, y, 0.0f);
    direction = glm::normalize(unproject(frame, x, y, 1.0f) - origin);
}

}  // namespace isotrack::render
