#pragma once
// A streaming pass over a mapped volume lets go of the slices it has left
// behind, a batch at a time, so that what stays resident is the few slices in
// flight, not the volume (isotrack/mapped_file.h). Releasing is always safe: a
// released page that something touches again is read again, so a neighbour
// chunk's thread may still read a slice this one has released. For a volume in
// memory it does nothing.
#include <algorithm>
#include <cstddef>

#include "isotrack/volume.h"

namespace isotrack::detail {

class SliceRelease {
public:
    SliceRelease(const Volume& volume, int zBegin) : volume_(volume), released_(zBegin) {
        if (!volume.mappedFile()) return;
        const std::size_t slice =
            std::size_t(volume.dims()[0]) * std::size_t(volume.dims()[1]) * scalarTypeSize(volume.type());
        batch_ = int(std::max<std::size_t>(1, kBatchBytes / std::max<std::size_t>(slice, 1)));
    }
    // The pass needs no slice below z any more. Throws FormatError when the file
    // was truncated or removed meanwhile, so that a pass stops at its next batch
    // instead of reading zeros to the end.
    void passed(int z) {
        if (batch_ && z - released_ >= batch_) {
            volume_.throwIfDamaged();
            volume_.releaseSlices(released_, z);
            released_ = z;
        }
    }
    // The pass is done with every slice below z.
    void finish(int z) {
        if (batch_ && z > released_) volume_.releaseSlices(released_, z);
        released_ = z;
    }

private:
    static constexpr std::size_t kBatchBytes = std::size_t(8) << 20;
    const Volume& volume_;
    int released_;
    int batch_ = 0;  // slices per release; 0: not mapped, nothing to release
};

}  // namespace isotrack::detail
