#pragma once
// What the viewer shows: the volume (its box, and what the panel says about
// it) and the surfaces, with the selection and the view settings that apply to
// all of them. Draws itself and its pick ids through the renderer; knows its
// CPU and GPU bytes.
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "render/camera.h"
#include "render/renderer.h"
#include "ui/panel_state.h"
#include "viewer/extraction_worker.h"
#include "viewer/surface_structure.h"

namespace isotrack::render {
class PickTarget;
}

namespace isotrack::viewer {

class Scene {
public:
    // ---- the volume ----
    const std::shared_ptr<const LoadedVolume>& volume() const { return volume_; }
    // Returns true when it is a different volume from before (the box moved).
    bool setVolume(std::shared_ptr<const LoadedVolume> volume);
    render::Bounds volumeBounds() const;
    glm::vec3 volumeCentre() const { return volumeBounds().centre(); }
    // The volume's box grown by every visible surface's offset: what the clip planes must hold.
    render::Bounds drawBounds() const;

    // ---- surfaces ----
    std::vector<std::unique_ptr<SurfaceStructure>>& surfaces() { return surfaces_; }
    const std::vector<std::unique_ptr<SurfaceStructure>>& surfaces() const { return surfaces_; }
    SurfaceStructure* find(std::uint32_t id);
    const SurfaceStructure* find(std::uint32_t id) const;
    const SurfaceStructure* findByPickId(std::uint32_t pickId) const;
    std::uint32_t newId() { return nextId_++; }
    void add(std::unique_ptr<SurfaceStructure> surface);
    void remove(std::uint32_t id);
    void clearSurfaces();
    bool anyGrowing() const;

    std::optional<std::uint32_t> selected;
    SurfaceStructure* selection() { return selected ? find(*selected) : nullptr; }

    // ---- view settings ----
    float explode() const { return explode_; }
    void setExplode(float factor);
    void refreshOffsets();  // after a user offset or the surfaces change
    bool wireframe = false;
    bool boundingBox = true;
    bool colourByGrowth = false;

    // ---- drawing ----
    void draw(const render::Renderer& renderer, const render::FrameView& frame,
              const render::FrameOptions& options) const;
    void drawPick(const render::Renderer& renderer, const render::FrameView& frame,
                  const render::PickTarget& target) const;
    void buildUI(ui::PanelState& state) const;
    // Changes whenever drawing the scene with `camera` and `options` would give a different image.
    std::uint64_t signature(const render::Camera& camera, const render::FrameOptions& options) const;

    // ---- memory ----
    std::size_t cpuVolumeBytes() const;
    std::size_t cpuMeshBytes() const;
    std::size_t gpuSurfaceBytes() const;

private:
    std::shared_ptr<const LoadedVolume> volume_;
    std::vector<std::unique_ptr<SurfaceStructure>> surfaces_;
    std::uint32_t nextId_ = 0;
    float explode_ = 0.0f;
};

}  // namespace isotrack::viewer
