#pragma once
// Picking: what is under a pixel of the 3D view.
//
// Surfaces: the scene is drawn into an offscreen R32UI id buffer (with a depth
// buffer) with the frame's camera, on demand, and the id and depth under the
// pixel are read back; the depth unprojects to the world point, which, minus
// the hit surface's offset, is the point on the surface where it lies in the
// volume. With no surface under the pixel (e.g. nothing extracted yet in the
// track method), the ray through the pixel is marched through the volume to
// its first crossing of the isovalue.
#include <cstdint>
#include <memory>
#include <optional>

#include <glm/vec3.hpp>

#include "isotrack/volume.h"
#include "render/pick_target.h"
#include "render/renderer.h"

namespace isotrack::viewer {

class Scene;

struct PickHit {
    std::optional<std::uint32_t> surface;  // id of the surface under the pixel
    std::optional<Vec3d> point;            // in the volume's (unmoved) world coordinates
};

class Picker {
public:
    // (x, y): pixels from the top-left of the frame's viewport.
    PickHit pickSurface(const Scene& scene, const render::Renderer& renderer, const render::FrameView& frame, float x,
                        float y);
    std::size_t gpuBytes() const { return target_ ? target_->bytes() : 0; }

private:
    std::unique_ptr<render::PickTarget> target_;
};

// The first point along the ray where the volume's trilinear interpolant
// crosses `iso`, searched in steps of half the smallest spacing and refined by
// bisection; nullopt when the ray misses the volume or never crosses.
std::optional<Vec3d> firstIsoCrossing(const Volume& volume, double iso, const glm::vec3& origin,
                                      const glm::vec3& direction);

}  // namespace isotrack::viewer
