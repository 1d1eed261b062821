#pragma once
// Shader programs. A program is built from named sources; a compile or link
// failure throws ShaderError with the shader's name and the driver's log.
#include <string>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "gl/check.h"
#include "gl/handle.h"

namespace isotrack::gl {

class ShaderError : public Error {
public:
    using Error::Error;
};

struct ShaderSource {
    std::string name;  // e.g. "surface.frag": used in error messages only
    std::string text;
};

enum class ShaderStage { Vertex, Fragment };

namespace detail {
void destroyShader(unsigned id);
void destroyProgram(unsigned id);
}  // namespace detail

// One compiled stage. Only needed until the program is linked.
class Shader {
public:
    Shader(ShaderStage stage, const ShaderSource& source);
    Shader(Shader&&) noexcept = default;
    Shader& operator=(Shader&&) noexcept = default;
    Shader(const Shader&) = delete;
    Shader& operator=(const Shader&) = delete;
    ~Shader() = default;

    unsigned id() const { return handle_.id(); }

private:
    UniqueHandle<detail::destroyShader> handle_;
};

class Program {
public:
    Program(const ShaderSource& vertex, const ShaderSource& fragment);
    Program(Program&&) noexcept = default;
    Program& operator=(Program&&) noexcept = default;
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;
    ~Program() = default;

    void use() const;
    // -1 when the program has no active uniform of that name (the setters then
    // do nothing, as GL does). Look locations up once, not per frame.
    int uniformLocation(const char* name) const;

    // Set uniforms of this program; it must be the one in use.
    static void set(int location, float value);
    static void set(int location, int value);
    static void set(int location, unsigned value);
    static void set(int location, const glm::vec3& value);
    static void set(int location, const glm::vec4& value);
    static void set(int location, const glm::mat4& value);

    unsigned id() const { return handle_.id(); }

private:
    UniqueHandle<detail::destroyProgram> handle_;
};

}  // namespace isotrack::gl
