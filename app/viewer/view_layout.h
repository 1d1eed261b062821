#pragma once
// Where the 3D view lies in the window: right of the panel, in window pixels
// and in framebuffer pixels (they differ on a high-density display), and the
// frame the scene is drawn and picked with there.
#include "render/camera.h"
#include "render/renderer.h"
#include "viewer/camera_controller.h"
#include "viewer/scene.h"
#include "viewer/window.h"

namespace isotrack::viewer {

class ViewLayout {
public:
    // Reads the window's sizes (once a frame: the window may have been resized).
    void update(const Window& window);

    int windowWidth() const { return windowWidth_; }
    int windowHeight() const { return windowHeight_; }
    int framebufferWidth() const { return framebufferWidth_; }
    int framebufferHeight() const { return framebufferHeight_; }
    const ViewRect& view() const { return view_; }  // window pixels
    float pixelScale() const { return pixelScale_; }

    // The view's rectangle in framebuffer pixels, with the scene's settings.
    render::FrameOptions frameOptions(const Scene& scene) const;
    render::FrameView frameView(const render::Camera& camera, const Scene& scene) const;

private:
    int windowWidth_ = 1, windowHeight_ = 1, framebufferWidth_ = 1, framebufferHeight_ = 1;
    ViewRect view_;
    float pixelScale_ = 1.0f;
};

}  // namespace isotrack::viewer
