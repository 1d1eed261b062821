#include "viewer/camera_controller.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace isotrack::viewer {
namespace {

constexpr float kDegreesPerPixel = 0.3f;
constexpr float kZoomPerWheelStep = 0.88f;
constexpr float kFrameMargin = 1.1f;

void readKeys(const std::vector<KeyPress>& presses, std::vector<KeyCommand>& keys) {
    const ImGuiIO& io = ImGui::GetIO();
    static const struct {
        int key;
        KeyCommand command;
    } kBindings[] = {
        {GLFW_KEY_F, KeyCommand::FrameSelection},
        {GLFW_KEY_A, KeyCommand::FrameAll},
        {GLFW_KEY_ESCAPE, KeyCommand::Deselect},
        {GLFW_KEY_SPACE, KeyCommand::PlayPause},
        {GLFW_KEY_N, KeyCommand::Step},
        {GLFW_KEY_S, KeyCommand::ShowAll},
        {GLFW_KEY_H, KeyCommand::HideSelected},
        {GLFW_KEY_I, KeyCommand::IsolateSelected},
        {GLFW_KEY_DELETE, KeyCommand::DeleteSelected},
        {GLFW_KEY_BACKSPACE, KeyCommand::DeleteSelected},
        {GLFW_KEY_E, KeyCommand::ExportSelected},
        {GLFW_KEY_W, KeyCommand::ToggleWireframe},
        {GLFW_KEY_G, KeyCommand::ToggleGrowthColour},
        {GLFW_KEY_P, KeyCommand::TimePlayPause},
        {GLFW_KEY_LEFT_BRACKET, KeyCommand::TimeBack},
        {GLFW_KEY_RIGHT_BRACKET, KeyCommand::TimeForward},
    };
    for (const KeyPress& press : presses) {
        if (press.ctrl && press.key == GLFW_KEY_Q) keys.push_back(KeyCommand::Quit);
        if (press.key == GLFW_KEY_F12) keys.push_back(KeyCommand::Screenshot);
        if (io.WantCaptureKeyboard || press.ctrl || press.super || press.alt) continue;
        for (const auto& binding : kBindings) {
            if (press.key == binding.key) keys.push_back(binding.command);
        }
    }
}

// Screen right and up at the target, in world space.
void screenAxes(const render::Camera& camera, glm::vec3& right, glm::vec3& up) {
    const glm::vec3 forward = glm::normalize(camera.target - camera.eye());
    right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 0.0f, 1.0f)));
    up = glm::cross(right, forward);
}

}  // namespace

float worldPerPixel(const render::Camera& camera, float heightPixels) {
    return 2.0f * camera.distance * std::tan(glm::radians(camera.fov) * 0.5f) / std::max(heightPixels, 1.0f);
}

render::Camera frameKeepingAngles(const render::Camera& camera, const render::Bounds& bounds) {
    render::Camera framed = camera;
    framed.target = bounds.centre();
    const float radius = std::max(bounds.radius(), 1e-3f);
    framed.distance = kFrameMargin * radius / std::sin(glm::radians(camera.fov) * 0.5f);
    return framed;
}

ViewInput CameraController::update(render::Camera& camera, const ViewRect& view, const std::vector<KeyPress>& keys) {
    ViewInput input;
    readKeys(keys, input.keys);
    const ImGuiIO& io = ImGui::GetIO();
    const ImVec2 mouse = io.MousePos;
    for (int button = 0; button < 3; ++button) {
        if (ImGui::IsMouseClicked(button))
            pressInView_[button] = !io.WantCaptureMouse && view.contains(mouse.x, mouse.y);
    }
    if (io.WantCaptureMouse && !pressInView_[0] && !pressInView_[1] && !pressInView_[2]) return input;

    if (view.contains(mouse.x, mouse.y) && io.MouseWheel != 0.0f && !io.WantCaptureMouse) {
        camera.zoom(std::pow(kZoomPerWheelStep, io.MouseWheel));
    }
    const glm::vec2 delta{io.MouseDelta.x, io.MouseDelta.y};
    const bool moved = delta.x != 0.0f || delta.y != 0.0f;
    const float perPixel = worldPerPixel(camera, view.height);
    if (pressInView_[0] && ImGui::IsMouseDragging(ImGuiMouseButton_Left) && moved) {
        if (io.KeyAlt) {
            glm::vec3 right, up;
            screenAxes(camera, right, up);
            input.moveSelection = (right * delta.x - up * delta.y) * perPixel;
        } else if (io.KeyShift) {
            camera.pan(-delta.x * perPixel / camera.distance, delta.y * perPixel / camera.distance);
        } else {
            camera.orbit(-delta.x * kDegreesPerPixel, delta.y * kDegreesPerPixel);
        }
    }
    for (int button : {ImGuiMouseButton_Right, ImGuiMouseButton_Middle}) {
        if (pressInView_[button] && ImGui::IsMouseDragging(button) && moved) {
            camera.pan(-delta.x * perPixel / camera.distance, delta.y * perPixel / camera.distance);
        }
    }
    // A click: pressed and released in the view without dragging past ImGui's threshold.
    if (pressInView_[0] && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
        const ImVec2 drag = ImGui::GetMouseDragDelta(ImGuiMouseButton_Left);
        if (drag.x == 0.0f && drag.y == 0.0f && view.contains(mouse.x, mouse.y)) {
            input.click = glm::vec2(mouse.x - view.x, mouse.y - view.y);
            input.trackClick = io.KeyCtrl;
        }
    }
    for (int button = 0; button < 3; ++button) {
        if (ImGui::IsMouseReleased(button)) pressInView_[button] = false;
    }
    return input;
}

}  // namespace isotrack::viewer
