// Volumes mapped from their files: the same surfaces as in memory, only the pages
// a surface crosses read by tracking, passed slices let go by streaming passes,
// and a file truncated under an extraction a FormatError naming it.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

#include "core/io/io_test_files.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/mapped_file.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"

using namespace isotrack;
using isotrack::testing::TempDir;

namespace {

// An n^3 float volume of zeros with a ball of radius r around (c, c, c) (1 inside).
Volume ballVolume(int n, double c, double r) {
    Volume v({n, n, n}, ScalarType::Float32);
    for (int z = int(c - r - 2); z <= int(c + r + 2); ++z)
        for (int y = int(c - r - 2); y <= int(c + r + 2); ++y)
            for (int x = int(c - r - 2); x <= int(c + r + 2); ++x)
                v.setValue(x, y, z, std::clamp(r + 0.5 - std::hypot(x - c, y - c, z - c), 0.0, 1.0));
    return v;
}

std::string writeRaw(const TempDir& dir, const Volume& v) {
    const std::string path = dir.file("ball.raw");
    isotrack::testing::writeFile(path, std::string(reinterpret_cast<const char*>(v.bytes()), v.byteSize()));
    return path;
}

RawLayout floatLayout(int n) {
    RawLayout layout;
    layout.dims = {n, n, n};
    layout.type = ScalarType::Float32;
    return layout;
}

}  // namespace

TEST_CASE("a raw file is mapped, not copied, and gives the surfaces memory gives", "[core][io][mapped]") {
    TempDir dir;
    const Volume inMemory = ballVolume(64, 30.0, 9.0);
    const Volume mapped = loadRaw(writeRaw(dir, inMemory), floatLayout(64));
    REQUIRE(mapped.mappedFile() != nullptr);
    CHECK(mapped.isView());
    CHECK(std::memcmp(mapped.bytes(), inMemory.bytes(), inMemory.byteSize()) == 0);
    const Mesh a = marchingCubes(inMemory, 0.5, TableKind::Consistent, 2);
    const Mesh b = marchingCubes(mapped, 0.5, TableKind::Consistent, 2);
    CHECK(a.indices == b.indices);
    CHECK(extractAllSurfaces(mapped, 0.5, TableKind::Consistent, 2).size() == 1);
    // A byte-swapped file is the exception: converted into memory.
    RawLayout big = floatLayout(64);
    big.bigEndian = true;
    CHECK(loadRaw(dir.file("ball.raw"), big).mappedFile() == nullptr);
}

TEST_CASE("samples at an odd offset are read into memory, aligned; isotrack's own NRRD is mapped",
          "[core][io][mapped]") {
    TempDir dir;
    const Volume ball = ballVolume(24, 11.0, 6.0);
    // An attached header of 83 bytes: float samples at an offset no multiple of 4.
    std::string header = "NRRD0004\ntype: float\ndimension: 3\nsizes: 24 24 24\nendian: little\nencoding: raw\n";
    header += std::string(83 - 2 - header.size(), '#') + "\n\n";
    REQUIRE(header.size() == 83);
    const std::string odd = dir.file("odd.nrrd");
    isotrack::testing::writeFile(odd,
                                 header + std::string(reinterpret_cast<const char*>(ball.bytes()), ball.byteSize()));
    const Volume read = loadVolume(odd);
    CHECK(read.mappedFile() == nullptr);
    CHECK(reinterpret_cast<std::uintptr_t>(read.bytes()) % alignof(float) == 0);
    CHECK(std::memcmp(read.bytes(), ball.bytes(), ball.byteSize()) == 0);
    // writeNrrd pads its header to a multiple of 8: what it writes is mapped.
    writeNrrd(ball, dir.file("own.nrrd"));
    const Volume own = loadVolume(dir.file("own.nrrd"));
    CHECK(own.mappedFile() != nullptr);
    CHECK(reinterpret_cast<std::uintptr_t>(own.bytes()) % 8 == 0);
    CHECK(std::memcmp(own.bytes(), ball.bytes(), ball.byteSize()) == 0);
}

TEST_CASE("tracking reads only the pages its surface crosses", "[core][io][mapped]") {
    TempDir dir;
    const int n = 256;  // 64 MiB of float samples, a ball of radius 6 in one corner
    const Volume mapped = loadRaw(writeRaw(dir, ballVolume(n, 20.0, 6.0)), floatLayout(n));
    const MappedFile& file = *mapped.mappedFile();
    const Surface surface = trackSurface(mapped, 0.5, nearestCrossedEdge(mapped, 0.5, {20.0, 20.0, 26.0}));
    CHECK(surface.mesh.indices.size() > 300);
    // The ball crosses 13 of the 256 slices; the tracker's blocks and the kernel's
    // fault-around (pages mapped in groups) round that up, to well under an eighth.
    CHECK(file.residentBytes() < file.size() / 8);
}

TEST_CASE("streaming passes let the slices they passed go", "[core][io][mapped]") {
    TempDir dir;
    const int n = 256;
    const Volume mapped = loadRaw(writeRaw(dir, ballVolume(n, 128.0, 40.0)), floatLayout(n));
    const MappedFile& file = *mapped.mappedFile();
    // Everything touched once is resident (and /proc/self/smaps reports it)...
    volatile float sum = 0;
    for (std::size_t i = 0; i < mapped.sampleCount(); i += 1024) sum = sum + mapped.data<float>()[i];
    REQUIRE(file.residentBytes() > file.size() / 2);
    // ...and what a pass lets go is not.
    mapped.releaseSlices(0, n);
    marchingCubes(mapped, 0.5, TableKind::Consistent, 2);
    CHECK(file.residentBytes() < file.size() / 4);
    extractAllSurfaces(mapped, 0.5, TableKind::Consistent, 2);
    CHECK(file.residentBytes() < file.size() / 4);
}

TEST_CASE("a file truncated under an extraction is a FormatError naming it", "[core][io][mapped]") {
    TempDir dir;
    const std::string path = writeRaw(dir, ballVolume(64, 32.0, 20.0));
    const Volume mapped = loadRaw(path, floatLayout(64));
    std::filesystem::resize_file(path, 4096 * 8);  // the volume's first slices only
    CHECK_THROWS_WITH(marchingCubes(mapped, 0.5), Catch::Contains(path) && Catch::Contains("truncated or removed"));
    CHECK_THROWS_AS(extractAllSurfaces(mapped, 0.5, TableKind::Consistent, 2), FormatError);
    CHECK(mapped.mappedFile()->damaged());
    // A volume loaded afresh from the shortened file is refused up front.
    CHECK_THROWS_AS(loadRaw(path, floatLayout(64)), FormatError);
}
