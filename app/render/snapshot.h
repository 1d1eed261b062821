#pragma once
// One picture of a set of surfaces: what `isotrack render` writes and what the
// golden-image tests compare. Needs a current GL context (a HeadlessContext).
#include <optional>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/volume.h"
#include "render/camera.h"
#include "render/image.h"
#include "render/renderer.h"

namespace isotrack::render {

struct SnapshotOptions {
    int width = 640, height = 480;
    std::optional<Camera> camera;  // default: frameBounds of the volume
    bool wireframe = false;
    bool boundingBox = true;
    std::optional<std::size_t> selected;
    // For benchmarks: draw the picture this many more times, each timed to the
    // end of the GPU's work (glFinish), and draw one call per surface instead
    // of one per arena page.
    int timedFrames = 0;
    bool oneCallPerSurface = false;
};

struct Snapshot {
    Image image;
    Camera camera;                 // the camera used, e.g. to print for --camera
    DrawCounters counters;         // of the picture's draw
    std::vector<double> frameMs;   // each timed frame's milliseconds, to glFinish
    std::vector<double> submitMs;  // of which issuing the frame's GL calls (the CPU's part)
};

// The volume's box in world units: from the first sample to the last.
Bounds volumeBounds(const Volume& volume);

// Draws `surfaces` in order, coloured by rank (surfaceColour(i) for the i-th),
// inside `bounds`.
Snapshot renderSnapshot(const std::vector<const Mesh*>& surfaces, const Bounds& bounds, const SnapshotOptions& options);

}  // namespace isotrack::render
