// What the viewer reports: the panel's plain state, memory, the --json summary
// and screenshots.
#include "isotrack/fields.h"
#include "render/image.h"
#include "render/window_frame.h"
#include "viewer/memory.h"
#include "viewer/viewer.h"

namespace isotrack::viewer {

namespace {

// The box's 24 line vertices.
constexpr std::size_t kBoxBytes = 24 * 3 * sizeof(float);

const char* presenceName(Presence presence) {
    switch (presence) {
        case Presence::Shown: return "shown";
        case Presence::Gone: return "gone";
        case Presence::Merged: return "merged";
    }
    return "shown";
}

nlohmann::json arenaJson(const render::ArenaStats& arena) {
    return {{"pages", arena.pages},
            {"capacity_bytes", arena.capacityBytes},
            {"reserved_bytes", arena.reservedBytes},
            {"used_bytes", arena.usedBytes},
            {"free_bytes", arena.freeBytes},
            {"largest_free_bytes", arena.largestFreeBytes},
            {"fragmentation", arena.fragmentation},
            {"moves", arena.moves},
            {"moved_bytes", arena.movedBytes}};
}

}  // namespace

std::size_t Viewer::cpuBytes() const { return scene_.cpuVolumeBytes() + scene_.cpuMeshBytes() + tableBytes(); }

std::size_t Viewer::gpuOtherBytes() const {
    return picker_.gpuBytes() + viewCache_.gpuBytes() + kBoxBytes + Window::imguiFontBytes();
}

// The surfaces' share is the arena's pages, whole: what the GPU holds for them.
std::size_t Viewer::gpuBytes() const { return renderer_->arena().stats().capacityBytes + gpuOtherBytes(); }

nlohmann::json Viewer::memoryJson() const {
    std::size_t gone = 0, merged = 0, triangles = 0;
    for (const auto& surface : scene_.surfaces()) {
        triangles += surface->mesh().triangleCount();
        gone += surface->presence() == Presence::Gone ? 1 : 0;
        merged += surface->presence() == Presence::Merged ? 1 : 0;
    }
    return {{"cpu_bytes", cpuBytes()},
            {"surfaces_gone", gone},
            {"triangles", triangles},
            {"surfaces_merged", merged},
            {"gpu_bytes", gpuBytes()},
            {"rss_bytes", residentBytes()},
            {"surfaces", scene_.surfaces().size()},
            {"extractions_applied", extraction_.appliedCount()},
            {"isovalue_shown", shownIso()},
            {"confirm_bytes", confirmation_ ? confirmation_->bytes : 0},
            {"method", ui::methodName(extraction_.method())},
            {"frame", profiler_.frames()}};
}

ui::PanelState Viewer::panelState() const {
    ui::PanelState state;
    state.displayWidth = windowWidth_;
    state.displayHeight = windowHeight_;
    for (const FieldInfo& field : builtinFields()) {
        state.data.fields.push_back(ui::FieldChoice{field.name, field.defaultSize, field.description});
    }
    scene_.buildUI(state);

    ui::ExtractionState& extraction = state.extraction;
    extraction.iso = currentIso();
    extraction.shownIso = shownIso();
    extraction.table = extraction_.table();
    extraction.method = extraction_.method();
    extraction.minPersistence = extraction_.minPersistence();
    const WorkerProgress progress = extraction_.progress();
    extraction.busy = progress.busy;
    extraction.busyWhat = progress.what;
    extraction.busySeconds = progress.seconds;
    extraction.fraction = progress.fraction;
    extraction.lastMs = extraction_.lastMs();
    extraction.error = extractionError_;
    if (confirmation_) {
        extraction.confirmBytes = confirmation_->bytes;
        extraction.confirmMethod = confirmation_->method;
    }

    state.tree.layout = treeLayout_;
    for (const auto& surface : scene_.surfaces()) {
        if (!surface->stats().arc || surface->presence() != Presence::Shown) continue;
        const glm::vec3& colour = surface->style().colour;
        state.tree.surfaces.push_back(
            {surface->id(), *surface->stats().arc, {colour.r, colour.g, colour.b}, shownIso()});
    }

    ui::GrowthState& growth = state.growth;
    growth.playing = playing_;
    growth.cellsPerFrame = cellsPerFrame_;
    growth.budgetMs = growthBudgetMs_;
    for (const auto& surface : scene_.surfaces()) {
        if (!surface->growing()) continue;
        growth.active = true;
        growth.triangles += surface->mesh().triangleCount();
    }
    for (const ui::SurfaceRow& row : state.surfaces) {
        if (row.growing) growth.cellsVisited += row.cellsVisited;
    }

    ui::StatsState& stats = state.stats;
    stats.deterministic = options_.deterministic;
    stats.fps = profiler_.fps();
    stats.frameMs = profiler_.lastFrameMs();
    stats.frameTimesMs = profiler_.history();
    stats.inputMs =
        profiler_.lastStageMs(Stage::Input) + profiler_.lastStageMs(Stage::Script) + profiler_.lastStageMs(Stage::Pick);
    stats.uiMs = profiler_.lastStageMs(Stage::Ui);
    stats.extractMs = profiler_.lastStageMs(Stage::Extract);
    stats.uploadMs = profiler_.lastStageMs(Stage::Upload);
    stats.drawMs = profiler_.lastStageMs(Stage::Draw);
    stats.presentMs = profiler_.lastStageMs(Stage::Present);
    stats.gpuMs = profiler_.lastGpuMs();
    stats.cpuVolumeBytes = scene_.cpuVolumeBytes();
    stats.volumeMapped = scene_.volume() && scene_.volume()->mapped;
    stats.cpuMeshBytes = scene_.cpuMeshBytes();
    stats.cpuTableBytes = tableBytes();
    const render::ArenaStats arena = renderer_->arena().stats();
    stats.gpuSurfaceBytes = arena.capacityBytes;
    stats.arenaPages = arena.pages;
    stats.arenaFreeBytes = arena.freeBytes;
    stats.arenaLargestFreeBytes = arena.largestFreeBytes;
    stats.arenaFragmentation = arena.fragmentation;
    stats.gpuOtherBytes = gpuOtherBytes();
    stats.rssBytes = options_.deterministic ? 0 : residentBytes();
    stats.renderer = window_.info().renderer;
    stats.frames = profiler_.frames();
    stats.drawCalls = drawn_.drawCalls;
    stats.trianglesDrawn = drawn_.triangles;
    stats.uploadedBytes = uploaded_;
    state.message = status_;
    return state;
}

// The volume's samples: in memory, or mapped from its file (how much of it is
// resident now, and whether it is over the memory budget, unread).
nlohmann::json Viewer::volumeJson() const {
    const std::shared_ptr<const LoadedVolume> volume = scene_.volume();
    nlohmann::json json = {{"mapped", volume && volume->mapped},
                           {"memory_budget_bytes", memoryBudget_},
                           {"awaiting_confirmation", confirmation_.has_value()}};
    if (!volume) return json;
    json["bytes"] = volume->volume.byteSize();
    json["values_read"] = volume->valuesRead;
    json["over_memory_budget"] = volume->overBudget;
    if (volume->mapped) json["resident_bytes"] = volume->mapped->residentBytes();
    return json;
}

nlohmann::json Viewer::summary() const {
    const nlohmann::json volumeJson = this->volumeJson();
    nlohmann::json surfaces = nlohmann::json::array();
    for (const auto& surface : scene_.surfaces()) {
        const Mesh& mesh = surface->mesh();
        const glm::vec3 colour = surface->style().colour;
        const glm::vec3 offset = surface->userOffset;
        surfaces.push_back({{"id", surface->id()},
                            {"triangles", mesh.triangleCount()},
                            {"vertices", mesh.vertices.size()},
                            {"bytes", surface->cpuBytes()},
                            {"gpu_bytes", surface->gpuBytes()},
                            {"cells_visited", surface->stats().cellsVisited},
                            {"area", surface->stats().area},
                            {"closed", surface->stats().closed},
                            {"growing", surface->growing()},
                            {"tracked", surface->tracked()},
                            {"state", presenceName(surface->presence())},
                            {"visible", surface->style().visible},
                            {"colour", {colour.r, colour.g, colour.b}},
                            {"offset", {offset.x, offset.y, offset.z}},
                            {"selected", scene_.selected == surface->id()},
                            {"isovalue", surface->ownIso ? surface->ownIso->shown : shownIso()},
                            {"own_isovalue", surface->ownIso.has_value()}});
        if (surface->stats().arc) surfaces.back()["arc"] = *surface->stats().arc;
        if (surface->presence() == Presence::Merged) surfaces.back()["merged_into"] = surface->mergedInto();
        if (const auto& seed = surface->seedPoint()) surfaces.back()["seed"] = *seed;
    }
    nlohmann::json summary = {
        {"source", scene_.volume() ? scene_.volume()->source.text : ""},
        {"default_isovalue", volumeJson.value("values_read", true) && scene_.volume()
                                 ? nlohmann::json(scene_.volume()->defaultIso)
                                 : nlohmann::json(nullptr)},
        {"volume", volumeJson},
        {"isovalue", currentIso()},
        {"isovalue_shown", shownIso()},
        {"extractions_applied", extraction_.appliedCount()},
        {"extractions_cancelled", extraction_.cancelledCount()},
        {"table", tableKindName(extraction_.table())},
        {"method", ui::methodName(extraction_.method())},
        {"min_persistence", extraction_.minPersistence()},
        {"surfaces", surfaces},
        {"cpu_bytes", cpuBytes()},
        {"cpu_bytes_detail",
         {{"volume", scene_.cpuVolumeBytes()}, {"meshes", scene_.cpuMeshBytes()}, {"tables", tableBytes()}}},
        {"gpu_bytes", gpuBytes()},
        {"gpu_bytes_detail",
         {{"surfaces", renderer_->arena().stats().capacityBytes},
          {"pick_buffer", picker_.gpuBytes()},
          {"view_image", viewCache_.gpuBytes()},
          {"box", kBoxBytes},
          {"font_atlas", Window::imguiFontBytes()}}},
        {"gpu_surface_arena", arenaJson(renderer_->arena().stats())},
        {"rss_bytes", residentBytes()},
        {"frames", profiler_.frames()},
        {"median_frame_ms", profiler_.medianFrameMs()},
        {"frame_counters",
         {{"max_draw_calls", sessionCounters_.maxDrawCalls},
          {"max_triangles_drawn", sessionCounters_.maxTrianglesDrawn},
          {"max_uploaded_bytes", sessionCounters_.maxUploadedBytes},
          {"uploaded_bytes", sessionCounters_.uploadedBytes}}},
        {"extraction_ms", extraction_.lastMs()},
        {"gpu_timer_queries", profiler_.gpuTimersAvailable()},
        {"renderer", window_.info().renderer},
        {"window", {framebufferWidth_, framebufferHeight_}},
        {"checkpoints", checkpoints_},
        {"picks", picks_},
    };
    return summary;
}

void Viewer::writeScreenshot(const std::string& path) const {
    render::writePng(render::readWindowImage(framebufferWidth_, framebufferHeight_), path);
}

}  // namespace isotrack::viewer
