#pragma once
// The viewer's window: GLFW with an OpenGL 3.3 core context, GL loaded through
// app/gl, and Dear ImGui on it with its standard GLFW + OpenGL3 backends.
// Both are RAII: the destructor shuts ImGui down, then destroys the window and
// terminates GLFW. Create GL objects after, and destroy them before, this.
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/check.h"

struct GLFWwindow;

namespace isotrack::viewer {

// No display to open a window on, or no OpenGL 3.3 there.
class DisplayError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A key that went down, with the modifiers held. Dear ImGui 1.86 keeps only
// which keys are down at each frame, so a press and release within one frame
// (a quick tap, or xdotool) would be lost; the window queues them instead.
struct KeyPress {
    int key = 0;  // GLFW_KEY_*
    bool ctrl = false, shift = false, alt = false, super = false;
};

class Window {
public:
    // `vsync`: swap with the display's refresh (interactive); off for scripts.
    Window(int width, int height, const std::string& title, bool vsync);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    const gl::ContextInfo& info() const { return info_; }

    bool shouldClose() const;
    void requestClose();
    void framebufferSize(int& width, int& height) const;
    void windowSize(int& width, int& height) const;
    // Sleeps until an event arrives or `seconds` pass (for an idle interactive window).
    static void waitEvents(double seconds);
    static void pollEvents();
    void swapBuffers();
    // The keys pressed since the last call, oldest first.
    std::vector<KeyPress> takeKeyPresses();

    // ImGui's frame: begin after polling events; finish (ImGui::Render) ends
    // building the widgets; draw renders them over whatever was drawn before.
    static void beginImGuiFrame();
    static void finishImGuiFrame();
    static void drawImGui();
    // The font atlas texture, for GPU accounting.
    static std::size_t imguiFontBytes();

private:
    static void onKey(GLFWwindow* window, int key, int scancode, int action, int mods);

    GLFWwindow* window_ = nullptr;
    std::vector<KeyPress> keyPresses_;
    gl::ContextInfo info_;
    bool imgui_ = false, imguiGlfw_ = false, imguiGl_ = false;
};

}  // namespace isotrack::viewer
