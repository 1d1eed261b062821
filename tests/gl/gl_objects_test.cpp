// The GL layer: move-only ownership and error checks that name the call site.
#include <catch2/catch.hpp>
#include <type_traits>

#include "gl/buffer.h"
#include "gl/check.h"
#include "gl/colour_depth_target.h"
#include "gl/framebuffer.h"
#include "gl/program.h"
#include "gl/timer_query.h"
#include "gl/vertex_array.h"
#include "gl_test_support.h"
#include "render/shader_library.h"

using namespace isotrack;

TEMPLATE_TEST_CASE("GL objects are move-only", "[gl]", gl::Buffer, gl::VertexArray, gl::Program, gl::Shader,
                   gl::Texture, gl::Renderbuffer, gl::Framebuffer) {
    STATIC_REQUIRE_FALSE(std::is_copy_constructible_v<TestType>);
    STATIC_REQUIRE_FALSE(std::is_copy_assignable_v<TestType>);
    STATIC_REQUIRE(std::is_nothrow_move_constructible_v<TestType>);
    STATIC_REQUIRE(std::is_nothrow_move_assignable_v<TestType>);
}

TEST_CASE("a move hands the handle over and zeroes the source", "[gl]") {
    test::useHeadlessGl();
    gl::Buffer first;
    first.allocate(64, nullptr, gl::BufferUsage::Static);
    const unsigned id = first.id();
    REQUIRE(id != 0);

    gl::Buffer second(std::move(first));
    CHECK(first.id() == 0);  // NOLINT(bugprone-use-after-move): checking the moved-from state
    CHECK(first.size() == 0);
    CHECK(second.id() == id);
    CHECK(second.size() == 64);

    gl::Buffer third;
    const unsigned replaced = third.id();
    third = std::move(second);
    CHECK(second.id() == 0);  // NOLINT(bugprone-use-after-move)
    CHECK(third.id() == id);
    // The handle third held before was freed; GL may hand the name out again.
    gl::Buffer fourth;
    CHECK((fourth.id() == replaced || fourth.id() != id));
}

TEST_CASE("GL errors throw, naming the call and where it was made", "[gl]") {
    test::useHeadlessGl();
    gl::Program program(render::loadShader("lines.vert"), render::loadShader("lines.frag"));
    program.use();
    // uColour is a vec3: setting it as one int is GL_INVALID_OPERATION.
    try {
        gl::Program::set(program.uniformLocation("uColour"), 1);
        FAIL("no gl::Error thrown");
    } catch (const gl::Error& e) {
        const std::string message = e.what();
        CHECK_THAT(message, Catch::Contains("GL_INVALID_OPERATION"));
        CHECK_THAT(message, Catch::Contains("glUniform1i"));
        CHECK_THAT(message, Catch::Contains("program.cpp:"));
    }
    gl::setErrorChecks(false);
    CHECK_NOTHROW(gl::Program::set(program.uniformLocation("uColour"), 1));
    gl::setErrorChecks(true);
    // The unchecked call left its flag set: the next check reports it, then all is clean.
    CHECK_THROWS_AS(gl::checkErrors("a later check", __FILE__, __LINE__), gl::Error);
    CHECK_NOTHROW(gl::checkErrors("the check after that", __FILE__, __LINE__));
}

TEST_CASE("buffer ranges outside the storage are refused before reaching GL", "[gl]") {
    test::useHeadlessGl();
    gl::Buffer buffer;
    buffer.allocate(16, nullptr, gl::BufferUsage::Dynamic);
    const char bytes[32] = {};
    CHECK_THROWS_AS(buffer.update(8, 16, bytes), std::out_of_range);
    CHECK_NOTHROW(buffer.update(8, 8, bytes));
}

TEST_CASE("render targets refuse absurd sizes", "[gl]") {
    test::useHeadlessGl();
    CHECK_THROWS_AS(gl::Renderbuffer(0, 10, gl::PixelFormat::Rgba8), gl::Error);
    CHECK_THROWS_AS(gl::Renderbuffer(1 << 20, 10, gl::PixelFormat::Rgba8), gl::Error);
}

TEST_CASE("every GL object type holds a name GL gave it, one per object", "[gl]") {
    test::useHeadlessGl();
    const gl::Buffer buffers[2];
    const gl::VertexArray arrays[2];
    const gl::Framebuffer framebuffers[2];
    const gl::TimerQuery queries[2];
    const gl::Texture textures[2] = {{4, 4, gl::PixelFormat::Rgba8}, {4, 4, gl::PixelFormat::Rgba8}};
    const gl::Renderbuffer renderbuffers[2] = {{4, 4, gl::PixelFormat::Rgba8}, {4, 4, gl::PixelFormat::Rgba8}};
    const gl::Program programs[2] = {{render::loadShader("lines.vert"), render::loadShader("lines.frag")},
                                     {render::loadShader("lines.vert"), render::loadShader("lines.frag")}};
    auto distinct = [](const auto& pair) {
        return pair[0].id() != 0 && pair[1].id() != 0 && pair[0].id() != pair[1].id();
    };
    CHECK(distinct(buffers));
    CHECK(distinct(arrays));
    CHECK(distinct(framebuffers));
    CHECK(distinct(queries));
    CHECK(distinct(textures));
    CHECK(distinct(renderbuffers));
    CHECK(distinct(programs));
}

TEST_CASE("a colour + depth target is complete, cleared and read back in either storage", "[gl]") {
    test::useHeadlessGl();
    const gl::ColourDepthTarget ids(8, 6, gl::PixelFormat::R32UI, gl::ColourStorage::Texture);
    CHECK(ids.width() == 8);
    CHECK(ids.height() == 6);
    CHECK(ids.bytes() == 8 * 6 * 8);
    ids.framebuffer().clearIdAndDepth(41);
    CHECK(ids.framebuffer().readUint(7, 5) == 41);
    CHECK(ids.framebuffer().readDepth(0, 0) == 1.0f);

    const gl::ColourDepthTarget picture(5, 3, gl::PixelFormat::Rgba8, gl::ColourStorage::Renderbuffer);
    CHECK(picture.framebuffer().readRgba(5, 3).size() == 5 * 3 * 4);
    gl::Framebuffer::bindDefault();

    CHECK_THROWS_AS(gl::ColourDepthTarget(0, 6, gl::PixelFormat::Rgba8, gl::ColourStorage::Renderbuffer), gl::Error);
    CHECK_THROWS_AS(gl::ColourDepthTarget(1 << 20, 6, gl::PixelFormat::R32UI, gl::ColourStorage::Texture), gl::Error);
}
