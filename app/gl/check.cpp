#include "gl/check.h"

#include <glad/gl.h>

#include <cstdlib>
#include <cstring>

namespace isotrack::gl {
namespace {

bool defaultErrorChecks() {
#if !defined(NDEBUG) || defined(ISOTRACK_GL_CHECK)
    return true;
#else
    const char* env = std::getenv("ISOTRACK_GL_CHECK");
    return env != nullptr && std::strcmp(env, "1") == 0;
#endif
}

bool& errorChecks() {
    static bool enabled = defaultErrorChecks();
    return enabled;
}

const char* errorName(GLenum error) {
    switch (error) {
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        default: return "unknown GL error";
    }
}

const char* baseName(const char* path) {
    const char* slash = std::strrchr(path, '/');
    return slash != nullptr ? slash + 1 : path;
}

std::string glString(GLenum name) {
    const GLubyte* text = glGetString(name);
    return text != nullptr ? reinterpret_cast<const char*>(text) : "";
}

}  // namespace

void setErrorChecks(bool enabled) { errorChecks() = enabled; }
bool errorChecksEnabled() { return errorChecks(); }

void checkErrors(const char* what, const char* file, int line) {
    if (!errorChecks()) return;
    const GLenum first = glGetError();
    if (first == GL_NO_ERROR) return;
    // GL may queue several flags; clear them so the next check starts clean.
    for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
    }
    throw Error(std::string(errorName(first)) + " after " + what + " at " + baseName(file) + ":" +
                std::to_string(line));
}

ContextInfo loadFunctions(ProcAddressLoader loader) {
    const int version = gladLoadGL(loader);
    if (version == 0) throw Error("could not load OpenGL functions from the current context");
    ContextInfo info;
    info.major = GLAD_VERSION_MAJOR(version);
    info.minor = GLAD_VERSION_MINOR(version);
    info.version = glString(GL_VERSION);
    info.renderer = glString(GL_RENDERER);
    info.vendor = glString(GL_VENDOR);
    if (info.major < 3 || (info.major == 3 && info.minor < 3)) {
        throw Error("OpenGL 3.3 core is required, the context offers " + info.version + " (" + info.renderer + ")");
    }
    return info;
}

}  // namespace isotrack::gl
