#pragma once
// The extraction controller: what the user asked to extract, the worker that
// makes it so, and its results applied to the scene so that surfaces keep who
// they are.
//
// Wanted: the source, isovalue, table and method (and the tree's
// simplification); submit() sends them with the scene's surfaces (their seeds
// and own isovalues). A request for another source, method or table makes
// every result of an older request void (the worker cancels the work); one
// for another isovalue or other seeds does not, so results keep arriving while
// the isovalue is dragged.
//
// Shown: takeResult() applies the newest finished result still wanted. Who
// each surface is, core decides (isotrack/follow.h: continueSurfaces, against
// the scene as it is when the result arrives); here its answer is mapped onto
// the scene's structures. A surface that continues one keeps that one's
// structure: its id (and so the selection), colour, visibility and offset;
// further parts of a split get new ids and the same look; new surfaces get new
// ids and fresh colours (the whole mesh of mc the first colour); the surfaces
// that ended are dropped. Tracked surfaces are updated first, then those with
// their own isovalue, then the others in list order, so the GPU arena fills as
// it always has.
//
// A volume over the memory budget: a method that reads it whole waits for the
// user's word (confirmation()); not chosen by anyone, the viewer goes to track.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "render/renderer.h"
#include "viewer/extraction_worker.h"
#include "viewer/profiler.h"
#include "viewer/scene.h"
#include "viewer/status_line.h"

namespace isotrack::viewer {

class ScriptRunner;

class ExtractionController {
public:
    ExtractionController(int threads, std::uint64_t memoryBudget, Scene& scene, render::Renderer& renderer,
                         Profiler& profiler, StatusLine& status);

    // A --script session: requests belong to its commands, and errors are its errors.
    void attachScript(ScriptRunner* script) { script_ = script; }
    // Called when a result brings a new volume, after the scene let go of the old one's surfaces.
    void onNewVolume(std::function<void()> callback) { onNewVolume_ = std::move(callback); }

    // ---- what is wanted ----
    const VolumeSource& source() const { return source_; }
    void setSource(VolumeSource source);  // also back to the source's default isovalue
    // The source's time series when it has several steps (a .pvd, a 4D NIfTI
    // or NRRD, numbered files), else null; read when the source is set.
    const std::shared_ptr<const TimeSeries>& series() const { return series_; }
    // Step `step` of the series, submitted; the isovalue shown stays (it is
    // fixed now if it was the source's default). InputError past the last step.
    void setTimeStep(std::size_t step);
    // The step of the volume on screen (0 for a single volume).
    std::size_t shownStep() const;
    const std::optional<double>& iso() const { return iso_; }  // nullopt: the source's default
    void setIso(double iso) { iso_ = iso; }
    TableKind table() const { return table_; }
    // The extractions' threads, which a tracked surface's growth shares too (SurfaceTracker).
    int threads() const { return worker_.threads(); }
    void setTable(TableKind table) { table_ = table; }
    Method method() const { return method_; }
    void setMethod(Method method) { method_ = method; }
    double minPersistence() const { return minPersistence_; }  // method tree: 0, or the simplification's
    void setMinPersistence(double persistence) { minPersistence_ = persistence; }

    // Another source, its default isovalue, submitted.
    void load(VolumeSource source);
    // Sends what is wanted with the scene's surfaces.
    void submit();
    // Flexible isosurfaces: surface `id` at its own isovalue; only it is extracted again.
    void setSurfaceIso(std::uint32_t id, double iso);

    // ---- a volume over the memory budget ----
    struct Confirmation {
        Method method = Method::All;
        std::uint64_t bytes = 0;
    };
    const std::optional<Confirmation>& confirmation() const { return confirmation_; }
    void confirm();             // the method waiting may read the whole volume (InputError if none waits)
    void cancelConfirmation();  // back to track (with the consistent table if it was snap)
    // A click to track with the snap table, whose sample states cover the whole
    // volume: on a volume over the budget it waits for confirm() (true), once
    // per volume; confirmed, takeConfirmedTrack() hands it back to be tracked.
    struct PendingTrack {
        Vec3d point{};
        std::optional<std::uint32_t> hit;
    };
    bool askBeforeTracking(const LoadedVolume& volume, const PendingTrack& track);
    std::optional<PendingTrack> takeConfirmedTrack() { return std::exchange(confirmedTrack_, std::nullopt); }
    void chooseMethod(Method method);                 // the user's choice, submitted: not switched to track on its own
    void setMethodChosen() { methodChosen_ = true; }  // --method was given
    std::uint64_t memoryBudget() const { return memoryBudget_; }

    // ---- what is shown ----
    // Applies the newest finished result that is still wanted, if one waits.
    void takeResult();
    double currentIso() const;  // the isovalue asked for (the slider)
    double shownIso() const;    // the isovalue of the surfaces on screen
    std::size_t appliedCount() const { return applied_; }
    double lastMs() const { return lastMs_; }
    const std::string& error() const { return error_; }
    const std::shared_ptr<const TreeLayout>& treeLayout() const { return treeLayout_; }
    // The build of the tree shown (method tree), once one is built.
    const std::optional<TreeBuildTimes>& treeBuild() const { return treeBuild_; }
    // The palette rank for the next new surface.
    std::size_t takeColour() { return nextColour_++; }

    WorkerProgress progress() const { return worker_.progress(); }
    bool busy() const { return worker_.busy(); }
    std::size_t cancelledCount() const { return worker_.cancelledCount(); }

private:
    void send(bool onlyOwnIsovalues);
    std::vector<PreviousSurface> previousSurfaces(bool footprints) const;
    void applyResult(ExtractionResult result);
    void askConfirmation(const ExtractionResult& result);
    void reportSkipped(const LoadedVolume& volume);
    void placeSurfaces(NextSurfaces next, bool onlyOwnIsovalues);

    ExtractionWorker worker_;
    Scene& scene_;
    render::Renderer& renderer_;
    Profiler& profiler_;
    StatusLine& status_;
    ScriptRunner* script_ = nullptr;
    std::function<void()> onNewVolume_;

    VolumeSource source_;
    std::shared_ptr<const TimeSeries> series_;  // source_'s, when it has several steps
    std::optional<double> iso_;
    TableKind table_ = TableKind::Consistent;
    Method method_ = Method::All;
    double minPersistence_ = 0.0;
    std::set<Method> confirmed_;  // for source_: methods the user let read the whole volume

    std::uint64_t generation_ = 0;
    std::uint64_t epoch_ = 0;  // results of requests before this one are void
    std::optional<ExtractionRequest> lastRequest_;

    std::uint64_t memoryBudget_ = 0;
    std::optional<Confirmation> confirmation_;
    std::optional<PendingTrack> pendingTrack_, confirmedTrack_;  // a click waiting for confirm(), and confirmed
    bool methodChosen_ = false;  // --method, or a method picked since: not switched to track on its own

    std::optional<double> shownIso_;
    std::size_t applied_ = 0;
    double lastMs_ = 0.0;
    std::string error_;
    std::size_t nextColour_ = 0;
    std::shared_ptr<const TreeLayout> treeLayout_;  // the volume's contour tree laid out (method tree)
    std::optional<TreeBuildTimes> treeBuild_;       // and how long its build took
};

}  // namespace isotrack::viewer
