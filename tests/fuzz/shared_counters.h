#pragma once
// For fuzz targets whose loader runs in a forked child (DICOM): makes the
// libFuzzer coverage counters the child increments visible to the parent.

namespace isotrack::fuzz {

// Remaps the pages wholly inside the inline 8-bit counters' section as shared
// memory, keeping their contents; counters on the section's first and last,
// partial pages stay private (their pages hold other data). Call it once,
// before any fork.
void shareCoverageCounters();

}  // namespace isotrack::fuzz
