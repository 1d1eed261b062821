#include "isotrack/threads.h"

#include <algorithm>
#include <thread>

namespace isotrack {

int defaultThreadCount() {
    // hardware_concurrency is 0 where the count is unknown.
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

int defaultInteractiveThreadCount() { return std::max(1, defaultThreadCount() - 1); }

}  // namespace isotrack
