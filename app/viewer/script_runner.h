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

namespace isotrack::viewer {

// What a script may ask of the viewer, and what its waits look at.
class ScriptHost {
public:
    virtual ~ScriptHost() = default;

    // ---- what the waits look at ----
    virtual bool extracting() const = 0;   // the worker has a request in hand
    virtual bool growing() const = 0;      // surfaces are growing and growth is playing
    virtual bool sourceShown() const = 0;  // the scene holds the volume of the source asked for
    virtual bool hasVolume() const = 0;    // any volume is loaded
    virtual bool screenshotPending() const = 0;
    virtual std::size_t surfaceCount() const = 0;
    virtual std::uint32_t surfaceId(std::size_t index) const = 0;  // index < surfaceCount()

    // ---- what the commands do ----
    virtual void apply(const ui::Action& action) = 0;
    virtual void load(const VolumeSource& source) = 0;            // and submit it for extraction
    virtual void clickView(float fx, float fy, bool track) = 0;   // fractions of the 3D view, origin top-left
    virtual void trackPoint(const Vec3d& point) = 0;              // as a ctrl-click at that world point
    virtual void requestScreenshot(const std::string& path) = 0;  // taken at the end of this frame
    virtual void startProfile(const std::string& path) = 0;
    virtual void checkpoint(const std::string& name, int line) = 0;
    virtual void setCamera(const std::string& spec) = 0;  // YAW,PITCH,DISTANCE,TX,TY,TZ[,FOV]
    virtual void frameCamera(bool selectionOnly) = 0;
    virtual void exportSurface(std::uint32_t id, const std::string& path) = 0;
    virtual void quit() = 0;
    // Reports a script error (one line, already "FILE:LINE: ...") and ends the
    // session with exit status 1.
    virtual void fail(const std::string& message) = 0;
};

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
    enum class Wait { None, Frames, Idle, Loaded, Screenshot, Sweep, Click };

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
