// Surfaces: one row per surface (colour, visibility, statistics), the selected
// surface's details and actions, and the export file pattern.
#include <imgui.h>

#include <cstdio>
#include <string>

#include "ui/sections.h"

namespace isotrack::ui {
namespace {

constexpr ImGuiTableFlags kTableFlags = ImGuiTableFlags_ScrollX | ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg |
                                        ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingFixedFit;

void surfaceMenu(const SurfaceRow& row, const PanelScratch& scratch, std::vector<Action>& actions) {
    if (ImGui::MenuItem("Isolate")) actions.push_back(Isolate{row.id});
    if (ImGui::MenuItem(row.visible ? "Hide" : "Show")) actions.push_back(SetVisible{row.id, !row.visible});
    if (ImGui::MenuItem("Frame")) {
        actions.push_back(Select{row.id});
        actions.push_back(FrameSelection{});
    }
    if (ImGui::MenuItem("Export")) actions.push_back(Export{row.id, exportPath(scratch.exportPattern.data(), row.id)});
    if (ImGui::MenuItem("Delete")) actions.push_back(Delete{row.id});
}

void surfaceRow(const SurfaceRow& row, bool selected, const PanelScratch& scratch, std::vector<Action>& actions) {
    ImGui::PushID(static_cast<int>(row.id));
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    std::array<float, 3> colour = row.colour;
    if (ImGui::ColorEdit3("##colour", colour.data(), ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_NoLabel)) {
        actions.push_back(SetColour{row.id, colour});
    }
    ImGui::TableSetColumnIndex(1);
    bool visible = row.visible;
    if (ImGui::Checkbox("##visible", &visible)) actions.push_back(SetVisible{row.id, visible});
    ImGui::TableSetColumnIndex(2);
    char name[48];
    if (row.presence == SurfaceRow::Gone) {
        std::snprintf(name, sizeof(name), "%u gone", row.id);
    } else if (row.presence == SurfaceRow::Merged) {
        std::snprintf(name, sizeof(name), "%u in %u", row.id, row.mergedInto);
    } else {
        std::snprintf(name, sizeof(name), "%u%s%s", row.id, row.tracked ? " *" : "", row.growing ? " +" : "");
    }
    if (ImGui::Selectable(name, selected,
                          ImGuiSelectableFlags_SpanAllColumns | ImGuiSelectableFlags_AllowItemOverlap)) {
        actions.push_back(Select{selected ? std::nullopt : std::optional<std::uint32_t>(row.id)});
    }
    if (ImGui::BeginPopupContextItem()) {
        surfaceMenu(row, scratch, actions);
        ImGui::EndPopup();
    }
    ImGui::TableSetColumnIndex(3);
    ImGui::TextUnformatted(formatCount(row.triangles).c_str());
    ImGui::TableSetColumnIndex(4);
    ImGui::TextUnformatted(formatCount(row.vertices).c_str());
    ImGui::TableSetColumnIndex(5);
    ImGui::TextUnformatted(formatBytes(row.cpuBytes).c_str());
    ImGui::TableSetColumnIndex(6);
    ImGui::TextUnformatted(formatBytes(row.gpuBytes).c_str());
    ImGui::TableSetColumnIndex(7);
    ImGui::TextUnformatted(formatCount(row.cellsVisited).c_str());
    ImGui::TableSetColumnIndex(8);
    ImGui::Text("%.4g", row.area);
    ImGui::PopID();
}

// Method tree: the surface's own isovalue, dragged across the data's range; only it is tracked again.
void ownIsoSlider(const SurfaceRow& row, const PanelState& state, std::vector<Action>& actions) {
    if (!row.hasArc) return;
    double iso = row.ownIsoWanted.value_or(state.extraction.shownIso);
    const double low = state.data.rangeMin, high = state.data.rangeMax;
    if (ImGui::SliderScalar("own isovalue", ImGuiDataType_Double, &iso, &low, &high, "%.5g")) {
        actions.push_back(SetSurfaceIso{row.id, iso});
    }
    if (row.ownIso) {
        ImGui::SameLine();
        ImGui::TextDisabled("showing %.5g", *row.ownIso);
    }
}

void selectedDetails(const SurfaceRow& row, const PanelState& state, PanelScratch& scratch,
                     std::vector<Action>& actions) {
    if (row.presence == SurfaceRow::Gone && row.ownIso) {
        ImGui::TextWrapped("surface %u: its contour-tree arc ends before its own isovalue %.5g; it comes back nearer",
                           row.id, *row.ownIso);
    } else if (row.presence == SurfaceRow::Gone) {
        ImGui::TextWrapped(
            "surface %u: no surface near its seed at isovalue %.5g; the seed is kept and the surface "
            "comes back where there is one again",
            row.id, row.absentIso);
    } else if (row.presence == SurfaceRow::Merged) {
        ImGui::TextWrapped("surface %u: merged into surface %u at isovalue %.5g; it comes back when they split", row.id,
                           row.mergedInto, row.absentIso);
    }
    ImGui::Text("surface %u: %s triangles, %s", row.id, formatCount(row.triangles).c_str(),
                row.growing ? "growing" : (row.closed ? "closed" : "open"));
    ImGui::Text("CPU %s, GPU %s, area %.5g", formatBytes(row.cpuBytes).c_str(), formatBytes(row.gpuBytes).c_str(),
                row.area);
    ImGui::Text("%s vertices, %s cells visited", formatCount(row.vertices).c_str(),
                formatCount(row.cellsVisited).c_str());
    if (row.euler && row.genus && row.borderLoops) {
        ImGui::Text("Euler characteristic %ld, genus %ld, %ld border loop%s", *row.euler, *row.genus, *row.borderLoops,
                    *row.borderLoops == 1 ? "" : "s");
    }
    if (row.persistence) ImGui::Text("contour-tree arc persistence %.5g", *row.persistence);
    timePlot(state);
    ownIsoSlider(row, state, actions);
    std::array<float, 3> offset = row.offset;
    if (ImGui::DragFloat3("offset", offset.data(), 0.25f)) actions.push_back(SetOffset{row.id, offset});
    if (ImGui::Button("Isolate")) actions.push_back(Isolate{row.id});
    ImGui::SameLine();
    if (ImGui::Button(row.visible ? "Hide" : "Show")) actions.push_back(SetVisible{row.id, !row.visible});
    ImGui::SameLine();
    if (ImGui::Button("Frame")) actions.push_back(FrameSelection{});
    ImGui::SameLine();
    if (ImGui::Button("Delete")) actions.push_back(Delete{row.id});
    ImGui::SameLine();
    if (ImGui::Button("Export")) actions.push_back(Export{row.id, exportPath(scratch.exportPattern.data(), row.id)});
    if (ImGui::Button("Smooth 20")) actions.push_back(ProcessMesh{row.id, 20, 1.0});
    ImGui::SameLine();
    if (ImGui::Button("Decimate to 10%")) actions.push_back(ProcessMesh{row.id, 0, 0.1});
    ImGui::SameLine();
    if (ImGui::Button("Undo")) actions.push_back(UndoMesh{row.id});
}

// PLY, OBJ or STL: rewrites the pattern's extension, which is what decides the format.
void exportFormatChooser(PanelScratch& scratch) {
    static const char* const kFormats[] = {"ply", "obj", "stl"};
    std::string pattern = scratch.exportPattern.data();
    const std::size_t dot = pattern.rfind('.');
    const std::string extension = dot == std::string::npos ? "" : pattern.substr(dot + 1);
    int current = -1;
    for (int i = 0; i < 3; ++i) {
        if (extension == kFormats[i]) current = i;
    }
    ImGui::TextUnformatted("format");
    for (int i = 0; i < 3; ++i) {
        ImGui::SameLine();
        if (ImGui::RadioButton(kFormats[i], current == i) && current != i) {
            pattern = (dot == std::string::npos ? pattern : pattern.substr(0, dot)) + "." + kFormats[i];
            std::snprintf(scratch.exportPattern.data(), scratch.exportPattern.size(), "%s", pattern.c_str());
        }
    }
}

}  // namespace

void surfacesSection(const PanelState& state, PanelScratch& scratch, std::vector<Action>& actions) {
    std::size_t triangles = 0;
    for (const SurfaceRow& row : state.surfaces) triangles += row.triangles;
    ImGui::Text("%zu surface%s, %s triangles", state.surfaces.size(), state.surfaces.size() == 1 ? "" : "s",
                formatCount(triangles).c_str());
    ImGui::SameLine();
    if (ImGui::SmallButton("Show all")) actions.push_back(ShowAll{});
    ImGui::InputText("export to", scratch.exportPattern.data(), scratch.exportPattern.size());
    exportFormatChooser(scratch);

    const float height = ImGui::GetTextLineHeightWithSpacing() * 6.5f;
    if (ImGui::BeginTable("surfaces", 9, kTableFlags, ImVec2(0.0f, height))) {
        ImGui::TableSetupScrollFreeze(3, 1);
        for (const char* column : {"", "vis", "id", "triangles", "vertices", "CPU", "GPU", "cells", "area"}) {
            ImGui::TableSetupColumn(column);
        }
        ImGui::TableHeadersRow();
        ImGuiListClipper clipper;
        clipper.Begin(static_cast<int>(state.surfaces.size()));
        while (clipper.Step()) {
            for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
                const SurfaceRow& row = state.surfaces[std::size_t(i)];
                surfaceRow(row, state.selected == row.id, scratch, actions);
            }
        }
        ImGui::EndTable();
    }
    for (const SurfaceRow& row : state.surfaces) {
        if (state.selected == row.id) selectedDetails(row, state, scratch, actions);
    }
    if (!state.selected) ImGui::TextDisabled("click a surface (here or in the view) to select it");
}

}  // namespace isotrack::ui
