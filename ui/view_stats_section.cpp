// View (explode, wireframe, box, framing, the controls) and stats (timings,
// the frame-time plot, memory).
#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "ui/sections.h"

namespace isotrack::ui {
namespace {

void controlsHelp() {
    if (!ImGui::TreeNode("Mouse and keys")) return;
    ImGui::TextUnformatted(
        "left drag: orbit     right/middle or shift-drag: pan\n"
        "wheel: zoom          click: select a surface\n"
        "ctrl-click (or track method): grow the surface there\n"
        "alt-drag: move the selected surface\n"
        "F: frame selection   A: frame all   Esc: deselect\n"
        "H: hide   I: isolate   S: show all   Del: delete\n"
        "E: export   Space: play/pause growth   N: step\n"
        "W: wireframe   G: colour by growth order\n"
        "F12: screenshot   ctrl-Q: quit");
    ImGui::TreePop();
}

}  // namespace

void viewSection(const PanelState& state, std::vector<Action>& actions) {
    float explode = state.view.explode;
    if (ImGui::SliderFloat("explode", &explode, 0.0f, 2.0f, "%.2f")) actions.push_back(SetExplode{explode});
    bool wireframe = state.view.wireframe;
    if (ImGui::Checkbox("wireframe", &wireframe)) actions.push_back(SetWireframe{wireframe});
    ImGui::SameLine();
    bool box = state.view.boundingBox;
    if (ImGui::Checkbox("box", &box)) actions.push_back(SetBoundingBox{box});
    ImGui::SameLine();
    if (ImGui::Button("Frame all")) actions.push_back(FrameAll{});
    ImGui::SameLine();
    if (ImGui::Button("Frame sel.")) actions.push_back(FrameSelection{});
    controlsHelp();
}

void statsSection(const PanelState& state) {
    const StatsState& stats = state.stats;
    const bool frozen = stats.deterministic;
    if (frozen) {
        ImGui::TextUnformatted("timings frozen (--deterministic)");
    } else {
        ImGui::Text("%.1f FPS, %s a frame (frame %zu)", stats.fps, formatMs(stats.frameMs, false).c_str(),
                    stats.frames);
    }
    ImGui::Text("input %s  ui %s  extract %s", formatMs(stats.inputMs, frozen).c_str(),
                formatMs(stats.uiMs, frozen).c_str(), formatMs(stats.extractMs, frozen).c_str());
    ImGui::Text("upload %s  draw %s  present %s", formatMs(stats.uploadMs, frozen).c_str(),
                formatMs(stats.drawMs, frozen).c_str(), formatMs(stats.presentMs, frozen).c_str());
    ImGui::Text("GPU draw %s   extraction %s", formatMs(stats.gpuMs, frozen).c_str(),
                formatMs(state.extraction.lastMs, frozen).c_str());
    if (frozen) {
        ImGui::TextUnformatted("draw calls --  triangles --  uploaded --");
    } else {
        ImGui::Text("draw calls %zu  triangles %s  uploaded %s", stats.drawCalls,
                    formatCount(stats.trianglesDrawn).c_str(), formatBytes(stats.uploadedBytes).c_str());
    }
    const std::vector<float> none;
    const std::vector<float>& times = frozen ? none : stats.frameTimesMs;
    const float highest = times.empty() ? 1.0f : *std::max_element(times.begin(), times.end());
    char overlay[48];
    std::snprintf(overlay, sizeof(overlay), frozen ? "frame ms" : "frame ms (top %.0f)", double(highest));
    ImGui::PlotLines("##frames", times.data(), static_cast<int>(times.size()), 0, overlay, 0.0f,
                     std::max(highest * 1.1f, 1.0f), ImVec2(ImGui::GetContentRegionAvail().x, 36.0f));

    ImGui::Text("CPU %s: volume %s, meshes %s,",
                formatBytes(stats.cpuVolumeBytes + stats.cpuMeshBytes + stats.cpuTableBytes).c_str(),
                stats.volumeMapped ? "mapped" : formatBytes(stats.cpuVolumeBytes).c_str(),
                formatBytes(stats.cpuMeshBytes).c_str());
    ImGui::Text("    tables %s; process RSS %s", formatBytes(stats.cpuTableBytes).c_str(),
                frozen ? "--" : formatBytes(stats.rssBytes).c_str());
    ImGui::Text("GPU %s: surfaces %s, other %s", formatBytes(stats.gpuSurfaceBytes + stats.gpuOtherBytes).c_str(),
                formatBytes(stats.gpuSurfaceBytes).c_str(), formatBytes(stats.gpuOtherBytes).c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", stats.renderer.c_str());
    ImGui::Text("    %zu page%s, free %s (largest %s), fragmented %.0f%%", stats.arenaPages,
                stats.arenaPages == 1 ? "" : "s", formatBytes(stats.arenaFreeBytes).c_str(),
                formatBytes(stats.arenaLargestFreeBytes).c_str(), 100.0 * stats.arenaFragmentation);
}

}  // namespace isotrack::ui
