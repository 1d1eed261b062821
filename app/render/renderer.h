#pragma once
// Draws isotrack's scene: surfaces, an optional wireframe over them, and the
// volume's bounding box, into whatever framebuffer is bound (a window's, or an
// OffscreenTarget); and surface ids into a PickTarget for picking.
//
// Surfaces live in the renderer's SurfaceArena (render/surface_arena.h): a few
// shared pages, each surface a range of one. Two ways in. The retained one:
// addSurface() a mesh with a plain SurfaceStyle a viewer can edit between
// frames, then draw() them all (what `isotrack render` and the golden tests
// use). The immediate one, for a viewer whose structures own their GpuMeshes
// (made in arena()) and draw themselves: beginFrame(), then beginSurfaces(),
// drawSurface() per surface and endSurfaces(); beginLines(), the wireframes
// between setWireframeMode(true) and (false), and the box; beginPick(),
// drawSurfaceId() per surface and endPick(). drawSurface and its kin only note
// the surface and its look in the surface table; the end of the pass draws the
// noted surfaces in list order with one glMultiDrawElementsBaseVertex per run of
// consecutive surfaces in the same page, so the number of calls follows the
// pages, not the surfaces. setOneCallPerSurface(true) draws the same list with
// one call per surface instead (the reference the tests compare against).
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

    SurfaceArena& arena() { return arena_; }
    const SurfaceArena& arena() const { return arena_; }
    // Room in one page for surfaces of this many vertices and indices in all,
    // before adding them one by one.
    void reserveSurfaces(std::size_t vertices, std::size_t indices) { arena_.prepare(vertices, indices); }
    void setOneCallPerSurface(bool enabled) { oneCallPerSurface_ = enabled; }

    std::size_t addSurface(GpuMesh mesh, const SurfaceStyle& style);  // a mesh of arena()
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
    void endSurfaces(bool underWireframe) const;

    // Lines: wireframes over surfaces (between setWireframeMode(true) and
    // setWireframeMode(false)) and the volume's box.
    void beginLines(const FrameView& frame) const;
    void setWireframeMode(bool lines) const;  // false draws the noted wireframes first
    void drawSurfaceWireframe(const GpuMesh& mesh, const SurfaceStyle& style) const;
    void drawBoundingBox() const;

    // Binds `target`, clears it to id 0 (nothing) and depth 1, and sets the pick program.
    void beginPick(const FrameView& frame, const PickTarget& target) const;
    void drawSurfaceId(const GpuMesh& mesh, const glm::vec3& offset, std::uint32_t id) const;
    void endPick() const;

    // The counters since the last call, which restarts them.
    DrawCounters takeCounters();

private:
    void count(std::size_t indices) const {
        ++counters_.drawCalls;
        counters_.triangles += indices / 3;
    }

    struct SurfaceProgram {
        gl::Program program;
        int view, projection;
    };
    struct LineProgram {
        gl::Program program;
        int viewProjection, offset, colour, fromTable, darkening;
    };
    struct PickProgram {
        gl::Program program;
        int viewProjection;
    };

    Bounds sceneBounds() const;
    void note(const GpuMesh& mesh, const SurfaceLook& look) const;
    void drawNoted(bool counted) const;

    SurfaceProgram surfaceProgram_;
    LineProgram lineProgram_;
    PickProgram pickProgram_;
    gl::Buffer boxVertices_;
    gl::VertexArray boxArray_;
    Bounds bounds_;
    // Drawing is const; the surface table it fills, the list of surfaces noted
    // for the pass and what it cost are not the drawing's state.
    mutable SurfaceArena arena_;
    std::vector<DrawnSurface> surfaces_;  // after arena_: freed before it
    mutable std::vector<std::uint32_t> noted_;
    mutable DrawCounters counters_;
    bool oneCallPerSurface_ = false;
};

}  // namespace isotrack::render
