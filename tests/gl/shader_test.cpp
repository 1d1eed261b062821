// Embedded shaders, the ISOTRACK_SHADER_DIR override, and shader errors.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gl_test_support.h"
#include "isotrack/fields.h"
#include "isotrack/marching_cubes.h"
#include "render/renderer.h"
#include "render/shader_library.h"

using namespace isotrack;
namespace fs = std::filesystem;

namespace {

std::string readText(const fs::path& path) {
    std::ifstream file(path);
    std::ostringstream text;
    text << file.rdbuf();
    return text.str();
}

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path) << text; }

// A copy of shaders/ to edit, in the build tree, and ISOTRACK_SHADER_DIR pointing
// at it for as long as this lives.
struct ShaderOverride {
    fs::path dir;
    explicit ShaderOverride(const std::string& name) : dir(fs::path(ISOTRACK_GOLDEN_OUT) / ("shaders-" + name)) {
        fs::remove_all(dir);
        fs::create_directories(dir);
        for (const auto& entry : fs::directory_iterator(fs::path(ISOTRACK_SOURCE_DIR) / "shaders")) {
            fs::copy_file(entry.path(), dir / entry.path().filename());
        }
        setenv("ISOTRACK_SHADER_DIR", dir.c_str(), 1);
    }
    ~ShaderOverride() { unsetenv("ISOTRACK_SHADER_DIR"); }
    void replace(const std::string& file, const std::string& from, const std::string& to) const {
        std::string text = readText(dir / file);
        const std::size_t at = text.find(from);
        REQUIRE(at != std::string::npos);
        text.replace(at, from.size(), to);
        writeText(dir / file, text);
    }
};

}  // namespace

TEST_CASE("every file in shaders/ is embedded, byte for byte", "[gl][shaders]") {
    std::vector<std::string> names = render::embeddedShaderNames();
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(fs::path(ISOTRACK_SOURCE_DIR) / "shaders")) {
        files.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    std::sort(files.begin(), files.end());
    CHECK(names == files);
    for (const std::string& name : names) {
        CHECK(render::loadShader(name).text == readText(fs::path(ISOTRACK_SOURCE_DIR) / "shaders" / name));
    }
    CHECK_THROWS_AS(render::loadShader("missing.frag"), gl::ShaderError);
}

TEST_CASE("a shader that does not compile throws with its name and the driver's log", "[gl][shaders]") {
    test::useHeadlessGl();
    const ShaderOverride shaders("broken");
    shaders.replace("surface.frag", "vec3 n = normalize(vNormalView);", "vec3 n = normalize(vNormalView)");
    try {
        render::Renderer renderer;
        FAIL("no gl::ShaderError thrown");
    } catch (const gl::ShaderError& e) {
        const std::string message = e.what();
        CHECK_THAT(message, Catch::Contains("surface.frag"));
        CHECK_THAT(message, Catch::Contains("error"));
        CHECK(message.find('\n') == std::string::npos);
    }
}

TEST_CASE("a missing override file names its path", "[gl][shaders]") {
    const ShaderOverride shaders("missing");
    fs::remove(shaders.dir / "lines.vert");
    CHECK_THROWS_WITH(render::loadShader("lines.vert"), Catch::Contains((shaders.dir / "lines.vert").string()));
}

TEST_CASE("the golden metric catches a changed surface colour", "[gl][shaders]") {
    test::useHeadlessGl();
    const Volume volume = makeField(parseFieldSpec("sphere:32"));
    const Mesh mesh = marchingCubes(volume, fieldDefaultIso("sphere"));
    const render::Image embedded = test::renderForGolden({&mesh}, volume);

    const ShaderOverride shaders("recoloured");
    shaders.replace("surface.frag", "vec3 albedo = vColour;", "vec3 albedo = vColour.bgr;");
    const render::Image recoloured = test::renderForGolden({&mesh}, volume);

    const test::GoldenTolerance tolerance;
    const test::ImageDifference difference = test::compareImages(embedded, recoloured, tolerance.channelTolerance);
    const double fraction = double(difference.differentPixels) / double(embedded.width * embedded.height);
    CHECK(fraction > tolerance.maxDifferentFraction);
}
