// libFuzzer target: the DICOM loader (through GDCM), on the input as a single
// .dcm file, and as the one file of a folder; both must agree. In the folder
// the file's series is named (--series 1), since by default a folder's single
// slice is not a volume; the default must give the same volume, or none for a
// single slice.
//
// GDCM runs in a child process; when it crashes there, the loader throws a
// LibraryFailure (a FormatError): the product's handled path, not a finding.
// Such inputs are kept for triage in $ISOTRACK_FUZZ_LIBRARY_FAILURES (scripts/
// fuzz.sh: build-fuzz/library-failures/), named by a hash of their bytes. A
// crash of isotrack's own code in the child comes back as an IsolatedCrash,
// which nothing here catches: libFuzzer reports it.
//
// The loader's own code (the structure walk, the header fields, the assembly)
// runs in that child too, where its coverage counters would be copies that die
// with it, and libFuzzer would fuzz blind. So the pages wholly inside the
// counters' section are remapped as shared memory before fuzzing starts: the
// child's counts land where libFuzzer reads them (shared_counters.cpp).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "fuzz_harness.h"
#include "isotrack/dicom.h"
#include "shared_counters.h"

namespace {

bool same(const isotrack::Volume& a, const isotrack::Volume& b) {
    return a.dims() == b.dims() && a.type() == b.type() && a.spacing() == b.spacing() && a.origin() == b.origin() &&
           a.direction() == b.direction() && a.byteSize() == b.byteSize() &&
           std::memcmp(a.bytes(), b.bytes(), a.byteSize()) == 0;
}

// Copies the input into the triage folder, once per distinct input.
void keepLibraryFailure(const std::uint8_t* data, std::size_t size) {
    const char* dir = std::getenv("ISOTRACK_FUZZ_LIBRARY_FAILURES");
    if (!dir) return;
    std::uint64_t hash = 1469598103934665603ull;  // FNV-1a
    for (std::size_t k = 0; k < size; ++k) hash = (hash ^ data[k]) * 1099511628211ull;
    char name[32];
    std::snprintf(name, sizeof name, "%016llx.dcm", static_cast<unsigned long long>(hash));
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = std::filesystem::path(dir) / name;
    if (std::filesystem::exists(path)) return;
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) return;
    if (size) std::fwrite(data, 1, size, f);
    std::fclose(f);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    isotrack::fuzz::shareCoverageCounters();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using isotrack::fuzz::tryLoad;
    using isotrack::fuzz::workDir;
    using isotrack::fuzz::writeInput;
    bool libraryFailed = false;
    auto load = [&](const std::string& p, const std::string& series) {
        try {
            return isotrack::loadDicom(p, series);
        } catch (const isotrack::LibraryFailure&) {
            libraryFailed = true;
            throw;
        }
    };
    const auto loadDefault = [&](const std::string& p) { return load(p, ""); };
    const auto loadFirst = [&](const std::string& p) { return load(p, "1"); };
    const auto file = tryLoad(loadDefault, writeInput(data, size, "input.dcm"));
    std::filesystem::create_directories(workDir() / "series");
    writeInput(data, size, "series/slice.dcm");
    const auto folder = tryLoad(loadFirst, (workDir() / "series").string());
    const auto chosen = tryLoad(loadDefault, (workDir() / "series").string());
    if (chosen && !(folder && same(*chosen, *folder))) std::abort();
    if (!chosen && folder && folder->dims()[2] != 1) std::abort();
    if (libraryFailed) keepLibraryFailure(data, size);
    if (file.has_value() != folder.has_value() || (file && !same(*file, *folder))) std::abort();
    return 0;
}
