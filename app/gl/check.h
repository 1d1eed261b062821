#pragma once
// GL error checks and the loader entry point.
//
// app/gl/ is the only folder that includes <glad/gl.h>; its public headers are
// GL-free, so the renderer, the headless context and a future window speak to
// GL only through the types declared here and beside this file.
#include <stdexcept>
#include <string>

namespace isotrack::gl {

// Any GL failure: an error flag after a call, an incomplete framebuffer, a
// context that is too old. The message names the call and where it was made.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Checking glGetError after every call costs a round trip per call, so it is on
// by default only in builds without NDEBUG, when ISOTRACK_GL_CHECK is defined at
// build time, or when the environment variable ISOTRACK_GL_CHECK is 1 at start.
// Tests turn it on explicitly.
void setErrorChecks(bool enabled);
bool errorChecksEnabled();

// Throws Error naming `what` and the call site if the GL error flag is set.
// Does nothing while checks are off.
void checkErrors(const char* what, const char* file, int line);

using ProcAddress = void (*)();
using ProcAddressLoader = ProcAddress (*)(const char* name);

struct ContextInfo {
    int major = 0, minor = 0;
    std::string version, renderer, vendor;
};

// Loads GL entry points through a context's loader (OSMesaGetProcAddress,
// glfwGetProcAddress) once that context is current. Throws Error unless the
// context offers at least OpenGL 3.3.
ContextInfo loadFunctions(ProcAddressLoader loader);

}  // namespace isotrack::gl

// For use inside app/gl/*.cpp: run a GL call, then check the error flag, naming
// the call text and the file:line it was made from.
#define ISOTRACK_GL_CALL(call)                                  \
    do {                                                        \
        call;                                                   \
        ::isotrack::gl::checkErrors(#call, __FILE__, __LINE__); \
    } while (0)
#define ISOTRACK_GL_CHECK(what) ::isotrack::gl::checkErrors(what, __FILE__, __LINE__)
