// Extraction (isovalue, table, method) and growth (the surface being tracked).
#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "ui/method_labels.h"
#include "ui/sections.h"

namespace isotrack::ui {
namespace {

// Before a radio button in a row: on the same line when the panel has room for it, else on a line of its own.
void sameLineIfRoom(const char* label) {
    const float width = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
    ImGui::SameLine();
    if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
}

void progress(const ExtractionState& extraction, bool frozen) {
    if (!extraction.busy) {
        ImGui::Text("last extraction %s", formatMs(extraction.lastMs, frozen).c_str());
        return;
    }
    static const char kSpinner[] = "|/-\\";
    const int turn = frozen ? 0 : static_cast<int>(extraction.busySeconds * 8.0) % 4;
    char label[96];
    if (frozen) {
        std::snprintf(label, sizeof(label), "%c %s", kSpinner[turn], extraction.busyWhat.c_str());
    } else {
        std::snprintf(label, sizeof(label), "%c %s %.1f s", kSpinner[turn], extraction.busyWhat.c_str(),
                      extraction.busySeconds);
    }
    if (extraction.fraction >= 0.0f && !frozen) {
        ImGui::ProgressBar(std::min(extraction.fraction, 1.0f), ImVec2(-1.0f, 0.0f), label);
    } else {
        ImGui::TextUnformatted(label);
    }
}

// Method tree: noise hidden by persistence. The tree is simplified (leaf branches whose value range is below
// the threshold pruned) and the surfaces extracted again from its remaining arcs.
void persistenceSlider(const PanelState& state, std::vector<Action>& actions) {
    double persistence = state.extraction.minPersistence;
    const double low = 0.0, high = std::max(state.data.rangeMax - state.data.rangeMin, 0.0);
    if (ImGui::SliderScalar("persistence", ImGuiDataType_Double, &persistence, &low, &high, "%.4g")) {
        actions.push_back(SetMinPersistence{persistence});
    }
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip(
            "min persistence: hide surfaces whose contour-tree branch spans less than this range of values (0: none)");
    }
}

// A volume over the memory budget: the method reads all of it from disk only when told to.
void confirmation(const ExtractionState& extraction, std::vector<Action>& actions) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.35f, 1.0f));
    // Track asks only with the snap table, whose sample states cover the whole volume.
    const bool snapTrack = extraction.confirmMethod == Method::Track;
    ImGui::TextWrapped("%s%s reads %s from disk (over the memory budget)",
                       methodLabels(extraction.confirmMethod).choice, snapTrack ? " with the snap table" : "",
                       formatBytes(extraction.confirmBytes).c_str());
    ImGui::PopStyleColor();
    if (ImGui::Button("Extract")) actions.push_back(ConfirmExtraction{});
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) actions.push_back(CancelExtraction{});
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(snapTrack ? "back to the consistent table: click a surface to grow it"
                                    : "back to track: click a surface to grow it");
}

}  // namespace

void extractionSection(const PanelState& state, std::vector<Action>& actions) {
    const ExtractionState& extraction = state.extraction;
    const DataState& data = state.data;
    double iso = extraction.iso;
    const double low = data.loaded ? data.rangeMin : 0.0, high = data.loaded ? data.rangeMax : 1.0;
    if (data.loaded && !data.valuesRead) {  // no range to slide across: typed in
        if (ImGui::InputDouble("isovalue", &iso, 0.0, 0.0, "%.5g", ImGuiInputTextFlags_EnterReturnsTrue)) {
            actions.push_back(SetIso{iso});
        }
    } else if (ImGui::SliderScalar("isovalue", ImGuiDataType_Double, &iso, &low, &high, "%.5g")) {
        actions.push_back(SetIso{iso});
    }

    if (data.loaded && extraction.shownIso != extraction.iso) {
        ImGui::TextDisabled("showing %.5g, following", extraction.shownIso);
    }

    int table = static_cast<int>(extraction.table);
    ImGui::TextUnformatted("table");
    for (const Table kind : kTableKinds) {
        sameLineIfRoom(tableName(kind));
        if (ImGui::RadioButton(tableName(kind), &table, static_cast<int>(kind))) actions.push_back(SetTable{kind});
        if (kind == Table::Trilinear && ImGui::IsItemHovered())
            ImGui::SetTooltip("the trilinear interpolant's topology (MC33)");
        if (kind == Table::Snap && ImGui::IsItemHovered())
            ImGui::SetTooltip("samples near the isovalue snapped onto it (SnapMC): no slivers, fewer triangles");
    }

    // The panel's order: exhaustive, every surface, track click, contour tree.
    int method = static_cast<int>(extraction.method);
    bool first = true;
    for (const Method choice : {Method::Exhaustive, Method::All, Method::Track, Method::Tree}) {
        const MethodLabels& labels = methodLabels(choice);
        if (!first) sameLineIfRoom(labels.choice);
        first = false;
        if (ImGui::RadioButton(labels.choice, &method, static_cast<int>(choice))) actions.push_back(SetMethod{choice});
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", labels.tooltip);
    }
    if (extraction.method == Method::Tree) persistenceSlider(state, actions);
    if (extraction.confirmBytes > 0) confirmation(extraction, actions);
    progress(extraction, state.stats.deterministic);
    if (!extraction.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", extraction.error.c_str());
        ImGui::PopStyleColor();
    }
}

void growthSection(const PanelState& state, std::vector<Action>& actions) {
    const GrowthState& growth = state.growth;
    if (growth.playing) {
        if (ImGui::Button("Pause")) actions.push_back(Growth{Growth::Pause});
    } else {
        if (ImGui::Button("Play")) actions.push_back(Growth{Growth::Play});
    }
    ImGui::SameLine();
    if (ImGui::Button("Step")) actions.push_back(Growth{Growth::Step});
    ImGui::SameLine();
    if (ImGui::Button("Restart")) actions.push_back(Growth{Growth::Restart});
    ImGui::SameLine();
    bool colourByGrowth = growth.colourByGrowth;
    if (ImGui::Checkbox("growth order", &colourByGrowth)) actions.push_back(SetColourByGrowth{colourByGrowth});

    int cells = growth.cellsPerFrame;
    ImGui::SetNextItemWidth(110.0f);
    if (ImGui::InputInt("cells/frame", &cells, 1000, 10000)) actions.push_back(SetCellsPerFrame{std::max(cells, 0)});
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("0: grow for a time budget per frame instead");
    if (growth.cellsPerFrame == 0) {
        ImGui::SameLine();
        float budget = growth.budgetMs;
        ImGui::SetNextItemWidth(70.0f);
        if (ImGui::SliderFloat("ms/frame", &budget, 1.0f, 32.0f, "%.0f")) actions.push_back(SetGrowthBudget{budget});
    }
    if (growth.active) {
        ImGui::Text("growing: %s cells, %s triangles", formatCount(growth.cellsVisited).c_str(),
                    formatCount(growth.triangles).c_str());
    } else if (state.extraction.method == Method::Track) {
        ImGui::TextDisabled("click in the view: the surface there grows");
    } else {
        ImGui::TextDisabled("ctrl-click a surface to grow it");
    }
}

}  // namespace isotrack::ui
