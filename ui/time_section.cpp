// Time (a time series of several steps only): the step slider with its time
// value, play or pause, the speed, and a step either way; the selected
// surface's area and volume over the steps seen (timePlot, in its details).
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cstdio>

#include "ui/sections.h"

namespace isotrack::ui {

void timeSection(const PanelState& state, std::vector<Action>& actions) {
    const TimeState& time = state.time;
    int step = int(time.step);
    char format[64];
    std::snprintf(format, sizeof(format), "%%d  (t = %.4g)", time.time);
    if (ImGui::SliderInt("step", &step, 0, int(time.steps) - 1, format, ImGuiSliderFlags_AlwaysClamp)) {
        actions.push_back(SetTimeStep{std::size_t(std::max(step, 0))});
    }
    if (time.shownStep != time.step) {
        ImGui::Text("showing step %zu (t = %.4g), step %zu on its way", time.shownStep, time.shownTime, time.step);
    } else {
        ImGui::Text("showing step %zu of %zu (t = %.4g)", time.shownStep, time.steps, time.shownTime);
    }
    if (ImGui::Button("<") && time.step > 0) actions.push_back(SetTimeStep{time.step - 1});
    ImGui::SameLine();
    if (ImGui::Button(time.playing ? "Pause" : "Play")) actions.push_back(PlayTime{!time.playing, std::nullopt});
    ImGui::SameLine();
    if (ImGui::Button(">") && time.step + 1 < time.steps) actions.push_back(SetTimeStep{time.step + 1});
    float speed = time.stepsPerSecond;
    if (ImGui::SliderFloat("steps/s", &speed, 0.5f, 30.0f, "%.1f", ImGuiSliderFlags_Logarithmic)) {
        actions.push_back(SetTimeSpeed{speed});
    }
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "playback speed; a step also waits for its extraction, so none is skipped ([ ] step, P play)");
    }
}

void timePlot(const PanelState& state) {
    const TimeState& time = state.time;
    if (time.steps < 2 || time.area.empty()) return;
    char label[96];
    std::snprintf(label, sizeof(label), "area over %zu step%s seen (%zu..%zu)", time.area.size(),
                  time.area.size() == 1 ? "" : "s", time.plotSteps.front(), time.plotSteps.back());
    ImGui::TextUnformatted(label);
    ImGui::PlotLines("##area", time.area.data(), int(time.area.size()), 0, nullptr, FLT_MAX, FLT_MAX,
                     ImVec2(-1.0f, 40.0f));
    ImGui::TextUnformatted("enclosed volume (0: open)");
    ImGui::PlotLines("##volume", time.volume.data(), int(time.volume.size()), 0, nullptr, FLT_MAX, FLT_MAX,
                     ImVec2(-1.0f, 40.0f));
}

}  // namespace isotrack::ui
