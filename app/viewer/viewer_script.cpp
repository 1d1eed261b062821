// The viewer as a script's host: what ScriptRunner may ask of it and look at.
#include <cstdio>

#include "render/camera.h"
#include "viewer/memory.h"
#include "viewer/viewer.h"

namespace isotrack::viewer {

bool Viewer::extracting() const { return extraction_.busy(); }

bool Viewer::growing() const { return scene_.anyGrowing() && playing_; }

bool Viewer::sourceShown() const { return scene_.volume() && scene_.volume()->source == extraction_.source(); }

bool Viewer::hasVolume() const { return scene_.volume() != nullptr; }

bool Viewer::screenshotPending() const { return screenshotPath_.has_value(); }

std::size_t Viewer::surfaceCount() const { return scene_.surfaces().size(); }

std::uint32_t Viewer::surfaceId(std::size_t index) const { return scene_.surfaces().at(index)->id(); }

void Viewer::load(const VolumeSource& source) {
    confirmation_.reset();
    extraction_.setSource(source);
    submit();
}

void Viewer::clickView(float fx, float fy, bool track) {
    const render::FrameOptions options = frameOptions();
    const float x = std::min(fx * float(options.width), float(options.width - 1));
    const float y = std::min(fy * float(options.height), float(options.height - 1));
    click(x, y, track);
}

void Viewer::trackPoint(const Vec3d& point) {
    if (picks_.size() >= kPicksKept) picks_.erase(picks_.begin());
    picks_.push_back({{"point", point}, {"track", true}, {"hit_surface", nullptr}});
    trackFrom(point, std::nullopt);
}

void Viewer::requestScreenshot(const std::string& path) { screenshotPath_ = path; }

void Viewer::startProfile(const std::string& path) { profiler_.startRecording(path); }

void Viewer::checkpoint(const std::string& name, int line) {
    releaseFreeMemory();  // so that the resident set counts live memory, not what malloc keeps around
    nlohmann::json mark = memoryJson();
    mark["name"] = name;
    mark["line"] = line;
    nlohmann::json triangles = nlohmann::json::object();  // by surface id, to tell which surfaces changed
    for (const auto& surface : scene_.surfaces()) {
        triangles[std::to_string(surface->id())] = surface->mesh().triangleCount();
    }
    mark["surface_triangles"] = triangles;
    nlohmann::json arcs = nlohmann::json::object();  // method tree: each surface's contour-tree arc, by id
    for (const auto& surface : scene_.surfaces()) {
        if (surface->stats().arc) arcs[std::to_string(surface->id())] = *surface->stats().arc;
    }
    mark["surface_arcs"] = arcs;
    checkpoints_.push_back(mark);
}

void Viewer::setCamera(const std::string& spec) { camera_ = render::parseCamera(spec); }

void Viewer::quit() { quit_ = true; }

void Viewer::fail(const std::string& message) {
    std::fprintf(stderr, "isotrack: %s\n", message.c_str());
    exitCode_ = 1;
    quit_ = true;
}

}  // namespace isotrack::viewer
