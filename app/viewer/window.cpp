#include "viewer/window.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <cstdlib>

namespace isotrack::viewer {
namespace {

std::string& lastGlfwError() {
    static std::string error;
    return error;
}

void recordGlfwError(int /*code*/, const char* description) { lastGlfwError() = description ? description : ""; }

std::string noDisplayMessage() {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    std::string why = lastGlfwError().empty() ? "GLFW could not start" : lastGlfwError();
    if ((display == nullptr || *display == '\0') && (wayland == nullptr || *wayland == '\0')) {
        why = "no display (DISPLAY is not set)";
    }
    return "cannot open a window: " + why +
           "; run it under a virtual display, e.g. xvfb-run -a -s \"-screen 0 1600x1000x24\" isotrack ...";
}

}  // namespace

Window::Window(int width, int height, const std::string& title, bool vsync) {
    glfwSetErrorCallback(recordGlfwError);
    if (glfwInit() != GLFW_TRUE) throw DisplayError(noDisplayMessage());
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_SAMPLES, 0);  // single-sampled: screenshots are reproducible
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (window_ == nullptr) {
        const std::string why = lastGlfwError();
        glfwTerminate();
        throw DisplayError("cannot create an OpenGL 3.3 core window (" + why + ")");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(vsync ? 1 : 0);
    try {
        info_ = gl::loadFunctions(reinterpret_cast<gl::ProcAddressLoader>(glfwGetProcAddress));
    } catch (const gl::Error& e) {
        glfwDestroyWindow(window_);
        glfwTerminate();
        throw DisplayError(e.what());
    }

    // Installed before ImGui's backend, which chains to it.
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, onKey);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    imgui_ = true;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini: the layout is fixed, and runs are reproducible
    ImGui::StyleColorsDark();
    imguiGlfw_ = ImGui_ImplGlfw_InitForOpenGL(window_, true);
    imguiGl_ = ImGui_ImplOpenGL3_Init("#version 330 core");
    if (!imguiGlfw_ || !imguiGl_) {
        this->~Window();  // a constructor that throws gets no destructor call
        throw DisplayError("cannot start Dear ImGui's GLFW + OpenGL3 backends");
    }
}

Window::~Window() {
    if (imguiGl_) ImGui_ImplOpenGL3_Shutdown();
    if (imguiGlfw_) ImGui_ImplGlfw_Shutdown();
    if (imgui_) ImGui::DestroyContext();
    if (window_ != nullptr) glfwDestroyWindow(window_);
    glfwTerminate();
}

bool Window::shouldClose() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }
void Window::requestClose() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }
void Window::framebufferSize(int& width, int& height) const { glfwGetFramebufferSize(window_, &width, &height); }
void Window::windowSize(int& width, int& height) const { glfwGetWindowSize(window_, &width, &height); }
void Window::waitEvents(double seconds) { glfwWaitEventsTimeout(seconds); }
void Window::pollEvents() { glfwPollEvents(); }
void Window::swapBuffers() { glfwSwapBuffers(window_); }

void Window::onKey(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
    if (action != GLFW_PRESS) return;
    auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
    constexpr std::size_t kMaxQueued = 64;
    if (self == nullptr || self->keyPresses_.size() >= kMaxQueued) return;
    self->keyPresses_.push_back(KeyPress{key, (mods & GLFW_MOD_CONTROL) != 0, (mods & GLFW_MOD_SHIFT) != 0,
                                         (mods & GLFW_MOD_ALT) != 0, (mods & GLFW_MOD_SUPER) != 0});
}

std::vector<KeyPress> Window::takeKeyPresses() {
    std::vector<KeyPress> presses;
    presses.swap(keyPresses_);
    return presses;
}

void Window::beginImGuiFrame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void Window::finishImGuiFrame() { ImGui::Render(); }

void Window::drawImGui() { ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData()); }

std::size_t Window::imguiFontBytes() {
    const ImFontAtlas* fonts = ImGui::GetIO().Fonts;
    return std::size_t(fonts->TexWidth) * std::size_t(fonts->TexHeight) * 4;
}

}  // namespace isotrack::viewer
