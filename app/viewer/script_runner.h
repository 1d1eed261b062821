#pragma once
// Running a --script session (the commands are in script.h): each frame the
// runner runs commands until one has to wait (frames, extraction, growth, a
// screenshot, a sweep, a click after extraction). It drives the viewer only
// through ScriptHost, so that it can be tested without a window.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include "isotrack/source.h"
#include "isotrack/volume.h"
#include "ui/actions.h"
#include "viewer/script.h"
#include "viewer/script_host.h"

namespace isotrack::viewer {

class ScriptRunner {
public:
    ScriptRunner(Script script, ScriptHost& host) : script_(std::move(script)), host_(host) {}
    ScriptRunner(const ScriptRunner&) = delete;
    ScriptRunner& operator=(const ScriptRunner&) = delete;

    const Script& script() const { return script_; }
    // The script's first command loads a volume, so the viewer need not load its default one.
    bool loadsFirst() const;

    // Called once a frame: finishes or continues the current wait, then runs
    // commands until one has to wait. Throws ScriptError (or the host's errors)
    // for a command that fails; the caller hands the message to fail().
    void advance();
    // Reports the first failure through the host, naming the current command's
    // line unless the message already names the script; later ones are dropped.
    void fail(const std::string& message);
    bool failed() const { return failed_; }
    // Every command has run (or quit has), and nothing is waited on.
    bool finished() const { return quit_ || (next_ == script_.commands.size() && wait_ == Wait::None); }

    // The extraction request just submitted belongs to the current command, so
    // that its error names that line.
    void noteSubmitted() { jobCommand_ = current_; }
    // An extraction's error as a script error naming the command behind the request.
    ScriptError extractionError(const std::string& message) const;

private:
    enum class Wait { None, Frames, Idle, Loaded, Screenshot, Sweep, Click, Play };

    bool waitDone();
    bool runCommand(const ScriptCommand& command);  // false: wait before the next one
    bool waitFor(Wait wait);
    std::uint32_t surfaceAt(const ScriptCommand& command, std::size_t argument) const;

    Script script_;
    ScriptHost& host_;
    std::size_t next_ = 0;
    const ScriptCommand* current_ = nullptr;     // the command running or waited on
    const ScriptCommand* jobCommand_ = nullptr;  // the command behind the latest extraction request
    Wait wait_ = Wait::None;
    std::chrono::steady_clock::time_point waitStart_{};
    std::uint64_t framesLeft_ = 0;
    double sweepFrom_ = 0.0, sweepTo_ = 0.0;
    std::uint64_t sweepSteps_ = 0, sweepDone_ = 0;
    float clickX_ = 0.0f, clickY_ = 0.0f;  // fractions of the 3D view
    bool clickTrack_ = false;
    bool quit_ = false;
    bool failed_ = false;
};

}  // namespace isotrack::viewer
