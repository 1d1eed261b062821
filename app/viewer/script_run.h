#pragma once
// Where a --script session is: the next command, and what the current one is
// waiting for. Private to the viewer (viewer.cpp, viewer_script.cpp).
#include <chrono>
#include <cstdint>

#include "viewer/extraction_worker.h"
#include "viewer/script.h"
#include "viewer/viewer.h"

namespace isotrack::viewer {

struct Viewer::ScriptRun {
    enum class Wait { None, Frames, Idle, Loaded, Screenshot, Sweep, Click };

    explicit ScriptRun(Script s) : script(std::move(s)) {}

    Script script;
    std::size_t next = 0;
    const ScriptCommand* current = nullptr;     // the command running or waited on
    const ScriptCommand* jobCommand = nullptr;  // the command behind the latest extraction request
    Wait wait = Wait::None;
    std::chrono::steady_clock::time_point waitStart{};
    std::uint64_t framesLeft = 0;
    double sweepFrom = 0.0, sweepTo = 0.0;
    std::uint64_t sweepSteps = 0, sweepDone = 0;
    float clickX = 0.0f, clickY = 0.0f;  // fractions of the 3D view
    bool clickTrack = false;
    bool failed = false;
};

}  // namespace isotrack::viewer
