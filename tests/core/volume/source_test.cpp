#include <catch2/catch.hpp>

#include <cstdio>
#include <fstream>
#include <string>

#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/isovalue.h"
#include "isotrack/source.h"

using namespace isotrack;

TEST_CASE("a field source: its canonical name and its own isovalue", "[core][source]") {
    const LoadedSource loaded = loadSource({VolumeSource::Kind::Field, "blobs:24", {}, "", "", 0});
    CHECK(loaded.name == "blobs:24");
    CHECK(loaded.volume.dims() == Dims{24, 24, 24});
    REQUIRE(loaded.defaultIso);
    CHECK(*loaded.defaultIso == fieldDefaultIso("blobs"));
    CHECK_THROWS_AS(loadSource({VolumeSource::Kind::Field, "nothing:24", {}, "", "", 0}), InputError);
}

TEST_CASE("a file source: its path and the isovalue its histogram suggests", "[core][source]") {
    const std::string path = "source_test_raw.bin";
    {
        std::ofstream out(path, std::ios::binary);
        const unsigned char samples[8] = {10, 20, 30, 40, 50, 60, 70, 90};
        out.write(reinterpret_cast<const char*>(samples), sizeof samples);
    }
    RawLayout layout;
    layout.dims = {2, 2, 2};
    layout.type = ScalarType::UInt8;
    const LoadedSource loaded = loadSource({VolumeSource::Kind::File, path, layout, "", "", 0});
    CHECK(loaded.name == path);
    REQUIRE(loaded.defaultIso);
    CHECK(*loaded.defaultIso == suggestIsovalue(loaded.volume));
    CHECK(*loaded.defaultIso > 10.0);  // between the lowest and the highest sample
    CHECK(*loaded.defaultIso < 90.0);
    std::remove(path.c_str());
    CHECK_THROWS(loadSource({VolumeSource::Kind::File, path, {}, "", "", 0}));
}
