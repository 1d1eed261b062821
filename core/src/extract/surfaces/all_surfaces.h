#pragma once
// Room extract/surfaces: every surface at once. components.cpp splits the
// labelled exhaustive pass into its connected surfaces (extractAllSurfaces,
// declared in isotrack/tracking.h beside trackAllSurfaces, which gives the same
// surfaces); chunk_edges.cpp names grid edges across a volume's chunks so that
// chunks extracted apart join into the same surfaces (isotrack/chunks.h). Uses
// extract/marching_cubes (the labelled pass), extract/measure, extract/trilinear
// (every surface with the trilinear table), extract/common, support/ and the
// public headers.
#include <atomic>
#include <vector>

#include "isotrack/extract.h"
#include "isotrack/surface.h"
#include "isotrack/tables.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

// extractAllSurfaces, abandoned (returning no surface) when `cancel` is set
// between the labelled pass and the split; its march reports to `progress`.
std::vector<Surface> extractAllSurfaces(const Volume& volume, double iso, TableKind table, int threads,
                                        const std::atomic<bool>* cancel, ExtractProgress* progress = nullptr);

}  // namespace isotrack::detail
