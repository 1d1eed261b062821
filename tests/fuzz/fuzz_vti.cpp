// libFuzzer target: the VTK XML ImageData loader (expat, base64, zlib blocks, appended offsets).
#include "fuzz_harness.h"
#include "isotrack/io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = isotrack::fuzz::writeInput(data, size, "input.vti");
    isotrack::fuzz::tryLoad([](const std::string& p) { return isotrack::loadVti(p); }, path);
    return 0;
}
