#include "headless/headless_context.h"

#include "headless/egl_context.h"
#include "headless/osmesa_context.h"

namespace isotrack::headless {

const char* backendName(Backend backend) {
    switch (backend) {
        case Backend::Auto: return "auto";
        case Backend::Egl: return "egl";
        case Backend::OSMesa: return "osmesa";
    }
    return "?";
}

Backend parseBackend(const std::string& text) {
    for (Backend backend : {Backend::Auto, Backend::Egl, Backend::OSMesa}) {
        if (text == backendName(backend)) return backend;
    }
    throw gl::Error("GL backend \"" + text + "\": expected auto, egl or osmesa");
}

bool isSoftwareRenderer(const std::string& renderer) {
    for (const char* name : {"llvmpipe", "softpipe", "swrast", "SwiftShader"}) {
        if (renderer.find(name) != std::string::npos) return true;
    }
    return false;
}

struct HeadlessContext::Impl {
    // At most one of the two is set; `info` describes it.
    std::unique_ptr<EglContext> egl;
    std::unique_ptr<OsmesaContext> osmesa;
    gl::ContextInfo info;
    std::string platform, fallbackReason;

    void useEgl(EglChoice choice) {
        egl = std::make_unique<EglContext>(choice);
        info = gl::loadFunctions(EglContext::procAddress);
        platform = egl->platform();
    }

    void useOsmesa() {
        osmesa = std::make_unique<OsmesaContext>();
        info = gl::loadFunctions(OsmesaContext::procAddress);
        platform = "OSMesa";
    }

    // An EGL hardware context, or the reason there is none.
    std::string tryEglHardware() {
        try {
            useEgl(EglChoice::HardwareOnly);
        } catch (const gl::Error& error) {
            egl.reset();
            return error.what();
        }
        // A device that is not flagged as software may still rasterise on the CPU.
        if (!isSoftwareRenderer(info.renderer)) return {};
        std::string why = platform + " renders with " + info.renderer;
        egl.reset();
        info = {};
        return why;
    }
};

HeadlessContext::HeadlessContext(Backend requested) : impl_(std::make_unique<Impl>()) {
    switch (requested) {
        case Backend::Egl: impl_->useEgl(EglChoice::HardwareOrSoftware); break;
        case Backend::OSMesa: impl_->useOsmesa(); break;
        case Backend::Auto:
            impl_->fallbackReason = impl_->tryEglHardware();
            if (impl_->fallbackReason.empty()) break;
            try {
                impl_->useOsmesa();
            } catch (const gl::Error& error) {
                throw gl::Error(std::string(error.what()) + "; and no EGL hardware context: " + impl_->fallbackReason);
            }
            break;
    }
}

HeadlessContext::~HeadlessContext() = default;

const gl::ContextInfo& HeadlessContext::info() const { return impl_->info; }

Backend HeadlessContext::backend() const { return impl_->egl ? Backend::Egl : Backend::OSMesa; }

const std::string& HeadlessContext::platform() const { return impl_->platform; }

const std::string& HeadlessContext::fallbackReason() const { return impl_->fallbackReason; }

}  // namespace isotrack::headless
