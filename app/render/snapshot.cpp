#include "render/snapshot.h"

#include <algorithm>

#include "render/offscreen_target.h"
#include "render/palette.h"
#include "render/renderer.h"

namespace isotrack::render {

Bounds volumeBounds(const Volume& volume) {
    Bounds bounds;
    for (int axis = 0; axis < 3; ++axis) {
        const double first = volume.origin()[axis];
        const double last = first + volume.spacing()[axis] * double(std::max(volume.dims()[axis] - 1, 0));
        bounds.min[axis] = static_cast<float>(std::min(first, last));
        bounds.max[axis] = static_cast<float>(std::max(first, last));
    }
    return bounds;
}

Snapshot renderSnapshot(const std::vector<const Mesh*>& surfaces, const Bounds& bounds,
                        const SnapshotOptions& options) {
    OffscreenTarget target(options.width, options.height);
    Renderer renderer;
    renderer.setBounds(bounds);
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        SurfaceStyle style;
        style.colour = surfaceColour(i);
        renderer.addSurface(*surfaces[i], style);
    }

    Snapshot snapshot;
    const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
    snapshot.camera = options.camera.value_or(frameBounds(bounds, aspect));
    FrameOptions frame;
    frame.width = options.width;
    frame.height = options.height;
    frame.wireframe = options.wireframe;
    frame.boundingBox = options.boundingBox;
    frame.selected = options.selected;

    target.bind();
    renderer.draw(snapshot.camera, frame);
    snapshot.image = target.read();
    return snapshot;
}

}  // namespace isotrack::render
