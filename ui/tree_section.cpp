// The contour-tree plot: isovalue upwards, a column per branch, the arcs of
// surfaces in the surfaces' colours, the isovalue as a line, each surface's
// isovalue as a mark. The layout is the viewer's cached one; the panel only
// maps it to pixels.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "ui/sections.h"
#include "ui/tree_plot.h"

namespace isotrack::ui {

std::optional<Action> treePlotClick(const TreePlotState& plot, float x, double value, float xTolerance,
                                    double valueTolerance) {
    if (!plot.layout) return std::nullopt;
    const TreeLayout::Segment* segment = plot.layout->pick(x, value, xTolerance, valueTolerance);
    if (!segment) return std::nullopt;
    for (const TreePlotSurface& surface : plot.surfaces) {
        if (surface.arc == segment->arc) return Action{Select{surface.id}};
    }
    return std::nullopt;
}

namespace {

constexpr float kPlotHeight = 240.0f, kPad = 6.0f;

ImU32 colourOf(const std::array<float, 3>& rgb, float alpha = 1.0f) {
    return ImGui::ColorConvertFloat4ToU32(ImVec4(rgb[0], rgb[1], rgb[2], alpha));
}

// Pixels of the plot's rectangle from the layout's coordinates and back.
struct PlotFrame {
    ImVec2 min, max;
    double lo = 0.0, hi = 1.0;
    float px(float x) const { return min.x + kPad + (max.x - min.x - 2 * kPad) * x; }
    float py(double v) const {
        const double t = std::clamp((v - lo) / (hi - lo), 0.0, 1.0);
        return max.y - kPad - static_cast<float>(double(max.y - min.y - 2 * kPad) * t);
    }
    float xAt(float pixel) const { return (pixel - min.x - kPad) / (max.x - min.x - 2 * kPad); }
    double valueAt(float pixel) const {
        return lo + (hi - lo) * double(max.y - kPad - pixel) / (max.y - min.y - 2 * kPad);
    }
};

void drawPlot(const PanelState& state, const PlotFrame& frame, ImDrawList& draw) {
    const TreeLayout& layout = *state.tree.layout;
    draw.AddRectFilled(frame.min, frame.max, IM_COL32(24, 24, 28, 255));
    for (const TreeLayout::Link& link : layout.links) {
        const float y = frame.py(link.value);
        draw.AddLine(ImVec2(frame.px(link.x0), y), ImVec2(frame.px(link.x1), y), IM_COL32(90, 90, 96, 255));
    }
    for (const TreeLayout::BranchLine& line : layout.branchLines) {
        const float x = frame.px(line.x);
        draw.AddLine(ImVec2(x, frame.py(line.lower)), ImVec2(x, frame.py(line.upper)), IM_COL32(150, 150, 150, 255));
    }
    for (const TreePlotSurface& surface : state.tree.surfaces) {
        const TreeLayout::Segment* segment = layout.segmentOf(surface.arc);
        if (!segment) continue;
        const float x = frame.px(segment->x);
        draw.AddLine(ImVec2(x, frame.py(segment->lower)), ImVec2(x, frame.py(segment->upper)), colourOf(surface.colour),
                     state.selected == surface.id ? 4.0f : 2.5f);
    }
    const float isoY = frame.py(state.extraction.iso);
    draw.AddLine(ImVec2(frame.min.x, isoY), ImVec2(frame.max.x, isoY), IM_COL32(255, 255, 255, 160));
    for (const TreePlotSurface& surface : state.tree.surfaces) {
        const TreeLayout::Segment* segment = layout.segmentOf(surface.arc);
        if (!segment) continue;
        const ImVec2 centre(frame.px(segment->x), frame.py(surface.iso));
        draw.AddCircleFilled(centre, 3.5f, colourOf(surface.colour));
        draw.AddCircle(centre, 3.5f, IM_COL32(0, 0, 0, 255));
    }
}

}  // namespace

void treeSection(const PanelState& state, std::vector<Action>& actions) {
    const TreePlotState& plot = state.tree;
    if (!plot.layout) {
        ImGui::TextDisabled("the contour tree is being built");
        return;
    }
    const TreeLayout& layout = *plot.layout;
    ImGui::Text("%s arcs in %s branches", formatCount(layout.segments.size()).c_str(),
                formatCount(layout.branches).c_str());
    if (plot.buildSeconds > 0.0) {
        const auto& phase = plot.buildPhaseSeconds;
        const bool frozen = state.stats.deterministic;  // timings shown as "--" for reproducible screenshots
        ImGui::PushTextWrapPos(0.0f);                   // wrapped at the panel's edge
        ImGui::TextDisabled("built in %s: sort %s, sweeps %s, merge %s, arcs %s, then its plot",
                            formatMs(plot.buildSeconds * 1e3, frozen).c_str(), formatMs(phase[0] * 1e3, frozen).c_str(),
                            formatMs(phase[1] * 1e3, frozen).c_str(), formatMs(phase[2] * 1e3, frozen).c_str(),
                            formatMs(phase[3] * 1e3, frozen).c_str());
        ImGui::PopTextWrapPos();
    }
    if (layout.hiddenArcs + layout.prunedArcs > 0) {
        ImGui::TextDisabled("%s arcs hidden (persistence < %.3g)",
                            formatCount(layout.hiddenArcs + layout.prunedArcs).c_str(), layout.minShownPersistence);
    }
    PlotFrame frame;
    frame.min = ImGui::GetCursorScreenPos();
    frame.max = ImVec2(frame.min.x + ImGui::GetContentRegionAvail().x, frame.min.y + kPlotHeight);
    frame.lo = layout.lo, frame.hi = layout.hi;
    ImGui::InvisibleButton("##tree-plot", ImVec2(frame.max.x - frame.min.x, kPlotHeight));
    if (ImGui::IsItemClicked(ImGuiMouseButton_Left)) {
        const ImVec2 mouse = ImGui::GetIO().MousePos;
        const float columnWidth = 1.0f / float(std::max<std::size_t>(layout.branches, 1));
        const double pixelValue = (frame.hi - frame.lo) / double(kPlotHeight);
        const float x = frame.xAt(mouse.x);
        const std::optional<Action> action =
            treePlotClick(plot, x, frame.valueAt(mouse.y),
                          std::max(columnWidth / 2, frame.xAt(frame.min.x + kPad + 4.0f)), 3.0 * pixelValue);
        if (action) actions.push_back(*action);
    }
    ImDrawList& draw = *ImGui::GetWindowDrawList();
    draw.PushClipRect(frame.min, frame.max, true);
    drawPlot(state, frame, draw);
    draw.PopClipRect();
}

}  // namespace isotrack::ui
