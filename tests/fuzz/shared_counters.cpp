// See shared_counters.h. This file is compiled without coverage
// instrumentation (tests/fuzz/CMakeLists.txt): an instrumented file that names
// the linker's __start___sancov_cntrs itself makes the compiler rename its own
// reference, and libFuzzer then finds no counters at all.
#include "shared_counters.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

extern "C" char __start___sancov_cntrs[] __attribute__((weak, visibility("hidden")));
extern "C" char __stop___sancov_cntrs[] __attribute__((weak, visibility("hidden")));

namespace isotrack::fuzz {

void shareCoverageCounters() {
    if (!__start___sancov_cntrs || !__stop___sancov_cntrs) return;
    const auto page = std::uintptr_t(::sysconf(_SC_PAGESIZE));
    const std::uintptr_t lo = (std::uintptr_t(__start___sancov_cntrs) + page - 1) / page * page;
    const std::uintptr_t hi = std::uintptr_t(__stop___sancov_cntrs) / page * page;
    if (hi <= lo) return;
    const std::size_t bytes = hi - lo;
    const std::vector<char> counts(reinterpret_cast<const char*>(lo), reinterpret_cast<const char*>(hi));
    void* shared = ::mmap(reinterpret_cast<void*>(lo), bytes, PROT_READ | PROT_WRITE,
                          MAP_SHARED | MAP_ANONYMOUS | MAP_FIXED, -1, 0);
    if (shared == MAP_FAILED) std::abort();
    std::memcpy(shared, counts.data(), bytes);
}

}  // namespace isotrack::fuzz
