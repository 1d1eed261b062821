#pragma once
// Draws isotrack's scene: surfaces, an optional wireframe over them, and the
// volume's bounding box, into whatever framebuffer is bound (a window's, or an
// OffscreenTarget).
//
// Every surface has its own GpuMesh and a plain SurfaceStyle that a viewer can
// edit between frames (visibility, colour, offset). Drawing sets each piece of
// state once per pass and only uniforms per surface; it never uploads meshes.
#include <cstddef>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/vertex_array.h"
#include "isotrack/mesh.h"
#include "render/camera.h"
#include "render/gpu_mesh.h"

namespace isotrack::render {

struct SurfaceStyle {
    bool visible = true;
    glm::vec3 colour{0.8f};
    glm::vec3 offset{0.0f};  // model translation in world units
};

struct DrawnSurface {
    GpuMesh mesh;
    SurfaceStyle style;
};

struct FrameOptions {
    int width = 0, height = 0;  // viewport in pixels
    glm::vec3 background{0.11f, 0.12f, 0.14f};
    bool wireframe = false;
    bool boundingBox = true;
    std::optional<std::size_t> selected;  // surface index to highlight
};

class Renderer {
public:
    // Compiles the shaders (embedded, or from ISOTRACK_SHADER_DIR). Needs a
    // current GL context; throws gl::ShaderError naming a shader that fails.
    Renderer();

    std::size_t addSurface(GpuMesh mesh, const SurfaceStyle& style);
    std::size_t addSurface(const Mesh& mesh, const SurfaceStyle& style);
    std::size_t surfaceCount() const { return surfaces_.size(); }
    DrawnSurface& surface(std::size_t index) { return surfaces_.at(index); }
    const DrawnSurface& surface(std::size_t index) const { return surfaces_.at(index); }
    void clearSurfaces() { surfaces_.clear(); }

    // The volume's box: drawn as lines, and what the clip planes are fitted to.
    void setBounds(const Bounds& bounds);
    const Bounds& bounds() const { return bounds_; }

    void draw(const Camera& camera, const FrameOptions& options) const;

private:
    struct SurfaceProgram {
        gl::Program program;
        int view, projection, offset, colour, highlight;
    };
    struct LineProgram {
        gl::Program program;
        int viewProjection, offset, colour;
    };

    Bounds sceneBounds() const;
    void drawSurfaces(const glm::mat4& view, const glm::mat4& projection, const FrameOptions& options) const;
    void drawWireframe(const glm::mat4& viewProjection) const;
    void drawBoundingBox(const glm::mat4& viewProjection) const;

    SurfaceProgram surfaceProgram_;
    LineProgram lineProgram_;
    gl::Buffer boxVertices_;
    gl::VertexArray boxArray_;
    Bounds bounds_;
    std::vector<DrawnSurface> surfaces_;
};

}  // namespace isotrack::render
