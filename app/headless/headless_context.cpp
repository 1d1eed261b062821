#include "headless/headless_context.h"

#include <array>
#include <cstdint>

#ifdef ISOTRACK_HAVE_OSMESA
#include <GL/osmesa.h>
#endif

namespace isotrack::headless {

#ifdef ISOTRACK_HAVE_OSMESA

struct HeadlessContext::Impl {
    OSMesaContext context = nullptr;
    std::array<std::uint8_t, 4> buffer{};  // 1x1 RGBA; rendering goes to framebuffer objects
    gl::ContextInfo info;
};

HeadlessContext::HeadlessContext() : impl_(std::make_unique<Impl>()) {
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
    impl_->context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (impl_->context == nullptr) throw gl::Error("OSMesa could not create an OpenGL 3.3 core context");
    if (!OSMesaMakeCurrent(impl_->context, impl_->buffer.data(), GL_UNSIGNED_BYTE, 1, 1)) {
        OSMesaDestroyContext(impl_->context);
        throw gl::Error("OSMesa could not make its context current");
    }
    try {
        impl_->info = gl::loadFunctions(OSMesaGetProcAddress);
    } catch (...) {
        OSMesaDestroyContext(impl_->context);
        throw;
    }
}

HeadlessContext::~HeadlessContext() { OSMesaDestroyContext(impl_->context); }

#else

struct HeadlessContext::Impl {
    gl::ContextInfo info;
};

HeadlessContext::HeadlessContext() {
    throw gl::Error("headless rendering is unavailable: isotrack was built without OSMesa (libosmesa6-dev)");
}

HeadlessContext::~HeadlessContext() = default;

#endif

const gl::ContextInfo& HeadlessContext::info() const { return impl_->info; }

}  // namespace isotrack::headless
