#include "render/shader_library.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace isotrack::render {
namespace {

std::string overrideDirectory() {
    const char* dir = std::getenv("ISOTRACK_SHADER_DIR");
    return dir != nullptr ? dir : "";
}

}  // namespace

gl::ShaderSource loadShader(const std::string& name) {
    const std::string dir = overrideDirectory();
    if (!dir.empty()) {
        const std::string path = dir + "/" + name;
        std::ifstream file(path, std::ios::binary);
        if (!file) throw gl::ShaderError("shader " + path + " (ISOTRACK_SHADER_DIR): cannot read the file");
        std::ostringstream text;
        text << file.rdbuf();
        return {path, text.str()};
    }
    for (std::size_t i = 0; i < detail::kEmbeddedShaderCount; ++i) {
        if (name == detail::kEmbeddedShaders[i].name) return {name, detail::kEmbeddedShaders[i].text};
    }
    throw gl::ShaderError("shader " + name + ": not among the shaders embedded from shaders/");
}

std::vector<std::string> embeddedShaderNames() {
    std::vector<std::string> names;
    for (std::size_t i = 0; i < detail::kEmbeddedShaderCount; ++i) names.emplace_back(detail::kEmbeddedShaders[i].name);
    return names;
}

}  // namespace isotrack::render
