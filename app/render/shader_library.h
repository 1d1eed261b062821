#pragma once
// The shaders in shaders/, embedded in the binary at build time.
//
// Setting ISOTRACK_SHADER_DIR makes loadShader read that folder instead, so a
// shader can be edited and tried without rebuilding.
#include <cstddef>
#include <string>
#include <vector>

#include "gl/program.h"

namespace isotrack::render {

// The source of shaders/<name>: $ISOTRACK_SHADER_DIR/<name> when the variable is
// set and not empty, else the embedded copy. Throws gl::ShaderError when there is
// no such shader.
gl::ShaderSource loadShader(const std::string& name);

std::vector<std::string> embeddedShaderNames();

namespace detail {
struct EmbeddedShader {
    const char* name;
    const char* text;
};
extern const EmbeddedShader kEmbeddedShaders[];
extern const std::size_t kEmbeddedShaderCount;
}  // namespace detail

}  // namespace isotrack::render
