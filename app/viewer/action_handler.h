#pragma once
// What the panel, the keys and scripts ask for, applied between frames: the
// panel's actions (ui/actions.h) and the keys' commands change what is wanted
// of the extraction, the scene's surfaces and view settings, growth, the
// camera's framing, and exports.
#include <cstdint>
#include <string>

#include "isotrack/orientation.h"
#include "render/camera.h"
#include "ui/actions.h"
#include "ui/panel.h"
#include "viewer/camera_controller.h"
#include "viewer/extraction_controller.h"
#include "viewer/frame_requests.h"
#include "viewer/growth.h"
#include "viewer/scene.h"
#include "viewer/status_line.h"
#include "viewer/time_player.h"

namespace isotrack::viewer {

class ActionHandler {
public:
    ActionHandler(ExtractionController& extraction, Scene& scene, Growth& growth, TimePlayer& time,
                  render::Camera& camera, const ui::Panel& panel, StatusLine& status, FrameRequests& requests,
                  WorldFrame exportFrame)
        : extraction_(extraction),
          scene_(scene),
          growth_(growth),
          time_(time),
          camera_(camera),
          panel_(panel),
          status_(status),
          requests_(requests),
          exportFrame_(exportFrame) {}

    void apply(const ui::Action& action);
    void applyKey(KeyCommand key);
    // The camera keeps its angles and takes in the selection (or everything).
    void frameCamera(bool selectionOnly);
    // Writes surface `id` to `path` (PLY, OBJ or STL by extension) in the export frame.
    void exportSurface(std::uint32_t id, const std::string& path);

private:
    void processMesh(const ui::ProcessMesh& request);

    ExtractionController& extraction_;
    Scene& scene_;
    Growth& growth_;
    TimePlayer& time_;
    render::Camera& camera_;
    const ui::Panel& panel_;
    StatusLine& status_;
    FrameRequests& requests_;
    WorldFrame exportFrame_;  // of exported meshes, as `isotrack extract --frame`
};

}  // namespace isotrack::viewer
