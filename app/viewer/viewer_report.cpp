#include "viewer/viewer_report.h"

#include "isotrack/fields.h"
#include "viewer/memory.h"

namespace isotrack::viewer {

namespace {

// The box's 24 line vertices.
constexpr std::size_t kBoxBytes = 24 * 3 * sizeof(float);

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

std::size_t ViewerReport::cpuBytes() const {
    return in_.scene.cpuVolumeBytes() + in_.scene.cpuMeshBytes() + tableBytes();
}

std::size_t ViewerReport::gpuOtherBytes() const {
    return in_.picker.gpuBytes() + in_.viewCache.gpuBytes() + kBoxBytes + Window::imguiFontBytes();
}

// The surfaces' share is the arena's pages, whole: what the GPU holds for them.
std::size_t ViewerReport::gpuBytes() const { return in_.renderer.arena().stats().capacityBytes + gpuOtherBytes(); }

nlohmann::json ViewerReport::memoryJson() const {
    std::size_t gone = 0, merged = 0, triangles = 0;
    for (const auto& surface : in_.scene.surfaces()) {
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
            {"surfaces", in_.scene.surfaces().size()},
            {"extractions_applied", in_.extraction.appliedCount()},
            {"isovalue_shown", in_.extraction.shownIso()},
            {"confirm_bytes", in_.extraction.confirmation() ? in_.extraction.confirmation()->bytes : 0},
            {"method", ui::methodName(in_.extraction.method())},
            {"frame", in_.profiler.frames()}};
}

void ViewerReport::checkpoint(const std::string& name, int line) {
    releaseFreeMemory();  // so that the resident set counts live memory, not what malloc keeps around
    nlohmann::json mark = memoryJson();
    mark["name"] = name;
    mark["line"] = line;
    nlohmann::json triangles = nlohmann::json::object();  // by surface id, to tell which surfaces changed
    for (const auto& surface : in_.scene.surfaces()) {
        triangles[std::to_string(surface->id())] = surface->mesh().triangleCount();
    }
    mark["surface_triangles"] = triangles;
    nlohmann::json arcs = nlohmann::json::object();  // method tree: each surface's contour-tree arc, by id
    for (const auto& surface : in_.scene.surfaces()) {
        if (surface->stats().arc) arcs[std::to_string(surface->id())] = *surface->stats().arc;
    }
    mark["surface_arcs"] = arcs;
    checkpoints_.push_back(mark);
}

ui::PanelState ViewerReport::panelState() const {
    ui::PanelState state;
    state.displayWidth = in_.layout.windowWidth();
    state.displayHeight = in_.layout.windowHeight();
    for (const FieldInfo& field : builtinFields()) {
        state.data.fields.push_back(ui::FieldChoice{field.name, field.defaultSize, field.description});
    }
    in_.scene.buildUI(state);
    state.time = in_.time.panelState();

    ui::ExtractionState& extraction = state.extraction;
    extraction.iso = in_.extraction.currentIso();
    extraction.shownIso = in_.extraction.shownIso();
    extraction.table = in_.extraction.table();
    extraction.method = in_.extraction.method();
    extraction.minPersistence = in_.extraction.minPersistence();
    const WorkerProgress progress = in_.extraction.progress();
    extraction.busy = progress.busy;
    extraction.busyWhat = progress.what;
    extraction.busySeconds = progress.seconds;
    extraction.fraction = progress.fraction;
    extraction.lastMs = in_.extraction.lastMs();
    extraction.error = in_.extraction.error();
    if (const auto& confirmation = in_.extraction.confirmation()) {
        extraction.confirmBytes = confirmation->bytes;
        extraction.confirmMethod = confirmation->method;
    }

    state.tree.layout = in_.extraction.treeLayout();
    if (const auto& build = in_.extraction.treeBuild()) {
        state.tree.buildSeconds = build->totalSeconds;
        state.tree.buildPhaseSeconds = build->seconds;
    }
    for (const auto& surface : in_.scene.surfaces()) {
        if (!surface->stats().arc || surface->presence() != Presence::Shown) continue;
        const glm::vec3& colour = surface->style().colour;
        state.tree.surfaces.push_back(
            {surface->id(), *surface->stats().arc, {colour.r, colour.g, colour.b}, in_.extraction.shownIso()});
    }

    ui::GrowthState& growth = state.growth;
    growth.playing = in_.growth.playing();
    growth.cellsPerFrame = in_.growth.cellsPerFrame();
    growth.budgetMs = in_.growth.budgetMs();
    for (const auto& surface : in_.scene.surfaces()) {
        if (!surface->growing()) continue;
        growth.active = true;
        growth.triangles += surface->mesh().triangleCount();
    }
    for (const ui::SurfaceRow& row : state.surfaces) {
        if (row.growing) growth.cellsVisited += row.cellsVisited;
    }

    ui::StatsState& stats = state.stats;
    stats.deterministic = deterministic_;
    stats.fps = in_.profiler.fps();
    stats.frameMs = in_.profiler.lastFrameMs();
    stats.frameTimesMs = in_.profiler.history();
    stats.inputMs = in_.profiler.lastStageMs(Stage::Input) + in_.profiler.lastStageMs(Stage::Script) +
                    in_.profiler.lastStageMs(Stage::Pick);
    stats.uiMs = in_.profiler.lastStageMs(Stage::Ui);
    stats.extractMs = in_.profiler.lastStageMs(Stage::Extract);
    stats.uploadMs = in_.profiler.lastStageMs(Stage::Upload);
    stats.drawMs = in_.profiler.lastStageMs(Stage::Draw);
    stats.presentMs = in_.profiler.lastStageMs(Stage::Present);
    stats.gpuMs = in_.profiler.lastGpuMs();
    stats.cpuVolumeBytes = in_.scene.cpuVolumeBytes();
    stats.volumeMapped = in_.scene.volume() && in_.scene.volume()->mapped;
    stats.cpuMeshBytes = in_.scene.cpuMeshBytes();
    stats.cpuTableBytes = tableBytes();
    const render::ArenaStats arena = in_.renderer.arena().stats();
    stats.gpuSurfaceBytes = arena.capacityBytes;
    stats.arenaPages = arena.pages;
    stats.arenaFreeBytes = arena.freeBytes;
    stats.arenaLargestFreeBytes = arena.largestFreeBytes;
    stats.arenaFragmentation = arena.fragmentation;
    stats.gpuOtherBytes = gpuOtherBytes();
    stats.rssBytes = deterministic_ ? 0 : residentBytes();
    stats.renderer = in_.window.info().renderer;
    stats.frames = in_.profiler.frames();
    stats.drawCalls = in_.totals.drawn.drawCalls;
    stats.trianglesDrawn = in_.totals.drawn.triangles;
    stats.uploadedBytes = in_.totals.uploaded;
    state.message = in_.status.text();
    return state;
}

// The volume's samples: in memory, or mapped from its file (how much of it is
// resident now, and whether it is over the memory budget, unread).
nlohmann::json ViewerReport::volumeJson() const {
    const std::shared_ptr<const LoadedVolume> volume = in_.scene.volume();
    nlohmann::json json = {{"mapped", volume && volume->mapped},
                           {"memory_budget_bytes", in_.extraction.memoryBudget()},
                           {"awaiting_confirmation", in_.extraction.confirmation().has_value()}};
    if (!volume) return json;
    json["bytes"] = volume->volume.byteSize();
    json["values_read"] = volume->valuesRead;
    json["over_memory_budget"] = volume->overBudget;
    if (volume->mapped) json["resident_bytes"] = volume->mapped->residentBytes();
    return json;
}

nlohmann::json ViewerReport::summary() const {
    const nlohmann::json volumeJson = this->volumeJson();
    nlohmann::json surfaces = nlohmann::json::array();
    for (const auto& surface : in_.scene.surfaces()) {
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
                            {"selected", in_.scene.selected == surface->id()},
                            {"isovalue", surface->ownIso ? surface->ownIso->shown : in_.extraction.shownIso()},
                            {"own_isovalue", surface->ownIso.has_value()}});
        if (surface->stats().arc) surfaces.back()["arc"] = *surface->stats().arc;
        if (surface->presence() == Presence::Merged) surfaces.back()["merged_into"] = surface->mergedInto();
        if (const auto& seed = surface->seedPoint()) surfaces.back()["seed"] = *seed;
    }
    nlohmann::json summary = {
        {"source", in_.scene.volume() ? in_.scene.volume()->source.text : ""},
        {"default_isovalue", volumeJson.value("values_read", true) && in_.scene.volume()
                                 ? nlohmann::json(in_.scene.volume()->defaultIso)
                                 : nlohmann::json(nullptr)},
        {"volume", volumeJson},
        {"isovalue", in_.extraction.currentIso()},
        {"isovalue_shown", in_.extraction.shownIso()},
        {"extractions_applied", in_.extraction.appliedCount()},
        {"extractions_cancelled", in_.extraction.cancelledCount()},
        {"table", tableKindName(in_.extraction.table())},
        {"method", ui::methodName(in_.extraction.method())},
        {"min_persistence", in_.extraction.minPersistence()},
        {"surfaces", surfaces},
        {"cpu_bytes", cpuBytes()},
        {"cpu_bytes_detail",
         {{"volume", in_.scene.cpuVolumeBytes()}, {"meshes", in_.scene.cpuMeshBytes()}, {"tables", tableBytes()}}},
        {"gpu_bytes", gpuBytes()},
        {"gpu_bytes_detail",
         {{"surfaces", in_.renderer.arena().stats().capacityBytes},
          {"pick_buffer", in_.picker.gpuBytes()},
          {"view_image", in_.viewCache.gpuBytes()},
          {"box", kBoxBytes},
          {"font_atlas", Window::imguiFontBytes()}}},
        {"gpu_surface_arena", arenaJson(in_.renderer.arena().stats())},
        {"rss_bytes", residentBytes()},
        {"frames", in_.profiler.frames()},
        {"median_frame_ms", in_.profiler.medianFrameMs()},
        {"frame_counters",
         {{"max_draw_calls", in_.totals.maxDrawCalls},
          {"max_triangles_drawn", in_.totals.maxTrianglesDrawn},
          {"max_uploaded_bytes", in_.totals.maxUploadedBytes},
          {"uploaded_bytes", in_.totals.uploadedBytes}}},
        {"extraction_ms", in_.extraction.lastMs()},
        {"gpu_timer_queries", in_.profiler.gpuTimersAvailable()},
        {"renderer", in_.window.info().renderer},
        {"window", {in_.layout.framebufferWidth(), in_.layout.framebufferHeight()}},
        {"checkpoints", checkpoints_},
        {"picks", in_.clicks.picks()},
    };
    if (in_.time.active()) summary["time"] = in_.time.summary();
    if (const auto& build = in_.extraction.treeBuild()) {
        const auto& phase = build->seconds;
        summary["contour_tree_build_ms"] = {{"total", build->totalSeconds * 1e3},
                                            {"sort", phase[0] * 1e3},
                                            {"sweeps", phase[1] * 1e3},
                                            {"merge", phase[2] * 1e3},
                                            {"arcs", phase[3] * 1e3}};
    }
    return summary;
}

}  // namespace isotrack::viewer
