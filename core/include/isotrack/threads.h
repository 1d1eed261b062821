#pragma once
// How many threads an extraction uses when the caller does not say: the one
// answer the command line, the viewer, bench and Python all take.
namespace isotrack {

// One per hardware thread the system reports (at least 1): the batch commands'
// default (`extract`, `tree`, and Python's threads=0).
int defaultThreadCount();

// One fewer than defaultThreadCount (at least 1): an interactive front end
// (the viewer) keeps a core to draw with while the worker extracts.
int defaultInteractiveThreadCount();

}  // namespace isotrack
