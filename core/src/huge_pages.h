#pragma once
// Large buffers written once from start to end (a tracked surface's mesh, its
// sparse blocks) spend much of their time in page faults when the kernel backs
// them with 4 KiB pages. Where the kernel offers transparent huge pages on
// request, ask for them on the 2 MiB-aligned part of such a buffer before it is
// first touched. Elsewhere this does nothing.
#include <cstddef>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace isotrack::detail {

inline void adviseHugePages(void* data, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHugePage = std::uintptr_t(2) << 20;
    const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(data);
    const std::uintptr_t begin = (start + kHugePage - 1) & ~(kHugePage - 1);
    const std::uintptr_t end = (start + bytes) & ~(kHugePage - 1);
    if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // only advice: failure is harmless
#else
    (void)data;
    (void)bytes;
#endif
}

}  // namespace isotrack::detail
