#pragma once
// Abandoning an extraction between its passes (ExtractRequest::cancel).
#include <atomic>
#include <vector>

#include "isotrack/surface.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

inline bool cancelled(const std::atomic<bool>* cancel) {
    return cancel != nullptr && cancel->load(std::memory_order_relaxed);
}

// extractAllSurfaces, abandoned (returning no surface) when `cancel` is set
// between the labelled pass and the split.
std::vector<Surface> extractAllSurfaces(const Volume& volume, double iso, TableKind table, int threads,
                                        const std::atomic<bool>* cancel);

}  // namespace isotrack::detail
