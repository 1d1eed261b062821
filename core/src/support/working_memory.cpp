#include "support/working_memory.h"

#include <cstdio>
#include <string>

#include "isotrack/errors.h"
#include "isotrack/mapped_file.h"

namespace isotrack::detail {

void requireWorkingMemory(const Volume& volume, int bytesPerSample, const char* what) {
    requireWorkingMemory(volume, bytesPerSample, what, availableMemoryBytes());
}

void requireWorkingMemory(const Volume& volume, int bytesPerSample, const char* what, std::uint64_t available) {
    const double needed = double(volume.sampleCount()) * bytesPerSample;
    if (needed <= double(available)) return;
    const Dims& n = volume.dims();
    const auto size = [](double bytes) {
        char text[32];
        if (bytes < double(1u << 30))
            std::snprintf(text, sizeof text, "%.1f MiB", bytes / double(1u << 20));
        else
            std::snprintf(text, sizeof text, "%.1f GiB", bytes / double(1u << 30));
        return std::string(text);
    };
    const std::string text = std::string(what) + ", " + std::to_string(bytesPerSample) +
                             " bytes a sample: " + std::to_string(n[0]) + " x " + std::to_string(n[1]) + " x " +
                             std::to_string(n[2]) + " samples need " + size(needed) + ", more than the " +
                             size(double(available)) + " of memory available";
    throw WorkingMemoryError(text);
}

}  // namespace isotrack::detail
