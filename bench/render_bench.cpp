// Where the time of one headless 320x240 picture goes: context, shaders, upload,
// draw (plain and wireframe) and read-back. Run build/bench/bench_render.
#include <chrono>
#include <cstdio>

#include "gl/state.h"
#include "headless/headless_context.h"
#include "isotrack/fields.h"
#include "isotrack/tracking.h"
#include "render/offscreen_target.h"
#include "render/palette.h"
#include "render/renderer.h"
#include "render/snapshot.h"

using namespace isotrack;

int main() {
    using Clock = std::chrono::steady_clock;
    auto ms = [](Clock::time_point from) {
        return std::chrono::duration<double, std::milli>(Clock::now() - from).count();
    };
    const Volume volume = makeField(parseFieldSpec("blobs:128"));
    const std::vector<Surface> surfaces = extractAllSurfaces(volume, fieldDefaultIso("blobs"));
    std::size_t triangles = 0;
    for (const Surface& s : surfaces) triangles += s.mesh.triangleCount();

    auto start = Clock::now();
    const headless::HeadlessContext context;
    const double contextMs = ms(start);
    start = Clock::now();
    render::Renderer renderer;
    const double shadersMs = ms(start);
    start = Clock::now();
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        renderer.addSurface(surfaces[i].mesh, render::SurfaceStyle{true, render::surfaceColour(i), glm::vec3(0.0f)});
    }
    renderer.setBounds(render::volumeBounds(volume));
    gl::finish();
    const double uploadMs = ms(start);
    const render::OffscreenTarget target(320, 240);
    target.bind();
    render::FrameOptions frame;
    frame.width = 320;
    frame.height = 240;
    const render::Camera camera = render::frameBounds(renderer.bounds(), 320.0f / 240.0f);
    renderer.draw(camera, frame);  // warm-up: llvmpipe compiles its shader variants on first use
    gl::finish();
    const int frames = 20;
    start = Clock::now();
    for (int i = 0; i < frames; ++i) renderer.draw(camera, frame);
    gl::finish();
    const double drawMs = ms(start) / frames;
    frame.wireframe = true;
    renderer.draw(camera, frame);
    gl::finish();
    start = Clock::now();
    for (int i = 0; i < frames; ++i) renderer.draw(camera, frame);
    gl::finish();
    const double wireMs = ms(start) / frames;
    start = Clock::now();
    const render::Image image = target.read();
    const double readMs = ms(start);
    std::printf(
        "blobs:128, %zu surfaces, %zu triangles, 320x240 on %s\n"
        "  context %.1f ms, shaders %.1f ms, upload %.1f ms, draw %.2f ms/frame (wireframe %.2f), read %.2f ms\n",
        surfaces.size(), triangles, context.info().renderer.c_str(), contextMs, shadersMs, uploadMs, drawMs, wireMs,
        readMs);
    return image.width == 320 ? 0 : 1;
}
