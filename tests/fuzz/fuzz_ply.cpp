// libFuzzer target: the PLY reader (readPly), which reads back what writePly wrote.
#include "fuzz_harness.h"
#include "isotrack/io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = isotrack::fuzz::writeInput(data, size, "input.ply");
    try {
        std::vector<std::int32_t> components;
        isotrack::readPly(path, &components);
    } catch (const isotrack::FormatError&) {
    } catch (const isotrack::InputError&) {
    }
    return 0;
}
