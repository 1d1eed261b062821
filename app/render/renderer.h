#pragma once
// Draws isotrack's scene: surfaces, an optional wireframe over them, and the
// volume's bounding box, into whatever framebuffer is bound (a window's, or an
// OffscreenTarget); and surface ids into a PickTarget for picking.
//
// Two ways in. The retained one: addSurface() a GpuMesh with a plain
// SurfaceStyle a viewer can edit between frames, then draw() them all (what
// `isotrack render` and the golden tests use). The immediate one, for a viewer
// whose structures own their GpuMeshes and draw themselves: beginFrame(), then
// beginSurfaces() and drawSurface() per surface, beginLines() and the box;
// beginPick() and drawSurfaceId() for the id buffer. Each pass sets its state
// once and only uniforms per surface; nothing here uploads meshes.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/vertex_array.h"
#include "isotrack/mesh.h"
#include "render/camera.h"
#include "render/gpu_mesh.h"

namespace isotrack::render {

class PickTarget;

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
    int x = 0, y = 0;                     // viewport origin (bottom-left) in the framebuffer
};

// One frame's camera as matrices and the viewport it draws into; every pass of
// the frame (colour and pick) uses the same one.
struct FrameView {
    glm::mat4 view{1.0f}, projection{1.0f};
    int x = 0, y = 0, width = 1, height = 1;
    glm::mat4 viewProjection() const { return projection * view; }
};

// How drawSurface shades one surface beyond its style.
struct SurfaceShading {
    bool highlighted = false;     // the selection: rim glow and stripes
    bool colourByGrowth = false;  // vertex order as a colour ramp (tracked surfaces)
};

// `bounds` grown to hold itself moved by each of `offsets` (surfaces drawn displaced).
Bounds boundsWithOffsets(const Bounds& bounds, const std::vector<glm::vec3>& offsets);

// What the drawing since the last takeCounters() cost: draw calls (surfaces,
// wireframes, the box; picking not counted) and the triangles they drew.
struct DrawCounters {
    std::size_t drawCalls = 0;
    std::size_t triangles = 0;
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

    // Draws every added surface.
    void draw(const Camera& camera, const FrameOptions& options) const;

    // ---- immediate passes --------------------------------------------------
    // The matrices for `camera`, with clip planes around `scene` (the volume's
    // box, grown by any surface offsets).
    static FrameView frameView(const Camera& camera, const FrameOptions& options, const Bounds& scene);
    // Viewport, depth state, and a clear of the whole bound framebuffer.
    static void beginFrame(const FrameView& frame, const FrameOptions& options);

    void beginSurfaces(const FrameView& frame, bool underWireframe) const;
    void drawSurface(const GpuMesh& mesh, const SurfaceStyle& style, const SurfaceShading& shading) const;
    static void endSurfaces(bool underWireframe);

    // Lines: wireframes over surfaces (between setWireframeMode(true) and
    // setWireframeMode(false)) and the volume's box.
    void beginLines(const FrameView& frame) const;
    static void setWireframeMode(bool lines);
    void drawSurfaceWireframe(const GpuMesh& mesh, const SurfaceStyle& style) const;
    void drawBoundingBox() const;

    // Binds `target`, clears it to id 0 (nothing) and depth 1, and sets the pick program.
    void beginPick(const FrameView& frame, const PickTarget& target) const;
    void drawSurfaceId(const GpuMesh& mesh, const glm::vec3& offset, std::uint32_t id) const;

    // The counters since the last call, which restarts them.
    DrawCounters takeCounters();

private:
    void count(std::size_t indices) const {
        ++counters_.drawCalls;
        counters_.triangles += indices / 3;
    }

    struct SurfaceProgram {
        gl::Program program;
        int view, projection, offset, colour, highlight, growthScale;
    };
    struct LineProgram {
        gl::Program program;
        int viewProjection, offset, colour;
    };
    struct PickProgram {
        gl::Program program;
        int viewProjection, offset, id;
    };

    Bounds sceneBounds() const;

    SurfaceProgram surfaceProgram_;
    LineProgram lineProgram_;
    PickProgram pickProgram_;
    gl::Buffer boxVertices_;
    gl::VertexArray boxArray_;
    Bounds bounds_;
    std::vector<DrawnSurface> surfaces_;
    mutable DrawCounters counters_;  // drawing is const; counting what it cost is not the drawing's state
};

}  // namespace isotrack::render
