#pragma once
// An OpenGL 3.3+ core context without a window or display, through Mesa's
// OSMesa (llvmpipe on the CPU). Draw into an OffscreenTarget; the context's own
// buffer is a token 1x1 and never read. Create it before, and destroy it after,
// every GL object (Renderer, GpuMesh, OffscreenTarget) used with it.
#include <memory>

#include "gl/check.h"

namespace isotrack::headless {

class HeadlessContext {
public:
    // Creates the context, makes it current on this thread and loads GL. Throws
    // gl::Error when OSMesa is unavailable (also when built without it) or the
    // context cannot be created.
    HeadlessContext();
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    const gl::ContextInfo& info() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace isotrack::headless
