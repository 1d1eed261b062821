#pragma once
// What the panel, the keys and a script ask of the frame loop itself: a
// screenshot at the end of this frame, the end of the session and its exit
// status.
#include <optional>
#include <string>

namespace isotrack::viewer {

struct FrameRequests {
    std::optional<std::string> screenshotPath;  // taken at the end of this frame
    int screenshots = 0;                        // taken with F12
    bool quit = false;
    int exitCode = 0;
};

}  // namespace isotrack::viewer
