#pragma once
// What the consistent, trilinear and snap tables' walks on several threads
// share: how long one thread walks alone, and vertex ids. Each thread's part
// numbers its vertices in its own mesh and puts its thread in the id's top
// bits, so no thread waits for another to number a vertex; joining the parts
// turns ids into indices.
#include <cstddef>
#include <cstdint>
#include <string>

#include "isotrack/errors.h"

namespace isotrack::detail {

// Pieces (cells, with the consistent table) a walk on several threads first
// walks on the calling thread alone: a small surface is done before more
// threads would pay for starting.
constexpr std::size_t kPiecesAlone = 8192;

// How a part's ids are made: the thread above `shift`, the index below.
struct PartIds {
    int shift = 32;

    // Room for `threads` threads' numbers in the top bits.
    explicit PartIds(int threads) {
        int tagBits = 0;
        while ((1 << tagBits) < threads) ++tagBits;
        shift = 32 - tagBits;
    }
    std::uint32_t base(int thread) const { return static_cast<std::uint32_t>(std::uint64_t(thread) << shift); }
    std::uint32_t indexMask() const { return static_cast<std::uint32_t>((std::uint64_t(1) << shift) - 1); }
};

// The id of the `index`-th vertex of a part with `idBase` and `indexMask`;
// InputError when the part has no room for it.
inline std::uint32_t partVertexId(std::uint32_t idBase, std::uint32_t indexMask, std::size_t index) {
    if (index >= indexMask)
        throw InputError("surface too large: more than " + std::to_string(indexMask) + " vertices per thread");
    return static_cast<std::uint32_t>(idBase | index);
}

}  // namespace isotrack::detail
