// The panel is plain state in, actions out: it builds with an ImGui context and
// no renderer backend, no window and no GL, and asks for nothing by itself.
#include <imgui.h>
#include <imgui_internal.h>

#include <catch2/catch.hpp>

#include "ui/format.h"
#include "ui/panel.h"

using namespace isotrack;

namespace {

struct HeadlessImGui {
    HeadlessImGui() {
        ImGui::CreateContext();
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr;
        io.DisplaySize = ImVec2(960.0f, 600.0f);
        io.DeltaTime = 1.0f / 60.0f;
        unsigned char* pixels = nullptr;
        int width = 0, height = 0;
        io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);  // a font atlas, never uploaded
    }
    ~HeadlessImGui() { ImGui::DestroyContext(); }
};

ui::PanelState busyState() {
    ui::PanelState state;
    state.data.fields = {{"sphere", 128, "a sphere"}, {"blobs", 128, "metaballs"}};
    state.data.source = "blobs:64";
    state.data.loaded = true;
    state.data.dims = {64, 64, 64};
    state.data.scalarType = "float32";
    state.data.rangeMax = 1.0;
    state.data.histogram.assign(128, 10.0f);
    state.extraction.iso = 0.25;
    state.extraction.busy = true;
    state.extraction.busyWhat = "every surface";
    state.extraction.fraction = 0.4f;
    state.growth.active = true;
    for (std::uint32_t id = 0; id < 300; ++id) {
        ui::SurfaceRow row;
        row.id = id;
        row.triangles = 1000 - id;
        state.surfaces.push_back(row);
    }
    state.selected = 7;
    state.stats.frameTimesMs.assign(300, 16.0f);
    state.message = "something happened";
    return state;
}

}  // namespace

TEST_CASE("the panel builds from plain state and records no actions by itself", "[viewer][ui]") {
    const HeadlessImGui imgui;
    ui::Panel panel;
    std::vector<ui::Action> actions;
    for (int frame = 0; frame < 3; ++frame) {
        ImGui::NewFrame();
        panel.build(busyState(), actions);
        ImGui::Render();
    }
    CHECK(actions.empty());
    CHECK(ImGui::GetDrawData()->TotalVtxCount > 0);

    ImGui::NewFrame();
    panel.build(ui::PanelState{}, actions);  // nothing loaded yet
    ImGui::Render();
    CHECK(actions.empty());
}

TEST_CASE("the panel's rows fit its width: radio rows wrap instead of running off the edge", "[viewer][ui]") {
    const HeadlessImGui imgui;
    ui::Panel panel;
    std::vector<ui::Action> actions;
    ui::PanelState state = busyState();
    state.extraction.busy = false;
    for (int frame = 0; frame < 3; ++frame) {  // later frames lay out with the earlier ones' sizes
        ImGui::NewFrame();
        panel.build(state, actions);
        ImGui::Render();
    }
    const ImGuiWindow* window = ImGui::FindWindowByName("isotrack");
    REQUIRE(window != nullptr);
    // The widest thing placed in the panel's window, against the room the window gives its contents.
    CHECK(window->ContentSize.x <= window->ContentRegionRect.GetWidth() + 0.5f);
}

TEST_CASE("panel text helpers", "[viewer][ui]") {
    CHECK(ui::exportPath("surface_{id}.ply", 42) == "surface_42.ply");
    CHECK(ui::exportPath("a{id}_{id}.ply", 3) == "a3_3.ply");
    CHECK(ui::formatBytes(512) == "512 B");
    CHECK(ui::formatBytes(1536) == "1.5 KB");
    CHECK(ui::formatBytes(3 * 1024 * 1024) == "3.0 MB");
    CHECK(ui::formatMs(12.345, false) == "12.3 ms");
    CHECK(ui::formatMs(12.345, true) == "--");
    CHECK(ui::formatCount(1234567) == "1,234,567");
    CHECK(std::string(ui::methodName(ui::Method::Exhaustive)) == "mc");
}

TEST_CASE("with the contour tree the panel adds the persistence and own isovalue sliders", "[viewer][ui]") {
    const HeadlessImGui imgui;
    ui::Panel panel;
    std::vector<ui::Action> actions;
    const auto vertices = [&](const ui::PanelState& state) {
        int count = 0;
        for (int frame = 0; frame < 3; ++frame) {
            ImGui::NewFrame();
            panel.build(state, actions);
            ImGui::Render();
            count = ImGui::GetDrawData()->TotalVtxCount;
        }
        return count;
    };
    ImGui::GetIO().DisplaySize = ImVec2(960.0f, 4000.0f);  // tall enough that nothing of the panel is clipped
    ui::PanelState plain = busyState();
    plain.displayHeight = 4000;
    plain.extraction.method = ui::Method::Tree;
    ui::PanelState tree = plain;
    tree.surfaces[7].hasArc = true;  // the selected surface, at its own isovalue
    tree.surfaces[7].ownIso = 0.5;
    tree.surfaces[7].ownIsoWanted = 0.5;
    plain.extraction.method = ui::Method::All;
    CHECK(vertices(tree) > vertices(plain));
    CHECK(actions.empty());
}

TEST_CASE("a volume over the memory budget: unread values and the Extract / Cancel question", "[viewer][ui]") {
    const HeadlessImGui imgui;
    ui::Panel panel;
    std::vector<ui::Action> actions;
    const auto vertices = [&](const ui::PanelState& state) {
        int count = 0;
        for (int frame = 0; frame < 3; ++frame) {
            ImGui::NewFrame();
            panel.build(state, actions);
            ImGui::Render();
            count = ImGui::GetDrawData()->TotalVtxCount;
        }
        return count;
    };
    ImGui::GetIO().DisplaySize = ImVec2(960.0f, 4000.0f);
    ui::PanelState unread = busyState();
    unread.displayHeight = 4000;
    unread.extraction.busy = false;
    unread.data.valuesRead = false;  // no range, no histogram: the isovalue is typed in
    unread.data.histogram.clear();
    unread.data.mappedBytes = std::size_t(32) << 30;
    ui::PanelState asking = unread;
    asking.extraction.confirmBytes = unread.data.mappedBytes;
    asking.extraction.confirmMethod = ui::Method::All;
    CHECK(vertices(asking) > vertices(unread));
    CHECK(actions.empty());  // the question alone asks nothing of the viewer
}

TEST_CASE("a time series adds the Time section and the selected surface's plot", "[viewer][ui]") {
    const HeadlessImGui imgui;
    ui::Panel panel;
    std::vector<ui::Action> actions;
    ui::PanelState state = busyState();
    ImGui::NewFrame();
    panel.build(state, actions);
    ImGui::Render();
    const int without = ImGui::GetDrawData()->TotalVtxCount;
    state.time.steps = 6;
    state.time.step = 3;
    state.time.shownStep = 2;
    state.time.time = 0.75;
    state.time.shownTime = 0.5;
    state.time.playing = true;
    state.time.plotSteps = {0, 1, 2};
    state.time.area = {275.0f, 276.0f, 274.0f};
    state.time.volume = {426.0f, 427.0f, 425.0f};
    for (int frame = 0; frame < 2; ++frame) {
        ImGui::NewFrame();
        panel.build(state, actions);
        ImGui::Render();
    }
    CHECK(actions.empty());
    CHECK(ImGui::GetDrawData()->TotalVtxCount > without);
}
