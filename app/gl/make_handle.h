#pragma once
// The one place GL object names are made for the RAII types (gl/handle.h): a
// glGen* call for one name, or glCreateProgram / glCreateShader, then a check of
// the error flag and of the name, so that no type ever holds a name GL did not
// give. Private to app/gl/*.cpp: it includes the loader.
#include <glad/gl.h>

namespace isotrack::gl {

using GenerateNames = void(GLAD_API_PTR*)(GLsizei, GLuint*);  // glGenBuffers, glGenTextures, ...
using CreateName = GLuint(GLAD_API_PTR*)();                   // glCreateProgram
using CreateNameOfType = GLuint(GLAD_API_PTR*)(GLenum);       // glCreateShader

// `call` names the GL function and `object` what it makes, for the message of
// the Error thrown when the call fails or returns 0: "glGenBuffers returned no buffer".
GLuint makeHandle(GenerateNames generate, const char* call, const char* object);
GLuint makeHandle(CreateName create, const char* call, const char* object);
GLuint makeHandle(CreateNameOfType create, GLenum type, const char* call, const char* object);

}  // namespace isotrack::gl
