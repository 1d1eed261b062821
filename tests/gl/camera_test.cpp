// The camera: its text form, and the default framing of a volume.
#include <catch2/catch.hpp>
#include <glm/glm.hpp>

#include "isotrack/errors.h"
#include "render/camera.h"
#include "render/palette.h"

using namespace isotrack;

TEST_CASE("a camera reads back exactly what it writes", "[gl][camera]") {
    render::Camera camera;
    camera.yaw = -61.25f;
    camera.pitch = 12.5f;
    camera.distance = 123.456f;
    camera.target = {1.0f / 3.0f, -2.0f, 1e-7f};
    camera.fov = 42.0f;
    const std::string text = render::formatCamera(camera);
    CHECK(render::parseCamera(text) == camera);
    CHECK(render::formatCamera(render::parseCamera(text)) == text);
    CHECK(render::formatCamera(render::parseCamera("30,20,100,1,2,3")) == "30,20,100,1,2,3,30");
    CHECK(render::parseCamera(" 30, 20, 100, 1, 2, 3, 45 ").fov == 45.0f);
}

TEST_CASE("malformed camera strings are refused with the field at fault", "[gl][camera]") {
    CHECK_THROWS_WITH(render::parseCamera("1,2,3"), Catch::Contains("got 3 fields"));
    CHECK_THROWS_WITH(render::parseCamera("a,0,1,0,0,0"), Catch::Contains("yaw \"a\""));
    CHECK_THROWS_WITH(render::parseCamera("0,90,1,0,0,0"), Catch::Contains("pitch"));
    CHECK_THROWS_WITH(render::parseCamera("0,0,0,0,0,0"), Catch::Contains("distance"));
    CHECK_THROWS_WITH(render::parseCamera("0,0,1,0,0,nan"), Catch::Contains("tz"));
    CHECK_THROWS_WITH(render::parseCamera("0,0,1,0,0,0,180"), Catch::Contains("fov"));
    CHECK_THROWS_AS(render::parseCamera("0,0,1,0,0,0,"), InputError);
}

TEST_CASE("the default camera shows every corner of the volume", "[gl][camera]") {
    const render::Bounds bounds{{0.0f, 0.0f, 0.0f}, {63.0f, 31.0f, 95.0f}};
    for (float aspect : {0.5f, 4.0f / 3.0f, 3.0f}) {
        const render::Camera camera = render::frameBounds(bounds, aspect);
        float near = 0.0f, far = 0.0f;
        render::clipPlanes(camera, bounds, near, far);
        const glm::mat4 clip = camera.projection(aspect, near, far) * camera.view();
        float widest = 0.0f;
        for (int i = 0; i < 8; ++i) {
            const glm::vec4 corner{(i & 1) ? bounds.max.x : 0.0f, (i & 2) ? bounds.max.y : 0.0f,
                                   (i & 4) ? bounds.max.z : 0.0f, 1.0f};
            const glm::vec4 p = clip * corner;
            const glm::vec3 ndc = glm::vec3(p) / p.w;
            CHECK(std::abs(ndc.x) <= 1.0f);
            CHECK(std::abs(ndc.y) <= 1.0f);
            CHECK(std::abs(ndc.z) <= 1.0f);
            widest = std::max({widest, std::abs(ndc.x), std::abs(ndc.y)});
        }
        CHECK(widest > 0.85f);  // framed, not lost in the middle
    }
}

TEST_CASE("orbiting keeps the pitch away from the poles", "[gl][camera]") {
    render::Camera camera;
    camera.orbit(400.0f, 200.0f);
    CHECK(camera.pitch == render::Camera::kMaxPitch);
    CHECK(std::abs(camera.yaw) <= 180.0f);
}

TEST_CASE("surface colours are distinct and deterministic", "[gl][palette]") {
    const std::size_t count = 200;
    float closest = 1.0f;
    for (std::size_t i = 0; i < count; ++i) {
        for (std::size_t j = i + 1; j < count; ++j) {
            closest = std::min(closest, glm::length(render::surfaceColour(i) - render::surfaceColour(j)));
        }
        CHECK(render::surfaceColour(i) == render::surfaceColour(i));
    }
    CHECK(closest > 0.04f);
    // Neighbours in rank (surfaces of similar size) are far apart.
    for (std::size_t i = 0; i + 1 < count; ++i) {
        CHECK(glm::length(render::surfaceColour(i) - render::surfaceColour(i + 1)) > 0.2f);
    }
}
