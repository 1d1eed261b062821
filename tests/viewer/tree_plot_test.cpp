// The contour-tree plot in the panel: a click on an arc asks to select its
// surface; the panel shows the plot with method tree only.
#include <imgui.h>

#include <catch2/catch.hpp>
#include <variant>

#include "isotrack/contour_tree.h"
#include "isotrack/fields.h"
#include "isotrack/tree_layout.h"
#include "ui/panel.h"
#include "ui/tree_plot.h"

using namespace isotrack;

namespace {

// The plot of noise:24 at `iso`, its surfaces numbered 100 onwards as the tree tracks them.
ui::TreePlotState noisePlot(double iso, std::size_t& arcsWithoutSurface) {
    const Volume volume = makeField({"noise", 24});
    const ContourTree tree = computeContourTree(volume, 2);
    ui::TreePlotState plot;
    plot.layout = std::make_shared<const TreeLayout>(layoutContourTree(tree, ui::kTreePlotBranches));
    std::vector<std::size_t> arcs;
    trackTreeSurfaces(tree, volume, iso, 1, &arcs);
    for (std::size_t k = 0; k < arcs.size(); ++k) {
        plot.surfaces.push_back({std::uint32_t(100 + k), arcs[k], {1.0f, 0.5f, 0.0f}, iso});
    }
    arcsWithoutSurface = plot.layout->segments.size() - arcs.size();
    return plot;
}

}  // namespace

TEST_CASE("a click on an arc in the tree plot selects its surface", "[viewer][ui][tree]") {
    std::size_t others = 0;
    const ui::TreePlotState plot = noisePlot(0.5, others);
    REQUIRE(plot.surfaces.size() > 3);
    REQUIRE(others > 0);
    const TreeLayout& layout = *plot.layout;
    const float column = 1.0f / float(layout.branches);
    std::size_t drawn = 0;
    for (const ui::TreePlotSurface& surface : plot.surfaces) {
        const TreeLayout::Segment* segment = layout.segmentOf(surface.arc);
        if (!segment) continue;  // on a branch too little persistent to draw
        ++drawn;
        // At the surface's isovalue, a little off the arc's column.
        const std::optional<ui::Action> action =
            ui::treePlotClick(plot, segment->x + column / 4, surface.iso, column / 2, 0.0);
        REQUIRE(action);
        REQUIRE(std::holds_alternative<ui::Select>(*action));
        REQUIRE(std::get<ui::Select>(*action).id == std::optional<std::uint32_t>(surface.id));
    }
    REQUIRE(drawn > plot.surfaces.size() / 2);
    std::size_t unselectable = 0;
    for (const TreeLayout::Segment& segment : layout.segments) {
        if (segment.upper <= segment.lower) continue;
        const auto action = ui::treePlotClick(plot, segment.x, (segment.lower + segment.upper) / 2, column / 2, 0.0);
        const bool onSurface = std::any_of(plot.surfaces.begin(), plot.surfaces.end(),
                                           [&](const ui::TreePlotSurface& s) { return s.arc == segment.arc; });
        REQUIRE(bool(action) == onSurface);
        unselectable += action ? 0 : 1;
    }
    REQUIRE(unselectable > 0);
    REQUIRE_FALSE(ui::treePlotClick(plot, 1.5f, layout.lo, column / 2, 0.0));
    REQUIRE_FALSE(ui::treePlotClick(ui::TreePlotState{}, 0.5f, 0.3, 1.0f, 1.0));
}

TEST_CASE("the panel draws the tree plot with method tree only", "[viewer][ui][tree]") {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(960.0f, 600.0f);
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);

    std::size_t others = 0;
    ui::PanelState state;
    state.data.loaded = true;
    state.extraction.iso = 0.5;
    state.tree = noisePlot(0.5, others);
    ui::Panel panel;
    std::vector<ui::Action> actions;
    auto vertices = [&](ui::Method method) {
        state.extraction.method = method;
        ImGui::NewFrame();
        panel.build(state, actions);
        ImGui::Render();
        return ImGui::GetDrawData()->TotalVtxCount;
    };
    vertices(ui::Method::All);  // the first frame lays the windows out
    const int all = vertices(ui::Method::All), tree = vertices(ui::Method::Tree);
    CHECK(tree > all + 4 * int(state.tree.layout->branches));  // a line per branch, 4 vertices at least
    CHECK(actions.empty());
    ImGui::DestroyContext();
}
