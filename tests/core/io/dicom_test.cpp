// DICOM series: slice order from positions, spacing from positions, rescale,
// orientation, series selection; and the CT sample written as DICOM by
// scripts/ct_to_dicom.py, which must load as the NRRD does.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "dicom_test_files.h"
#include "io_test_files.h"
#include "isotrack/dicom.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/orientation.h"

using namespace isotrack;
using isotrack::testing::DicomSlice;
using isotrack::testing::TempDir;
using isotrack::testing::writeFile;

namespace {

// Slices at the given z, written under names that sort in the opposite order.
void writeSeries(const TempDir& dir, const std::string& folder, const std::vector<double>& zs,
                 const std::string& uid = "1.2.3.4", int columns = 6, int rows = 5) {
    std::filesystem::create_directories(dir.file(folder));
    for (std::size_t k = 0; k < zs.size(); ++k)
        writeFile(dir.file(folder + "/" + std::to_string(900 - k) + ".dcm"),
                  DicomSlice(columns, rows, zs[k], uid).bytes());
}

void expectFormatError(const std::string& path, const std::string& expect) {
    std::string message;
    try {
        loadVolume(path);
    } catch (const FormatError& e) {
        message = e.what();
    }
    CAPTURE(message);
    CHECK(message.find(expect) != std::string::npos);
}

bool sameSamples(const Volume& a, const Volume& b) {
    return a.dims() == b.dims() && a.type() == b.type() && std::memcmp(a.bytes(), b.bytes(), a.byteSize()) == 0;
}

}  // namespace

TEST_CASE("DICOM: slices ordered by position, spacing from positions, pixel spacing per axis", "[core][dicom]") {
    TempDir dir;
    writeSeries(dir, "s", {4.0, -2.0, 1.0, 7.0});  // any file order
    const Volume v = loadVolume(dir.file("s"));
    REQUIRE(v.dims() == Dims{6, 5, 4});
    REQUIRE(v.type() == ScalarType::UInt16);
    CHECK(v.spacing() == Vec3d{0.75, 0.5, 3.0});  // PixelSpacing is rows\columns
    CHECK(v.origin() == Vec3d{0, 0, -2});
    CHECK(isIdentity(v.direction()));
    for (int z = 0; z < 4; ++z) CHECK(v.value(3, 2, z) == 3 + 20 + (-2 + 3 * z));
    // A single file is one slice.
    const Volume one = loadVolume(dir.file("s/900.dcm"));
    CHECK(one.dims() == Dims{6, 5, 1});
    CHECK(one.origin() == Vec3d{0, 0, 4});
}

TEST_CASE("DICOM: orientation from ImageOrientationPatient, slices along its normal", "[core][dicom]") {
    TempDir dir;
    std::filesystem::create_directories(dir.file("sag"));
    // Sagittal: rows run towards posterior (+y), columns towards inferior (-z); normal -x.
    for (int k = 0; k < 3; ++k) {
        DicomSlice s(4, 4, 0);
        s.text(0x0020, 0x0037, "DS", "0\\1\\0\\0\\0\\-1");
        s.text(0x0020, 0x0032, "DS", DicomSlice::number(10.0 - 2.0 * k) + "\\5\\6");
        writeFile(dir.file("sag/" + std::to_string(k) + ".dcm"), s.bytes());
    }
    const Volume v = loadVolume(dir.file("sag"));
    CHECK(v.direction() == Mat3d{{{0, 1, 0}, {0, 0, -1}, {-1, 0, 0}}});
    CHECK(v.spacing()[2] == 2.0);
    CHECK(v.origin() == Vec3d{10, 5, 6});
    CHECK(orientationCode(v.direction()) == "PIR");
}

TEST_CASE("DICOM: RescaleSlope/Intercept, int16 when exact, else float32", "[core][dicom]") {
    TempDir dir;
    std::filesystem::create_directories(dir.file("exact"));
    std::filesystem::create_directories(dir.file("float"));
    for (int k = 0; k < 2; ++k) {
        DicomSlice s(3, 2, k);
        s.text(0x0028, 0x1052, "DS", "-1024");
        s.text(0x0028, 0x1053, "DS", "1");
        writeFile(dir.file("exact/" + std::to_string(k) + ".dcm"), s.bytes());
        s.text(0x0028, 0x1053, "DS", "0.5");
        writeFile(dir.file("float/" + std::to_string(k) + ".dcm"), s.bytes());
    }
    const Volume exact = loadVolume(dir.file("exact"));
    CHECK(exact.type() == ScalarType::Int16);
    CHECK(exact.value(2, 1, 1) == 2 + 10 + 1 - 1024);
    const Volume scaled = loadVolume(dir.file("float"));
    CHECK(scaled.type() == ScalarType::Float32);
    CHECK(scaled.value(2, 1, 1) == 0.5 * 13 - 1024);
}

TEST_CASE("DICOM: several series in a folder, the largest by default, or by UID or number", "[core][dicom]") {
    TempDir dir;
    writeSeries(dir, "mixed", {0, 1, 2}, "1.2.3.big");
    std::filesystem::create_directories(dir.file("mixed/sub"));
    writeFile(dir.file("mixed/sub/a.dcm"), DicomSlice(8, 8, 0, "1.2.3.small").bytes());
    writeFile(dir.file("mixed/sub/b.dcm"), DicomSlice(8, 8, 5, "1.2.3.small").bytes());
    writeFile(dir.file("mixed/notes.txt"), "not DICOM, and skipped in a folder");
    const DicomContents contents = scanDicom(dir.file("mixed"));
    const auto& list = contents.series;
    REQUIRE(list.size() == 2);
    CHECK(list[0].uid == "1.2.3.big");
    CHECK(list[0].images == 3);
    CHECK(list[1].dims == Dims{8, 8, 2});
    REQUIRE(contents.skipped.size() == 1);
    CHECK(contents.skipped[0].file == dir.file("mixed/notes.txt"));
    CHECK_THAT(contents.skipped[0].why, Catch::StartsWith("not a DICOM file"));
    CHECK(loadVolume(dir.file("mixed")).dims() == Dims{6, 5, 3});
    CHECK(loadDicom(dir.file("mixed"), "2").dims() == Dims{8, 8, 2});
    CHECK(loadDicom(dir.file("mixed"), "1.2.3.small").spacing()[2] == 5.0);
    CHECK_THROWS_WITH(loadDicom(dir.file("mixed"), "3"), Catch::Contains("no series \"3\""));
}

TEST_CASE("DICOM: uneven spacing, gantry tilt, duplicates and mixed sizes are refused by file", "[core][dicom]") {
    TempDir dir;
    writeSeries(dir, "uneven", {0, 1, 2, 4});
    expectFormatError(dir.file("uneven"), "uneven slice spacing");
    writeSeries(dir, "duplicate", {0, 1, 1, 2});
    expectFormatError(dir.file("duplicate"), "same ImagePositionPatient");
    std::filesystem::create_directories(dir.file("tilt"));
    for (int k = 0; k < 3; ++k) {
        DicomSlice s(4, 4, k);
        s.text(0x0020, 0x0032, "DS", "0\\" + DicomSlice::number(0.4 * k) + "\\" + std::to_string(k));
        writeFile(dir.file("tilt/" + std::to_string(k) + ".dcm"), s.bytes());
    }
    expectFormatError(dir.file("tilt"), "gantry tilt");
    writeSeries(dir, "sizes", {0, 1});
    writeFile(dir.file("sizes/other.dcm"), DicomSlice(7, 5, 2).bytes());
    expectFormatError(dir.file("sizes"), "mixed sizes");
    expectFormatError(dir.file("sizes"), "other.dcm");
}

TEST_CASE("the CT as a DICOM series loads as the NRRD does, whatever the file order or other series",
          "[core][dicom][ct]") {
    const std::string source = std::string(ISOTRACK_SOURCE_DIR);
    const std::string nhdr = source + "/assets/ct/cranium.nhdr";
    if (!std::filesystem::exists(nhdr)) {
        WARN("skipped: " << nhdr << " is missing (scripts/get_ct.sh makes it)");
        return;
    }
    TempDir dir;
    const std::string script = "/usr/bin/python3 " + source + "/scripts/ct_to_dicom.py " + nhdr + " ";
    REQUIRE(std::system((script + dir.file("plain") + " >/dev/null").c_str()) == 0);
    REQUIRE(std::system((script + dir.file("shuffled") + " --shuffle 11 --second-series >/dev/null").c_str()) == 0);
    REQUIRE(std::system((script + dir.file("dicomdir") + " --dicomdir --second-series >/dev/null").c_str()) == 0);

    const Volume nrrd = loadVolume(source + "/assets/ct/cranium.nrrd");
    for (const std::string& path : {dir.file("plain"), dir.file("shuffled"), dir.file("dicomdir/DICOMDIR")}) {
        CAPTURE(path);
        const Volume v = loadVolume(path);
        REQUIRE(v.type() == ScalarType::Int16);  // stored unsigned, rescaled exactly
        REQUIRE(sameSamples(v, nrrd));
        for (std::size_t a = 0; a < 3; ++a) CHECK(v.spacing()[a] == Approx(nrrd.spacing()[a]).epsilon(1e-12));
        CHECK(v.origin() == nrrd.origin());
        CHECK(v.direction() == nrrd.direction());
    }
    CHECK(scanDicom(dir.file("shuffled")).series.size() == 2);
    CHECK(scanDicom(dir.file("dicomdir/DICOMDIR")).series.size() == 2);
    CHECK(loadDicom(dir.file("shuffled"), "2").dims() == Dims{64, 64, 4});
}

TEST_CASE("DICOM: a file GDCM aborts on is a one-line error naming it, or skipped in a folder",
          "[core][dicom][hostile]") {
    // No preamble, one file meta element in implicit VR and nothing after it:
    // GDCM's file meta reader asserts (FileMetaInformation.cxx:467).
    const std::string source = std::string(ISOTRACK_SOURCE_DIR);
    const std::string crashing =
        isotrack::testing::readFile(source + "/tests/fuzz/corpus/dicom/implicit_meta_group.dcm");
    TempDir dir;
    writeFile(dir.file("meta.dcm"), crashing);
    const std::string crashed =
        "the DICOM library failed on it (it crashed: Aborted); the file is damaged or not "
        "supported";
    const std::string expected = dir.file("meta.dcm") + ": " + crashed;
    CHECK_THROWS_MATCHES(loadVolume(dir.file("meta.dcm")), LibraryFailure, Catch::Message(expected));
    CHECK_THROWS_MATCHES(scanDicom(dir.file("meta.dcm")), LibraryFailure, Catch::Message(expected));
    // Among good slices, each such file is skipped (the headers are read again
    // without it), and the series loads.
    writeSeries(dir, "series", {0, 2, 4});
    writeFile(dir.file("series/meta.dcm"), crashing);
    std::filesystem::create_directories(dir.file("series/sub"));
    writeFile(dir.file("series/sub/again.dcm"), crashing);
    const DicomVolume read = readDicom(dir.file("series"));
    CHECK(read.volume.dims() == Dims{6, 5, 3});
    REQUIRE(read.contents.skipped.size() == 2);
    CHECK(read.contents.skipped[0].file == dir.file("series/meta.dcm"));
    CHECK(read.contents.skipped[0].why == crashed);
    CHECK(read.contents.skipped[1].file == dir.file("series/sub/again.dcm"));
}
