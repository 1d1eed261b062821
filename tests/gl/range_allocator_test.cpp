// RangeAllocator: first fit, coalescing, growth in place. No GL.
#include <catch2/catch.hpp>
#include <stdexcept>

#include "render/range_allocator.h"

using isotrack::render::RangeAllocator;

TEST_CASE("ranges come first fit and freed neighbours coalesce", "[arena]") {
    RangeAllocator space(100);
    CHECK(space.allocate(10) == 0u);
    CHECK(space.allocate(20) == 10u);
    CHECK(space.allocate(30) == 30u);
    CHECK(space.freeSize() == 40);
    CHECK(space.largestFree() == 40);
    CHECK(space.fragmentation() == 0.0);

    space.release(10, 20);  // a hole of 20 before the tail of 40
    CHECK(space.freeRangeCount() == 2);
    CHECK(space.fragmentation() == Approx(1.0 - 40.0 / 60.0));
    CHECK(space.allocate(15) == 10u);  // the first hole that fits
    CHECK(space.allocate(15) == 60u);  // the hole's 5 left are too few
    space.release(0, 10);
    space.release(10, 15);  // joins the range before it
    space.release(30, 30);  // and the one after: 0..60 free again
    CHECK(space.freeRangeCount() == 2);
    CHECK(space.largestFree() == 60);
    CHECK(space.allocate(60) == 0u);
    CHECK_FALSE(space.allocate(26).has_value());
    CHECK(space.allocate(25) == 75u);
    CHECK(space.freeSize() == 0);
}

TEST_CASE("a range grows in place only into free space right after it", "[arena]") {
    RangeAllocator space(100);
    const std::size_t a = *space.allocate(10);
    const std::size_t b = *space.allocate(10);
    CHECK_FALSE(space.tryGrow(a, 10, 11));  // b is in the way
    CHECK(space.tryGrow(b, 10, 50));
    CHECK(space.freeSize() == 40);
    CHECK(space.tryGrow(b, 50, 90));
    CHECK_FALSE(space.tryGrow(b, 90, 91));  // past the capacity
    space.shrink(b, 90, 5);
    CHECK(space.freeSize() == 85);
    CHECK(space.allocate(85) == 15u);
}

TEST_CASE("giving back what was not allocated is refused", "[arena]") {
    RangeAllocator space(100);
    CHECK_THROWS_AS(space.allocate(0), std::invalid_argument);
    CHECK_THROWS_AS(space.release(10, 5), std::invalid_argument);  // already free
    const std::size_t a = *space.allocate(50);
    CHECK_THROWS_AS(space.release(a + 40, 20), std::invalid_argument);  // runs into free space
    CHECK_THROWS_AS(space.release(90, 20), std::invalid_argument);      // past the capacity
    space.release(a, 50);
    CHECK(space.freeSize() == 100);
    CHECK(space.freeRangeCount() == 1);
}
