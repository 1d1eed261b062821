// The safe writer: a failed write leaves the old file byte-identical and no
// temporary behind, and says which file and why.
#include <catch2/catch.hpp>

#include <cerrno>
#include <filesystem>
#include <string>

#include "io_test_files.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/safe_write.h"

using namespace isotrack;
using isotrack::testing::readFile;
using isotrack::testing::TempDir;
using isotrack::testing::writeFile;

namespace {

std::size_t filesIn(const TempDir& dir) {
    const std::filesystem::path folder = std::filesystem::path(dir.file("x")).parent_path();
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++n;
    return n;
}

// Turns the injected fault off however the test ends.
struct FaultAfter {
    FaultAfter(long long bytes, int error) { isotrack::testing::failWritesAfter(bytes, error); }
    ~FaultAfter() { isotrack::testing::failWritesAfter(-1, 0); }
};

Mesh sphereMesh() {
    const Volume v = makeField(parseFieldSpec("sphere:24"));
    return marchingCubes(v, 0.0);
}

}  // namespace

TEST_CASE("safe write replaces the file only when complete", "[core][io][safe_write]") {
    TempDir dir;
    const std::string path = dir.file("out.txt");
    writeFile(path, "old contents");
    writeFileSafely(path, "new contents, longer");
    CHECK(readFile(path) == "new contents, longer");
    CHECK(filesIn(dir) == 1);

    SECTION("an abandoned writer leaves the old file and no temporary") {
        {
            SafeWriter writer(path);
            writer.write("partial");
        }
        CHECK(readFile(path) == "new contents, longer");
        CHECK(filesIn(dir) == 1);
    }
    SECTION("a directory is refused by name") {
        CHECK_THROWS_WITH(writeFileSafely(dir.file(""), "x"), Catch::Contains("Is a directory"));
    }
    SECTION("a missing folder is refused by name") {
        CHECK_THROWS_WITH(writeFileSafely(dir.file("no/such/out.txt"), "x"),
                          Catch::Contains("no/such/out.txt") && Catch::Contains("No such file or directory"));
    }
}

TEST_CASE("a full disk while overwriting an export leaves the old file byte-identical", "[core][io][safe_write]") {
    TempDir dir;
    const Mesh mesh = sphereMesh();
    REQUIRE(mesh.triangleCount() > 100);
    for (const char* name : {"mesh.ply", "mesh.obj", "mesh.stl", "volume.nrrd"}) {
        INFO(name);
        const std::string path = dir.file(name);
        const std::string old = "an earlier export that must survive";
        writeFile(path, old);
        // Fail half way through a buffer, and at the very first byte.
        for (long long budget : {1000LL, 0LL}) {
            FaultAfter full(budget, ENOSPC);
            const auto write = [&] {
                if (std::string(name) == "volume.nrrd") {
                    writeNrrd(makeField(parseFieldSpec("sphere:24")), path);
                } else {
                    writeMesh(path, mesh);
                }
            };
            CHECK_THROWS_AS(write(), FormatError);
            CHECK_THROWS_WITH(write(), Catch::Contains(path) && Catch::Contains("No space left on device"));
            CHECK(readFile(path) == old);
            CHECK(filesIn(dir) == 1);
        }
        // With room again the same call replaces it.
        if (std::string(name) != "volume.nrrd") {
            writeMesh(path, mesh);
            CHECK(readFile(path).size() > 1000);
        }
        std::filesystem::remove(path);
    }
}

TEST_CASE("safe write keeps an existing file's permissions", "[core][io][safe_write]") {
    TempDir dir;
    const std::string path = dir.file("mode.txt");
    writeFile(path, "x");
    std::filesystem::permissions(path, std::filesystem::perms::owner_read | std::filesystem::perms::owner_write |
                                           std::filesystem::perms::group_read);
    writeFileSafely(path, "y");
    CHECK(std::filesystem::status(path).permissions() ==
          (std::filesystem::perms::owner_read | std::filesystem::perms::owner_write |
           std::filesystem::perms::group_read));
}
