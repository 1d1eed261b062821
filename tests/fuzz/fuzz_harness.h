#pragma once
// What every loader fuzz target shares: the input goes to a file (loaders read
// paths), the loader runs, and only a Volume or a FormatError / InputError may
// come back. Anything else (another exception, a crash, a sanitizer report, a
// huge allocation or a hang, which libFuzzer flags) is a finding.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "isotrack/errors.h"
#include "isotrack/volume.h"

namespace isotrack::fuzz {

// A private directory for this process, under $ISOTRACK_FUZZ_DIR (scripts/fuzz.sh
// sets it and removes it afterwards: libFuzzer does not always exit through atexit),
// else on tmpfs when there is one.
inline const std::filesystem::path& workDir() {
    static const std::filesystem::path dir = [] {
        std::error_code ec;
        std::filesystem::path base = std::filesystem::temp_directory_path();
        if (std::filesystem::is_directory("/dev/shm", ec)) base = "/dev/shm";
        if (const char* chosen = std::getenv("ISOTRACK_FUZZ_DIR")) base = chosen;
        std::filesystem::path d = base / ("isotrack-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        std::atexit([] {
            std::error_code ignored;
            std::filesystem::remove_all(workDir(), ignored);
        });
        return d;
    }();
    return dir;
}

inline std::string writeInput(const std::uint8_t* data, std::size_t size, const std::string& name) {
    const std::string path = (workDir() / name).string();
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) std::abort();
    if (size && std::fwrite(data, 1, size, f) != size) std::abort();
    std::fclose(f);
    return path;
}

// The loaded volume, or nullopt when the loader refused the file as it should.
template <class Load>
std::optional<Volume> tryLoad(Load&& load, const std::string& path) {
    try {
        return load(path);
    } catch (const FormatError&) {
    } catch (const InputError&) {
    }
    return std::nullopt;
}

}  // namespace isotrack::fuzz
