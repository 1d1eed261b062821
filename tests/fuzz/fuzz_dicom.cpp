// libFuzzer target: the DICOM loader (through GDCM), on the input as a single
// .dcm file, and as the one file of a folder; both must agree.
#include <cstring>
#include <filesystem>

#include "fuzz_harness.h"
#include "isotrack/dicom.h"

namespace {

bool same(const isotrack::Volume& a, const isotrack::Volume& b) {
    return a.dims() == b.dims() && a.type() == b.type() && a.spacing() == b.spacing() && a.origin() == b.origin() &&
           a.direction() == b.direction() && a.byteSize() == b.byteSize() &&
           std::memcmp(a.bytes(), b.bytes(), a.byteSize()) == 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using isotrack::fuzz::tryLoad;
    using isotrack::fuzz::workDir;
    using isotrack::fuzz::writeInput;
    auto load = [](const std::string& p) { return isotrack::loadDicom(p); };
    const auto file = tryLoad(load, writeInput(data, size, "input.dcm"));
    std::filesystem::create_directories(workDir() / "series");
    writeInput(data, size, "series/slice.dcm");
    const auto folder = tryLoad(load, (workDir() / "series").string());
    if (file.has_value() != folder.has_value() || (file && !same(*file, *folder))) std::abort();
    return 0;
}
