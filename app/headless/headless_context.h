#pragma once
// An OpenGL 3.3+ core context without a window or display. Draw into an
// OffscreenTarget; the context's own buffer, if any, is never read. Create it
// before, and destroy it after, every GL object (Renderer, GpuMesh,
// OffscreenTarget) used with it.
//
// Backends (docs/headless.md):
//   OSMesa  Mesa's llvmpipe on the CPU: the reference the golden images are drawn with.
//   Egl     an EGL device (a GPU, no X server) if there is one, else Mesa's
//           surfaceless EGL platform (llvmpipe again, through EGL).
//   Auto    an EGL hardware device if there is one, else OSMesa.
// Both libraries are opened at run time: a machine lacking one still starts.
#include <memory>
#include <string>

#include "gl/check.h"

namespace isotrack::headless {

enum class Backend { Auto, Egl, OSMesa };

// "auto", "egl", "osmesa".
const char* backendName(Backend backend);
// The inverse of backendName; throws gl::Error naming `text` otherwise.
Backend parseBackend(const std::string& text);

class HeadlessContext {
public:
    // Creates the context, makes it current on this thread and loads GL. Throws
    // gl::Error when the backend asked for is unavailable or fails; for Egl,
    // EglUnavailable (egl_context.h) when EGL offers nothing to try at all.
    explicit HeadlessContext(Backend requested = Backend::OSMesa);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    const gl::ContextInfo& info() const;
    // The backend drawing: Egl or OSMesa, never Auto.
    Backend backend() const;
    // Where: "OSMesa", "EGL device 0 (...)", "EGL surfaceless (Mesa)".
    const std::string& platform() const;
    // Why Auto did not use EGL, when it fell back to OSMesa; else empty.
    const std::string& fallbackReason() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// Whether `renderer` (GL_RENDERER) is one of Mesa's CPU rasterisers.
bool isSoftwareRenderer(const std::string& renderer);

}  // namespace isotrack::headless
