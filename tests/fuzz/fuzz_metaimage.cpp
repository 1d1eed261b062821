// libFuzzer target: the MetaImage (.mha, LOCAL or detached data) loader.
#include "fuzz_harness.h"
#include "isotrack/io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = isotrack::fuzz::writeInput(data, size, "input.mha");
    isotrack::fuzz::tryLoad([](const std::string& p) { return isotrack::loadMetaImage(p); }, path);
    return 0;
}
