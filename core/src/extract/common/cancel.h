#pragma once
// Room extract/common: what several extraction rooms share. edge_vertex.h
// places the vertex of a crossed grid edge (every extractor, so that an edge
// gives the same vertex whichever visits it), sparse_blocks.h keeps a walk's
// per-surface storage (tracking and the trilinear walk), and this file checks
// whether an extraction was abandoned (ExtractRequest::cancel). Uses only the
// public headers (isotrack/...); no other room.
#include <atomic>

namespace isotrack::detail {

inline bool cancelled(const std::atomic<bool>* cancel) {
    return cancel != nullptr && cancel->load(std::memory_order_relaxed);
}

}  // namespace isotrack::detail
