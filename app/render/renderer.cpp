#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <utility>

#include "gl/state.h"
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

}  // namespace

Renderer::Renderer()
    : surfaceProgram_{buildProgram("surface.vert", "surface.frag"), 0, 0, 0, 0, 0},
      lineProgram_{buildProgram("lines.vert", "lines.frag"), 0, 0, 0} {
    const gl::Program& surface = surfaceProgram_.program;
    surfaceProgram_.view = surface.uniformLocation("uView");
    surfaceProgram_.projection = surface.uniformLocation("uProjection");
    surfaceProgram_.offset = surface.uniformLocation("uOffset");
    surfaceProgram_.colour = surface.uniformLocation("uColour");
    surfaceProgram_.highlight = surface.uniformLocation("uHighlight");
    const gl::Program& lines = lineProgram_.program;
    lineProgram_.viewProjection = lines.uniformLocation("uViewProjection");
    lineProgram_.offset = lines.uniformLocation("uOffset");
    lineProgram_.colour = lines.uniformLocation("uColour");

    boxVertices_.allocate(sizeof(glm::vec3) * 24, nullptr, gl::BufferUsage::Static);
    boxArray_.setFloatAttribute(0, boxVertices_, 3, sizeof(glm::vec3), 0);
    setBounds(bounds_);
}

std::size_t Renderer::addSurface(GpuMesh mesh, const SurfaceStyle& style) {
    surfaces_.push_back(DrawnSurface{std::move(mesh), style});
    return surfaces_.size() - 1;
}

std::size_t Renderer::addSurface(const Mesh& mesh, const SurfaceStyle& style) {
    return addSurface(GpuMesh(mesh), style);
}

void Renderer::setBounds(const Bounds& bounds) {
    bounds_ = bounds;
    const std::array<glm::vec3, 24> lines = boxLines(bounds);
    boxVertices_.update(0, sizeof(lines), lines.data());
}

Bounds Renderer::sceneBounds() const {
    Bounds scene = bounds_;
    for (const DrawnSurface& surface : surfaces_) {
        if (!surface.style.visible) continue;
        scene.min = glm::min(scene.min, bounds_.min + surface.style.offset);
        scene.max = glm::max(scene.max, bounds_.max + surface.style.offset);
    }
    return scene;
}

void Renderer::draw(const Camera& camera, const FrameOptions& options) const {
    gl::setViewport(0, 0, options.width, options.height);
    gl::setDepthTest(true);
    gl::setDepthWrite(true);
    gl::setDepthLessEqual(false);
    gl::setFaceCulling(false);  // two-sided: open surfaces show their inside
    gl::clear(glm::vec4(options.background, 1.0f));

    float near = 0.0f, far = 0.0f;
    clipPlanes(camera, sceneBounds(), near, far);
    const float aspect = static_cast<float>(options.width) / static_cast<float>(std::max(options.height, 1));
    const glm::mat4 view = camera.view();
    const glm::mat4 projection = camera.projection(aspect, near, far);

    drawSurfaces(view, projection, options);
    if (options.wireframe || options.boundingBox) {
        lineProgram_.program.use();
        gl::setDepthLessEqual(true);
        if (options.wireframe) drawWireframe(projection * view);
        if (options.boundingBox) drawBoundingBox(projection * view);
    }
}

void Renderer::drawSurfaces(const glm::mat4& view, const glm::mat4& projection, const FrameOptions& options) const {
    const SurfaceProgram& p = surfaceProgram_;
    p.program.use();
    gl::Program::set(p.view, view);
    gl::Program::set(p.projection, projection);
    if (options.wireframe) {
        gl::setPolygonOffsetFill(kWireOffsetFactor, kWireOffsetUnits);
    } else {
        gl::setPolygonOffsetFill(0.0f, 0.0f);
    }
    for (std::size_t i = 0; i < surfaces_.size(); ++i) {
        const DrawnSurface& surface = surfaces_[i];
        if (!surface.style.visible || surface.mesh.indexCount() == 0) continue;
        gl::Program::set(p.offset, surface.style.offset);
        gl::Program::set(p.colour, surface.style.colour);
        gl::Program::set(p.highlight, options.selected == i ? 1.0f : 0.0f);
        surface.mesh.draw();
    }
    if (options.wireframe) gl::setPolygonOffsetFill(0.0f, 0.0f);
}

void Renderer::drawWireframe(const glm::mat4& viewProjection) const {
    const LineProgram& p = lineProgram_;
    gl::Program::set(p.viewProjection, viewProjection);
    gl::setPolygonLines(true);
    for (const DrawnSurface& surface : surfaces_) {
        if (!surface.style.visible || surface.mesh.indexCount() == 0) continue;
        gl::Program::set(p.offset, surface.style.offset);
        gl::Program::set(p.colour, surface.style.colour * kWireDarkening);
        surface.mesh.draw();
    }
    gl::setPolygonLines(false);
}

void Renderer::drawBoundingBox(const glm::mat4& viewProjection) const {
    const LineProgram& p = lineProgram_;
    gl::Program::set(p.viewProjection, viewProjection);
    gl::Program::set(p.offset, glm::vec3(0.0f));
    gl::Program::set(p.colour, kBoxColour);
    boxArray_.drawLines(24);
}

}  // namespace isotrack::render
