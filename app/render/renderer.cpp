#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

#include "gl/state.h"
#include "render/pick_target.h"
#include "render/shader_library.h"

namespace isotrack::render {
namespace {

const glm::vec3 kBoxColour{0.50f, 0.53f, 0.58f};
constexpr float kWireDarkening = 0.35f;
// Filled triangles are pushed back this much when the wireframe is drawn over them.
constexpr float kWireOffsetFactor = 1.0f, kWireOffsetUnits = 1.0f;

gl::Program buildProgram(const char* vertex, const char* fragment) {
    return gl::Program(loadShader(vertex), loadShader(fragment));
}

// The 12 edges of the box as 24 line-list vertices.
std::array<glm::vec3, 24> boxLines(const Bounds& b) {
    std::array<glm::vec3, 8> corner;
    for (int i = 0; i < 8; ++i) {
        corner[i] = {(i & 1) ? b.max.x : b.min.x, (i & 2) ? b.max.y : b.min.y, (i & 4) ? b.max.z : b.min.z};
    }
    std::array<glm::vec3, 24> lines;
    std::size_t n = 0;
    for (int i = 0; i < 8; ++i) {
        for (int axis = 1; axis <= 4; axis <<= 1) {
            if ((i & axis) == 0) {
                lines[n++] = corner[i];
                lines[n++] = corner[i | axis];
            }
        }
    }
    return lines;
}

bool drawable(const GpuMesh& mesh, const SurfaceStyle& style) { return style.visible && mesh.indexCount() > 0; }

constexpr int kSurfaceTableUnit = 0;

}  // namespace

Bounds boundsWithOffsets(const Bounds& bounds, const std::vector<glm::vec3>& offsets) {
    Bounds scene = bounds;
    for (const glm::vec3& offset : offsets) {
        scene.min = glm::min(scene.min, bounds.min + offset);
        scene.max = glm::max(scene.max, bounds.max + offset);
    }
    return scene;
}

Renderer::Renderer()
    : surfaceProgram_{buildProgram("surface.vert", "surface.frag"), 0, 0},
      lineProgram_{buildProgram("lines.vert", "lines.frag"), 0, 0, 0, 0, 0},
      pickProgram_{buildProgram("pick.vert", "pick.frag"), 0} {
    const gl::Program& surface = surfaceProgram_.program;
    surfaceProgram_.view = surface.uniformLocation("uView");
    surfaceProgram_.projection = surface.uniformLocation("uProjection");
    const gl::Program& lines = lineProgram_.program;
    lineProgram_.viewProjection = lines.uniformLocation("uViewProjection");
    lineProgram_.offset = lines.uniformLocation("uOffset");
    lineProgram_.colour = lines.uniformLocation("uColour");
    lineProgram_.fromTable = lines.uniformLocation("uFromTable");
    lineProgram_.darkening = lines.uniformLocation("uDarkening");
    const gl::Program& pick = pickProgram_.program;
    pickProgram_.viewProjection = pick.uniformLocation("uViewProjection");
    for (const gl::Program* program : {&surface, &lines, &pick}) {  // every one reads the table from one unit
        program->use();
        gl::Program::set(program->uniformLocation("uSurfaces"), kSurfaceTableUnit);
    }

    boxVertices_.allocate(sizeof(glm::vec3) * 24, nullptr, gl::BufferUsage::Static);
    boxArray_.setFloatAttribute(0, boxVertices_, 3, sizeof(glm::vec3), 0);
    setBounds(bounds_);
}

std::size_t Renderer::addSurface(GpuMesh mesh, const SurfaceStyle& style) {
    surfaces_.push_back(DrawnSurface{std::move(mesh), style});
    return surfaces_.size() - 1;
}

std::size_t Renderer::addSurface(const Mesh& mesh, const SurfaceStyle& style) {
    return addSurface(GpuMesh(arena_, mesh), style);
}

void Renderer::setBounds(const Bounds& bounds) {
    bounds_ = bounds;
    const std::array<glm::vec3, 24> lines = boxLines(bounds);
    boxVertices_.update(0, sizeof(lines), lines.data());
}

Bounds Renderer::sceneBounds() const {
    std::vector<glm::vec3> offsets;
    for (const DrawnSurface& surface : surfaces_) {
        if (surface.style.visible) offsets.push_back(surface.style.offset);
    }
    return boundsWithOffsets(bounds_, offsets);
}

void Renderer::draw(const Camera& camera, const FrameOptions& options) const {
    const FrameView frame = frameView(camera, options, sceneBounds());
    beginFrame(frame, options);

    beginSurfaces(frame, options.wireframe);
    for (std::size_t i = 0; i < surfaces_.size(); ++i) {
        if (&surfaces_[i].mesh.arena() != &arena_) throw std::logic_error("Renderer: a surface from another arena");
        SurfaceShading shading;
        shading.highlighted = options.selected == i;
        drawSurface(surfaces_[i].mesh, surfaces_[i].style, shading);
    }
    endSurfaces(options.wireframe);

    if (options.wireframe || options.boundingBox) {
        beginLines(frame);
        if (options.wireframe) {
            setWireframeMode(true);
            for (const DrawnSurface& surface : surfaces_) drawSurfaceWireframe(surface.mesh, surface.style);
            setWireframeMode(false);
        }
        if (options.boundingBox) drawBoundingBox();
    }
}

FrameView Renderer::frameView(const Camera& camera, const FrameOptions& options, const Bounds& scene) {
    float near = 0.0f, far = 0.0f;
    clipPlanes(camera, scene, near, far);
    const float aspect = static_cast<float>(options.width) / static_cast<float>(std::max(options.height, 1));
    FrameView frame;
    frame.view = camera.view();
    frame.projection = camera.projection(aspect, near, far);
    frame.x = options.x;
    frame.y = options.y;
    frame.width = options.width;
    frame.height = options.height;
    return frame;
}

void Renderer::beginFrame(const FrameView& frame, const FrameOptions& options) {
    gl::setViewport(frame.x, frame.y, frame.width, frame.height);
    gl::setDepthTest(true);
    gl::setDepthWrite(true);
    gl::setDepthLessEqual(false);
    gl::setFaceCulling(false);  // two-sided: open surfaces show their inside
    gl::clear(glm::vec4(options.background, 1.0f));
}

void Renderer::beginSurfaces(const FrameView& frame, bool underWireframe) const {
    noted_.clear();
    const SurfaceProgram& p = surfaceProgram_;
    p.program.use();
    gl::Program::set(p.view, frame.view);
    gl::Program::set(p.projection, frame.projection);
    if (underWireframe) {
        gl::setPolygonOffsetFill(kWireOffsetFactor, kWireOffsetUnits);
    } else {
        gl::setPolygonOffsetFill(0.0f, 0.0f);
    }
}

void Renderer::drawSurface(const GpuMesh& mesh, const SurfaceStyle& style, const SurfaceShading& shading) const {
    if (!drawable(mesh, style)) return;
    SurfaceLook look = arena_.look(mesh.slot());
    look.colour = style.colour;
    look.offset = style.offset;
    look.highlight = shading.highlighted ? 1.0f : 0.0f;
    look.growthScale =
        shading.colourByGrowth ? 1.0f / static_cast<float>(std::max<std::size_t>(mesh.vertexCount(), 1)) : 0.0f;
    note(mesh, look);
}

void Renderer::endSurfaces(bool underWireframe) const {
    drawNoted(true);
    if (underWireframe) gl::setPolygonOffsetFill(0.0f, 0.0f);
}

void Renderer::note(const GpuMesh& mesh, const SurfaceLook& look) const {
    arena_.setLook(mesh.slot(), look);
    noted_.push_back(mesh.slot());
}

// The noted surfaces in list order: one multi-draw per run of consecutive
// surfaces in the same page (or one draw each, as the reference).
void Renderer::drawNoted(bool counted) const {
    if (noted_.empty()) return;
    arena_.sync();
    arena_.bindTable(kSurfaceTableUnit);
    std::vector<int> counts, baseVertices;
    std::vector<std::size_t> firstIndices;
    std::size_t i = 0;
    while (i < noted_.size()) {
        const int page = arena_.place(noted_[i]).page;
        counts.clear();
        baseVertices.clear();
        firstIndices.clear();
        std::size_t triangles = 0;
        for (; i < noted_.size() && arena_.place(noted_[i]).page == page; ++i) {
            const SlotPlace& place = arena_.place(noted_[i]);
            counts.push_back(static_cast<int>(place.indexCount));
            firstIndices.push_back(place.firstIndex);
            baseVertices.push_back(static_cast<int>(place.firstVertex));
            triangles += place.indexCount / 3;
            if (oneCallPerSurface_) {
                ++i;
                break;
            }
        }
        arena_.page(page)->array.multiDrawTriangles(counts.size(), counts.data(), firstIndices.data(),
                                                    baseVertices.data());
        if (counted) {
            ++counters_.drawCalls;
            counters_.triangles += triangles;
        }
    }
    noted_.clear();
}

void Renderer::beginLines(const FrameView& frame) const {
    const LineProgram& p = lineProgram_;
    p.program.use();
    gl::setDepthLessEqual(true);
    gl::Program::set(p.viewProjection, frame.viewProjection());
}

void Renderer::setWireframeMode(bool lines) const {
    const LineProgram& p = lineProgram_;
    if (lines) {
        noted_.clear();
        gl::Program::set(p.fromTable, 1);
        gl::Program::set(p.darkening, kWireDarkening);
    } else {
        drawNoted(true);
        gl::Program::set(p.fromTable, 0);
    }
    gl::setPolygonLines(lines);
}

void Renderer::drawSurfaceWireframe(const GpuMesh& mesh, const SurfaceStyle& style) const {
    if (!drawable(mesh, style)) return;
    SurfaceLook look = arena_.look(mesh.slot());
    look.colour = style.colour;
    look.offset = style.offset;
    note(mesh, look);
}

void Renderer::drawBoundingBox() const {
    const LineProgram& p = lineProgram_;
    gl::Program::set(p.fromTable, 0);
    gl::Program::set(p.offset, glm::vec3(0.0f));
    gl::Program::set(p.colour, kBoxColour);
    boxArray_.drawLines(24);
    ++counters_.drawCalls;
}

DrawCounters Renderer::takeCounters() {
    const DrawCounters counters = counters_;
    counters_ = DrawCounters{};
    return counters;
}

void Renderer::beginPick(const FrameView& frame, const PickTarget& target) const {
    target.bindAndClear();
    gl::setViewport(0, 0, target.width(), target.height());
    gl::setDepthTest(true);
    gl::setDepthWrite(true);
    gl::setDepthLessEqual(false);
    gl::setPolygonOffsetFill(0.0f, 0.0f);
    noted_.clear();
    const PickProgram& p = pickProgram_;
    p.program.use();
    gl::Program::set(p.viewProjection, frame.viewProjection());
}

void Renderer::drawSurfaceId(const GpuMesh& mesh, const glm::vec3& offset, std::uint32_t id) const {
    if (mesh.indexCount() == 0) return;
    SurfaceLook look = arena_.look(mesh.slot());
    look.offset = offset;
    look.pickId = id;
    note(mesh, look);
}

void Renderer::endPick() const { drawNoted(false); }

}  // namespace isotrack::render
