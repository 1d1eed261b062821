#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "isotrack/errors.h"
#include "isotrack/mapped_file.h"
#include "isotrack/volume.h"

using namespace isotrack;

namespace {

const ScalarType kAllTypes[] = {ScalarType::UInt8,  ScalarType::Int8,  ScalarType::UInt16,  ScalarType::Int16,
                                ScalarType::UInt32, ScalarType::Int32, ScalarType::Float32, ScalarType::Float64};

}  // namespace

TEST_CASE("scalar type names and sizes", "[core][volume]") {
    CHECK(std::string(scalarTypeName(ScalarType::UInt8)) == "uint8");
    CHECK(std::string(scalarTypeName(ScalarType::Int8)) == "int8");
    CHECK(std::string(scalarTypeName(ScalarType::UInt16)) == "uint16");
    CHECK(std::string(scalarTypeName(ScalarType::Int16)) == "int16");
    CHECK(std::string(scalarTypeName(ScalarType::UInt32)) == "uint32");
    CHECK(std::string(scalarTypeName(ScalarType::Int32)) == "int32");
    CHECK(std::string(scalarTypeName(ScalarType::Float32)) == "float32");
    CHECK(std::string(scalarTypeName(ScalarType::Float64)) == "float64");
    const std::size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
    for (int i = 0; i < 8; ++i) CHECK(scalarTypeSize(kAllTypes[i]) == sizes[i]);
}

TEST_CASE("sample type names parse back to their types", "[core][volume]") {
    for (ScalarType type : kScalarTypes) CHECK(parseScalarType(scalarTypeName(type)) == type);
    CHECK(kScalarTypes.size() == static_cast<std::size_t>(ScalarType::Float64) + 1);
    CHECK_THROWS_AS(parseScalarType("float16"), InputError);
    CHECK_THROWS_AS(parseScalarType("UInt8"), InputError);
    CHECK_THROWS_AS(parseScalarType(""), InputError);
}

TEST_CASE("volume is zero-filled with the requested geometry", "[core][volume]") {
    for (ScalarType type : kAllTypes) {
        Volume v({3, 4, 5}, type, {0.5, 1, 2}, {-1, 0, 10});
        CHECK(v.sampleCount() == 60);
        CHECK(v.byteSize() == 60 * scalarTypeSize(type));
        CHECK(v.spacing() == Vec3d{0.5, 1, 2});
        CHECK(v.origin() == Vec3d{-1, 0, 10});
        for (std::size_t i = 0; i < v.byteSize(); ++i) REQUIRE(v.bytes()[i] == std::byte{0});
        CHECK(v.range() == std::array<double, 2>{0, 0});
    }
}

TEST_CASE("value and setValue round-trip for every type", "[core][volume]") {
    for (ScalarType type : kAllTypes) {
        INFO(scalarTypeName(type));
        Volume v({4, 3, 2}, type);
        const bool isSigned = type == ScalarType::Int8 || type == ScalarType::Int16 || type == ScalarType::Int32 ||
                              type == ScalarType::Float32 || type == ScalarType::Float64;
        for (int z = 0; z < 2; ++z)
            for (int y = 0; y < 3; ++y)
                for (int x = 0; x < 4; ++x) v.setValue(x, y, z, double(x + 4 * y + 12 * z) - (isSigned ? 10 : 0));
        for (int z = 0; z < 2; ++z)
            for (int y = 0; y < 3; ++y)
                for (int x = 0; x < 4; ++x) CHECK(v.value(x, y, z) == double(x + 4 * y + 12 * z) - (isSigned ? 10 : 0));
        // The x-fastest layout is part of the contract.
        CHECK(v.index(1, 2, 1) == 1 + 4 * (2 + 3 * 1));
        const auto r = v.range();
        CHECK(r[0] == (isSigned ? -10.0 : 0.0));
        CHECK(r[1] == (isSigned ? 13.0 : 23.0));
    }
}

TEST_CASE("setValue saturates and rounds integer samples", "[core][volume]") {
    Volume u8({2, 1, 1}, ScalarType::UInt8);
    u8.setValue(0, 0, 0, 300);
    u8.setValue(1, 0, 0, -5);
    CHECK(u8.value(0, 0, 0) == 255);
    CHECK(u8.value(1, 0, 0) == 0);
    Volume i16({2, 1, 1}, ScalarType::Int16);
    i16.setValue(0, 0, 0, 2.6);
    i16.setValue(1, 0, 0, -1e9);
    CHECK(i16.value(0, 0, 0) == 3);
    CHECK(i16.value(1, 0, 0) == -32768);
    Volume u32({1, 1, 1}, ScalarType::UInt32);
    u32.setValue(0, 0, 0, 4294967295.0);
    CHECK(u32.value(0, 0, 0) == 4294967295.0);
    Volume f64({1, 1, 1}, ScalarType::Float64);
    f64.setValue(0, 0, 0, 0.1);
    CHECK(f64.value(0, 0, 0) == 0.1);
}

TEST_CASE("range skips non-finite samples", "[core][volume]") {
    const double inf = std::numeric_limits<double>::infinity();
    Volume v({3, 1, 1}, ScalarType::Float32);
    v.setValue(0, 0, 0, std::nan(""));
    v.setValue(1, 0, 0, 2.5);
    v.setValue(2, 0, 0, -inf);
    CHECK(v.range() == std::array<double, 2>{2.5, 2.5});

    Volume allBad({2, 1, 1}, ScalarType::Float64);
    allBad.setValue(0, 0, 0, inf);
    allBad.setValue(1, 0, 0, std::nan(""));
    const auto r = allBad.range();
    CHECK(std::isnan(r[0]));
    CHECK(std::isnan(r[1]));
    CHECK(std::isnan(Volume().range()[0]));
}

TEST_CASE("volume rejects bad dimensions without allocating", "[core][volume]") {
    CHECK_THROWS_AS(Volume({0, 4, 4}, ScalarType::UInt8), InputError);
    CHECK_THROWS_AS(Volume({4, -1, 4}, ScalarType::UInt8), InputError);
    CHECK_THROWS_AS(Volume({4, 4, 0}, ScalarType::Float32), InputError);
    // Would overflow 64 bits if multiplied naively; must be refused up front.
    CHECK_THROWS_AS(Volume({2147483647, 2147483647, 2147483647}, ScalarType::Float64), InputError);
    // More than the memory available (asked for first): refused before allocating,
    // saying how much it needs and how much there is.
    const std::uint64_t available = availableMemoryBytes();
    const int slices = int(available / (std::uint64_t(1024) * 1024 * 8)) + 1;
    CHECK_THROWS_WITH(Volume({1024, 1024, slices}, ScalarType::Float64), Catch::Contains("of memory, more than"));
    CHECK_THROWS_WITH(Volume({2, 0, 3}, ScalarType::UInt8), Catch::Contains("2 x 0 x 3"));
}

TEST_CASE("sample histogram: finite samples in equal bins, the ends clamped", "[core][volume]") {
    Volume volume({6, 1, 1}, ScalarType::Float32);
    const double values[6] = {0.0, 0.9, 1.0, 3.99, 4.0, std::nan("")};
    for (int x = 0; x < 6; ++x) volume.setValue(x, 0, 0, values[x]);
    // [0, 4] in 4 bins of width 1: 4.0 belongs to the last bin, NaN to none.
    CHECK(sampleHistogram(volume, volume.range(), 4) == std::vector<std::uint64_t>{2, 1, 0, 2});
    // A range narrower than the data clamps to the end bins; a flat range puts everything in the first.
    CHECK(sampleHistogram(volume, {1.0, 3.0}, 2) == std::vector<std::uint64_t>{3, 2});
    CHECK(sampleHistogram(volume, {2.0, 2.0}, 3) == std::vector<std::uint64_t>{5, 0, 0});
}

TEST_CASE("a view reads the caller's samples in place", "[core][volume]") {
    Volume owned({5, 4, 3}, ScalarType::Int16, {0.5, 1, 2}, {1, 2, 3});
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 5; ++x) owned.setValue(x, y, z, x - 2 * y + 7 * z);
    const Volume view = Volume::view(owned.dims(), owned.type(), owned.bytes(), owned.spacing(), owned.origin());
    CHECK(view.isView());
    CHECK_FALSE(owned.isView());
    CHECK(view.bytes() == owned.bytes());  // the same memory, not a copy
    CHECK(view.byteSize() == owned.byteSize());
    CHECK(view.spacing() == owned.spacing());
    CHECK(view.origin() == owned.origin());
    CHECK(view.range() == owned.range());
    CHECK(view.value(4, 3, 2) == owned.value(4, 3, 2));
    const Volume copy = view;  // copies of a view still read the caller's samples
    CHECK(copy.bytes() == owned.bytes());
    const std::int16_t sample = 0;
    CHECK_THROWS_AS(Volume::view({0, 4, 3}, ScalarType::Int16, &sample), InputError);
    CHECK_THROWS_AS(Volume::view({kMaxDimension + 1, 1, 1}, ScalarType::Int16, &sample), InputError);
}
