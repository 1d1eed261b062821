#include "gl/make_handle.h"

#include <string>

#include "gl/check.h"

namespace isotrack::gl {
namespace {

GLuint checked(GLuint id, const char* call, const char* object) {
    checkErrors(call, __FILE__, __LINE__);
    if (id == 0) throw Error(std::string(call) + " returned no " + object);
    return id;
}

}  // namespace

GLuint makeHandle(GenerateNames generate, const char* call, const char* object) {
    GLuint id = 0;
    generate(1, &id);
    return checked(id, call, object);
}

GLuint makeHandle(CreateName create, const char* call, const char* object) { return checked(create(), call, object); }

GLuint makeHandle(CreateNameOfType create, GLenum type, const char* call, const char* object) {
    return checked(create(type), call, object);
}

}  // namespace isotrack::gl
