// A time series read one step ahead (isotrack/time_step_reader.h), on numbered
// NRRD files written here: each step's samples are its index plus the sample's.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

#include "io_test_files.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/time_step_reader.h"

using namespace isotrack;
using isotrack::testing::TempDir;
using isotrack::testing::writeFile;

namespace {

Volume stepVolume(int step, Dims dims = {5, 4, 3}, Vec3d spacing = {1, 1, 1}) {
    Volume volume(dims, ScalarType::Float32, spacing, {2, 3, 4});
    for (std::size_t i = 0; i < volume.sampleCount(); ++i) volume.data<float>()[i] = float(step * 100 + int(i));
    return volume;
}

std::string stepFile(const TempDir& dir, int step) {
    char name[32];
    std::snprintf(name, sizeof name, "step_%02d.nrrd", step);
    return dir.file(name);
}

void requireStep(const Volume& volume, int step) {
    REQUIRE(volume.dims() == Dims{5, 4, 3});
    CHECK(volume.origin() == Vec3d{2, 3, 4});
    for (std::size_t i = 0; i < volume.sampleCount(); ++i)
        REQUIRE(volume.data<float>()[i] == float(step * 100 + int(i)));
}

}  // namespace

TEST_CASE("a time series reads each step, in order or not", "[core][io]") {
    TempDir dir;
    for (int k = 0; k < 4; ++k) writeNrrd(stepVolume(k), stepFile(dir, k));
    TimeStepReader reader(dir.file("step_%02d.nrrd"));
    REQUIRE(reader.size() == 4);
    CHECK(reader.time(3) == 3.0);
    for (int k = 0; k < 4; ++k) requireStep(*reader.load(std::size_t(k)), k);
    requireStep(*reader.load(1), 1);  // back: read again, not the prefetch
    requireStep(*reader.load(3), 3);
    CHECK_THROWS_AS(reader.load(4), InputError);

    TimeStepReader fromTwo(dir.file("step_%02d.nrrd"));
    requireStep(*fromTwo.load(2), 2);
}

TEST_CASE("a step's read error comes when that step is asked for", "[core][io]") {
    TempDir dir;
    writeNrrd(stepVolume(0), stepFile(dir, 0));
    writeFile(stepFile(dir, 1), "NRRD0004\ntype: float\n");  // no sizes: read in the background, refused later
    writeNrrd(stepVolume(2), stepFile(dir, 2));
    TimeStepReader reader(dir.file("step_%02d.nrrd"));
    requireStep(*reader.load(0), 0);
    CHECK_THROWS_AS(reader.load(1), FormatError);
    requireStep(*reader.load(2), 2);
}

TEST_CASE("a step on another grid is refused in one line naming its file and field", "[core][io]") {
    TempDir dir;
    writeNrrd(stepVolume(0), stepFile(dir, 0));
    writeNrrd(stepVolume(1), stepFile(dir, 1));
    writeNrrd(stepVolume(2, {5, 4, 4}), stepFile(dir, 2));
    writeNrrd(stepVolume(3, {5, 4, 3}, {1, 1, 2}), stepFile(dir, 3));
    TimeStepReader reader(dir.file("step_%02d.nrrd"));
    requireStep(*reader.load(0), 0);
    requireStep(*reader.load(1), 1);
    try {
        reader.load(2);
        FAIL("a step of other dims was read");
    } catch (const GridMismatch& e) {
        const std::string message = e.what();
        CHECK(message.find("step_02.nrrd") != std::string::npos);
        CHECK(message.find("dims 5x4x4, the first step's 5x4x3") != std::string::npos);
        CHECK(message.find('\n') == std::string::npos);
    }
    try {
        reader.load(3);
        FAIL("a step of other spacing was read");
    } catch (const GridMismatch& e) {
        CHECK(std::string(e.what()).find("spacing (1, 1, 2)") != std::string::npos);
    }
}
