// Many surfaces in a few calls: the batched path (one multi-draw per run of
// surfaces in one arena page) draws exactly the pixels and pick ids of one call
// per surface, and its number of calls does not grow with the surfaces.
#include <algorithm>
#include <catch2/catch.hpp>

#include "gl_test_support.h"
#include "isotrack/fields.h"
#include "isotrack/tracking.h"
#include "render/offscreen_target.h"
#include "render/pick_target.h"
#include "render/renderer.h"

using namespace isotrack;

namespace {

constexpr int kWidth = 320, kHeight = 240;

struct Drawn {
    render::Image image;
    render::DrawCounters counters;
};

// Every connected surface of `spec` at its default isovalue, in the renderer,
// in one page (prepared up front, as the viewer does).
std::vector<Surface> addAll(render::Renderer& renderer, const std::string& spec, const Volume& volume) {
    const FieldSpec field = parseFieldSpec(spec);
    std::vector<Surface> surfaces = extractAllSurfaces(volume, fieldDefaultIso(field.name));
    std::size_t vertices = 0, indices = 0;
    for (const Surface& s : surfaces) {
        vertices += s.mesh.vertices.size();
        indices += s.mesh.indices.size();
    }
    renderer.reserveSurfaces(vertices, indices);
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        render::SurfaceStyle style;
        style.colour = glm::vec3(float(i % 7) / 7.0f, float(i % 5) / 5.0f, float(i % 3) / 3.0f);
        renderer.addSurface(surfaces[i].mesh, style);
    }
    renderer.setBounds(render::volumeBounds(volume));
    return surfaces;
}

render::FrameOptions frameOptions() {
    render::FrameOptions options;
    options.width = kWidth;
    options.height = kHeight;
    return options;
}

Drawn draw(render::Renderer& renderer, const render::FrameOptions& options, bool oneCallPerSurface) {
    const render::OffscreenTarget target(kWidth, kHeight);
    const render::Camera camera = render::frameBounds(renderer.bounds(), float(kWidth) / float(kHeight));
    renderer.setOneCallPerSurface(oneCallPerSurface);
    renderer.takeCounters();
    target.bind();
    renderer.draw(camera, options);
    Drawn drawn{target.read(), renderer.takeCounters()};
    renderer.setOneCallPerSurface(false);
    return drawn;
}

// Pick ids at every 8th pixel, drawing `only` (or every visible surface).
std::vector<std::uint32_t> pickIds(render::Renderer& renderer, bool oneCallPerSurface,
                                   std::optional<std::size_t> only = std::nullopt) {
    const render::Camera camera = render::frameBounds(renderer.bounds(), float(kWidth) / float(kHeight));
    const render::FrameView frame = render::Renderer::frameView(camera, frameOptions(), renderer.bounds());
    const render::PickTarget target(kWidth, kHeight);
    renderer.setOneCallPerSurface(oneCallPerSurface);
    renderer.beginPick(frame, target);
    for (std::size_t i = 0; i < renderer.surfaceCount(); ++i) {
        const render::DrawnSurface& s = renderer.surface(i);
        if (s.style.visible && (!only || *only == i)) {
            renderer.drawSurfaceId(s.mesh, s.style.offset, static_cast<std::uint32_t>(i + 1));
        }
    }
    renderer.endPick();
    renderer.setOneCallPerSurface(false);
    std::vector<std::uint32_t> ids;
    for (int y = 0; y < kHeight; y += 8) {
        for (int x = 0; x < kWidth; x += 8) ids.push_back(target.idAt(x, y));
    }
    render::PickTarget::unbind();
    return ids;
}

}  // namespace

TEST_CASE("batched surfaces draw exactly what one call per surface draws", "[gl][arena]") {
    test::useHeadlessGl();
    render::Renderer renderer;
    const Volume volume = makeField(parseFieldSpec("noise:48"));
    const std::vector<Surface> surfaces = addAll(renderer, "noise:48", volume);
    REQUIRE(surfaces.size() > 100);
    // Some hidden, some moved, one selected, one of them re-uploaded elsewhere.
    for (std::size_t i = 0; i < surfaces.size(); i += 5) renderer.surface(i).style.visible = false;
    for (std::size_t i = 1; i < surfaces.size(); i += 7) renderer.surface(i).style.offset = glm::vec3(0, 0, 6);
    renderer.surface(2).mesh = render::GpuMesh(renderer.arena(), surfaces[2].mesh);
    std::size_t visible = 0;
    for (std::size_t i = 0; i < surfaces.size(); ++i) visible += renderer.surface(i).style.visible ? 1 : 0;
    render::FrameOptions options = frameOptions();
    options.selected = 3;

    for (bool wireframe : {false, true}) {
        options.wireframe = wireframe;
        const Drawn batched = draw(renderer, options, false);
        const Drawn reference = draw(renderer, options, true);
        CHECK(batched.image.rgba == reference.image.rgba);
        CHECK(batched.counters.triangles == reference.counters.triangles);
        CHECK(batched.counters.drawCalls <= (wireframe ? 2 : 1) * renderer.arena().stats().pages + 1);
        CHECK(reference.counters.drawCalls == (wireframe ? 2 : 1) * visible + 1);
    }
}

TEST_CASE("picking through the batched path finds the surface drawn there", "[gl][arena]") {
    test::useHeadlessGl();
    render::Renderer renderer;
    const Volume volume = makeField(parseFieldSpec("noise:48"));
    const std::vector<Surface> surfaces = addAll(renderer, "noise:48", volume);
    for (std::size_t i = 0; i < surfaces.size(); i += 4) renderer.surface(i).style.visible = false;
    renderer.surface(1).style.offset = glm::vec3(4, 0, 0);

    const std::vector<std::uint32_t> batched = pickIds(renderer, false);
    CHECK(batched == pickIds(renderer, true));
    // At sampled pixels, the surface picked there covers that pixel when drawn alone.
    std::vector<std::size_t> hits;
    for (std::size_t p = 0; p < batched.size(); ++p) {
        if (batched[p] != 0) hits.push_back(p);
    }
    REQUIRE(hits.size() >= 12);
    for (std::size_t k = 0; k < 12; ++k) {
        const std::size_t p = hits[k * hits.size() / 12];
        CHECK(pickIds(renderer, false, batched[p] - 1)[p] == batched[p]);
    }
}

TEST_CASE("noise:96, every surface: at most 8 draw calls, however many surfaces", "[gl][arena]") {
    test::useHeadlessGl();
    render::Renderer renderer;
    const Volume volume = makeField(parseFieldSpec("noise:96"));
    const std::vector<Surface> surfaces = addAll(renderer, "noise:96", volume);
    CHECK(surfaces.size() == 8461);
    std::size_t triangles = 0;
    for (const Surface& s : surfaces) triangles += s.mesh.triangleCount();

    const Drawn batched = draw(renderer, frameOptions(), false);
    CHECK(batched.counters.drawCalls <= 8);  // the surfaces' pages and the box
    CHECK(batched.counters.triangles == triangles);
    const Drawn reference = draw(renderer, frameOptions(), true);
    CHECK(reference.counters.drawCalls == surfaces.size() + 1);
    CHECK(batched.image.rgba == reference.image.rgba);
}
