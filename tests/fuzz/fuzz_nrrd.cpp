// libFuzzer target: the NRRD (attached header) loader.
#include "fuzz_harness.h"
#include "isotrack/io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = isotrack::fuzz::writeInput(data, size, "input.nrrd");
    isotrack::fuzz::tryLoad([](const std::string& p) { return isotrack::loadNrrd(p); }, path);
    return 0;
}
