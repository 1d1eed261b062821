#include "viewer/view_layout.h"

#include <algorithm>

#include "ui/panel.h"

namespace isotrack::viewer {

void ViewLayout::update(const Window& window) {
    window.windowSize(windowWidth_, windowHeight_);
    window.framebufferSize(framebufferWidth_, framebufferHeight_);
    pixelScale_ = windowWidth_ > 0 ? float(framebufferWidth_) / float(windowWidth_) : 1.0f;
    view_.x = ui::Panel::kWidth;
    view_.y = 0.0f;
    view_.width = std::max(float(windowWidth_) - ui::Panel::kWidth, 1.0f);
    view_.height = std::max(float(windowHeight_), 1.0f);
}

render::FrameOptions ViewLayout::frameOptions(const Scene& scene) const {
    render::FrameOptions options;
    options.x = static_cast<int>(view_.x * pixelScale_);
    options.y = 0;
    options.width = std::max(framebufferWidth_ - options.x, 1);
    options.height = std::max(framebufferHeight_, 1);
    options.wireframe = scene.wireframe;
    options.boundingBox = scene.boundingBox;
    return options;
}

render::FrameView ViewLayout::frameView(const render::Camera& camera, const Scene& scene) const {
    return render::Renderer::frameView(camera, frameOptions(scene), scene.drawBounds());
}

}  // namespace isotrack::viewer
