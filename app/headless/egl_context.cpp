#include "headless/egl_context.h"

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "headless/shared_library.h"

#ifdef ISOTRACK_HAVE_EGL
// Only the types, constants and PFN typedefs: every function comes from
// libEGL.so.1 at run time, and no X11 headers come along.
#define EGL_NO_X11
#define EGL_EGL_PROTOTYPES 0
#include <EGL/egl.h>
#include <EGL/eglext.h>
#endif

namespace isotrack::headless {

#ifdef ISOTRACK_HAVE_EGL

namespace {

// glvnd's libEGL.so.1, which finds the vendor's driver (NVIDIA's, Mesa's) itself;
// ISOTRACK_EGL_LIBRARY names another file, e.g. where a driver bundle keeps it.
const char* eglLibraryName() {
    const char* env = std::getenv("ISOTRACK_EGL_LIBRARY");
    return env != nullptr && *env != '\0' ? env : "libEGL.so.1";
}

struct EglApi {
    SharedLibrary library{eglLibraryName()};
    PFNEGLGETPROCADDRESSPROC getProcAddress = nullptr;
    PFNEGLGETERRORPROC getError = nullptr;
    PFNEGLQUERYSTRINGPROC queryString = nullptr;
    PFNEGLINITIALIZEPROC initialize = nullptr;
    PFNEGLTERMINATEPROC terminate = nullptr;
    PFNEGLBINDAPIPROC bindApi = nullptr;
    PFNEGLCHOOSECONFIGPROC chooseConfig = nullptr;
    PFNEGLCREATECONTEXTPROC createContext = nullptr;
    PFNEGLDESTROYCONTEXTPROC destroyContext = nullptr;
    PFNEGLCREATEPBUFFERSURFACEPROC createPbufferSurface = nullptr;
    PFNEGLDESTROYSURFACEPROC destroySurface = nullptr;
    PFNEGLMAKECURRENTPROC makeCurrent = nullptr;
    // Extensions: null when the client lacks them.
    PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay = nullptr;
    PFNEGLQUERYDEVICESEXTPROC queryDevices = nullptr;
    PFNEGLQUERYDEVICESTRINGEXTPROC queryDeviceString = nullptr;
    std::string clientExtensions;

    EglApi() {
        if (!library.ok()) throw EglUnavailable("EGL is unavailable (" + library.error() + ")");
        getProcAddress = reinterpret_cast<PFNEGLGETPROCADDRESSPROC>(library.symbol("eglGetProcAddress"));
        if (getProcAddress == nullptr)
            throw EglUnavailable("EGL is unavailable: " + library.name() + " lacks eglGetProcAddress");
        require("eglGetError", getError);
        require("eglQueryString", queryString);
        require("eglInitialize", initialize);
        require("eglTerminate", terminate);
        require("eglBindAPI", bindApi);
        require("eglChooseConfig", chooseConfig);
        require("eglCreateContext", createContext);
        require("eglDestroyContext", destroyContext);
        require("eglCreatePbufferSurface", createPbufferSurface);
        require("eglDestroySurface", destroySurface);
        require("eglMakeCurrent", makeCurrent);
        // EGL_EXT_client_extensions: the string of a display-less query; null without it.
        const char* extensions = queryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        clientExtensions = extensions != nullptr ? extensions : "";
        if (hasClientExtension("EGL_EXT_platform_base")) load("eglGetPlatformDisplayEXT", getPlatformDisplay);
        if (hasClientExtension("EGL_EXT_device_enumeration") || hasClientExtension("EGL_EXT_device_base")) {
            load("eglQueryDevicesEXT", queryDevices);
            load("eglQueryDeviceStringEXT", queryDeviceString);
        }
    }

    bool hasClientExtension(const std::string& name) const { return hasWord(clientExtensions, name); }

    static bool hasWord(const std::string& list, const std::string& word) {
        for (std::size_t at = list.find(word); at != std::string::npos; at = list.find(word, at + 1)) {
            const std::size_t end = at + word.size();
            if ((at == 0 || list[at - 1] == ' ') && (end == list.size() || list[end] == ' ')) return true;
        }
        return false;
    }

private:
    template <typename Function>
    void load(const char* name, Function& function) {
        function = reinterpret_cast<Function>(getProcAddress(name));
        if (function == nullptr) function = reinterpret_cast<Function>(library.symbol(name));
    }

    template <typename Function>
    void require(const char* name, Function& function) {
        load(name, function);
        if (function == nullptr) throw EglUnavailable("EGL is unavailable: " + library.name() + " lacks " + name);
    }
};

// Opened once and kept (see shared_library.h); a failed open is retried on the next call.
const EglApi& egl() {
    static const EglApi api;
    return api;
}

std::string errorText(const EglApi& api) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(api.getError()));
    return std::string("EGL error ") + code;
}

// A display to try, and what to call it.
struct Candidate {
    EGLDisplay display = EGL_NO_DISPLAY;
    std::string name;
};

std::string deviceString(const EglApi& api, EGLDeviceEXT device, EGLint name) {
    const char* text = api.queryDeviceString(device, name);
    return text != nullptr ? text : "";
}

// "EGL device 1 (NVIDIA, /dev/dri/card1)": what the device tells about itself.
std::string describeDevice(const EglApi& api, EGLDeviceEXT device, int index, const std::string& extensions) {
    std::vector<std::string> parts;
    if (EglApi::hasWord(extensions, "EGL_EXT_device_persistent_id")) {
        for (EGLint name : {EGLint(EGL_DRIVER_NAME_EXT), EGLint(EGL_RENDERER_EXT)}) {
            const std::string text = deviceString(api, device, name);
            if (!text.empty()) parts.push_back(text);
        }
    }
    if (EglApi::hasWord(extensions, "EGL_EXT_device_drm")) {
        const std::string file = deviceString(api, device, EGL_DRM_DEVICE_FILE_EXT);
        if (!file.empty()) parts.push_back(file);
    }
    if (EglApi::hasWord(extensions, "EGL_NV_device_cuda")) parts.push_back("NVIDIA CUDA device");
    std::string text = "EGL device " + std::to_string(index);
    for (std::size_t i = 0; i < parts.size(); ++i) text += (i == 0 ? " (" : ", ") + parts[i];
    return parts.empty() ? text : text + ")";
}

// EGL devices other than Mesa's software one, in the order EGL lists them.
std::vector<Candidate> hardwareDevices(const EglApi& api) {
    std::vector<Candidate> candidates;
    if (api.queryDevices == nullptr || api.queryDeviceString == nullptr || api.getPlatformDisplay == nullptr ||
        !api.hasClientExtension("EGL_EXT_platform_device")) {
        return candidates;
    }
    EGLint count = 0;
    if (!api.queryDevices(0, nullptr, &count) || count <= 0) return candidates;
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    if (!api.queryDevices(count, devices.data(), &count)) return candidates;
    devices.resize(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        EGLDeviceEXT device = devices[static_cast<std::size_t>(i)];
        const std::string extensions = deviceString(api, device, EGL_EXTENSIONS);
        if (EglApi::hasWord(extensions, "EGL_MESA_device_software")) continue;
        const EGLDisplay display = api.getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
        if (display != EGL_NO_DISPLAY) candidates.push_back({display, describeDevice(api, device, i, extensions)});
    }
    return candidates;
}

std::vector<Candidate> surfacelessPlatform(const EglApi& api) {
    if (api.getPlatformDisplay == nullptr || !api.hasClientExtension("EGL_MESA_platform_surfaceless")) return {};
    const EGLDisplay display = api.getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) return {};
    return {{display, "EGL surfaceless (Mesa)"}};
}

}  // namespace

struct EglContext::Handles {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    EGLSurface surface = EGL_NO_SURFACE;  // a 1x1 pbuffer where surfaceless contexts are not offered

    ~Handles() {
        if (display == EGL_NO_DISPLAY) return;
        const EglApi& api = egl();
        api.makeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        if (context != EGL_NO_CONTEXT) api.destroyContext(display, context);
        if (surface != EGL_NO_SURFACE) api.destroySurface(display, surface);
        api.terminate(display);
    }
};

namespace {

// Makes a GL 3.3 core context current on `display`; empty on success, else why not.
std::string makeContext(const EglApi& api, EGLDisplay display, EglContext::Handles& handles);

}  // namespace

EglContext::EglContext(EglChoice choice) {
    const EglApi& api = egl();
    std::vector<Candidate> candidates = hardwareDevices(api);
    if (choice == EglChoice::HardwareOrSoftware) {
        for (Candidate& candidate : surfacelessPlatform(api)) candidates.push_back(std::move(candidate));
    }
    if (candidates.empty()) {
        throw EglUnavailable(choice == EglChoice::HardwareOnly
                                 ? "EGL offers no hardware device"
                                 : "EGL offers neither a device nor Mesa's surfaceless platform");
    }
    std::string failures;
    for (const Candidate& candidate : candidates) {
        auto handles = std::make_unique<Handles>();
        const std::string why = makeContext(api, candidate.display, *handles);
        if (why.empty()) {
            handles_ = std::move(handles);
            platform_ = candidate.name;
            return;
        }
        failures += (failures.empty() ? "" : "; ") + candidate.name + ": " + why;
    }
    throw gl::Error("EGL could not create an OpenGL 3.3 core context: " + failures);
}

EglContext::~EglContext() = default;

gl::ProcAddress EglContext::procAddress(const char* name) { return egl().getProcAddress(name); }

namespace {

std::string makeContext(const EglApi& api, EGLDisplay display, EglContext::Handles& handles) {
    EGLint major = 0, minor = 0;
    if (!api.initialize(display, &major, &minor)) return "eglInitialize failed, " + errorText(api);
    handles.display = display;  // from here on, ~Handles terminates it
    const char* extensionText = api.queryString(display, EGL_EXTENSIONS);
    const std::string extensions = extensionText != nullptr ? extensionText : "";
    if (!api.bindApi(EGL_OPENGL_API)) return "no desktop OpenGL (eglBindAPI), " + errorText(api);

    // Pixels go to framebuffer objects; the config matters only for a pbuffer fallback.
    const EGLint configAttributes[] = {EGL_SURFACE_TYPE,
                                       EGL_PBUFFER_BIT,
                                       EGL_RENDERABLE_TYPE,
                                       EGL_OPENGL_BIT,
                                       EGL_RED_SIZE,
                                       8,
                                       EGL_GREEN_SIZE,
                                       8,
                                       EGL_BLUE_SIZE,
                                       8,
                                       EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (!api.chooseConfig(display, configAttributes, &config, 1, &configs) || configs < 1) {
        if (!EglApi::hasWord(extensions, "EGL_KHR_no_config_context")) return "no OpenGL config";
        config = EGL_NO_CONFIG_KHR;
    }
    const EGLint contextAttributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,           3,       EGL_CONTEXT_MINOR_VERSION, 3, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    handles.context = api.createContext(display, config, EGL_NO_CONTEXT, contextAttributes);
    if (handles.context == EGL_NO_CONTEXT) return "no OpenGL 3.3 core context, " + errorText(api);
    if (!EglApi::hasWord(extensions, "EGL_KHR_surfaceless_context")) {
        if (config == EGL_NO_CONFIG_KHR) return "neither surfaceless contexts nor a pbuffer config";
        const EGLint pbufferAttributes[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
        handles.surface = api.createPbufferSurface(display, config, pbufferAttributes);
        if (handles.surface == EGL_NO_SURFACE) return "no 1x1 pbuffer, " + errorText(api);
    }
    if (!api.makeCurrent(display, handles.surface, handles.surface, handles.context)) {
        return "eglMakeCurrent failed, " + errorText(api);
    }
    return {};
}

}  // namespace

#else

struct EglContext::Handles {};

EglContext::EglContext(EglChoice) {
    throw EglUnavailable("EGL is unavailable: isotrack was built without its headers (libegl-dev)");
}

EglContext::~EglContext() = default;

gl::ProcAddress EglContext::procAddress(const char*) { return nullptr; }

#endif

}  // namespace isotrack::headless
