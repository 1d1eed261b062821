#pragma once
// Refusing work whose arrays of a few bytes per sample would not fit in memory,
// before allocating them: a clear error instead of the kernel's out-of-memory
// killer on a volume bigger than memory (a mapped file).
#include <cstdint>

#include "isotrack/volume.h"

namespace isotrack::detail {

// Throws WorkingMemoryError when bytesPerSample for each of volume's samples
// exceeds `available` (by default isotrack::availableMemoryBytes()), e.g.
// "the snap table's sample states, 3 bytes a sample: 4096 x 4096 x 4096
// samples need 192.0 GiB, more than the 11.3 GiB of memory available".
void requireWorkingMemory(const Volume& volume, int bytesPerSample, const char* what);
void requireWorkingMemory(const Volume& volume, int bytesPerSample, const char* what, std::uint64_t available);

}  // namespace isotrack::detail
