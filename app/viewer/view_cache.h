#pragma once
// The 3D view is drawn into an offscreen target and copied into the window
// every frame, and redrawn only when what it shows has changed: the signature
// covers the camera, the view's size and settings, the selection, and each
// surface's drawn index count, visibility, colour and offset. Through llvmpipe
// a frame where only the panel changes then costs a copy of the view instead of
// every triangle of the scene again.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "render/offscreen_target.h"

namespace isotrack::viewer {

class ViewCache {
public:
    // True when the image must be drawn again for `signature` at this size;
    // the target is (re)made to the size first. Then bind() and draw.
    bool needsRedraw(std::uint64_t signature, int width, int height);
    void bind() const { target_->bind(); }
    // Copies the image into the window's framebuffer at (x, y), bottom-left origin.
    void present(int x, int y) const;
    void invalidate() { valid_ = false; }
    std::size_t gpuBytes() const { return target_ ? target_->bytes() : 0; }

private:
    std::unique_ptr<render::OffscreenTarget> target_;
    std::uint64_t signature_ = 0;
    bool valid_ = false;
};

}  // namespace isotrack::viewer
