#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io_test_files.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"

using namespace isotrack;

namespace {

using isotrack::testing::gzipBytes;
using isotrack::testing::patterned;
using isotrack::testing::readFile;
using isotrack::testing::requireSameVolume;
using isotrack::testing::sampleBytes;
using isotrack::testing::TempDir;
using isotrack::testing::writeFile;

const char* kHeader16 =
    "NRRD0004\n"
    "type: short\n"
    "dimension: 3\n"
    "sizes: 2 2 2\n"
    "endian: little\n"
    "encoding: raw\n"
    "\n";

std::string withField(std::string header, const std::string& from, const std::string& to) {
    const std::size_t at = header.find(from);
    REQUIRE(at != std::string::npos);
    return header.replace(at, from.size(), to);
}

Mesh sampleMesh() {
    Mesh m;
    for (int i = 0; i < 5; ++i) m.vertices.push_back({{float(i), float(i) * 0.5f, -float(i)}, {0.0f, 0.6f, 0.8f}});
    m.indices = {0, 1, 2, 2, 3, 4, 4, 1, 0};
    return m;
}

}  // namespace

TEST_CASE("NRRD write/read round trip for every type", "[core][io]") {
    TempDir dir;
    const ScalarType types[] = {ScalarType::UInt8,  ScalarType::Int8,  ScalarType::UInt16,  ScalarType::Int16,
                                ScalarType::UInt32, ScalarType::Int32, ScalarType::Float32, ScalarType::Float64};
    for (ScalarType type : types) {
        INFO(scalarTypeName(type));
        const Volume v = patterned(type);
        const std::string path = dir.file(std::string("v_") + scalarTypeName(type) + ".nrrd");
        writeNrrd(v, path);
        requireSameVolume(loadNrrd(path), v);
        requireSameVolume(loadVolume(path), v);
    }
    const Volume field = makeField({"torus", 20});
    writeNrrd(field, dir.file("torus.NRRD"));
    requireSameVolume(loadVolume(dir.file("torus.NRRD")), field);
}

TEST_CASE("NRRD big-endian data is swapped to host order", "[core][io]") {
    TempDir dir;
    struct Case {
        ScalarType type;
        const char* nrrdName;
    };
    for (const Case& c : {Case{ScalarType::Int16, "signed short int"}, Case{ScalarType::UInt16, "ushort"},
                          Case{ScalarType::UInt32, "unsigned int"}, Case{ScalarType::Float32, "float"},
                          Case{ScalarType::Float64, "double"}, Case{ScalarType::UInt8, "unsigned char"}}) {
        INFO(c.nrrdName);
        const Volume v = patterned(c.type);
        const std::string header = std::string("NRRD0005\n# hand written\n") + "type: " + c.nrrdName +
                                   "\ndimension: 3\nsizes: 5 4 3\nspacings: 0.5 1.25 3\n"
                                   "space origin: (-10.5, 0.25, 7)\nkey:=value: with colon\n"
                                   "endian: big\nencoding: raw\n\n";
        const std::string path = dir.file("be.nrrd");
        writeFile(path, header + sampleBytes(v, true));
        requireSameVolume(loadNrrd(path), v);
    }
}

TEST_CASE("NRRD space directions give spacing", "[core][io]") {
    TempDir dir;
    const std::string header =
        "NRRD0004\r\ntype: uint8\r\ndimension: 3\r\nspace: left-posterior-superior\r\n"
        "sizes: 2 2 2\r\nspace directions: (-0.75,0,0) (0,2,0) (0,0,0.5)\r\n"
        "space origin: (1,2,3)\r\nencoding: raw\r\n\r\n";
    writeFile(dir.file("dirs.nrrd"), header + std::string(8, '\x07'));
    const Volume v = loadNrrd(dir.file("dirs.nrrd"));
    CHECK(v.spacing() == Vec3d{0.75, 2, 0.5});
    CHECK(v.origin() == Vec3d{1, 2, 3});
    CHECK(v.value(1, 1, 1) == 7);
    CHECK(v.type() == ScalarType::UInt8);
}

TEST_CASE("NRRD gzip encoding", "[core][io]") {
    TempDir dir;
    const Volume v = patterned(ScalarType::Int32, {31, 17, 9});
    const std::string raw(reinterpret_cast<const char*>(v.bytes()), v.byteSize());
    const std::string header =
        "NRRD0004\ntype: int32\ndimension: 3\nsizes: 31 17 9\nspacings: 0.5 1.25 3\n"
        "space origin: (-10.5,0.25,7)\nendian: little\nencoding: gzip\n\n";
    writeFile(dir.file("gz.nrrd"), header + gzipBytes(raw));
    requireSameVolume(loadNrrd(dir.file("gz.nrrd")), v);

    // Too much data for the sizes given.
    writeFile(dir.file("more.nrrd"), withField(header, "sizes: 31 17 9", "sizes: 31 17 8") + gzipBytes(raw));
    CHECK_THROWS_WITH(loadNrrd(dir.file("more.nrrd")), Catch::Contains("more than"));
    // Stream cut short.
    const std::string gz = gzipBytes(raw);
    writeFile(dir.file("cut.nrrd"), header + gz.substr(0, gz.size() / 2));
    CHECK_THROWS_AS(loadNrrd(dir.file("cut.nrrd")), FormatError);
    // Complete stream holding too little.
    writeFile(dir.file("less.nrrd"), withField(header, "sizes: 31 17 9", "sizes: 31 17 10") + gzipBytes(raw));
    CHECK_THROWS_WITH(loadNrrd(dir.file("less.nrrd")), Catch::Contains("truncated"));
    // Not gzip at all.
    writeFile(dir.file("junk.nrrd"), header + std::string(1000, 'x'));
    CHECK_THROWS_AS(loadNrrd(dir.file("junk.nrrd")), FormatError);
    // A tiny stream claiming 8 GB is refused before anything is allocated.
    writeFile(dir.file("bomb.nrrd"), withField(header, "sizes: 31 17 9", "sizes: 2000 2000 500") + gz);
    CHECK_THROWS_WITH(loadNrrd(dir.file("bomb.nrrd")), Catch::Contains("field \"sizes\""));
}

TEST_CASE("NRRD detached header", "[core][io]") {
    TempDir dir;
    const Volume v = patterned(ScalarType::Float32);
    writeFile(dir.file("data.raw"), sampleBytes(v, true));
    writeFile(dir.file("vol.nhdr"),
              "NRRD0004\ntype: float\ndimension: 3\nsizes: 5 4 3\nspacings: 0.5 1.25 3\n"
              "space origin: (-10.5,0.25,7)\nendian: big\nencoding: raw\ndata file: data.raw\n");
    requireSameVolume(loadVolume(dir.file("vol.nhdr")), v);

    writeFile(dir.file("missing.nhdr"),
              "NRRD0004\ntype: float\ndimension: 3\nsizes: 5 4 3\nendian: big\nencoding: raw\ndata file: nope.raw\n");
    CHECK_THROWS_WITH(loadVolume(dir.file("missing.nhdr")),
                      Catch::Contains("nope.raw") && Catch::Contains("cannot open"));
}

TEST_CASE("NRRD loader refuses malformed files", "[core][io]") {
    TempDir dir;
    const std::string data(8 * 2, '\0');
    auto load = [&](const std::string& bytes) {
        const std::string path = dir.file("bad.nrrd");
        writeFile(path, bytes);
        return loadNrrd(path);
    };
    // The baseline is valid, so each failure below is due to its one change.
    CHECK(load(kHeader16 + data).dims() == Dims{2, 2, 2});

    CHECK_THROWS_WITH(loadNrrd(dir.file("absent.nrrd")), Catch::Contains("absent.nrrd: cannot open: "));
    CHECK_THROWS_WITH(loadVolume(dir.file("absent.nrrd")), Catch::Contains("cannot open"));
    CHECK_THROWS_WITH(load("NRRX0004\n" + data), Catch::Contains("not a NRRD file"));
    CHECK_THROWS_AS(load(""), FormatError);
    CHECK_THROWS_AS(load("NRRD0004"), FormatError);
    CHECK_THROWS_AS(load(std::string(5000, '\xff')), FormatError);

    CHECK_THROWS_WITH(load(withField(kHeader16, "sizes: 2 2 2", "sizes: 2 0 2") + data),
                      Catch::Contains("field \"sizes\": expected 3 positive integers, got \"2 0 2\""));
    CHECK_THROWS_AS(load(withField(kHeader16, "sizes: 2 2 2", "sizes: 2 -2 2") + data), FormatError);
    CHECK_THROWS_AS(load(withField(kHeader16, "sizes: 2 2 2", "sizes: 2 2") + data), FormatError);
    CHECK_THROWS_AS(load(withField(kHeader16, "sizes: 2 2 2", "sizes: 2 2 2 2") + data), FormatError);
    CHECK_THROWS_AS(load(withField(kHeader16, "sizes: 2 2 2", "sizes: 2 2 x") + data), FormatError);
    CHECK_THROWS_AS(load(withField(kHeader16, "sizes: 2 2 2", "sizes: 2 2 99999999999999999999") + data), FormatError);
    CHECK_THROWS_AS(load(withField(kHeader16, "sizes: 2 2 2", "sizes: 2147483647 2147483647 2147483647") + data),
                    FormatError);
    // Refused on the size check, before anything is allocated (the hostile-file
    // tests also bound every refusal's largest allocation).
    CHECK_THROWS_AS(load(withField(kHeader16, "sizes: 2 2 2", "sizes: 100000 100000 100000") + data), FormatError);
    CHECK_THROWS_WITH(load(withField(kHeader16, "sizes: 2 2 2", "sizes: 1000 1000 1000") + data),
                      Catch::Contains("field \"sizes\"") && Catch::Contains("has only 16"));
    CHECK_THROWS_WITH(load(kHeader16 + data.substr(0, 15)), Catch::Contains("has only 15"));

    CHECK_THROWS_WITH(load(withField(kHeader16, "type: short", "type: quaternion") + data),
                      Catch::Contains("field \"type\"") && Catch::Contains("quaternion"));
    CHECK_THROWS_AS(load(withField(kHeader16, "type: short", "type: int64") + data), FormatError);
    CHECK_THROWS_WITH(load(withField(kHeader16, "encoding: raw", "encoding: bzip2") + data),
                      Catch::Contains("field \"encoding\"") && Catch::Contains("bzip2"));
    CHECK_THROWS_AS(load(withField(kHeader16, "encoding: raw", "encoding: zstd") + data), FormatError);
    CHECK_THROWS_WITH(load(withField(kHeader16, "dimension: 3", "dimension: 2") + data),
                      Catch::Contains("field \"dimension\": expected 3 (or 4, time last), got \"2\""));
    CHECK_THROWS_AS(load(withField(kHeader16, "endian: little", "endian: middle") + data), FormatError);
    CHECK_THROWS_WITH(load(withField(kHeader16, "endian: little\n", "") + data), Catch::Contains("endian"));
    CHECK_THROWS_WITH(load(withField(kHeader16, "type: short\n", "") + data), Catch::Contains("\"type\""));
    CHECK_THROWS_AS(load(withField(kHeader16, "encoding: raw\n", "") + data), FormatError);
    CHECK_THROWS_AS(load(withField(kHeader16, "dimension: 3", "dimension: 3\ndimension: 3") + data), FormatError);
    CHECK_THROWS_AS(load(withField(kHeader16, "dimension: 3", "this line has no separator") + data), FormatError);
    CHECK_THROWS_AS(load(withField(kHeader16, "dimension: 3", "dimension: 3\nspacings: 1 0 1") + data), FormatError);
    CHECK_THROWS_AS(load(withField(kHeader16, "dimension: 3", "dimension: 3\nspacings: 1 nan 1") + data), FormatError);
    CHECK_THROWS_AS(
        load(withField(kHeader16, "dimension: 3", "dimension: 3\nspace directions: (1,0,0) none (0,0,1)") + data),
        FormatError);
    CHECK_THROWS_AS(load(withField(kHeader16, "dimension: 3", "dimension: 3\nspace origin: (1,2)") + data),
                    FormatError);
    // Header never ends: no blank line and no data file.
    CHECK_THROWS_AS(load(withField(kHeader16, "\n\n", "\n")), FormatError);

    // One-line messages, even when the header holds control characters.
    try {
        load(withField(kHeader16, "type: short", std::string("type: sh\rort\x01") + std::string(200, 'z')) + data);
        FAIL("expected FormatError");
    } catch (const FormatError& e) {
        const std::string msg = e.what();
        CHECK(msg.find('\n') == std::string::npos);
        CHECK(msg.find('\r') == std::string::npos);
        CHECK(msg.size() < 300);
    }

    writeFile(dir.file("vol.raw"), data);
    CHECK_THROWS_WITH(loadVolume(dir.file("vol.raw")),
                      Catch::Contains("vol.raw") && Catch::Contains(".nrrd") && Catch::Contains(".nhdr"));
}

TEST_CASE("PLY write/read round trip", "[core][io]") {
    TempDir dir;
    const Mesh mesh = sampleMesh();

    writePly(dir.file("plain.ply"), mesh);
    std::vector<std::int32_t> comps = {7};
    const Mesh back = readPly(dir.file("plain.ply"), &comps);
    CHECK(comps.empty());
    REQUIRE(back.vertices.size() == mesh.vertices.size());
    CHECK(back.indices == mesh.indices);
    CHECK(back.vertexEdges.empty());
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            CHECK(back.vertices[i].position[k] == mesh.vertices[i].position[k]);
            CHECK(back.vertices[i].normal[k] == mesh.vertices[i].normal[k]);
        }
    const std::string text = readFile(dir.file("plain.ply"));
    CHECK(text.find("format binary_little_endian 1.0\n") != std::string::npos);
    CHECK(text.find("element vertex 5\n") != std::string::npos);
    CHECK(text.find("element face 3\n") != std::string::npos);
    CHECK(text.find("property list uchar int vertex_indices\n") != std::string::npos);
    CHECK(text.find("component") == std::string::npos);

    const std::vector<std::int32_t> faceComponent = {0, 2, -1};
    writePly(dir.file("comp.ply"), mesh, &faceComponent);
    CHECK(readFile(dir.file("comp.ply")).find("property int component\n") != std::string::npos);
    const Mesh back2 = readPly(dir.file("comp.ply"), &comps);
    CHECK(back2.indices == mesh.indices);
    CHECK(comps == faceComponent);
    CHECK(readPly(dir.file("comp.ply")).indices == mesh.indices);

    writePly(dir.file("empty.ply"), Mesh{});
    CHECK(readPly(dir.file("empty.ply")).vertices.empty());
}

TEST_CASE("PLY errors", "[core][io]") {
    TempDir dir;
    const Mesh mesh = sampleMesh();
    const std::vector<std::int32_t> wrongCount = {1, 2};
    CHECK_THROWS_AS(writePly(dir.file("x.ply"), mesh, &wrongCount), InputError);
    Mesh broken = mesh;
    broken.indices[4] = 99;
    CHECK_THROWS_AS(writePly(dir.file("x.ply"), broken), InputError);
    CHECK_THROWS_WITH(writePly(dir.file("no/such/dir/x.ply"), mesh), Catch::Contains("cannot open"));

    CHECK_THROWS_WITH(readPly(dir.file("absent.ply")), Catch::Contains("cannot open"));
    writeFile(dir.file("ascii.ply"), "ply\nformat ascii 1.0\nelement vertex 0\nend_header\n");
    CHECK_THROWS_AS(readPly(dir.file("ascii.ply")), FormatError);
    writeFile(dir.file("notply.ply"), std::string(100, '\0'));
    CHECK_THROWS_AS(readPly(dir.file("notply.ply")), FormatError);

    writePly(dir.file("good.ply"), mesh);
    const std::string good = readFile(dir.file("good.ply"));
    writeFile(dir.file("short.ply"), good.substr(0, good.size() - 3));
    CHECK_THROWS_AS(readPly(dir.file("short.ply")), FormatError);
    writeFile(dir.file("huge.ply"), withField(good, "element vertex 5", "element vertex 999999999999"));
    CHECK_THROWS_AS(readPly(dir.file("huge.ply")), FormatError);
    // Corrupt the last face's last index to point past the vertices.
    std::string badIndex = good;
    badIndex[badIndex.size() - 4] = '\x09';
    writeFile(dir.file("index.ply"), badIndex);
    CHECK_THROWS_WITH(readPly(dir.file("index.ply")), Catch::Contains("out of range"));
}
