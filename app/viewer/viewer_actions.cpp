// What the panel, the keys and scripts ask for, applied between frames.
#include <algorithm>
#include <type_traits>

#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/orientation.h"
#include "viewer/viewer.h"

namespace isotrack::viewer {
namespace {

glm::vec3 toVec3(const std::array<float, 3>& v) { return {v[0], v[1], v[2]}; }

template <class... Ts>
struct Overloaded : Ts... {
    using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;

}  // namespace

void Viewer::apply(const ui::Action& action) {
    std::visit(Overloaded{
                   [&](const ui::LoadField& a) {
                       confirmation_.reset();
                       extraction_.setSource(VolumeSource::field(a.name + ":" + std::to_string(a.size)));
                       submit();
                   },
                   [&](const ui::LoadFile& a) {
                       confirmation_.reset();
                       extraction_.setSource(VolumeSource::file(a.path));
                       submit();
                   },
                   [&](const ui::SetIso& a) {
                       extraction_.setIso(a.iso);
                       submit();
                   },
                   [&](const ui::SetTable& a) {
                       extraction_.setTable(a.table);
                       submit();
                   },
                   [&](const ui::SetMethod& a) {
                       methodChosen_ = true;
                       confirmation_.reset();
                       extraction_.setMethod(a.method);
                       submit();
                   },
                   [&](const ui::ConfirmExtraction&) {
                       if (!confirmation_) throw InputError("confirm: no extraction waits for confirmation");
                       extraction_.confirm(confirmation_->method);
                       extraction_.setMethod(confirmation_->method);
                       confirmation_.reset();
                       submit();
                   },
                   [&](const ui::CancelExtraction&) {
                       if (!confirmation_) return;
                       confirmation_.reset();
                       extraction_.setMethod(ui::Method::Track);
                       submit();
                   },
                   [&](const ui::Growth& a) {
                       switch (a.kind) {
                           case ui::Growth::Play: playing_ = true; break;
                           case ui::Growth::Pause: playing_ = false; break;
                           case ui::Growth::Step:
                               playing_ = false;
                               stepOnce_ = true;
                               break;
                           case ui::Growth::Restart:
                               for (auto& surface : scene_.surfaces()) {
                                   if (!scene_.selected || scene_.selected == surface->id()) surface->restartGrowth();
                               }
                               scene_.refreshOffsets();
                               break;
                       }
                   },
                   [&](const ui::SetCellsPerFrame& a) { cellsPerFrame_ = a.cells; },
                   [&](const ui::SetGrowthBudget& a) { growthBudgetMs_ = std::clamp(a.ms, 0.25f, 1000.0f); },
                   [&](const ui::SetColourByGrowth& a) { scene_.colourByGrowth = a.on; },
                   [&](const ui::Select& a) { scene_.selected = a.id; },
                   [&](const ui::SetVisible& a) {
                       if (SurfaceStructure* s = scene_.find(a.id)) s->style().visible = a.visible;
                   },
                   [&](const ui::Isolate& a) {
                       for (auto& surface : scene_.surfaces()) surface->style().visible = surface->id() == a.id;
                       scene_.selected = a.id;
                   },
                   [&](const ui::ShowAll&) {
                       for (auto& surface : scene_.surfaces()) surface->style().visible = true;
                   },
                   [&](const ui::Delete& a) { scene_.remove(a.id); },
                   [&](const ui::Export& a) { exportSurface(a.id, a.path); },
                   [&](const ui::SetSurfaceIso& a) { setSurfaceIso(a.id, a.iso); },
                   [&](const ui::SetMinPersistence& a) {
                       extraction_.setMinPersistence(std::max(a.persistence, 0.0));
                       submit();
                   },
                   [&](const ui::SetColour& a) {
                       if (SurfaceStructure* s = scene_.find(a.id)) s->style().colour = toVec3(a.colour);
                   },
                   [&](const ui::SetOffset& a) {
                       if (SurfaceStructure* s = scene_.find(a.id)) {
                           s->userOffset = toVec3(a.offset);
                           scene_.refreshOffsets();
                       }
                   },
                   [&](const ui::SetExplode& a) { scene_.setExplode(a.factor); },
                   [&](const ui::SetWireframe& a) { scene_.wireframe = a.on; },
                   [&](const ui::SetBoundingBox& a) { scene_.boundingBox = a.on; },
                   [&](const ui::ProcessMesh& a) { processMesh(a); },
                   [&](const ui::UndoMesh& a) {
                       SurfaceStructure* s = scene_.find(a.id);
                       if (s && s->undoProcessing())
                           status("surface " + std::to_string(a.id) + ": back to " +
                                  std::to_string(s->mesh().triangleCount()) + " triangles");
                   },
                   [&](const ui::FrameSelection&) { frameCamera(true); },
                   [&](const ui::FrameAll&) { frameCamera(false); },
               },
               action);
}

void Viewer::applyKey(KeyCommand key) {
    const std::optional<std::uint32_t> selected = scene_.selected;
    switch (key) {
        case KeyCommand::FrameSelection: apply(ui::FrameSelection{}); break;
        case KeyCommand::FrameAll: apply(ui::FrameAll{}); break;
        case KeyCommand::Deselect: apply(ui::Select{std::nullopt}); break;
        case KeyCommand::PlayPause: apply(ui::Growth{playing_ ? ui::Growth::Pause : ui::Growth::Play}); break;
        case KeyCommand::Step: apply(ui::Growth{ui::Growth::Step}); break;
        case KeyCommand::ShowAll: apply(ui::ShowAll{}); break;
        case KeyCommand::ToggleWireframe: apply(ui::SetWireframe{!scene_.wireframe}); break;
        case KeyCommand::ToggleGrowthColour: apply(ui::SetColourByGrowth{!scene_.colourByGrowth}); break;
        case KeyCommand::HideSelected:
            if (selected) apply(ui::SetVisible{*selected, false});
            break;
        case KeyCommand::IsolateSelected:
            if (selected) apply(ui::Isolate{*selected});
            break;
        case KeyCommand::DeleteSelected:
            if (selected) apply(ui::Delete{*selected});
            break;
        case KeyCommand::Quit: quit_ = true; break;
        case KeyCommand::Screenshot: {
            screenshotPath_ = "isotrack_screenshot_" + std::to_string(++screenshots_) + ".png";
            status("screenshot: " + *screenshotPath_);
            break;
        }
        case KeyCommand::ExportSelected:
            if (selected) apply(ui::Export{*selected, ui::exportPath(panel_.exportPattern(), *selected)});
            break;
    }
}

void Viewer::frameCamera(bool selectionOnly) {
    render::Bounds bounds = scene_.drawBounds();
    const SurfaceStructure* selected = selectionOnly ? scene_.selection() : nullptr;
    if (selected != nullptr && selected->mesh().triangleCount() > 0) {
        const SurfaceStats& stats = selected->stats();
        for (int axis = 0; axis < 3; ++axis) {
            bounds.min[axis] = static_cast<float>(stats.boundsMin[axis]) + selected->offset()[axis];
            bounds.max[axis] = static_cast<float>(stats.boundsMax[axis]) + selected->offset()[axis];
        }
    }
    camera_ = frameKeepingAngles(camera_, bounds);
}

// The path's extension picks the format (PLY, OBJ or STL), as for `isotrack extract --out`;
// the mesh leaves the grid the view draws in for --frame (LPS world by default),
// through the same transform, so the file equals extract's for the same surface.
// Smoothing and decimation of one surface, with the command line's defaults
// (core's defaultDecimateError for the volume shown).
void Viewer::processMesh(const ui::ProcessMesh& request) {
    SurfaceStructure* surface = scene_.find(request.id);
    if (surface == nullptr) return;
    MeshProcessing processing;
    processing.smoothIterations = request.smooth;
    processing.decimateRatio = request.decimate;
    if (processing.decimates() && scene_.volume())
        processing.decimateError = defaultDecimateError(scene_.volume()->volume);
    const std::size_t before = surface->mesh().triangleCount();
    if (!surface->processMesh(processing)) {
        status("surface " + std::to_string(request.id) + ": no finished mesh to smooth or decimate");
        return;
    }
    status("surface " + std::to_string(request.id) + ": " + std::to_string(before) + " -> " +
           std::to_string(surface->mesh().triangleCount()) + " triangles (undo to go back)");
}

void Viewer::exportSurface(std::uint32_t id, const std::string& path) {
    const SurfaceStructure* surface = scene_.find(id);
    if (surface == nullptr) return;
    if (surface->presence() != Presence::Shown) {
        throw InputError("export " + path + ": surface " + std::to_string(id) + " has no mesh at isovalue " +
                         std::to_string(shownIso()));
    }
    const MeshFormat format = meshFormatOf(path);
    Mesh mesh = surface->mesh();
    if (scene_.volume()) transformMesh(mesh, gridToFrame(scene_.volume()->volume, options_.frame));
    writeMesh(path, mesh);
    status("surface " + std::to_string(id) + ": wrote " + std::to_string(surface->mesh().triangleCount()) +
           " triangles to " + path + " (" + meshFormatExtension(format) + ")");
}

}  // namespace isotrack::viewer
