#pragma once
// What the panel shows: plain values the viewer fills in every frame. The panel
// reads this and nothing else; it owns no GL objects, volumes or meshes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "isotrack/extract.h"
#include "isotrack/tables.h"
#include "ui/tree_plot_state.h"

namespace isotrack::ui {

// The panel speaks core's vocabulary: the methods and tables the extraction takes.
using Method = isotrack::Method;    // Exhaustive, Track, All, Tree: "mc", "track", "all", "tree" (methodName)
using Table = isotrack::TableKind;  // Consistent, Classic, Trilinear, Snap
using isotrack::methodName;
inline const char* tableName(Table table) { return tableKindName(table); }  // "consistent", "classic", "trilinear"

struct FieldChoice {
    std::string name;
    int defaultSize = 0;
    std::string description;
};

struct DataState {
    std::vector<FieldChoice> fields;
    std::string source;      // file path or field spec; empty before the first load
    std::string sourceName;  // what the panel calls it: the file's name or the field spec
    bool sourceIsFile = false;
    bool loaded = false;
    std::array<int, 3> dims{0, 0, 0};
    std::string scalarType;
    double rangeMin = 0.0, rangeMax = 1.0;
    std::vector<float> histogram;  // sample counts per bin, bins evenly across [rangeMin, rangeMax]
    std::size_t mappedBytes = 0;   // a mapped file's samples: its bytes (0: in memory)
    bool valuesRead = true;        // false: mapped and over the memory budget, range and histogram not read
};

struct ExtractionState {
    double iso = 0.0;       // asked for (the slider)
    double shownIso = 0.0;  // of the surfaces on screen; trails `iso` by about one extraction while it is dragged
    Table table = Table::Consistent;
    Method method = Method::All;
    double minPersistence = 0.0;  // method tree: surfaces whose arc's persistence is below it are hidden
    bool busy = false;            // the worker is loading or extracting
    std::string busyWhat;         // e.g. "extracting every surface"
    double busySeconds = 0.0;     // elapsed
    float fraction = -1.0f;       // estimated completion 0..1, or < 0 when unknown
    double lastMs = 0.0;          // the last finished extraction (worker time)
    std::string error;            // the last failure, shown until the next success
    // Nonzero: `confirmMethod` reads this many bytes of a volume over the memory
    // budget, and waits for Extract (ConfirmExtraction) or Cancel.
    std::size_t confirmBytes = 0;
    Method confirmMethod = Method::All;
};

// A time series of several steps (steps > 1; else the Time section is not shown).
struct TimeState {
    std::size_t steps = 0;
    std::size_t step = 0, shownStep = 0;  // asked for, and on screen
    double time = 0.0, shownTime = 0.0;   // their time values
    bool playing = false;
    float stepsPerSecond = 4.0f;
    // The selected surface at each step seen so far: its step, area and
    // enclosed volume (0 when open), for the plot in its details.
    std::vector<std::size_t> plotSteps;
    std::vector<float> area, volume;
};

struct GrowthState {
    bool active = false;  // a surface is growing
    bool playing = true;
    int cellsPerFrame = 0;  // 0: a time budget per frame instead
    float budgetMs = 4.0f;
    bool colourByGrowth = false;
    std::size_t cellsVisited = 0;  // by the growing surfaces so far
    std::size_t triangles = 0;
};

struct SurfaceRow {
    std::uint32_t id = 0;  // stable while the surface exists
    std::array<float, 3> colour{0.8f, 0.8f, 0.8f};
    bool visible = true;
    bool growing = false;
    bool closed = false;
    std::array<float, 3> offset{0.0f, 0.0f, 0.0f};  // moved by the user (explode comes on top)
    std::size_t triangles = 0, vertices = 0, cellsVisited = 0;
    std::size_t cpuBytes = 0, gpuBytes = 0;
    double area = 0.0;
    // Topology (Euler characteristic, border loops, genus) and the contour-tree
    // arc's persistence, when the extraction measured them (method tree).
    std::optional<long> euler, borderLoops, genus;
    std::optional<double> persistence;
    // Method tree: the surface is on a contour-tree arc, so it may have an isovalue of its
    // own; `ownIso` is that of its mesh on screen, `ownIsoWanted` the one asked for.
    bool hasArc = false;
    std::optional<double> ownIso, ownIsoWanted;
    bool tracked = false;  // has a seed, kept across isovalues
    // A tracked surface may have no mesh at this isovalue: gone, or merged into another tracked surface.
    enum Presence { Shown, Gone, Merged } presence = Shown;
    double absentIso = 0.0;
    std::uint32_t mergedInto = 0;
};

struct StatsState {
    bool deterministic = false;  // timings frozen (shown as "--") for reproducible screenshots
    double fps = 0.0;
    double frameMs = 0.0;
    std::vector<float> frameTimesMs;  // oldest first, the last few hundred frames
    // The last frame's stages, CPU milliseconds, and the GPU's time for the 3D draw (< 0: unknown).
    double inputMs = 0, uiMs = 0, extractMs = 0, uploadMs = 0, drawMs = 0, presentMs = 0, gpuMs = -1;
    std::size_t cpuVolumeBytes = 0, cpuMeshBytes = 0, cpuTableBytes = 0;  // a mapped volume: 0, it is the file's
    bool volumeMapped = false;
    std::size_t gpuSurfaceBytes = 0, gpuOtherBytes = 0;
    // The surfaces' shared GPU pages: how many, their free space, its largest
    // range, and how split it is (0: one range per buffer, towards 1: many small).
    std::size_t arenaPages = 0, arenaFreeBytes = 0, arenaLargestFreeBytes = 0;
    double arenaFragmentation = 0.0;
    std::size_t rssBytes = 0;
    std::string renderer;  // GL_RENDERER
    std::size_t frames = 0;
    // The last frame: draw calls and triangles into the 3D view (none when its cached image was
    // only copied), and bytes of vertices and indices uploaded.
    std::size_t drawCalls = 0, trianglesDrawn = 0, uploadedBytes = 0;
};

struct ViewState {
    float explode = 0.0f;  // surfaces pulled from the volume's centre by this factor
    bool wireframe = false;
    bool boundingBox = true;
};

struct PanelState {
    DataState data;
    ExtractionState extraction;
    TimeState time;
    GrowthState growth;
    std::vector<SurfaceRow> surfaces;
    std::optional<std::uint32_t> selected;  // surface id
    StatsState stats;
    ViewState view;
    TreePlotState tree;                           // method tree: the contour-tree plot
    std::string message;                          // the last thing that went wrong or was done (export, pick)
    int displayWidth = 960, displayHeight = 600;  // the window, in pixels
};

}  // namespace isotrack::ui
