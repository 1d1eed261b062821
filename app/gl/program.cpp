#include "gl/program.h"

#include <glad/gl.h>

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <vector>

#include "gl/make_handle.h"

namespace isotrack::gl {

void detail::destroyShader(unsigned id) { glDeleteShader(id); }
void detail::destroyProgram(unsigned id) { glDeleteProgram(id); }

namespace {

// Driver logs span several lines; error messages are one line.
std::string oneLine(std::string log) {
    while (!log.empty() && (log.back() == '\n' || log.back() == '\0' || log.back() == ' ')) log.pop_back();
    std::string out;
    for (char c : log) {
        if (c == '\n') {
            out += "; ";
        } else {
            out += c;
        }
    }
    return out.empty() ? "(the driver gave no log)" : out;
}

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return oneLine(log.data());
}

std::string programLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return oneLine(log.data());
}

GLuint compile(ShaderStage stage, const ShaderSource& source) {
    GLuint id = 0;
    try {
        id = makeHandle(glCreateShader, stage == ShaderStage::Vertex ? GL_VERTEX_SHADER : GL_FRAGMENT_SHADER,
                        "glCreateShader", "shader");
    } catch (const Error& e) {
        throw ShaderError("shader " + source.name + ": " + e.what());
    }
    const char* text = source.text.c_str();
    const auto length = static_cast<GLint>(source.text.size());
    glShaderSource(id, 1, &text, &length);
    glCompileShader(id);
    GLint ok = GL_FALSE;
    glGetShaderiv(id, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = shaderLog(id);
        glDeleteShader(id);
        throw ShaderError("shader " + source.name + " does not compile: " + log);
    }
    return id;
}

GLuint link(const Shader& vertex, const Shader& fragment, const std::string& name) {
    GLuint id = 0;
    try {
        id = makeHandle(glCreateProgram, "glCreateProgram", "program");
    } catch (const Error& e) {
        throw ShaderError("program " + name + ": " + e.what());
    }
    glAttachShader(id, vertex.id());
    glAttachShader(id, fragment.id());
    glLinkProgram(id);
    glDetachShader(id, vertex.id());
    glDetachShader(id, fragment.id());
    GLint ok = GL_FALSE;
    glGetProgramiv(id, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = programLog(id);
        glDeleteProgram(id);
        throw ShaderError("program " + name + " does not link: " + log);
    }
    return id;
}

}  // namespace

Shader::Shader(ShaderStage stage, const ShaderSource& source) : handle_(compile(stage, source)) {}

Program::Program(const ShaderSource& vertex, const ShaderSource& fragment)
    : handle_(link(Shader(ShaderStage::Vertex, vertex), Shader(ShaderStage::Fragment, fragment),
                   vertex.name + " + " + fragment.name)) {}

void Program::use() const { ISOTRACK_GL_CALL(glUseProgram(handle_.id())); }

int Program::uniformLocation(const char* name) const { return glGetUniformLocation(handle_.id(), name); }

void Program::set(int location, float value) { ISOTRACK_GL_CALL(glUniform1f(location, value)); }
void Program::set(int location, int value) { ISOTRACK_GL_CALL(glUniform1i(location, value)); }
void Program::set(int location, unsigned value) { ISOTRACK_GL_CALL(glUniform1ui(location, value)); }
void Program::set(int location, const glm::vec3& value) {
    ISOTRACK_GL_CALL(glUniform3fv(location, 1, glm::value_ptr(value)));
}
void Program::set(int location, const glm::vec4& value) {
    ISOTRACK_GL_CALL(glUniform4fv(location, 1, glm::value_ptr(value)));
}
void Program::set(int location, const glm::mat4& value) {
    ISOTRACK_GL_CALL(glUniformMatrix4fv(location, 1, GL_FALSE, glm::value_ptr(value)));
}

}  // namespace isotrack::gl
