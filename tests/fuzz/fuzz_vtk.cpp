// libFuzzer target: the VTK legacy loader.
#include "fuzz_harness.h"
#include "isotrack/io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = isotrack::fuzz::writeInput(data, size, "input.vtk");
    isotrack::fuzz::tryLoad([](const std::string& p) { return isotrack::loadVtkLegacy(p); }, path);
    return 0;
}
