#pragma once
// Files written by the I/O tests themselves: a temporary directory, compressed
// bytes, samples in either byte order, and NIfTI-1 headers built field by field.
#include <unistd.h>
#include <zlib.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "isotrack/volume.h"

namespace isotrack::testing {

// A fresh directory per test case, removed afterwards.
class TempDir {
public:
    TempDir() {
        static std::atomic<int> counter{0};
        const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
        path_ = std::filesystem::temp_directory_path() / ("isotrack-io-" + std::to_string(::getpid()) + "-" +
                                                          std::to_string(stamp) + "-" + std::to_string(counter++));
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::string file(const std::string& name) const { return (path_ / name).string(); }

private:
    std::filesystem::path path_;
};

inline void writeFile(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    REQUIRE(out.good());
}

inline std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// windowBits 16 + 15 makes a gzip stream, 15 a zlib stream.
inline std::string deflateBytes(const std::string& raw, int windowBits) {
    z_stream zs{};
    REQUIRE(deflateInit2(&zs, Z_BEST_SPEED, Z_DEFLATED, windowBits, 8, Z_DEFAULT_STRATEGY) == Z_OK);
    std::string out(deflateBound(&zs, uLong(raw.size())) + 64, '\0');
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(raw.data()));
    zs.avail_in = uInt(raw.size());
    zs.next_out = reinterpret_cast<Bytef*>(&out[0]);
    zs.avail_out = uInt(out.size());
    REQUIRE(deflate(&zs, Z_FINISH) == Z_STREAM_END);
    out.resize(zs.total_out);
    deflateEnd(&zs);
    return out;
}
inline std::string gzipBytes(const std::string& raw) { return deflateBytes(raw, 16 + MAX_WBITS); }
inline std::string zlibBytes(const std::string& raw) { return deflateBytes(raw, MAX_WBITS); }

inline bool hostIsBigEndian() {
    const std::uint16_t probe = 1;
    unsigned char first = 0;
    std::memcpy(&first, &probe, 1);
    return first == 0;
}

// The volume's samples as a file would hold them.
inline std::string sampleBytes(const Volume& v, bool bigEndian) {
    std::string bytes(reinterpret_cast<const char*>(v.bytes()), v.byteSize());
    const std::size_t width = scalarTypeSize(v.type());
    if (bigEndian != hostIsBigEndian())
        for (std::size_t i = 0; i + width <= bytes.size(); i += width) std::reverse(&bytes[i], &bytes[i] + width);
    return bytes;
}

// Numbers in a chosen byte order, for hand-built binary headers.
template <class T>
std::string encode(T value, bool bigEndian) {
    std::string bytes(sizeof(T), '\0');
    std::memcpy(&bytes[0], &value, sizeof(T));
    if (bigEndian != hostIsBigEndian()) std::reverse(bytes.begin(), bytes.end());
    return bytes;
}

inline const std::vector<ScalarType>& allScalarTypes() {
    static const std::vector<ScalarType> types = {ScalarType::UInt8,   ScalarType::Int8,   ScalarType::UInt16,
                                                  ScalarType::Int16,   ScalarType::UInt32, ScalarType::Int32,
                                                  ScalarType::Float32, ScalarType::Float64};
    return types;
}

// A volume whose samples all differ, so byte order and layout mistakes show.
inline Volume patterned(ScalarType type, Dims dims = {5, 4, 3}, Vec3d spacing = {0.5, 1.25, 3.0},
                        Vec3d origin = {-10.5, 0.25, 7.0}) {
    Volume v(dims, type, spacing, origin);
    const bool isSigned = type != ScalarType::UInt8 && type != ScalarType::UInt16 && type != ScalarType::UInt32;
    for (int z = 0; z < dims[2]; ++z)
        for (int y = 0; y < dims[1]; ++y)
            for (int x = 0; x < dims[0]; ++x) {
                const double base = double(v.index(x, y, z) % 100);
                v.setValue(x, y, z, isSigned ? base - 20 : base + 1);
            }
    if (type == ScalarType::UInt16) v.setValue(0, 0, 0, 0xABCD);
    if (type == ScalarType::Int16) v.setValue(0, 0, 0, -12345);
    if (type == ScalarType::Int32) v.setValue(0, 0, 0, -123456789);
    if (type == ScalarType::UInt32) v.setValue(0, 0, 0, 0xDEADBEEF);
    if (type == ScalarType::Float32) v.setValue(0, 0, 0, 0.1);
    if (type == ScalarType::Float64) v.setValue(0, 0, 0, 1.0 / 3.0);
    return v;
}

inline void requireSameVolume(const Volume& a, const Volume& b) {
    REQUIRE(a.dims() == b.dims());
    REQUIRE(a.type() == b.type());
    CHECK(a.spacing() == b.spacing());
    CHECK(a.origin() == b.origin());
    CHECK(a.direction() == b.direction());
    REQUIRE(a.byteSize() == b.byteSize());
    CHECK(std::memcmp(a.bytes(), b.bytes(), a.byteSize()) == 0);
}

// A NIfTI-1 header, field by field; bytes() lays it out in either byte order.
struct NiftiHeader {
    bool bigEndian = false;
    std::int32_t sizeofHdr = 348;
    std::int16_t dim[8] = {3, 1, 1, 1, 1, 1, 1, 1};
    std::int16_t datatype = 2;
    std::int16_t bitpix = 8;
    float pixdim[8] = {1, 1, 1, 1, 1, 1, 1, 1};
    float voxOffset = 352;
    float sclSlope = 0, sclInter = 0;
    std::int16_t qformCode = 0, sformCode = 0;
    float quatern[3] = {0, 0, 0};  // b, c, d
    float qoffset[3] = {0, 0, 0};
    float srow[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    std::string magic = std::string("n+1\0", 4);

    std::string bytes() const {
        std::string h(348, '\0');
        auto put = [&](std::size_t at, const std::string& b) { h.replace(at, b.size(), b); };
        put(0, encode(sizeofHdr, bigEndian));
        for (std::size_t i = 0; i < 8; ++i) put(40 + 2 * i, encode(dim[i], bigEndian));
        put(70, encode(datatype, bigEndian));
        put(72, encode(bitpix, bigEndian));
        for (std::size_t i = 0; i < 8; ++i) put(76 + 4 * i, encode(pixdim[i], bigEndian));
        put(108, encode(voxOffset, bigEndian));
        put(112, encode(sclSlope, bigEndian));
        put(116, encode(sclInter, bigEndian));
        put(252, encode(qformCode, bigEndian));
        put(254, encode(sformCode, bigEndian));
        for (std::size_t i = 0; i < 3; ++i) put(256 + 4 * i, encode(quatern[i], bigEndian));
        for (std::size_t i = 0; i < 3; ++i) put(268 + 4 * i, encode(qoffset[i], bigEndian));
        for (std::size_t r = 0; r < 3; ++r)
            for (std::size_t c = 0; c < 4; ++c) put(280 + 16 * r + 4 * c, encode(srow[r][c], bigEndian));
        put(344, magic.substr(0, 4));
        return h;
    }
};

// NIfTI codes and widths of Volume's types.
inline std::int16_t niftiDatatype(ScalarType type) {
    switch (type) {
        case ScalarType::UInt8: return 2;
        case ScalarType::Int8: return 256;
        case ScalarType::UInt16: return 512;
        case ScalarType::Int16: return 4;
        case ScalarType::UInt32: return 768;
        case ScalarType::Int32: return 8;
        case ScalarType::Float32: return 16;
        case ScalarType::Float64: return 64;
    }
    return 0;
}

// A header describing `v` (spacing in pixdim, origin and direction through the
// sform, which is RAS where the volume is LPS: rows x and y change sign).
inline NiftiHeader niftiHeaderFor(const Volume& v, bool bigEndian) {
    NiftiHeader h;
    h.bigEndian = bigEndian;
    for (std::size_t a = 0; a < 3; ++a) {
        h.dim[a + 1] = std::int16_t(v.dims()[a]);
        h.pixdim[a + 1] = float(v.spacing()[a]);
        const double toRas = a < 2 ? -1.0 : 1.0;
        for (std::size_t c = 0; c < 3; ++c) h.srow[a][c] = float(toRas * v.direction()[c][a] * v.spacing()[c]);
        h.srow[a][3] = float(toRas * v.origin()[a]);
    }
    h.datatype = niftiDatatype(v.type());
    h.bitpix = std::int16_t(8 * scalarTypeSize(v.type()));
    h.sformCode = 1;
    return h;
}

// A whole single-file NIfTI: header, the 4-byte extension flag, samples.
inline std::string niftiFile(const NiftiHeader& h, const std::string& samples) {
    std::string out = h.bytes() + std::string(4, '\0');
    out.resize(std::size_t(h.voxOffset), '\0');
    return out + samples;
}

}  // namespace isotrack::testing
