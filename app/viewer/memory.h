#pragma once
// Memory the viewer accounts for: the process's resident set, and the bytes of
// the triangle and continuation tables.
#include <cstddef>

namespace isotrack::viewer {

// Resident set size from /proc/self/statm (0 where that file does not exist).
std::size_t residentBytes();

// Hands memory the allocator holds free back to the system (glibc's
// malloc_trim), so a following residentBytes() measures what is in use.
void releaseFreeMemory();

// Both kinds of triangle table and their continuation tables (built once, kept).
std::size_t tableBytes();

}  // namespace isotrack::viewer
