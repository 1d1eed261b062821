#pragma once
// The interface a --script session drives the viewer through (ScriptRunner,
// script_runner.h), so that the runner can be tested without a window;
// SessionHost (session_host.h) is the viewer's.
#include <cstddef>
#include <cstdint>
#include <string>

#include "isotrack/source.h"
#include "isotrack/volume.h"
#include "ui/actions.h"

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
    virtual bool timePlaying() const = 0;  // a time series is being played
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

}  // namespace isotrack::viewer
