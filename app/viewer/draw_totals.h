#pragma once
// What the last frame drew and uploaded, and the most any frame of the
// session did (the --json summary's frame_counters).
#include <algorithm>
#include <cstddef>

#include "render/renderer.h"

namespace isotrack::viewer {

struct DrawTotals {
    render::DrawCounters drawn;  // this frame's so far (a frame that only copies the cached view draws nothing)
    std::size_t uploaded = 0;    // bytes, the last finished frame's
    std::size_t maxDrawCalls = 0, maxTrianglesDrawn = 0, maxUploadedBytes = 0, uploadedBytes = 0;

    void beginFrame() { drawn = render::DrawCounters{}; }
    void endFrame(std::size_t frameUploaded) {
        uploaded = frameUploaded;
        maxDrawCalls = std::max(maxDrawCalls, drawn.drawCalls);
        maxTrianglesDrawn = std::max(maxTrianglesDrawn, drawn.triangles);
        maxUploadedBytes = std::max(maxUploadedBytes, uploaded);
        uploadedBytes += uploaded;
    }
};

}  // namespace isotrack::viewer
