#include "viewer/memory.h"

#include <unistd.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <array>
#include <fstream>

#include "isotrack/continuation.h"
#include "isotrack/tables.h"

namespace isotrack::viewer {

std::size_t residentBytes() {
    std::ifstream statm("/proc/self/statm");
    std::size_t totalPages = 0, residentPages = 0;
    if (!(statm >> totalPages >> residentPages)) return 0;
    return residentPages * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

void releaseFreeMemory() {
#ifdef __GLIBC__
    malloc_trim(0);
#endif
}

std::size_t tableBytes() { return 2 * (sizeof(TriangleTable) + sizeof(std::array<CaseContinuation, 256>)); }

}  // namespace isotrack::viewer
