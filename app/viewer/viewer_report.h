#pragma once
// What the viewer reports: the panel's plain state (ui/panel_state.h), its
// memory, script checkpoints and the --json summary. Reads the viewer's parts;
// changes none of them.
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "render/renderer.h"
#include "ui/panel_state.h"
#include "viewer/draw_totals.h"
#include "viewer/extraction_controller.h"
#include "viewer/growth.h"
#include "viewer/picker.h"
#include "viewer/profiler.h"
#include "viewer/scene.h"
#include "viewer/status_line.h"
#include "viewer/surface_clicks.h"
#include "viewer/time_player.h"
#include "viewer/view_cache.h"
#include "viewer/view_layout.h"
#include "viewer/window.h"

namespace isotrack::viewer {

// The parts a report reads.
struct ReportSources {
    const Window& window;
    const render::Renderer& renderer;
    const Profiler& profiler;
    const Scene& scene;
    const Picker& picker;
    const ViewCache& viewCache;
    const ExtractionController& extraction;
    const Growth& growth;
    const TimePlayer& time;
    const StatusLine& status;
    const SurfaceClicks& clicks;
    const ViewLayout& layout;
    const DrawTotals& totals;
};

class ViewerReport {
public:
    ViewerReport(ReportSources sources, bool deterministic) : in_(sources), deterministic_(deterministic) {}

    ui::PanelState panelState() const;
    // The --json summary of the session so far.
    nlohmann::json summary() const;
    // A script's checkpoint: memory and each surface's triangles and arc now.
    void checkpoint(const std::string& name, int line);

    std::size_t cpuBytes() const;
    std::size_t gpuBytes() const;

private:
    std::size_t gpuOtherBytes() const;
    nlohmann::json memoryJson() const;
    nlohmann::json volumeJson() const;

    ReportSources in_;
    bool deterministic_;
    nlohmann::json checkpoints_ = nlohmann::json::array();
};

}  // namespace isotrack::viewer
