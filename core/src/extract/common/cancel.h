#pragma once
// Abandoning an extraction between its passes (ExtractRequest::cancel), and
// reporting how far its march has got (ExtractRequest::progress).
#include <atomic>
#include <vector>

#include "isotrack/extract.h"
#include "isotrack/mesh.h"
#include "isotrack/surface.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

inline bool cancelled(const std::atomic<bool>* cancel) {
    return cancel != nullptr && cancel->load(std::memory_order_relaxed);
}

// extractAllSurfaces, abandoned (returning no surface) when `cancel` is set
// between the labelled pass and the split; its march reports to `progress`.
std::vector<Surface> extractAllSurfaces(const Volume& volume, double iso, TableKind table, int threads,
                                        const std::atomic<bool>* cancel, ExtractProgress* progress = nullptr);

// marchingCubes, its march reporting to `progress` (consistent and classic tables).
Mesh marchingCubes(const Volume& volume, double iso, TableKind table, int threads, ExtractProgress* progress);

}  // namespace isotrack::detail
