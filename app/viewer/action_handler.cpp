// What the panel, the keys and scripts ask for, applied between frames.
#include <algorithm>
#include <type_traits>
#include <variant>

#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/orientation.h"
#include "viewer/action_handler.h"

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

void ActionHandler::apply(const ui::Action& action) {
    std::visit(Overloaded{
                   [&](const ui::LoadField& a) {
                       extraction_.load(VolumeSource::field(a.name + ":" + std::to_string(a.size)));
                   },
                   [&](const ui::LoadFile& a) { extraction_.load(VolumeSource::file(a.path)); },
                   [&](const ui::SetIso& a) {
                       extraction_.setIso(a.iso);
                       extraction_.submit();
                   },
                   [&](const ui::SetTable& a) {
                       extraction_.setTable(a.table);
                       extraction_.submit();
                   },
                   [&](const ui::SetMethod& a) { extraction_.chooseMethod(a.method); },
                   [&](const ui::ConfirmExtraction&) { extraction_.confirm(); },
                   [&](const ui::CancelExtraction&) { extraction_.cancelConfirmation(); },
                   [&](const ui::Growth& a) {
                       switch (a.kind) {
                           case ui::Growth::Play: growth_.play(); break;
                           case ui::Growth::Pause: growth_.pause(); break;
                           case ui::Growth::Step: growth_.step(); break;
                           case ui::Growth::Restart:
                               for (auto& surface : scene_.surfaces()) {
                                   if (!scene_.selected || scene_.selected == surface->id()) surface->restartGrowth();
                               }
                               scene_.refreshOffsets();
                               break;
                       }
                   },
                   [&](const ui::SetCellsPerFrame& a) { growth_.setCellsPerFrame(a.cells); },
                   [&](const ui::SetGrowthBudget& a) { growth_.setBudgetMs(a.ms); },
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
                   [&](const ui::SetSurfaceIso& a) { extraction_.setSurfaceIso(a.id, a.iso); },
                   [&](const ui::SetTimeStep& a) { time_.setStep(a.step); },
                   [&](const ui::PlayTime& a) {
                       if (a.play) {
                           time_.play(a.steps);
                       } else {
                           time_.pause();
                       }
                   },
                   [&](const ui::SetTimeSpeed& a) { time_.setSpeed(a.stepsPerSecond); },
                   [&](const ui::SetMinPersistence& a) {
                       extraction_.setMinPersistence(std::max(a.persistence, 0.0));
                       extraction_.submit();
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
                           status_.show("surface " + std::to_string(a.id) + ": back to " +
                                        std::to_string(s->mesh().triangleCount()) + " triangles");
                   },
                   [&](const ui::FrameSelection&) { frameCamera(true); },
                   [&](const ui::FrameAll&) { frameCamera(false); },
               },
               action);
}

void ActionHandler::applyKey(KeyCommand key) {
    const std::optional<std::uint32_t> selected = scene_.selected;
    switch (key) {
        case KeyCommand::FrameSelection: apply(ui::FrameSelection{}); break;
        case KeyCommand::FrameAll: apply(ui::FrameAll{}); break;
        case KeyCommand::Deselect: apply(ui::Select{std::nullopt}); break;
        case KeyCommand::PlayPause: apply(ui::Growth{growth_.playing() ? ui::Growth::Pause : ui::Growth::Play}); break;
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
        case KeyCommand::TimePlayPause: time_.togglePlay(); break;
        case KeyCommand::TimeBack: time_.stepBy(-1); break;
        case KeyCommand::TimeForward: time_.stepBy(1); break;
        case KeyCommand::Quit: requests_.quit = true; break;
        case KeyCommand::Screenshot: {
            requests_.screenshotPath = "isotrack_screenshot_" + std::to_string(++requests_.screenshots) + ".png";
            status_.show("screenshot: " + *requests_.screenshotPath);
            break;
        }
        case KeyCommand::ExportSelected:
            if (selected) apply(ui::Export{*selected, ui::exportPath(panel_.exportPattern(), *selected)});
            break;
    }
}

void ActionHandler::frameCamera(bool selectionOnly) {
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
// (core's applyVolumeDefaults for the volume shown).
void ActionHandler::processMesh(const ui::ProcessMesh& request) {
    SurfaceStructure* surface = scene_.find(request.id);
    if (surface == nullptr) return;
    MeshProcessing processing;
    processing.smoothIterations = request.smooth;
    processing.decimateRatio = request.decimate;
    if (scene_.volume()) applyVolumeDefaults(processing, scene_.volume()->volume);
    const std::size_t before = surface->mesh().triangleCount();
    if (!surface->processMesh(processing)) {
        status_.show("surface " + std::to_string(request.id) + ": no finished mesh to smooth or decimate");
        return;
    }
    status_.show("surface " + std::to_string(request.id) + ": " + std::to_string(before) + " -> " +
                 std::to_string(surface->mesh().triangleCount()) + " triangles (undo to go back)");
}

void ActionHandler::exportSurface(std::uint32_t id, const std::string& path) {
    const SurfaceStructure* surface = scene_.find(id);
    if (surface == nullptr) return;
    if (surface->presence() != Presence::Shown) {
        throw InputError("export " + path + ": surface " + std::to_string(id) + " has no mesh at isovalue " +
                         std::to_string(extraction_.shownIso()));
    }
    const MeshFormat format = meshFormatOf(path);
    Mesh mesh = surface->mesh();
    if (scene_.volume()) transformMesh(mesh, gridToFrame(scene_.volume()->volume, exportFrame_));
    writeMesh(path, mesh);
    status_.show("surface " + std::to_string(id) + ": wrote " + std::to_string(surface->mesh().triangleCount()) +
                 " triangles to " + path + " (" + meshFormatExtension(format) + ")");
}

}  // namespace isotrack::viewer
