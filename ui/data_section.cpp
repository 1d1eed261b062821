// Data: which volume, what it holds, and where the isovalue sits in its values.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "ui/sections.h"

namespace isotrack::ui {
namespace {

// Points the chooser at the field being shown, or the path box at the file, when that changes.
void followSource(const DataState& data, PanelScratch& scratch) {
    if (data.source == scratch.shownSource) return;
    scratch.shownSource = data.source;
    if (data.sourceIsFile) {
        std::snprintf(scratch.path.data(), scratch.path.size(), "%s", data.source.c_str());
        return;
    }
    const std::size_t colon = data.source.find(':');
    const std::string name = data.source.substr(0, colon);
    for (std::size_t i = 0; i < data.fields.size(); ++i) {
        if (data.fields[i].name != name) continue;
        scratch.fieldIndex = int(i);
        scratch.fieldSize =
            colon == std::string::npos ? data.fields[i].defaultSize : std::atoi(data.source.c_str() + colon + 1);
    }
}

void fieldChooser(const DataState& data, PanelScratch& scratch, std::vector<Action>& actions) {
    if (data.fields.empty()) return;
    scratch.fieldIndex = std::clamp(scratch.fieldIndex, 0, static_cast<int>(data.fields.size()) - 1);
    const FieldChoice& chosen = data.fields[std::size_t(scratch.fieldIndex)];
    if (scratch.fieldSize <= 0) scratch.fieldSize = chosen.defaultSize;
    ImGui::SetNextItemWidth(130.0f);
    if (ImGui::BeginCombo("##field", chosen.name.c_str())) {
        for (std::size_t i = 0; i < data.fields.size(); ++i) {
            const bool current = int(i) == scratch.fieldIndex;
            if (ImGui::Selectable(data.fields[i].name.c_str(), current)) {
                scratch.fieldIndex = int(i);
                scratch.fieldSize = data.fields[i].defaultSize;
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", data.fields[i].description.c_str());
        }
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::TextUnformatted("N");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(60.0f);
    ImGui::InputInt("##size", &scratch.fieldSize, 0, 0);
    scratch.fieldSize = std::clamp(scratch.fieldSize, 8, 1024);
    ImGui::SameLine();
    if (ImGui::Button("Build field")) {
        actions.push_back(LoadField{data.fields[std::size_t(scratch.fieldIndex)].name, scratch.fieldSize});
    }
}

void fileChooser(PanelScratch& scratch, std::vector<Action>& actions) {
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - 48.0f);
    const bool entered =
        ImGui::InputTextWithHint("##file", "volume file or DICOM folder (.nrrd .nii .mha .vtk .dcm)",
                                 scratch.path.data(), scratch.path.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("Load") || entered) && scratch.path[0] != '\0') {
        actions.push_back(LoadFile{scratch.path.data()});
    }
}

// Counts per bin on a log scale, so that the few samples of bone in a CT still show.
void histogram(const DataState& data, const ExtractionState& extraction, std::vector<Action>& actions) {
    if (data.histogram.empty()) return;
    std::vector<float> heights(data.histogram.size());
    float tallest = 0.0f;
    for (std::size_t i = 0; i < heights.size(); ++i) {
        heights[i] = std::log1p(data.histogram[i]);
        tallest = std::max(tallest, heights[i]);
    }
    const ImVec2 size(ImGui::GetContentRegionAvail().x, 40.0f);
    ImGui::PlotHistogram("##histogram", heights.data(), static_cast<int>(heights.size()), 0, nullptr, 0.0f, tallest,
                         size);
    const ImVec2 min = ImGui::GetItemRectMin(), max = ImGui::GetItemRectMax();
    const double span = data.rangeMax - data.rangeMin;
    if (span > 0.0) {
        const float t = static_cast<float>(std::clamp((extraction.iso - data.rangeMin) / span, 0.0, 1.0));
        const float x = min.x + t * (max.x - min.x);
        ImGui::GetWindowDrawList()->AddLine(ImVec2(x, min.y), ImVec2(x, max.y), IM_COL32(255, 70, 60, 255), 2.0f);
        if (ImGui::IsItemHovered()) {
            const float mouse = (ImGui::GetIO().MousePos.x - min.x) / std::max(max.x - min.x, 1.0f);
            const double value = data.rangeMin + span * double(std::clamp(mouse, 0.0f, 1.0f));
            ImGui::SetTooltip("value %.4g (click to set the isovalue)", value);
            if (ImGui::IsMouseClicked(ImGuiMouseButton_Left)) actions.push_back(SetIso{value});
        }
    }
}

}  // namespace

void dataSection(const PanelState& state, PanelScratch& scratch, std::vector<Action>& actions) {
    const DataState& data = state.data;
    followSource(data, scratch);
    if (data.loaded) {
        ImGui::Text("showing %s %s", data.sourceIsFile ? "file" : "field", data.sourceName.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", data.source.c_str());
    } else {
        ImGui::TextDisabled("no volume loaded yet");
    }
    ImGui::TextDisabled("open another: a built-in field, or a file");
    fieldChooser(data, scratch, actions);
    fileChooser(scratch, actions);
    if (!data.loaded) return;
    if (!data.valuesRead) {
        ImGui::Text("%d x %d x %d %s, values not read", data.dims[0], data.dims[1], data.dims[2],
                    data.scalarType.c_str());
        if (ImGui::IsItemHovered()) {
            ImGui::SetTooltip("%s mapped, over the memory budget: samples are read only where a surface goes",
                              formatBytes(data.mappedBytes).c_str());
        }
        return;
    }
    ImGui::Text("%d x %d x %d %s, values %.5g .. %.5g", data.dims[0], data.dims[1], data.dims[2],
                data.scalarType.c_str(), data.rangeMin, data.rangeMax);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", data.source.c_str());
    histogram(data, state.extraction, actions);
}

}  // namespace isotrack::ui
