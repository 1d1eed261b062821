#pragma once
// The id buffer for picking: an R32UI colour texture holding, per pixel, the id
// of the surface drawn there (0: nothing), and a depth buffer, the size of the
// 3D view. Drawn on demand (a click), with the same camera as the frame, then
// one pixel of each is read back.
#include <cstddef>
#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

#include "gl/colour_depth_target.h"
#include "render/renderer.h"

namespace isotrack::render {

class PickTarget {
public:
    PickTarget(int width, int height);  // needs a current context

    void bindAndClear() const;  // ids to 0, depth to 1
    static void unbind();       // back to the default framebuffer

    // The id and window depth at pixel (x, y), counted from the top-left as a
    // window's mouse position is.
    std::uint32_t idAt(int x, int y) const;
    float depthAt(int x, int y) const;

    int width() const { return target_.width(); }
    int height() const { return target_.height(); }
    std::size_t bytes() const { return target_.bytes(); }  // ids + depth/stencil

private:
    gl::ColourDepthTarget target_;
};

// The world point seen at pixel (x, y) from the top-left of the frame's
// viewport, at window depth `depth` (0 near .. 1 far).
glm::vec3 unproject(const FrameView& frame, float x, float y, float depth);

// The ray through pixel (x, y) from the top-left: origin on the near plane and
// unit direction.
void pixelRay(const FrameView& frame, float x, float y, glm::vec3& origin, glm::vec3& direction);

}  // namespace isotrack::render
