// The viewer's Load and a script's `load DIR` on a DICOM folder: the path a
// script names, resolved as the runner does, loads through the worker's
// loadForView into the largest series that forms a volume, with the files
// skipped listed for the viewer to report.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "core/io/dicom_test_files.h"
#include "viewer/extraction_worker.h"
#include "viewer/script.h"

using namespace isotrack;
using namespace isotrack::viewer;
using isotrack::testing::DicomSlice;
using isotrack::testing::TempDir;
using isotrack::testing::writeFile;

TEST_CASE("a script's load DIR reads a DICOM folder, skipping what is not an image", "[viewer][script][dicom]") {
    TempDir dir;
    std::filesystem::create_directories(dir.file("scan/ct"));
    for (int z = 0; z < 4; ++z)
        writeFile(dir.file("scan/ct/" + std::to_string(z) + ".dcm"), DicomSlice(6, 5, z, "1.2.ct").bytes());
    writeFile(dir.file("scan/localizer.dcm"), DicomSlice(8, 8, 0, "1.2.localizer").bytes());
    writeFile(dir.file("scan/notes.txt"), "not DICOM");
    std::ofstream(dir.file("session.isotrack")) << "load scan\n";

    const Script script = parseScript(dir.file("session.isotrack"));
    REQUIRE(script.commands.size() == 1);
    const VolumeSource source = VolumeSource::file(scriptInputPath(script, script.commands[0].text));
    const std::shared_ptr<LoadedVolume> loaded = loadForView(source);
    CHECK(loaded->volume.dims() == Dims{6, 5, 4});
    CHECK(loaded->range == std::array<double, 2>{0.0, 5 + 40 + 3});  // x + 10 y + z
    REQUIRE(loaded->skipped.size() == 1);
    CHECK(std::filesystem::path(loaded->skipped[0].file).filename() == "notes.txt");
    CHECK(displayName(source) == "scan");

    // A folder where nothing forms a volume: the worker's error lists the series.
    std::filesystem::create_directories(dir.file("flat"));
    writeFile(dir.file("flat/one.dcm"), DicomSlice(6, 5, 0, "1.2.one").bytes());
    CHECK_THROWS_WITH(loadForView(VolumeSource::file(dir.file("flat"))),
                      dir.file("flat") + ": no series forms a volume (1: CT 1 slice of 6 x 5, single slice)");
}
