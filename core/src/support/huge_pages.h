#pragma once
// Large buffers written once from start to end (a tracked surface's mesh, the
// exhaustive pass's mesh and labels) spend much of their time in page faults
// when the kernel backs them with 4 KiB pages, and a volume streamed by the
// exhaustive pass (64 MB for a 256^3 float volume) misses the TLB every 4 KiB;
// on 2 MiB pages the blobs field marched 7% faster on one thread and 14% on two
// (`isotrack extract --volume blobs_256.nrrd --iso 0.25 --method mc`, 40 runs
// each, processes alternated). Where the kernel offers transparent huge pages on
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
    if (end > begin)
        madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // only advice: failure is harmless
#else
    (void)data;
    (void)bytes;
#endif
}

// Sizes a vector, asking for huge pages on its memory before the resize touches
// it (a Buffer's new elements are left uninitialised, so only their writers do).
template <class V>
void resizeOnHugePages(V& buffer, std::size_t size) {
    buffer.reserve(size);
    adviseHugePages(buffer.data(), size * sizeof(typename V::value_type));
    buffer.resize(size);
}

}  // namespace isotrack::detail
