#include "ui/panel.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "ui/sections.h"

namespace isotrack::ui {

std::string exportPath(const std::string& pattern, std::uint32_t id) {
    std::string path = pattern;
    const std::string key = "{id}";
    for (std::size_t at = path.find(key); at != std::string::npos; at = path.find(key, at)) {
        path.replace(at, key.size(), std::to_string(id));
    }
    return path;
}

std::string formatBytes(std::size_t bytes) {
    char text[32];
    const double b = static_cast<double>(bytes);
    if (bytes < 1024) {
        std::snprintf(text, sizeof(text), "%zu B", bytes);
    } else if (bytes < 1024 * 1024) {
        std::snprintf(text, sizeof(text), "%.1f KB", b / 1024.0);
    } else if (bytes < std::size_t(1024) * 1024 * 1024) {
        std::snprintf(text, sizeof(text), "%.1f MB", b / (1024.0 * 1024.0));
    } else {
        std::snprintf(text, sizeof(text), "%.2f GB", b / (1024.0 * 1024.0 * 1024.0));
    }
    return text;
}

std::string formatMs(double ms, bool frozen) {
    if (frozen || ms < 0.0) return "--";
    char text[32];
    std::snprintf(text, sizeof(text), ms < 10.0 ? "%.2f ms" : "%.1f ms", ms);
    return text;
}

std::string formatCount(std::size_t count) {
    std::string digits = std::to_string(count);
    for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3) digits.insert(std::size_t(at), ",");
    return digits;
}

namespace {

constexpr ImGuiWindowFlags kFixedWindow = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                          ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings;

void compactStyle() {
    ImGuiStyle& style = ImGui::GetStyle();
    style.ItemSpacing = ImVec2(6.0f, 3.0f);
    style.FramePadding = ImVec2(4.0f, 2.0f);
    style.WindowPadding = ImVec2(6.0f, 6.0f);
}

void statsWindow(const PanelState& state) {
    constexpr float kWidth = 372.0f, kHeight = 196.0f, kMargin = 8.0f;
    const float x = static_cast<float>(state.displayWidth) - kWidth - kMargin;
    const float y = static_cast<float>(state.displayHeight) - kHeight - kMargin;
    ImGui::SetNextWindowPos(ImVec2(std::max(x, Panel::kWidth + kMargin), std::max(y, 0.0f)), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(kWidth, kHeight), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.72f);
    if (ImGui::Begin("Stats", nullptr, kFixedWindow & ~ImGuiWindowFlags_NoCollapse)) statsSection(state);
    ImGui::End();
}

}  // namespace

std::string Panel::exportPattern() const {
    return scratch_.initialised ? std::string(scratch_.exportPattern.data()) : std::string(kDefaultExportPattern);
}

void Panel::build(const PanelState& state, std::vector<Action>& actions) {
    if (!scratch_.initialised) {
        compactStyle();
        std::snprintf(scratch_.exportPattern.data(), scratch_.exportPattern.size(), "%s", kDefaultExportPattern);
        scratch_.initialised = true;
    }
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(kWidth, static_cast<float>(state.displayHeight)), ImGuiCond_Always);
    if (ImGui::Begin("isotrack", nullptr, kFixedWindow)) {
        ImGui::PushItemWidth(-90.0f);
        if (!state.message.empty()) {
            ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.8f, 0.4f, 1.0f));
            ImGui::TextWrapped("%s", state.message.c_str());
            ImGui::PopStyleColor();
        }
        if (ImGui::CollapsingHeader("Data", ImGuiTreeNodeFlags_DefaultOpen)) dataSection(state, scratch_, actions);
        if (ImGui::CollapsingHeader("Extraction", ImGuiTreeNodeFlags_DefaultOpen)) extractionSection(state, actions);
        if (state.extraction.method == Method::Tree &&
            ImGui::CollapsingHeader("Contour tree", ImGuiTreeNodeFlags_DefaultOpen)) {
            treeSection(state, actions);
        }
        if (state.time.steps > 1 && ImGui::CollapsingHeader("Time", ImGuiTreeNodeFlags_DefaultOpen)) {
            timeSection(state, actions);
        }
        if (ImGui::CollapsingHeader("Growth", ImGuiTreeNodeFlags_DefaultOpen)) growthSection(state, actions);
        if (ImGui::CollapsingHeader("Surfaces", ImGuiTreeNodeFlags_DefaultOpen)) {
            surfacesSection(state, scratch_, actions);
        }
        if (ImGui::CollapsingHeader("View", ImGuiTreeNodeFlags_DefaultOpen)) viewSection(state, actions);
        ImGui::PopItemWidth();
    }
    ImGui::End();
    statsWindow(state);
}

}  // namespace isotrack::ui
