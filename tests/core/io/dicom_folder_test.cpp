// DICOM folders as they come: files that cannot be read are skipped and listed,
// every series says whether it forms a volume and why not, and the default is
// the largest series that does.
#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "dicom_test_files.h"
#include "io_test_files.h"
#include "isotrack/dicom.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/source.h"

using namespace isotrack;
using isotrack::testing::DicomSlice;
using isotrack::testing::TempDir;
using isotrack::testing::writeFile;

namespace {

// Slices of one series at the given z, 6 x 5 unless told.
void writeSeries(const TempDir& dir, const std::string& folder, const std::vector<double>& zs, const std::string& uid,
                 int columns = 6, int rows = 5) {
    std::filesystem::create_directories(dir.file(folder));
    for (std::size_t k = 0; k < zs.size(); ++k)
        writeFile(dir.file(folder + "/" + uid + "_" + std::to_string(k) + ".dcm"),
                  DicomSlice(columns, rows, zs[k], uid).bytes());
}

// Slices through one axis at evenly turned angles, as a radial MR acquisition:
// one position, the row direction turning about the z axis.
void writeRadial(const TempDir& dir, const std::string& folder, int count, const std::string& uid) {
    std::filesystem::create_directories(dir.file(folder));
    for (int k = 0; k < count; ++k) {
        DicomSlice s(4, 4, 0, uid);
        const double angle = M_PI * k / count;
        s.text(0x0020, 0x0037, "DS",
               DicomSlice::number(std::cos(angle)) + "\\" + DicomSlice::number(std::sin(angle)) + "\\0\\0\\0\\-1");
        s.text(0x0008, 0x0060, "CS", "MR");
        writeFile(dir.file(folder + "/radial_" + std::to_string(k) + ".dcm"), s.bytes());
    }
}

const DicomSeries& seriesOf(const DicomContents& contents, const std::string& uid) {
    for (const DicomSeries& s : contents.series)
        if (s.uid == uid) return s;
    FAIL("no series " << uid);
    return contents.series.front();
}

}  // namespace

TEST_CASE("DICOM folder: each series says whether it forms a volume and why not", "[core][dicom]") {
    TempDir dir;
    writeSeries(dir, "f", {0, 1, 2}, "1.2.good");
    writeRadial(dir, "f", 6, "1.2.radial");
    writeSeries(dir, "f", {0, 1, 2, 4}, "1.2.gap");
    writeSeries(dir, "f", {7}, "1.2.one");
    writeSeries(dir, "f", {0, 1}, "1.2.sizes");
    writeFile(dir.file("f/other_size.dcm"), DicomSlice(7, 5, 2, "1.2.sizes").bytes());
    writeSeries(dir, "f", {0, 1, 1}, "1.2.twice");
    const DicomContents contents = scanDicom(dir.file("f"));
    REQUIRE(contents.series.size() == 6);
    CHECK(seriesOf(contents, "1.2.good").formsVolume());
    CHECK(seriesOf(contents, "1.2.radial").problem == DicomProblem::MixedOrientation);
    CHECK(seriesOf(contents, "1.2.gap").problem == DicomProblem::UnevenSpacing);
    CHECK(seriesOf(contents, "1.2.one").problem == DicomProblem::SingleSlice);
    CHECK(seriesOf(contents, "1.2.sizes").problem == DicomProblem::MixedSizes);
    CHECK(seriesOf(contents, "1.2.twice").problem == DicomProblem::DuplicateSlices);
    CHECK(std::string(dicomProblemText(DicomProblem::MixedOrientation)) == "orientation differs per slice");
    // The detail names a file of the series; a single slice has none.
    CHECK_THAT(seriesOf(contents, "1.2.gap").detail, Catch::Contains("uneven slice spacing"));
    CHECK_THAT(seriesOf(contents, "1.2.sizes").detail, Catch::Contains("other_size.dcm"));
    CHECK(seriesOf(contents, "1.2.one").detail.empty());
    CHECK(seriesOf(contents, "1.2.radial").dims == Dims{4, 4, 6});
    // The largest (radial, 6 slices) does not form a volume; the largest that does is read.
    CHECK(contents.series.front().uid == "1.2.radial");
    REQUIRE(contents.chosen);
    CHECK(contents.series[*contents.chosen].uid == "1.2.good");
    const DicomVolume read = readDicom(dir.file("f"));
    CHECK(read.series == *contents.chosen);
    CHECK(read.volume.dims() == Dims{6, 5, 3});
    CHECK(loadVolume(dir.file("f")).dims() == Dims{6, 5, 3});
}

TEST_CASE("DICOM folder: a series named with --series is read, or refused with its file", "[core][dicom]") {
    TempDir dir;
    writeSeries(dir, "f", {0, 1, 2}, "1.2.good");
    writeSeries(dir, "f", {0, 1, 2, 4}, "1.2.gap");
    writeSeries(dir, "f", {7}, "1.2.one");
    CHECK(loadDicom(dir.file("f"), "1.2.one").dims() == Dims{6, 5, 1});  // one slice, as a file named alone
    std::string message;
    try {
        loadDicom(dir.file("f"), "1");  // the largest: the one with a gap
    } catch (const FormatError& e) {
        message = e.what();
    }
    CHECK_THAT(message, Catch::Contains("uneven slice spacing") && Catch::Contains("1.2.gap_1.dcm"));
}

TEST_CASE("DICOM folder: no series forms a volume, an error listing them", "[core][dicom]") {
    TempDir dir;
    writeRadial(dir, "f", 5, "1.2.radial");
    writeSeries(dir, "f", {3}, "1.2.localizer");
    writeFile(dir.file("f/cut.dcm"), DicomSlice(6, 5, 0).bytes().substr(0, 300));
    try {
        readDicom(dir.file("f"));
        FAIL("no error");
    } catch (const DicomNoVolume& e) {
        CHECK(std::string(e.what()) == dir.file("f") +
                                           ": no series forms a volume (1: MR 5 slices of 4 x 4, orientation differs "
                                           "per slice; 2: CT 1 slice of 6 x 5, single slice); 1 file skipped");
        REQUIRE(e.contents().skipped.size() == 1);
        CHECK(e.contents().skipped[0].file == dir.file("f/cut.dcm"));
        CHECK(e.contents().series.size() == 2);
        CHECK_FALSE(e.contents().chosen);
    }
    // The one series of a folder: its own message names the file.
    writeSeries(dir, "gap", {0, 1, 3}, "1.2.gap");
    CHECK_THROWS_MATCHES(
        loadVolume(dir.file("gap")), DicomNoVolume, Catch::Predicate<DicomNoVolume>([&](const DicomNoVolume& e) {
            return std::string(e.what()).find(dir.file("gap") + ": no series forms a volume: " +
                                              dir.file("gap/1.2.gap_1.dcm") + ": uneven slice spacing") == 0;
        }));
    // Nothing readable at all.
    std::filesystem::create_directories(dir.file("junk"));
    writeFile(dir.file("junk/a.txt"), "hello");
    CHECK_THROWS_MATCHES(loadVolume(dir.file("junk")), DicomNoVolume,
                         Catch::Message(dir.file("junk") + ": no DICOM images found (1 file skipped, the first " +
                                        dir.file("junk/a.txt") +
                                        ": not a DICOM file (no \"DICM\" after a 128-byte preamble, nor a dataset "
                                        "without one))"));
}

TEST_CASE("DICOM folder: unreadable files are skipped with why, in path order", "[core][dicom]") {
    TempDir dir;
    writeSeries(dir, "f", {0, 1, 2}, "1.2.good");
    const std::string slice = DicomSlice(6, 5, 9, "1.2.good").bytes();
    writeFile(dir.file("f/a_truncated.dcm"), slice.substr(0, slice.size() - 7));
    writeFile(dir.file("f/b_empty.dcm"), "");
    DicomSlice noImage(6, 5, 0, "1.2.report");
    noImage.erase(0x0028, 0x0010);
    noImage.erase(0x0028, 0x0011);
    writeFile(dir.file("f/c_report.dcm"), noImage.bytes());
    DicomSlice colour(6, 5, 3, "1.2.good");
    colour.us(0x0028, 0x0002, 3);
    writeFile(dir.file("f/d_colour.dcm"), colour.bytes());
    const LoadedSource loaded = loadSource(VolumeSource::file(dir.file("f")));
    CHECK(loaded.volume.dims() == Dims{6, 5, 3});
    REQUIRE(loaded.dicom);
    const auto& skipped = loaded.dicom->skipped;
    REQUIRE(skipped.size() == 4);
    CHECK(skipped[0].file == dir.file("f/a_truncated.dcm"));
    CHECK_THAT(skipped[0].why, Catch::StartsWith("truncated: element (7FE0,0010)"));
    CHECK_THAT(skipped[1].why, Catch::StartsWith("not a DICOM file"));
    CHECK(skipped[2].why == "holds no image (no Rows or Columns)");
    CHECK_THAT(skipped[3].why, Catch::Contains("SamplesPerPixel"));
    // Named directly, the same file is an error.
    CHECK_THROWS_WITH(loadVolume(dir.file("f/a_truncated.dcm")), Catch::StartsWith(dir.file("f/a_truncated.dcm")));
}
