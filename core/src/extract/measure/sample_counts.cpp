// Counts over every sample: the grid edges the surface crosses, and the samples
// at or above the isovalue (the floor an extraction's time is measured against).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "extract/common/edge_vertex.h"
#include "isotrack/marching_cubes.h"
#include "support/parallel.h"

namespace isotrack {

std::size_t countCrossedEdges(const Volume& volume, double iso) {
    return visitSamples(volume, [&](const auto* samples) {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(samples)>>;
        const detail::SampleGrid<T> grid(volume, samples, iso);
        std::size_t crossed = 0;
        for (int z = 0; z < grid.nz(); ++z)
            for (int y = 0; y < grid.ny(); ++y)
                for (int x = 0; x < grid.nx(); ++x) {
                    const std::size_t i = grid.index(x, y, z);
                    const bool a = grid.above(i);
                    if (x + 1 < grid.nx()) crossed += a != grid.above(i + 1);
                    if (y + 1 < grid.ny()) crossed += a != grid.above(i + grid.strideY());
                    if (z + 1 < grid.nz()) crossed += a != grid.above(i + grid.strideZ());
                }
        return crossed;
    });
}

std::size_t countSamplesAbove(const Volume& volume, double iso, int threads) {
    return visitSamples(volume, [&](const auto* samples) -> std::size_t {
        using T = std::remove_cv_t<std::remove_pointer_t<decltype(samples)>>;
        const detail::NativeThreshold<T> threshold(iso);
        const std::size_t total = volume.sampleCount();
        if (threshold.all || threshold.none) return threshold.all ? total : 0;
        // Equal contiguous parts, one per thread, each a loop the compiler vectorises.
        const int parts = std::max(1, threads);
        std::vector<std::size_t> counts(std::size_t(parts), 0);
        const T t = threshold.value;
        detail::parallelFor(parts, parts, [&](int p) {
            const std::size_t begin = total * std::size_t(p) / std::size_t(parts),
                              end = total * std::size_t(p + 1) / std::size_t(parts);
            std::size_t count = 0;
            for (std::size_t block = begin; block < end; block += 65536) {
                std::uint32_t inBlock = 0;  // narrow sums keep the vector lanes wide
                for (std::size_t i = block, stop = std::min(end, block + 65536); i < stop; ++i)
                    inBlock += samples[i] >= t;
                count += inBlock;
            }
            counts[std::size_t(p)] = count;
        });
        std::size_t count = 0;
        for (const std::size_t c : counts) count += c;
        return count;
    });
}

}  // namespace isotrack
