#include "viewer/session_host.h"

#include <algorithm>
#include <cstdio>

namespace isotrack::viewer {

bool SessionHost::extracting() const { return parts_.extraction.busy(); }

bool SessionHost::growing() const { return parts_.scene.anyGrowing() && parts_.growth.playing(); }

bool SessionHost::sourceShown() const {
    return parts_.scene.volume() && parts_.scene.volume()->source == parts_.extraction.source();
}

bool SessionHost::hasVolume() const { return parts_.scene.volume() != nullptr; }

bool SessionHost::screenshotPending() const { return parts_.requests.screenshotPath.has_value(); }

bool SessionHost::timePlaying() const { return parts_.time.playing(); }

std::size_t SessionHost::surfaceCount() const { return parts_.scene.surfaces().size(); }

std::uint32_t SessionHost::surfaceId(std::size_t index) const { return parts_.scene.surfaces().at(index)->id(); }

void SessionHost::apply(const ui::Action& action) { parts_.actions.apply(action); }

void SessionHost::load(const VolumeSource& source) { parts_.extraction.load(source); }

void SessionHost::clickView(float fx, float fy, bool track) {
    const render::FrameOptions options = parts_.layout.frameOptions(parts_.scene);
    const float x = std::min(fx * float(options.width), float(options.width - 1));
    const float y = std::min(fy * float(options.height), float(options.height - 1));
    parts_.clicks.click(parts_.layout.frameView(parts_.camera, parts_.scene), x, y, track);
}

void SessionHost::trackPoint(const Vec3d& point) { parts_.clicks.trackPoint(point); }

void SessionHost::requestScreenshot(const std::string& path) { parts_.requests.screenshotPath = path; }

void SessionHost::startProfile(const std::string& path) { parts_.profiler.startRecording(path); }

void SessionHost::checkpoint(const std::string& name, int line) { parts_.report.checkpoint(name, line); }

void SessionHost::setCamera(const std::string& spec) { parts_.camera = render::parseCamera(spec); }

void SessionHost::frameCamera(bool selectionOnly) { parts_.actions.frameCamera(selectionOnly); }

void SessionHost::exportSurface(std::uint32_t id, const std::string& path) { parts_.actions.exportSurface(id, path); }

void SessionHost::quit() { parts_.requests.quit = true; }

void SessionHost::fail(const std::string& message) {
    std::fprintf(stderr, "isotrack: %s\n", message.c_str());
    parts_.requests.exitCode = 1;
    parts_.requests.quit = true;
}

}  // namespace isotrack::viewer
