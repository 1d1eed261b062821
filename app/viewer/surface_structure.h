#pragma once
// One surface in the viewer, Polyscope-style: it owns its CPU mesh (or the
// tracker still growing it), its GPU mesh and its style, and it draws itself
// (draw), its id for picking (drawPick), and describes itself for the panel
// (buildUI: a plain row, which ui/ turns into widgets).
//
// A growing surface is fed a budget per frame: grow() runs the tracker for that
// long (or that many cells) and appends exactly the new vertex and index ranges
// to the GPU buffers; the tracker measures area and bounds as it walks, so
// finishing costs nothing extra (but the edge check of a classic-table surface).
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "isotrack/follow.h"
#include "isotrack/mesh_processing.h"
#include "isotrack/tracking.h"
#include "render/gpu_mesh.h"
#include "render/renderer.h"
#include "ui/panel_state.h"

namespace isotrack::viewer {

struct LoadedVolume;

struct GrowthBudget {
    std::chrono::nanoseconds time{std::chrono::milliseconds(4)};
    std::size_t cells = 0;  // when > 0, this many cells instead of a time budget
};

struct GrowthStep {
    std::size_t cells = 0;
    std::chrono::nanoseconds extract{0}, upload{0};
};

// Whether a surface shows a mesh at the current isovalue is core's Presence
// (isotrack/follow.h). A tracked surface keeps its seed when its surface
// vanishes (Gone) or when another tracked surface's seed lies on the same
// surface (Merged): it comes back with its own style when the isovalue moves
// back or the surfaces split again.

// Method tree: a surface with an isovalue of its own (a flexible isosurface).
// `wanted` is the one asked for, `shown` that of the mesh on screen; `origin`
// is its contour-tree arc when it got its own isovalue, the arc it stands in
// for at the common isovalue; `arc` the arc of its last mesh (kept while it is gone).
struct OwnIso {
    double wanted = 0.0, shown = 0.0;
    std::size_t origin = 0, arc = 0;
};

class SurfaceStructure {
public:
    // A finished surface, uploaded in one go. Its GPU mesh lives in `arena`,
    // which must outlive it (as every constructor's).
    SurfaceStructure(render::SurfaceArena& arena, std::uint32_t id, Surface surface, SurfaceFootprint footprint,
                     const glm::vec3& colour);
    // A surface to grow from `seed`, tracked on `volume` (kept alive by this);
    // its tracker's `threads` decide the snap table's states (SurfaceTracker).
    SurfaceStructure(render::SurfaceArena& arena, std::uint32_t id, std::shared_ptr<const LoadedVolume> volume,
                     double iso, TableKind table, const GridEdge& seed, const Vec3d& seedPoint, const glm::vec3& colour,
                     int threads);
    ~SurfaceStructure();

    // A new mesh for the same surface (another isovalue); style, offset and id stay.
    void replaceSurface(Surface surface, SurfaceFootprint footprint);
    // Smooths and decimates the shown mesh (core's processSurface), keeping the
    // mesh before it for undoProcessing; a new mesh (replaceSurface, setAbsent)
    // forgets them. False while the surface grows or has no mesh.
    bool processMesh(const MeshProcessing& processing);
    // The mesh before the last processMesh; false when there is none.
    bool undoProcessing();
    // Tracked surfaces: the seed as followed to the new isovalue.
    void setSeed(const FollowedSeed& seed, double iso);
    // No mesh at this isovalue: gone, or merged into surface `into`; the seed stays.
    void setAbsent(Presence presence, double iso, std::uint32_t into = 0);
    // Becomes a tracked surface growing from `seed` (a ctrl-click on an extracted surface).
    void startTracking(std::shared_ptr<const LoadedVolume> volume, double iso, TableKind table, const GridEdge& seed,
                       const Vec3d& seedPoint, int threads);
    Presence presence() const { return presence_; }
    std::uint32_t mergedInto() const { return mergedInto_; }
    double absentSince() const { return absentIso_; }
    const SurfaceFootprint& footprint() const { return footprint_; }
    SurfaceStructure(const SurfaceStructure&) = delete;
    SurfaceStructure& operator=(const SurfaceStructure&) = delete;

    void draw(const render::Renderer& renderer, bool selected, bool colourByGrowth) const;
    void drawWireframe(const render::Renderer& renderer) const;
    void drawPick(const render::Renderer& renderer) const;
    void buildUI(ui::PanelState& state) const;

    bool growing() const { return tracker_ != nullptr; }
    GrowthStep grow(const GrowthBudget& budget);
    // Starts growing again from the seed, with empty buffers.
    void restartGrowth();

    std::uint32_t id() const { return id_; }
    std::uint32_t pickId() const { return id_ + 1; }  // 0 is the background
    const Mesh& mesh() const;
    const SurfaceStats& stats() const { return stats_; }
    const std::optional<Vec3d>& seedPoint() const { return seedPoint_; }
    bool tracked() const { return seedPoint_.has_value(); }
    bool containsEdge(const GridEdge& edge) const;

    render::SurfaceStyle& style() { return style_; }
    const render::SurfaceStyle& style() const { return style_; }
    // The user's move; the exploded view adds explodeOffset on top.
    glm::vec3 userOffset{0.0f};
    std::optional<OwnIso> ownIso;  // nullopt: at the common isovalue
    // Kept in its place by its seed or its own isovalue, not matched by footprint.
    bool keepsPlace() const { return tracked() || ownIso.has_value(); }
    void setExplode(float factor, const glm::vec3& volumeCentre);
    glm::vec3 offset() const { return style_.offset; }
    glm::vec3 centre() const;  // of its bounds, unmoved

    std::size_t cpuBytes() const;  // vertices, indices and their grid edges (Mesh::byteSize)
    std::size_t gpuBytes() const { return gpu_.bytes().capacityBytes; }
    std::size_t drawnIndexCount() const { return gpu_.indexCount(); }

private:
    void finishGrowth();

    std::uint32_t id_;
    Mesh mesh_;
    SurfaceStats stats_;
    std::vector<Surface> beforeProcessing_;  // the meshes processMesh replaced, last on top
    void upload();
    render::GpuMesh gpu_;
    render::SurfaceStyle style_;
    glm::vec3 explodeOffset_{0.0f};
    std::optional<Vec3d> seedPoint_;
    SurfaceFootprint footprint_;
    Presence presence_ = Presence::Shown;
    std::uint32_t mergedInto_ = 0;
    double absentIso_ = 0.0;

    // While growing.
    std::shared_ptr<const LoadedVolume> volume_;
    std::unique_ptr<SurfaceTracker> tracker_;
    double iso_ = 0.0;
    TableKind table_ = TableKind::Consistent;
    GridEdge seed_{};
    int threads_ = 1;  // the tracker's
};

}  // namespace isotrack::viewer
