#include "headless/osmesa_context.h"

#include <array>
#include <cstdint>

#include "headless/shared_library.h"

#ifdef ISOTRACK_HAVE_OSMESA
#include <GL/osmesa.h>
#endif

namespace isotrack::headless {

#ifdef ISOTRACK_HAVE_OSMESA

namespace {

template <typename Function>
void bind(const SharedLibrary& library, const char* name, Function& function) {
    function = reinterpret_cast<Function>(library.symbol(name));
    if (function == nullptr) throw gl::Error("OSMesa is unusable: " + library.name() + " lacks " + name);
}

struct OsmesaApi {
    SharedLibrary library{"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"};
    decltype(&::OSMesaCreateContextAttribs) createContextAttribs = nullptr;
    decltype(&::OSMesaMakeCurrent) makeCurrent = nullptr;
    decltype(&::OSMesaDestroyContext) destroyContext = nullptr;
    decltype(&::OSMesaGetProcAddress) getProcAddress = nullptr;

    OsmesaApi() {
        if (!library.ok())
            throw gl::Error("OSMesa is unavailable (" + library.error() + "; Debian package libosmesa6)");
        bind(library, "OSMesaCreateContextAttribs", createContextAttribs);
        bind(library, "OSMesaMakeCurrent", makeCurrent);
        bind(library, "OSMesaDestroyContext", destroyContext);
        bind(library, "OSMesaGetProcAddress", getProcAddress);
    }
};

// Opened once and kept (see shared_library.h); a failed open is retried on the next call.
const OsmesaApi& osmesa() {
    static const OsmesaApi api;
    return api;
}

}  // namespace

struct OsmesaContext::Handles {
    OSMesaContext context = nullptr;
    std::array<std::uint8_t, 4> buffer{};  // 1x1 RGBA; rendering goes to framebuffer objects
};

OsmesaContext::OsmesaContext() : handles_(std::make_unique<Handles>()) {
    const OsmesaApi& api = osmesa();
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_STENCIL_BITS,
                              8,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    handles_->context = api.createContextAttribs(attributes, nullptr);
    if (handles_->context == nullptr) throw gl::Error("OSMesa could not create an OpenGL 3.3 core context");
    if (!api.makeCurrent(handles_->context, handles_->buffer.data(), GL_UNSIGNED_BYTE, 1, 1)) {
        api.destroyContext(handles_->context);
        throw gl::Error("OSMesa could not make its context current");
    }
}

OsmesaContext::~OsmesaContext() { osmesa().destroyContext(handles_->context); }

gl::ProcAddress OsmesaContext::procAddress(const char* name) { return osmesa().getProcAddress(name); }

#else

struct OsmesaContext::Handles {};

OsmesaContext::OsmesaContext() {
    throw gl::Error("OSMesa is unavailable: isotrack was built without its headers (libosmesa6-dev)");
}

OsmesaContext::~OsmesaContext() = default;

gl::ProcAddress OsmesaContext::procAddress(const char*) { return nullptr; }

#endif

}  // namespace isotrack::headless
