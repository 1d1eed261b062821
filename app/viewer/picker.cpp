#include "viewer/picker.h"

#include <algorithm>
#include <cmath>

#include "render/snapshot.h"
#include "viewer/scene.h"

namespace isotrack::viewer {
namespace {

constexpr int kBisections = 12;

// The value at a world point, trilinear between samples; the point must be inside.
double sampleAt(const Volume& volume, const Vec3d& point) {
    const Dims& n = volume.dims();
    int base[3];
    double t[3];
    for (int axis = 0; axis < 3; ++axis) {
        const double g = (point[axis] - volume.origin()[axis]) / volume.spacing()[axis];
        base[axis] = std::clamp(static_cast<int>(std::floor(g)), 0, std::max(n[axis] - 2, 0));
        t[axis] = std::clamp(g - base[axis], 0.0, 1.0);
    }
    auto at = [&](int dx, int dy, int dz) {
        return volume.value(std::min(base[0] + dx, n[0] - 1), std::min(base[1] + dy, n[1] - 1),
                            std::min(base[2] + dz, n[2] - 1));
    };
    const double x00 = at(0, 0, 0) + t[0] * (at(1, 0, 0) - at(0, 0, 0));
    const double x10 = at(0, 1, 0) + t[0] * (at(1, 1, 0) - at(0, 1, 0));
    const double x01 = at(0, 0, 1) + t[0] * (at(1, 0, 1) - at(0, 0, 1));
    const double x11 = at(0, 1, 1) + t[0] * (at(1, 1, 1) - at(0, 1, 1));
    const double y0 = x00 + t[1] * (x10 - x00), y1 = x01 + t[1] * (x11 - x01);
    return y0 + t[2] * (y1 - y0);
}

Vec3d along(const glm::vec3& origin, const glm::vec3& direction, double s) {
    return {origin.x + s * direction.x, origin.y + s * direction.y, origin.z + s * direction.z};
}

}  // namespace

PickHit Picker::pickSurface(const Scene& scene, const render::Renderer& renderer, const render::FrameView& frame,
                            float x, float y) {
    if (!target_ || target_->width() != frame.width || target_->height() != frame.height) {
        target_.reset();  // free the old one first
        target_ = std::make_unique<render::PickTarget>(frame.width, frame.height);
    }
    scene.drawPick(renderer, frame, *target_);
    const int px = static_cast<int>(x), py = static_cast<int>(y);
    const std::uint32_t id = target_->idAt(px, py);
    const float depth = target_->depthAt(px, py);
    render::PickTarget::unbind();

    PickHit hit;
    const SurfaceStructure* surface = scene.findByPickId(id);
    if (surface == nullptr || depth >= 1.0f) return hit;
    hit.surface = surface->id();
    const glm::vec3 world = render::unproject(frame, float(px) + 0.5f, float(py) + 0.5f, depth) - surface->offset();
    hit.point = Vec3d{world.x, world.y, world.z};
    return hit;
}

std::optional<Vec3d> firstIsoCrossing(const Volume& volume, double iso, const glm::vec3& origin,
                                      const glm::vec3& direction) {
    const render::Bounds box = render::volumeBounds(volume);
    // Slab test: the stretch of the ray inside the box.
    double enter = 0.0, leave = 1e30;
    for (int axis = 0; axis < 3; ++axis) {
        const double d = direction[axis], o = origin[axis];
        if (std::abs(d) < 1e-12) {
            if (o < box.min[axis] || o > box.max[axis]) return std::nullopt;
            continue;
        }
        double a = (box.min[axis] - o) / d, b = (box.max[axis] - o) / d;
        if (a > b) std::swap(a, b);
        enter = std::max(enter, a);
        leave = std::min(leave, b);
    }
    if (enter > leave) return std::nullopt;
    const Vec3d& spacing = volume.spacing();
    const double step = 0.5 * std::min({std::abs(spacing[0]), std::abs(spacing[1]), std::abs(spacing[2])});
    if (!(step > 0.0)) return std::nullopt;

    const bool startsAbove = sampleAt(volume, along(origin, direction, enter)) > iso;
    double previous = enter;
    for (double s = enter + step; s <= leave + 0.5 * step; s += step) {
        const double at = std::min(s, leave);
        if ((sampleAt(volume, along(origin, direction, at)) > iso) == startsAbove) {
            previous = at;
            continue;
        }
        double low = previous, high = at;  // the crossing lies between
        for (int i = 0; i < kBisections; ++i) {
            const double mid = 0.5 * (low + high);
            ((sampleAt(volume, along(origin, direction, mid)) > iso) == startsAbove ? low : high) = mid;
        }
        return along(origin, direction, high);
    }
    return std::nullopt;
}

}  // namespace isotrack::viewer
