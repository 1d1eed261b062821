// Round trips through every volume format, with headers written by hand here,
// and the mesh writers read back.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "io_test_files.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"

using namespace isotrack;
using namespace isotrack::testing;

namespace {

const char* metaTypeName(ScalarType type) {
    switch (type) {
        case ScalarType::UInt8: return "MET_UCHAR";
        case ScalarType::Int8: return "MET_CHAR";
        case ScalarType::UInt16: return "MET_USHORT";
        case ScalarType::Int16: return "MET_SHORT";
        case ScalarType::UInt32: return "MET_UINT";
        case ScalarType::Int32: return "MET_INT";
        case ScalarType::Float32: return "MET_FLOAT";
        case ScalarType::Float64: return "MET_DOUBLE";
    }
    return "";
}

const char* vtkTypeName(ScalarType type) {
    switch (type) {
        case ScalarType::UInt8: return "unsigned_char";
        case ScalarType::Int8: return "char";
        case ScalarType::UInt16: return "unsigned_short";
        case ScalarType::Int16: return "short";
        case ScalarType::UInt32: return "unsigned_int";
        case ScalarType::Int32: return "int";
        case ScalarType::Float32: return "float";
        case ScalarType::Float64: return "double";
    }
    return "";
}

std::string metaHeader(const Volume& v, bool msb, const std::string& dataFile, const std::string& extra = "") {
    std::ostringstream h;
    h.precision(17);
    const Dims& d = v.dims();
    const Vec3d& s = v.spacing();
    const Vec3d& o = v.origin();
    h << "ObjectType = Image\nNDims = 3\nBinaryData = True\n"
      << "BinaryDataByteOrderMSB = " << (msb ? "True" : "False") << "\n"
      << extra << "Offset = " << o[0] << " " << o[1] << " " << o[2] << "\n"
      << "ElementSpacing = " << s[0] << " " << s[1] << " " << s[2] << "\n"
      << "DimSize = " << d[0] << " " << d[1] << " " << d[2] << "\n"
      << "ElementType = " << metaTypeName(v.type()) << "\n"
      << "ElementDataFile = " << dataFile << "\n";
    return h.str();
}

std::string vtkHeader(const Volume& v, bool binary) {
    std::ostringstream h;
    h.precision(17);
    const Dims& d = v.dims();
    const Vec3d& s = v.spacing();
    const Vec3d& o = v.origin();
    h << "# vtk DataFile Version 3.0\nwritten by io_formats_test\n"
      << (binary ? "BINARY" : "ASCII") << "\n"
      << "DATASET STRUCTURED_POINTS\nDIMENSIONS " << d[0] << " " << d[1] << " " << d[2] << "\n"
      << "SPACING " << s[0] << " " << s[1] << " " << s[2] << "\nORIGIN " << o[0] << " " << o[1] << " " << o[2] << "\n"
      << "POINT_DATA " << v.sampleCount() << "\nSCALARS values " << vtkTypeName(v.type())
      << " 1\nLOOKUP_TABLE default\n";
    return h.str();
}

std::string asciiSamples(const Volume& v) {
    std::ostringstream out;
    out.precision(17);
    const Dims& d = v.dims();
    for (int z = 0; z < d[2]; ++z)
        for (int y = 0; y < d[1]; ++y) {
            for (int x = 0; x < d[0]; ++x) out << v.value(x, y, z) << (x + 1 < d[0] ? " " : "");
            out << "\n";
        }
    return out.str();
}

// The volume with geometry rounded through float, as NIfTI stores it.
Volume withFloatGeometry(Volume v) {
    Vec3d s = v.spacing(), o = v.origin();
    for (std::size_t a = 0; a < 3; ++a) s[a] = double(float(s[a])), o[a] = double(float(o[a]));
    v.setSpacing(s);
    v.setOrigin(o);
    return v;
}

}  // namespace

TEST_CASE("NIfTI-1 round trip for every type, both endians, .nii and .nii.gz", "[core][io][nifti]") {
    TempDir dir;
    for (ScalarType type : allScalarTypes()) {
        for (bool big : {false, true}) {
            CAPTURE(scalarTypeName(type), big);
            const Volume v = withFloatGeometry(patterned(type));
            const std::string file = niftiFile(niftiHeaderFor(v, big), sampleBytes(v, big));
            writeFile(dir.file("v.nii"), file);
            requireSameVolume(loadNifti(dir.file("v.nii")), v);
            writeFile(dir.file("v.nii.gz"), gzipBytes(file));
            requireSameVolume(loadNifti(dir.file("v.nii.gz")), v);
            requireSameVolume(loadVolume(dir.file("v.nii.gz")), v);
        }
    }
}

TEST_CASE("NIfTI-1 origin: sform, else qoffset, else zero; extra dims of 1 and extensions are fine",
          "[core][io][nifti]") {
    TempDir dir;
    const Volume v = withFloatGeometry(patterned(ScalarType::Int16));
    NiftiHeader h = niftiHeaderFor(v, false);
    const std::string samples = sampleBytes(v, false);

    h.sformCode = 0;
    h.qformCode = 1;
    h.qoffset[0] = 1.5f, h.qoffset[1] = -2.0f, h.qoffset[2] = 3.25f;
    writeFile(dir.file("q.nii"), niftiFile(h, samples));
    // NIfTI's RAS qoffset, in isotrack's LPS world.
    CHECK(loadNifti(dir.file("q.nii")).origin() == Vec3d{-1.5, 2.0, 3.25});

    h.qformCode = 0;
    writeFile(dir.file("none.nii"), niftiFile(h, samples));
    CHECK(loadNifti(dir.file("none.nii")).origin() == Vec3d{0, 0, 0});

    h = niftiHeaderFor(v, true);
    h.dim[0] = 5, h.dim[4] = 1, h.dim[5] = 1;
    h.voxOffset = 352 + 64;  // an extension before the samples
    writeFile(dir.file("5d.nii"), niftiFile(h, sampleBytes(v, true)));
    requireSameVolume(loadNifti(dir.file("5d.nii")), v);
}

TEST_CASE("NIfTI-1 scl_slope and scl_inter: float32 when they scale, native otherwise", "[core][io][nifti]") {
    TempDir dir;
    const Volume v = withFloatGeometry(patterned(ScalarType::Int16));
    NiftiHeader h = niftiHeaderFor(v, true);
    const std::string samples = sampleBytes(v, true);

    for (auto [slope, inter] : {std::pair<float, float>{0, 0}, {0, 7}, {1, 0}}) {
        h.sclSlope = slope, h.sclInter = inter;
        writeFile(dir.file("native.nii"), niftiFile(h, samples));
        requireSameVolume(loadNifti(dir.file("native.nii")), v);
    }

    h.sclSlope = 2.0f, h.sclInter = -5.0f;
    writeFile(dir.file("scaled.nii.gz"), gzipBytes(niftiFile(h, samples)));
    const Volume scaled = loadVolume(dir.file("scaled.nii.gz"));
    REQUIRE(scaled.type() == ScalarType::Float32);
    CHECK(scaled.spacing() == v.spacing());
    CHECK(scaled.origin() == v.origin());
    for (int z = 0; z < 3; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 5; ++x) CHECK(scaled.value(x, y, z) == float(2.0 * v.value(x, y, z) - 5.0));

    h.sclSlope = 1.0f, h.sclInter = 1000.0f;  // an offset alone scales too
    writeFile(dir.file("offset.nii"), niftiFile(h, samples));
    const Volume shifted = loadNifti(dir.file("offset.nii"));
    REQUIRE(shifted.type() == ScalarType::Float32);
    CHECK(shifted.value(0, 0, 0) == v.value(0, 0, 0) + 1000.0);

    const Volume d = withFloatGeometry(patterned(ScalarType::Float64));
    NiftiHeader hd = niftiHeaderFor(d, false);
    hd.sclSlope = 0.5f;
    writeFile(dir.file("double.nii"), niftiFile(hd, sampleBytes(d, false)));
    const Volume halved = loadNifti(dir.file("double.nii"));
    REQUIRE(halved.type() == ScalarType::Float32);
    CHECK(halved.value(4, 3, 2) == float(0.5 * d.value(4, 3, 2)));
}

TEST_CASE("MetaImage round trip: .mhd detached, .mha LOCAL, both byte orders, every type", "[core][io][metaimage]") {
    TempDir dir;
    std::filesystem::create_directories(dir.file("data"));
    for (ScalarType type : allScalarTypes()) {
        for (bool msb : {false, true}) {
            CAPTURE(scalarTypeName(type), msb);
            const Volume v = patterned(type);
            writeFile(dir.file("data/v.raw"), sampleBytes(v, msb));
            writeFile(dir.file("v.mhd"), metaHeader(v, msb, "data/v.raw"));
            requireSameVolume(loadMetaImage(dir.file("v.mhd")), v);
            writeFile(dir.file("v.mha"), metaHeader(v, msb, "LOCAL") + sampleBytes(v, msb));
            requireSameVolume(loadVolume(dir.file("v.mha")), v);
        }
    }
}

TEST_CASE("MetaImage zlib data, Origin for Offset, HeaderSize", "[core][io][metaimage]") {
    TempDir dir;
    const Volume v = patterned(ScalarType::Float32);
    const std::string samples = sampleBytes(v, false);

    const std::string packed = zlibBytes(samples);
    writeFile(dir.file("z.mha"),
              metaHeader(v, false, "LOCAL",
                         "CompressedData = True\nCompressedDataSize = " + std::to_string(packed.size()) + "\n") +
                  packed);
    requireSameVolume(loadMetaImage(dir.file("z.mha")), v);
    writeFile(dir.file("zd.raw"), packed);
    writeFile(dir.file("zd.mhd"), metaHeader(v, false, "zd.raw", "CompressedData = True\n"));
    requireSameVolume(loadMetaImage(dir.file("zd.mhd")), v);

    std::string header = metaHeader(v, false, "LOCAL");
    header.replace(header.find("Offset"), 6, "Origin");
    writeFile(dir.file("origin.mha"), header + samples);
    requireSameVolume(loadMetaImage(dir.file("origin.mha")), v);

    writeFile(dir.file("skip.raw"), std::string(100, 'x') + samples);
    writeFile(dir.file("skip.mhd"), metaHeader(v, false, "skip.raw", "HeaderSize = 100\n"));
    requireSameVolume(loadMetaImage(dir.file("skip.mhd")), v);
    writeFile(dir.file("end.mhd"), metaHeader(v, false, "skip.raw", "HeaderSize = -1\n"));
    requireSameVolume(loadMetaImage(dir.file("end.mhd")), v);
}

TEST_CASE("VTK legacy round trip: BINARY is big-endian, ASCII, every type", "[core][io][vtk]") {
    TempDir dir;
    for (ScalarType type : allScalarTypes()) {
        CAPTURE(scalarTypeName(type));
        const Volume v = patterned(type);
        writeFile(dir.file("b.vtk"), vtkHeader(v, true) + sampleBytes(v, true) + "\n");
        requireSameVolume(loadVtkLegacy(dir.file("b.vtk")), v);
        writeFile(dir.file("a.vtk"), vtkHeader(v, false) + asciiSamples(v));
        requireSameVolume(loadVolume(dir.file("a.vtk")), v);
    }
}

TEST_CASE("VTK legacy: keyword order and case, ASPECT_RATIO, CRLF, later attributes", "[core][io][vtk]") {
    TempDir dir;
    const Volume v = patterned(ScalarType::Int16);
    const Dims& d = v.dims();
    const std::string head =
        "# vtk DataFile Version 2.0\r\ntitle\r\nbinary\r\ndataset structured_points\r\n"
        "origin -10.5 0.25 7\r\naspect_ratio 0.5 1.25 3\r\ndimensions " +
        std::to_string(d[0]) + " " + std::to_string(d[1]) + " " + std::to_string(d[2]) +
        "\r\npoint_data 60\r\nscalars s short\r\nlookup_table default\r\n";
    writeFile(dir.file("mixed.vtk"), head + sampleBytes(v, true) + "\nVECTORS v float\n1 2 3\n");
    requireSameVolume(loadVtkLegacy(dir.file("mixed.vtk")), v);
}

TEST_CASE("raw files with an explicit layout", "[core][io][raw]") {
    TempDir dir;
    for (ScalarType type : allScalarTypes()) {
        for (bool big : {false, true}) {
            CAPTURE(scalarTypeName(type), big);
            const Volume v = patterned(type);
            writeFile(dir.file("v.bin"), sampleBytes(v, big));
            RawLayout layout;
            layout.dims = v.dims();
            layout.type = type;
            layout.spacing = v.spacing();
            layout.origin = v.origin();
            layout.bigEndian = big;
            requireSameVolume(loadRaw(dir.file("v.bin"), layout), v);
        }
    }
}

TEST_CASE("NRRD corner cases: detached gzip big-endian, byte skip -1, line skip", "[core][io]") {
    TempDir dir;
    const Volume v = patterned(ScalarType::UInt16);
    const std::string head =
        "NRRD0004\ntype: uint16\ndimension: 3\nsizes: 5 4 3\nspacings: 0.5 1.25 3\n"
        "space origin: (-10.5,0.25,7)\n";
    writeFile(dir.file("v.raw.gz"), gzipBytes(sampleBytes(v, true)));
    writeFile(dir.file("v.nhdr"), head + "endian: big\nencoding: gzip\ndata file: v.raw.gz\n");
    requireSameVolume(loadVolume(dir.file("v.nhdr")), v);

    writeFile(dir.file("tail.raw"), std::string(33, '#') + sampleBytes(v, false));
    writeFile(dir.file("tail.nhdr"), head + "endian: little\nencoding: raw\nbyte skip: -1\ndata file: tail.raw\n");
    requireSameVolume(loadVolume(dir.file("tail.nhdr")), v);

    writeFile(dir.file("lines.raw"), "first line\nsecond\n" + sampleBytes(v, false));
    writeFile(dir.file("lines.nhdr"), head + "endian: little\nencoding: raw\nline skip: 2\ndata file: lines.raw\n");
    requireSameVolume(loadVolume(dir.file("lines.nhdr")), v);
}

TEST_CASE("loadVolume picks the loader by extension, case-insensitively", "[core][io]") {
    CHECK(volumeFormatOf("a/b.NRRD") == VolumeFormat::Nrrd);
    CHECK(volumeFormatOf("b.nhdr") == VolumeFormat::Nrrd);
    CHECK(volumeFormatOf("b.nii") == VolumeFormat::Nifti);
    CHECK(volumeFormatOf("b.Nii.GZ") == VolumeFormat::Nifti);
    CHECK(volumeFormatOf("b.mhd") == VolumeFormat::MetaImage);
    CHECK(volumeFormatOf("b.MHA") == VolumeFormat::MetaImage);
    CHECK(volumeFormatOf("b.vtk") == VolumeFormat::VtkLegacy);
    CHECK(volumeFormatOf("b.raw") == VolumeFormat::Raw);
    CHECK(volumeFormatOf("b.DCM") == VolumeFormat::Dicom);
    CHECK(volumeFormatOf("a/DICOMDIR") == VolumeFormat::Dicom);
    CHECK_FALSE(volumeFormatOf("b.gz"));
    CHECK_FALSE(volumeFormatOf("b.tar.gz"));
    CHECK_FALSE(volumeFormatOf("noextension"));

    TempDir dir;
    const Volume v = patterned(ScalarType::Int8);
    writeFile(dir.file("UPPER.MHA"), metaHeader(v, false, "LOCAL") + sampleBytes(v, false));
    requireSameVolume(loadVolume(dir.file("UPPER.MHA")), v);
    CHECK_THROWS_WITH(loadVolume(dir.file("v.img")),
                      Catch::Contains("v.img") && Catch::Contains("\".img\"") && Catch::Contains(".nii.gz"));
}

namespace {

Mesh sphereMesh() { return marchingCubes(makeField({"sphere", 12}), fieldDefaultIso("sphere")); }

std::uint32_t u32At(const std::string& s, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v |= std::uint32_t(static_cast<unsigned char>(s[at + i])) << (8 * i);
    return v;
}

float floatAt(const std::string& s, std::size_t at) {
    const std::uint32_t bits = u32At(s, at);
    float f = 0;
    std::memcpy(&f, &bits, 4);
    return f;
}

}  // namespace

TEST_CASE("OBJ export: v, vn and f v//vn that read back exactly, groups per component", "[core][io][mesh]") {
    TempDir dir;
    const Mesh mesh = sphereMesh();
    REQUIRE(mesh.triangleCount() > 100);
    writeMesh(dir.file("s.OBJ"), mesh);
    std::istringstream in(readFile(dir.file("s.OBJ")));
    std::vector<std::array<float, 3>> v, vn;
    Buffer<std::uint32_t> faces;
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string tag;
        words >> tag;
        if (tag == "v" || tag == "vn") {
            std::array<float, 3> p{};
            words >> p[0] >> p[1] >> p[2];
            (tag == "v" ? v : vn).push_back(p);
        } else if (tag == "f") {
            for (int k = 0; k < 3; ++k) {
                std::string corner;
                words >> corner;
                const std::size_t slashes = corner.find("//");
                REQUIRE(slashes != std::string::npos);
                REQUIRE(corner.substr(0, slashes) == corner.substr(slashes + 2));
                faces.push_back(std::uint32_t(std::stoul(corner.substr(0, slashes)) - 1));
            }
        }
    }
    REQUIRE(v.size() == mesh.vertices.size());
    REQUIRE(vn.size() == mesh.vertices.size());
    CHECK(faces == mesh.indices);
    for (std::size_t i = 0; i < v.size(); ++i)
        for (std::size_t k = 0; k < 3; ++k) {
            REQUIRE(v[i][k] == mesh.vertices[i].position[k]);
            REQUIRE(vn[i][k] == mesh.vertices[i].normal[k]);
        }

    std::vector<std::int32_t> component(mesh.triangleCount(), 0);
    for (std::size_t t = mesh.triangleCount() / 2; t < component.size(); ++t) component[t] = 1;
    writeMesh(dir.file("g.obj"), mesh, &component);
    const std::string grouped = readFile(dir.file("g.obj"));
    CHECK(grouped.find("g component_0\n") != std::string::npos);
    CHECK(grouped.find("g component_1\n") != std::string::npos);
}

TEST_CASE("STL export: binary, one facet per triangle, normals from the triangle agree with the vertices",
          "[core][io][mesh]") {
    TempDir dir;
    const Mesh mesh = sphereMesh();
    writeMesh(dir.file("s.stl"), mesh);
    const std::string stl = readFile(dir.file("s.stl"));
    REQUIRE(stl.size() == 84 + 50 * mesh.triangleCount());
    CHECK(stl.compare(0, 5, "solid") != 0);
    REQUIRE(u32At(stl, 80) == mesh.triangleCount());
    std::size_t agreeing = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::size_t at = 84 + 50 * t;
        const float n[3] = {floatAt(stl, at), floatAt(stl, at + 4), floatAt(stl, at + 8)};
        CHECK(std::fabs(std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) - 1.0f) < 1e-5f);
        double dot = 0;
        for (std::size_t k = 0; k < 3; ++k) {
            const Vertex& corner = mesh.vertices[mesh.indices[3 * t + k]];
            for (std::size_t c = 0; c < 3; ++c) {
                REQUIRE(floatAt(stl, at + 12 + 12 * k + 4 * c) == corner.position[c]);
                dot += double(n[c]) * corner.normal[c];
            }
        }
        agreeing += dot > 0;
    }
    CHECK(agreeing == mesh.triangleCount());
}

TEST_CASE("writeMesh: PLY by extension keeps components; unknown extensions are refused", "[core][io][mesh]") {
    TempDir dir;
    const Mesh mesh = sphereMesh();
    std::vector<std::int32_t> component(mesh.triangleCount(), 3);
    writeMesh(dir.file("s.Ply"), mesh, &component);
    std::vector<std::int32_t> back;
    CHECK(readPly(dir.file("s.Ply"), &back).triangleCount() == mesh.triangleCount());
    CHECK(back == component);

    CHECK(meshFormatOf("x.STL") == MeshFormat::Stl);
    CHECK_THROWS_AS(writeMesh(dir.file("s.off"), mesh), InputError);
    CHECK_THROWS_WITH(writeMesh(dir.file("s.off"), mesh),
                      Catch::Contains("s.off") && Catch::Contains("\".off\"") && Catch::Contains(".ply, .obj, .stl"));
    CHECK_THROWS_WITH(writeMesh(dir.file("noext"), mesh), Catch::Contains("noext") && Catch::Contains("\"\""));
    Mesh broken = mesh;
    broken.indices.back() = 1u << 30;
    CHECK_THROWS_AS(writeMesh(dir.file("b.obj"), broken), InputError);
    CHECK_THROWS_AS(writeMesh(dir.file("b.stl"), broken), InputError);
    CHECK_THROWS_WITH(writeMesh(dir.file("no/such/dir/x.stl"), mesh), Catch::Contains("cannot open"));

    writeMesh(dir.file("empty.stl"), Mesh{});
    CHECK(readFile(dir.file("empty.stl")).size() == 84);
    writeMesh(dir.file("empty.obj"), Mesh{});
}
