#pragma once
// The window's own framebuffer, for the viewer: cleared before the 3D view's
// cached image and the panel are drawn into it, and read back for screenshots.
#include <glm/vec3.hpp>

#include "render/image.h"

namespace isotrack::render {

// Binds the window's framebuffer, sets the viewport to all of it and clears it.
void beginWindowFrame(int width, int height, const glm::vec3& background);

// What the window's framebuffer holds now, top row first.
Image readWindowImage(int width, int height);

}  // namespace isotrack::render
