#pragma once
// The one builder of off-screen targets: a framebuffer with one colour
// attachment and a depth/stencil renderbuffer of the same size, checked
// complete. Pictures (render::OffscreenTarget) keep their Rgba8 colour in a
// renderbuffer; the pick buffer (render::PickTarget) keeps its R32UI ids in a
// texture.
#include <cstddef>
#include <optional>

#include "gl/framebuffer.h"

namespace isotrack::gl {

enum class ColourStorage { Renderbuffer, Texture };

class ColourDepthTarget {
public:
    // Needs a current context; throws Error for a size outside what GL allows
    // or an incomplete framebuffer. Leaves this framebuffer bound.
    ColourDepthTarget(int width, int height, PixelFormat colour, ColourStorage storage);

    const Framebuffer& framebuffer() const { return framebuffer_; }
    int width() const { return width_; }
    int height() const { return height_; }
    // Colour and depth/stencil, 4 bytes each per pixel (Rgba8 and R32UI alike).
    std::size_t bytes() const { return std::size_t(width_) * std::size_t(height_) * 8; }

private:
    int width_, height_;
    std::optional<Renderbuffer> colourBuffer_;
    std::optional<Texture> colourTexture_;
    Renderbuffer depth_;
    Framebuffer framebuffer_;
};

}  // namespace isotrack::gl
