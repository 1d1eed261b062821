#pragma once
// The viewer's control panel: one Dear ImGui window down the left of the
// window. Plain state in (PanelState), actions out (Action): it owns no GL or
// core objects, only what the user is in the middle of typing.
//
// Sections: data (built-in fields, a file, the volume's dims, type, range and
// histogram with the isovalue), extraction (isovalue, table, method),
// growth (play, pause, step, restart, cells per frame, colour by growth order),
// surfaces (colour, visibility, isolate, delete, export and statistics per
// surface), view (explode, wireframe, box, framing) and, with method tree, the
// contour tree (a plot of its branches; a click on an arc selects its surface). The stats (timings,
// frame-time plot, CPU and GPU memory) sit in a small window over the 3D
// view's bottom-right corner.
#include <array>
#include <string>
#include <vector>

#include "ui/actions.h"
#include "ui/panel_state.h"

namespace isotrack::ui {

// What the user is editing in the panel's text boxes and choices.
struct PanelScratch {
    std::array<char, 1024> path{};
    std::array<char, 256> exportPattern{};  // "surface_{id}.ply": the extension picks PLY, OBJ or STL
    int fieldIndex = 0;
    int fieldSize = 0;
    std::string shownSource;  // the source the field chooser was last set from
    bool initialised = false;
};

class Panel {
public:
    static constexpr float kWidth = 360.0f;  // pixels; the 3D view is the rest of the window

    // Between ImGui::NewFrame() and ImGui::Render(): builds the panel and
    // appends the user's requests to `actions`.
    void build(const PanelState& state, std::vector<Action>& actions);
    // Where the E key exports the selected surface to.
    std::string exportPattern() const;

private:
    PanelScratch scratch_;
};

}  // namespace isotrack::ui
