#pragma once
// An OpenGL 3.3 core context through EGL, with no window, display or X server:
// on an EGL device (EGL_EXT_platform_device: a GPU driver such as NVIDIA's) or
// on Mesa's surfaceless platform (llvmpipe on the CPU here). It is made current
// without a surface; drawing goes into framebuffer objects (OffscreenTarget).
// libEGL.so.1 is opened at run time, so machines without it still start.
#include <memory>
#include <string>

#include "gl/check.h"

namespace isotrack::headless {

// EGL offers nothing to try: no libEGL.so.1, or neither a device nor the
// surfaceless platform. (A platform that is there but fails throws gl::Error.)
class EglUnavailable : public gl::Error {
public:
    using gl::Error::Error;
};

enum class EglChoice {
    HardwareOnly,        // EGL devices that are not Mesa's software device
    HardwareOrSoftware,  // those first, then Mesa's surfaceless platform
};

class EglContext {
public:
    // Creates the context and makes it current on this thread.
    explicit EglContext(EglChoice choice);
    ~EglContext();
    EglContext(const EglContext&) = delete;
    EglContext& operator=(const EglContext&) = delete;

    // Where the context lives, e.g. "EGL device 0 (/dev/dri/card0)" or "EGL surfaceless (Mesa)".
    const std::string& platform() const { return platform_; }

    // eglGetProcAddress, for gl::loadFunctions.
    static gl::ProcAddress procAddress(const char* name);

    struct Handles;  // display, context and surface; defined in egl_context.cpp

private:
    std::unique_ptr<Handles> handles_;
    std::string platform_;
};

}  // namespace isotrack::headless
