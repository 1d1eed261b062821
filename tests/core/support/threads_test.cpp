// The default thread counts every front end takes (isotrack/threads.h).
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>

#include "isotrack/threads.h"

using namespace isotrack;

TEST_CASE("the default thread count is the processors online, at least one", "[core][threads]") {
    // An independent count: POSIX's processors online, which the C++ library's reads too.
    const long online = sysconf(_SC_NPROCESSORS_ONLN);
    CHECK(defaultThreadCount() >= 1);
    if (online > 0) CHECK(defaultThreadCount() == static_cast<int>(online));
    CHECK(defaultThreadCount() == defaultThreadCount());  // the same answer every time
}

TEST_CASE("the viewer's default leaves one of them to draw with, at least one", "[core][threads]") {
    CHECK(defaultInteractiveThreadCount() == std::max(1, defaultThreadCount() - 1));
    CHECK(defaultInteractiveThreadCount() >= 1);
    CHECK(defaultInteractiveThreadCount() <= defaultThreadCount());
}
