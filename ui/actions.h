#pragma once
// What the panel (and the keyboard, mouse and scripts) ask the viewer to do.
// The panel records these; the viewer applies them between frames.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "ui/panel_state.h"

namespace isotrack::ui {

struct LoadField {
    std::string name;
    int size = 0;
};
struct LoadFile {
    std::string path;
};
struct SetIso {
    double iso = 0.0;
};
struct SetTable {
    Table table = Table::Consistent;
};
struct SetMethod {
    Method method = Method::All;
};
struct Growth {
    enum Kind { Play, Pause, Step, Restart } kind = Play;
};
struct SetCellsPerFrame {
    int cells = 0;  // 0: time budget
};
struct SetGrowthBudget {
    float ms = 4.0f;  // extraction time per frame, when cells per frame is 0
};
struct SetColourByGrowth {
    bool on = false;
};
struct Select {
    std::optional<std::uint32_t> id;  // nullopt: clear the selection
};
struct SetVisible {
    std::uint32_t id = 0;
    bool visible = true;
};
struct Isolate {
    std::uint32_t id = 0;
};
struct ShowAll {};
struct Delete {
    std::uint32_t id = 0;
};
struct Export {
    std::uint32_t id = 0;
    std::string path;
};
struct SetColour {
    std::uint32_t id = 0;
    std::array<float, 3> colour{};
};
struct SetOffset {
    std::uint32_t id = 0;
    std::array<float, 3> offset{};
};
struct SetExplode {
    float factor = 0.0f;
};
struct SetWireframe {
    bool on = false;
};
struct SetBoundingBox {
    bool on = true;
};
struct SetMinPersistence {  // method tree: hide surfaces whose arc's persistence is below this
    double persistence = 0.0;
};
struct SetSurfaceIso {  // method tree: surface `id` at an isovalue of its own
    std::uint32_t id = 0;
    double iso = 0.0;
};
// A volume over the memory budget: let the method asked for read it whole, or
// do not (back to track).
struct ConfirmExtraction {};
struct CancelExtraction {};
// Smooth (iterations, 0: none) then decimate (fraction of triangles kept, 1:
// none) surface `id`'s mesh, as `isotrack extract --smooth --decimate` does.
struct ProcessMesh {
    std::uint32_t id = 0;
    int smooth = 0;
    double decimate = 1.0;
};
// Back to the surface's mesh before its last ProcessMesh.
struct UndoMesh {
    std::uint32_t id = 0;
};
struct FrameSelection {};
struct FrameAll {};
// A time series: show step `step`; play or pause; playback speed.
struct SetTimeStep {
    std::size_t step = 0;
};
struct PlayTime {
    bool play = true;
    std::optional<std::size_t> steps;  // how many steps to play; nullopt: to the last
};
struct SetTimeSpeed {
    float stepsPerSecond = 4.0f;
};

using Action = std::variant<LoadField, LoadFile, SetIso, SetTable, SetMethod, Growth, SetCellsPerFrame, SetGrowthBudget,
                            SetColourByGrowth, Select, SetVisible, Isolate, ShowAll, Delete, Export, SetColour,
                            SetOffset, SetExplode, SetWireframe, SetBoundingBox, SetMinPersistence, SetSurfaceIso,
                            ConfirmExtraction, CancelExtraction, ProcessMesh, UndoMesh, FrameSelection, FrameAll,
                            SetTimeStep, PlayTime, SetTimeSpeed>;

inline constexpr const char* kDefaultExportPattern = "surface_{id}.ply";

// "surface_{id}.ply" with {id} replaced by the surface id.
std::string exportPath(const std::string& pattern, std::uint32_t id);

}  // namespace isotrack::ui
