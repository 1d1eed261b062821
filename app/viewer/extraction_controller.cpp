#include "viewer/extraction_controller.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "isotrack/errors.h"
#include "render/palette.h"
#include "ui/format.h"
#include "ui/method_labels.h"
#include "ui/tree_plot.h"
#include "viewer/script_runner.h"

namespace isotrack::viewer {
namespace {

using Structures = std::vector<std::unique_ptr<SurfaceStructure>>;

void copyLook(const SurfaceStructure& from, SurfaceStructure& to) {
    to.style().colour = from.style().colour;
    to.style().visible = from.style().visible;
    to.userOffset = from.userOffset;
}

// A surface that continues: its seed, its own isovalue, its mesh or its absence.
void continueSurface(SurfaceStructure& surface, NextSurface& next, double iso) {
    if (next.unchanged) return;
    if (next.seed) surface.setSeed(*next.seed, iso);
    if (next.ownShown && surface.ownIso) {
        surface.ownIso->shown = *next.ownShown;
        if (next.ownArc) surface.ownIso->arc = *next.ownArc;
    }
    switch (next.presence) {
        case Presence::Shown: surface.replaceSurface(std::move(*next.surface), std::move(next.footprint)); break;
        case Presence::Gone: surface.setAbsent(Presence::Gone, next.ownShown.value_or(iso)); break;
        case Presence::Merged: surface.setAbsent(Presence::Merged, iso, next.mergedInto); break;
    }
}

// A file's steps when it is a time series of several (read here: a .pvd or a
// header, no samples); a file that cannot be read is the worker's to report.
std::shared_ptr<const TimeSeries> seriesOf(const VolumeSource& source) {
    if (source.kind != VolumeSource::Kind::File || source.raw || !source.series.empty()) return nullptr;
    std::error_code error;
    if (std::filesystem::is_directory(source.text, error)) return nullptr;
    try {
        auto series = std::make_shared<const TimeSeries>(readTimeSeries(source.text));
        return series->steps.size() > 1 ? series : nullptr;
    } catch (const std::exception&) {
        return nullptr;
    }
}

}  // namespace

ExtractionController::ExtractionController(int threads, std::uint64_t memoryBudget, Scene& scene,
                                           render::Renderer& renderer, Profiler& profiler, StatusLine& status)
    : worker_(threads, memoryBudget, ui::kTreePlotBranches),
      scene_(scene),
      renderer_(renderer),
      profiler_(profiler),
      status_(status),
      memoryBudget_(memoryBudget) {}

void ExtractionController::setSource(VolumeSource source) {
    if (source != source_) confirmed_.clear();
    if (!sameSeries(source, source_) || !series_) series_ = seriesOf(source);
    source_ = std::move(source);
    iso_.reset();
}

void ExtractionController::setTimeStep(std::size_t step) {
    const std::size_t steps = series_ ? series_->steps.size() : 1;
    if (step >= steps) {
        throw InputError("time " + std::to_string(step) + ": " + displayName(source_) + " has " +
                         std::to_string(steps) +
                         (steps == 1 ? " step (0)" : " steps (0.." + std::to_string(steps - 1) + ")"));
    }
    if (step == source_.time) return;
    // Each step's own suggestion would move the isovalue under the surfaces: the one shown stays.
    if (!iso_ && scene_.volume() && scene_.volume()->valuesRead) iso_ = shownIso();
    source_.time = step;
    submit();
}

std::size_t ExtractionController::shownStep() const { return scene_.volume() ? scene_.volume()->source.time : 0; }

void ExtractionController::load(VolumeSource source) {
    confirmation_.reset();
    setSource(std::move(source));
    submit();
}

double ExtractionController::currentIso() const {
    if (iso_) return *iso_;
    return scene_.volume() ? scene_.volume()->defaultIso : 0.0;
}

double ExtractionController::shownIso() const { return shownIso_.value_or(currentIso()); }

// The scene's surfaces as core's follow.h names them; the worker gets them
// without footprints, continueSurfaces with them.
std::vector<PreviousSurface> ExtractionController::previousSurfaces(bool footprints) const {
    std::vector<PreviousSurface> previous;
    previous.reserve(scene_.surfaces().size());
    for (const auto& surface : scene_.surfaces()) {
        PreviousSurface p;
        p.id = surface->id();
        p.seed = surface->seedPoint();
        if (surface->ownIso) {
            const OwnIso& own = *surface->ownIso;
            p.own = OwnIsovalue{own.wanted, own.arc, own.origin, own.wanted != own.shown};
        }
        p.arc = surface->stats().arc;
        if (footprints) p.footprint = &surface->footprint();
        previous.push_back(p);
    }
    return previous;
}

void ExtractionController::submit() { send(false); }

void ExtractionController::send(bool onlyOwnIsovalues) {
    ExtractionRequest request;
    request.generation = ++generation_;
    request.source = source_;
    request.iso = iso_;
    request.table = table_;
    request.method = method_;
    request.work = ui::methodLabels(method_).work;
    request.minPersistence = minPersistence_;
    request.confirmed = confirmed_.count(method_) != 0;
    request.series = series_;
    const std::shared_ptr<const LoadedVolume>& shown = scene_.volume();
    request.nextStep = shown && sameSeries(shown->source, source_) && shown->source.time != source_.time;
    if (!lastRequest_ || supersedes(request, *lastRequest_)) epoch_ = request.generation;
    lastRequest_ = request;
    request.surfaces = previousSurfaces(false);
    request.onlyOwnIsovalues = onlyOwnIsovalues;
    worker_.submit(std::move(request));
    if (script_) script_->noteSubmitted();
}

// Flexible isosurfaces: the surface gets an isovalue of its own and only it is
// tracked again, along its contour-tree arc; the others keep theirs.
void ExtractionController::setSurfaceIso(std::uint32_t id, double iso) {
    SurfaceStructure* surface = scene_.find(id);
    if (!surface) return;
    if (method_ != Method::Tree || (!surface->stats().arc && !surface->ownIso) || surface->tracked()) {
        const std::string message = "surface " + std::to_string(id) +
                                    " is on no contour-tree arc: an isovalue of its own needs the method tree";
        if (script_) throw InputError(message);
        status_.show(message);
        return;
    }
    if (!surface->ownIso) surface->ownIso = OwnIso{iso, shownIso(), *surface->stats().arc, *surface->stats().arc};
    surface->ownIso->wanted = iso;
    send(true);
}

void ExtractionController::confirm() {
    if (!confirmation_) throw InputError("confirm: no extraction waits for confirmation");
    confirmed_.insert(confirmation_->method);
    if (pendingTrack_) {  // a click's track, not a request: tracked by the caller of takeConfirmedTrack
        confirmedTrack_ = std::exchange(pendingTrack_, std::nullopt);
        confirmation_.reset();
        return;
    }
    method_ = confirmation_->method;
    confirmation_.reset();
    submit();
}

void ExtractionController::cancelConfirmation() {
    if (!confirmation_) return;
    confirmation_.reset();
    pendingTrack_.reset();
    method_ = Method::Track;
    if (table_ == TableKind::Snap) table_ = TableKind::Consistent;  // snap tracking reads the whole volume too
    submit();
}

void ExtractionController::chooseMethod(Method method) {
    methodChosen_ = true;
    confirmation_.reset();
    method_ = method;
    submit();
}

void ExtractionController::takeResult() {
    std::optional<ExtractionResult> result = worker_.poll();
    if (!result || result->generation < epoch_) return;  // none, or void
    Profiler::Scope scope(profiler_, Stage::Upload);
    applyResult(std::move(*result));
}

void ExtractionController::applyResult(ExtractionResult result) {
    profiler_.addWorkerSpan(ui::methodLabels(result.method).work, result.started, result.finished);
    if (result.treeBuild) {  // the tree's phases, each a span of its own inside the extraction's
        auto at = result.treeBuild->start;
        for (std::size_t k = 0; k < result.treeBuild->seconds.size(); ++k) {
            const auto end = at + std::chrono::duration_cast<Profiler::Clock::duration>(
                                      std::chrono::duration<double>(result.treeBuild->seconds[k]));
            profiler_.addWorkerSpan(
                std::string("contour tree: ") + contourTreePhaseName(static_cast<ContourTreeProgress::Phase>(k)), at,
                end);
            at = end;
        }
    }
    if (!result.error.empty()) {
        error_ = result.error;
        if (script_) throw script_->extractionError(result.error);
        status_.show(result.error);
        return;
    }
    error_.clear();
    // Another step of the series shown: the surfaces continue (by seed and footprint), the view stays.
    const std::shared_ptr<const LoadedVolume> before = scene_.volume();
    const bool anotherStep = before && sameSeries(before->source, result.volume->source) &&
                             before->source.time != result.volume->source.time;
    const bool newVolume = scene_.setVolume(result.volume) && !anotherStep;
    if (newVolume) reportSkipped(*result.volume);
    if (newVolume) {  // a new box, and the default view of it; nothing carries over
        renderer_.setBounds(scene_.volumeBounds());
        if (onNewVolume_) onNewVolume_();
        scene_.clearSurfaces();
        renderer_.arena().trim();  // pages sized for the old volume's surfaces go
        nextColour_ = 0;
        treeLayout_.reset();
        treeBuild_.reset();
    }
    if (result.confirmBytes > 0) {  // nothing extracted: the method waits for the user's word
        askConfirmation(result);
        return;
    }
    confirmation_.reset();
    if (result.treeLayout) treeLayout_ = result.treeLayout;
    if (result.treeBuild) treeBuild_ = result.treeBuild;
    const std::optional<double> previousIso = shownIso_;  // of the surfaces in the scene
    if (!result.next.onlyOwnIsovalues) {                  // otherwise the common isovalue shown is as it was
        shownIso_ = result.iso;
        lastMs_ = result.extractMs;
        ++applied_;
        // Room for the whole result in one page before its surfaces arrive one
        // by one: they then draw in one call, and no page is made halfway.
        std::size_t vertices = 0, indices = 0;
        for (const Surface& surface : result.next.surfaces) {
            vertices += surface.mesh.vertices.size();
            indices += surface.mesh.indices.size();
        }
        if (vertices > 0) renderer_.reserveSurfaces(vertices, indices);
    }
    const bool onlyOwnIsovalues = result.next.onlyOwnIsovalues;
    placeSurfaces(continueSurfaces(previousSurfaces(true), previousIso, std::move(result.next)), onlyOwnIsovalues);
    if (scene_.selected && !scene_.find(*scene_.selected)) scene_.selected.reset();
}

// A method that reads the whole of a volume over the memory budget ran into
// the worker's gate. Not chosen by anyone (the default at start-up), the viewer
// goes to track and waits for a click; chosen, the panel asks.
void ExtractionController::askConfirmation(const ExtractionResult& result) {
    const std::string size = ui::formatBytes(result.confirmBytes);
    if (!methodChosen_) {
        methodChosen_ = true;
        method_ = Method::Track;
        status_.show(displayName(result.volume->source) + " maps " + size + ", over the memory budget of " +
                     ui::formatBytes(memoryBudget_) + ": method track, click a surface");
        return;
    }
    confirmation_ = Confirmation{result.method, result.confirmBytes};
}

bool ExtractionController::askBeforeTracking(const LoadedVolume& volume, const PendingTrack& track) {
    if (!readsWholeVolume(Method::Track, table_) || !volume.overBudget || confirmed_.count(Method::Track)) return false;
    pendingTrack_ = track;
    confirmation_ = Confirmation{Method::Track, volume.mappedBytes};
    return true;
}

// A DICOM folder's files that were left out: a line each on stderr, and a
// count in the status line.
void ExtractionController::reportSkipped(const LoadedVolume& volume) {
    if (volume.skipped.empty()) return;
    for (const DicomSkipped& s : volume.skipped)
        std::fprintf(stderr, "isotrack: %s: skipped: %s\n", s.file.c_str(), s.why.c_str());
    const std::size_t n = volume.skipped.size();
    status_.set(displayName(volume.source) + ": " + std::to_string(n) + (n == 1 ? " file" : " files") +
                " skipped (not readable DICOM images; listed on stderr)");
}

// Core's answer on the scene: `next` in the order the list takes (isotrack/follow.h).
void ExtractionController::placeSurfaces(NextSurfaces next, bool onlyOwnIsovalues) {
    const auto keeper = [&](const NextSurface& n) -> SurfaceStructure* {
        return n.continues && !n.split ? scene_.find(*n.continues) : nullptr;
    };
    for (const NextSurface& n : next.surfaces) {  // first, so that keepsPlace() says what core took
        SurfaceStructure* surface = keeper(n);
        if (surface != nullptr && !n.ownIsovalue) surface->ownIso.reset();
    }
    // Tracked surfaces, then those with their own isovalue, in place.
    std::set<std::uint32_t> done;
    for (const bool tracked : {true, false}) {
        for (NextSurface& n : next.surfaces) {
            SurfaceStructure* surface = keeper(n);
            if (surface == nullptr || !surface->keepsPlace() || surface->tracked() != tracked) continue;
            continueSurface(*surface, n, next.iso);
            done.insert(surface->id());
        }
    }
    if (onlyOwnIsovalues) return;  // the others are as they were, and so is the list
    Structures old = std::move(scene_.surfaces());
    scene_.surfaces().clear();
    std::map<std::uint32_t, std::unique_ptr<SurfaceStructure>> byId;
    for (auto& surface : old) byId[surface->id()] = std::move(surface);
    Structures placed;
    placed.reserve(next.surfaces.size());
    std::map<std::uint32_t, const SurfaceStructure*> looks;  // by id: the structures placed so far
    for (NextSurface& n : next.surfaces) {
        if (n.continues && !n.split) {
            std::unique_ptr<SurfaceStructure>& surface = byId.at(*n.continues);
            if (done.count(surface->id()) == 0) continueSurface(*surface, n, next.iso);
            looks[surface->id()] = surface.get();
            placed.push_back(std::move(surface));
        } else if (n.split) {  // a further part of a split, right after the largest
            const SurfaceStructure& look = *looks.at(*n.continues);
            auto part = std::make_unique<SurfaceStructure>(renderer_.arena(), scene_.newId(), std::move(*n.surface),
                                                           std::move(n.footprint), look.style().colour);
            copyLook(look, *part);
            placed.push_back(std::move(part));
        } else {
            std::size_t colour = takeColour();
            if (n.wholeVolume) {  // the exhaustive mesh keeps the first colour
                colour = 0;
                nextColour_ = std::max<std::size_t>(nextColour_ - 1, 1);
            }
            placed.push_back(std::make_unique<SurfaceStructure>(renderer_.arena(), scene_.newId(),
                                                                std::move(*n.surface), std::move(n.footprint),
                                                                render::surfaceColour(colour)));
        }
    }
    for (auto& surface : placed) scene_.add(std::move(surface));
}

}  // namespace isotrack::viewer
