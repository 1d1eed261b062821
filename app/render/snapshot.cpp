#include "render/snapshot.h"

#include <algorithm>
#include <chrono>

#include "gl/state.h"
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
    renderer.setOneCallPerSurface(options.oneCallPerSurface);
    std::size_t vertices = 0, indices = 0;
    for (const Mesh* mesh : surfaces) {
        vertices += mesh->vertices.size();
        indices += mesh->indices.size();
    }
    if (vertices > 0) renderer.reserveSurfaces(vertices, indices);  // one page for them all
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
    snapshot.counters = renderer.takeCounters();
    snapshot.image = target.read();
    for (int i = 0; i < options.timedFrames; ++i) {
        const auto start = std::chrono::steady_clock::now();
        renderer.draw(snapshot.camera, frame);
        const auto submitted = std::chrono::steady_clock::now();
        gl::finish();
        const auto finished = std::chrono::steady_clock::now();
        snapshot.submitMs.push_back(std::chrono::duration<double, std::milli>(submitted - start).count());
        snapshot.frameMs.push_back(std::chrono::duration<double, std::milli>(finished - start).count());
    }
    return snapshot;
}

}  // namespace isotrack::render
