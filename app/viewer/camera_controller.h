#pragma once
// Mouse and keys in the 3D view, read from Dear ImGui's IO: the mouse only when
// ImGui does not want it (!io.WantCaptureMouse), keys only when it does not
// want the keyboard.
//
//   left drag: orbit            right or middle drag, shift + left drag: pan
//   wheel: zoom                 click: pick (select); ctrl + click: track there
//   alt + left drag: move the selected surface in the view plane
//   keys: F frame selection, A frame all, Esc deselect, H hide, I isolate,
//   S show all, Delete delete, E export, Space play/pause, N step growth,
//   W wireframe, G colour by growth order, P play/pause time, [ ] step back
//   and forward in time, F12 screenshot, ctrl + Q quit
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "render/camera.h"
#include "viewer/window.h"

namespace isotrack::viewer {

// The 3D view in window coordinates (pixels from the window's top-left).
struct ViewRect {
    float x = 0.0f, y = 0.0f, width = 1.0f, height = 1.0f;
    bool contains(float px, float py) const { return px >= x && py >= y && px < x + width && py < y + height; }
};

enum class KeyCommand {
    FrameSelection,
    FrameAll,
    Deselect,
    PlayPause,
    Step,
    ShowAll,
    HideSelected,
    IsolateSelected,
    DeleteSelected,
    ExportSelected,
    ToggleWireframe,
    ToggleGrowthColour,
    TimePlayPause,  // P
    TimeBack,       // [
    TimeForward,    // ]
    Screenshot,     // F12
    Quit,           // ctrl + Q
};

struct ViewInput {
    std::optional<glm::vec2> click;  // in view pixels from the view's top-left
    bool trackClick = false;         // ctrl was held
    glm::vec3 moveSelection{0.0f};   // world translation for the selected surface
    std::vector<KeyCommand> keys;
};

class CameraController {
public:
    // `keys`: the key presses of this frame, from the window's queue.
    ViewInput update(render::Camera& camera, const ViewRect& view, const std::vector<KeyPress>& keys);

private:
    bool pressInView_[3] = {false, false, false};
};

// The camera turned as it is, moved back far enough to see all of `bounds`.
render::Camera frameKeepingAngles(const render::Camera& camera, const render::Bounds& bounds);

// World units per pixel at the camera's target, for a view `heightPixels` tall.
float worldPerPixel(const render::Camera& camera, float heightPixels);

}  // namespace isotrack::viewer
