// Applying the worker's results so that surfaces keep who they are.
//
// A result replaces the scene's meshes, not its surfaces. Tracked surfaces
// (those with a seed) are matched by seed: the worker followed each seed to the
// new isovalue and says which result surface holds it; the first tracked
// surface in the list to claim a result surface shows it, a later one whose
// seed lies on the same surface is Merged into it, and one whose seed found no
// surface is Gone; either keeps its seed and style for when the isovalue comes
// back. Surfaces with an isovalue of their own (method tree) keep their place
// and get the mesh the worker tracked along their arc, or are Gone when their
// arc ended on the way. With the contour tree, the other surfaces are matched
// by arc (viewer/arc_match.h); otherwise by footprint (isotrack/follow.h): each
// new surface continues the old one it shares the most 4x4x4-cell blocks with.
// The largest new surface continuing an old one takes its place in the list,
// its id (and so the selection), colour, visibility and offset; further parts
// of a split take the same style and new ids, right after it; old surfaces
// nothing continues are dropped; new surfaces that continue nothing come last,
// largest first, in fresh colours. So the list does not reshuffle under the
// cursor while the isovalue moves.
#include <algorithm>
#include <cstdio>
#include <map>

#include "render/palette.h"
#include "ui/format.h"
#include "ui/method_labels.h"
#include "viewer/arc_match.h"
#include "viewer/viewer.h"

namespace isotrack::viewer {
namespace {

using Structures = std::vector<std::unique_ptr<SurfaceStructure>>;

void copyLook(const SurfaceStructure& from, SurfaceStructure& to) {
    to.style().colour = from.style().colour;
    to.style().visible = from.style().visible;
    to.userOffset = from.userOffset;
}

}  // namespace

void Viewer::takeResult() {
    std::optional<ExtractionResult> result = extraction_.take();
    if (!result) return;
    Profiler::Scope scope(profiler_, Stage::Upload);
    applyResult(std::move(*result));
}

void Viewer::applyResult(ExtractionResult result) {
    profiler_.addWorkerSpan(ui::methodLabels(result.method).work, result.started, result.finished);
    if (!result.error.empty()) {
        extractionError_ = result.error;
        if (script_) throw script_->extractionError(result.error);
        status(result.error);
        return;
    }
    extractionError_.clear();
    const bool newVolume = scene_.setVolume(result.volume);
    if (newVolume) reportSkipped(*result.volume);
    if (newVolume) {  // a new box, and the default view of it; nothing carries over
        renderer_->setBounds(scene_.volumeBounds());
        const render::FrameOptions options = frameOptions();
        camera_ = render::frameBounds(scene_.volumeBounds(), float(options.width) / float(options.height));
        scene_.clearSurfaces();
        renderer_->arena().trim();  // pages sized for the old volume's surfaces go
        nextColour_ = 0;
        treeLayout_.reset();
    }
    if (result.confirmBytes > 0) {  // nothing extracted: the method waits for the user's word
        askConfirmation(result);
        return;
    }
    confirmation_.reset();
    if (result.treeLayout) treeLayout_ = result.treeLayout;
    if (result.onlyFlexible) {  // the other surfaces, and the common isovalue shown, are as they were
        placeFlexible(result, scene_.surfaces());
        return;
    }
    const std::optional<double> previousIso = extraction_.shownIso();  // of the surfaces in the scene
    extraction_.applied(result);
    if (result.method != ui::Method::Tree) {  // own isovalues live on the contour tree's arcs
        for (auto& surface : scene_.surfaces()) surface->ownIso.reset();
    }

    // Room for the whole result in one page before its surfaces arrive one by
    // one: they then draw in one call, and no page is made halfway.
    std::size_t vertices = 0, indices = 0;
    for (const Surface& surface : result.surfaces) {
        vertices += surface.mesh.vertices.size();
        indices += surface.mesh.indices.size();
    }
    if (vertices > 0) renderer_->reserveSurfaces(vertices, indices);

    Structures old = std::move(scene_.surfaces());
    scene_.surfaces().clear();
    std::vector<bool> claimed(result.surfaces.size(), false);
    Structures next;
    next.reserve(old.size() + result.surfaces.size());
    placeTracked(result, old, claimed);
    placeFlexible(result, old);
    placeUntracked(result, old, claimed, next, previousIso);
    for (auto& surface : next) scene_.add(std::move(surface));
    if (scene_.selected && !scene_.find(*scene_.selected)) scene_.selected.reset();
}

// A method that reads the whole of a volume over the memory budget ran into
// the worker's gate. Not chosen by anyone (the default at start-up), the viewer
// goes to track and waits for a click; chosen, the panel asks.
void Viewer::askConfirmation(const ExtractionResult& result) {
    const std::string size = ui::formatBytes(result.confirmBytes);
    if (!methodChosen_) {
        methodChosen_ = true;
        extraction_.setMethod(ui::Method::Track);
        status(displayName(result.volume->source) + " maps " + size + ", over the memory budget of " +
               ui::formatBytes(memoryBudget_) + ": method track, click a surface");
        return;
    }
    confirmation_ = Confirmation{result.method, result.confirmBytes};
}

// A DICOM folder's files that were left out: a line each on stderr, and a
// count in the status line.
void Viewer::reportSkipped(const LoadedVolume& volume) {
    if (volume.skipped.empty()) return;
    for (const DicomSkipped& s : volume.skipped)
        std::fprintf(stderr, "isotrack: %s: skipped: %s\n", s.file.c_str(), s.why.c_str());
    const std::size_t n = volume.skipped.size();
    status_ = displayName(volume.source) + ": " + std::to_string(n) + (n == 1 ? " file" : " files") +
              " skipped (not readable DICOM images; listed on stderr)";
}

// Tracked surfaces get their seed's surface, or become Gone or Merged; they stay where they are in `old`.
void Viewer::placeTracked(ExtractionResult& result, Structures& old, std::vector<bool>& claimed) {
    std::map<std::uint32_t, const SeedResult*> seeds;
    for (const SeedResult& seed : result.seeds) seeds[seed.surface] = &seed;
    std::map<int, std::uint32_t> owner;  // result surface -> the tracked surface showing it
    for (auto& surface : old) {
        if (!surface || !surface->tracked()) continue;
        const auto found = seeds.find(surface->id());
        if (found == seeds.end()) continue;  // tracked since the request was made: keeps growing
        const SeedResult& seed = *found->second;
        if (!seed.seed || seed.index < 0) {
            surface->setAbsent(Presence::Gone, result.iso);
            continue;
        }
        surface->setSeed(*seed.seed, result.iso);
        const auto taken = owner.find(seed.index);
        if (taken != owner.end()) {
            surface->setAbsent(Presence::Merged, result.iso, taken->second);
            continue;
        }
        owner[seed.index] = surface->id();
        claimed[std::size_t(seed.index)] = true;
        surface->replaceSurface(std::move(result.surfaces[std::size_t(seed.index)]),
                                std::move(result.footprints[std::size_t(seed.index)]));
    }
}

// Surfaces with their own isovalue get their mesh at it, or are gone when their arc ended on the way.
void Viewer::placeFlexible(ExtractionResult& result, Structures& surfaces) {
    for (FlexibleResult& flexible : result.flexible) {
        const auto found = std::find_if(surfaces.begin(), surfaces.end(),
                                        [&](const auto& s) { return s && s->id() == flexible.surface; });
        if (found == surfaces.end() || !(*found)->ownIso) continue;  // deleted, or back at the common isovalue
        SurfaceStructure& surface = **found;
        surface.ownIso->shown = flexible.iso;
        if (flexible.mesh) {
            surface.ownIso->arc = flexible.mesh->stats.arc.value_or(surface.ownIso->arc);
            surface.replaceSurface(std::move(*flexible.mesh), std::move(flexible.footprint));
        } else {
            surface.setAbsent(Presence::Gone, flexible.iso);
        }
    }
}

// The result's other surfaces continue the untracked ones by footprint; `next` receives the whole list.
void Viewer::placeUntracked(ExtractionResult& result, Structures& old, std::vector<bool>& claimed, Structures& next,
                            std::optional<double> previousIso) {
    std::vector<const SurfaceFootprint*> previous, fresh;
    std::vector<std::size_t> previousSlot, freshIndex;
    for (std::size_t i = 0; i < old.size(); ++i) {
        if (old[i]->keepsPlace()) continue;
        previous.push_back(&old[i]->footprint());
        previousSlot.push_back(i);
    }
    for (std::size_t j = 0; j < result.surfaces.size(); ++j) {
        if (claimed[j]) continue;
        fresh.push_back(&result.footprints[j]);
        freshIndex.push_back(j);
    }
    std::optional<std::vector<int>> byArc;  // method tree: exact, by the contour tree's arcs (arc_match.h)
    if (result.tree && previousIso && result.method == ui::Method::Tree) {
        std::vector<std::optional<std::size_t>> oldArcs, newArcs;
        for (std::size_t i : previousSlot) oldArcs.push_back(old[i]->stats().arc);
        for (std::size_t j : freshIndex) newArcs.push_back(result.surfaces[j].stats.arc);
        byArc = matchByArc(*result.tree, *previousIso, oldArcs, newArcs);
    }
    const std::vector<int> match = byArc ? *byArc : matchSurfaces(previous, fresh);
    // The parts continuing each old surface, largest first (result order is largest first in `all`).
    std::vector<std::vector<std::size_t>> parts(previous.size());
    std::vector<std::size_t> unmatched;
    for (std::size_t k = 0; k < fresh.size(); ++k) {
        if (match[k] >= 0) {
            parts[std::size_t(match[k])].push_back(k);
        } else {
            unmatched.push_back(k);
        }
    }
    for (auto& list : parts) {
        std::stable_sort(list.begin(), list.end(),
                         [&](std::size_t a, std::size_t b) { return fresh[a]->triangles > fresh[b]->triangles; });
    }
    std::size_t slot = 0;  // index into previous
    for (std::size_t i = 0; i < old.size(); ++i) {
        std::unique_ptr<SurfaceStructure>& surface = old[i];
        if (surface->keepsPlace()) {
            next.push_back(std::move(surface));
            continue;
        }
        const std::vector<std::size_t>& continuing = parts[slot++];
        if (continuing.empty()) {
            if (scene_.selected == surface->id()) scene_.selected.reset();
            continue;  // vanished at this isovalue
        }
        const std::size_t largest = freshIndex[continuing.front()];
        surface->replaceSurface(std::move(result.surfaces[largest]), std::move(result.footprints[largest]));
        const SurfaceStructure& look = *surface;
        next.push_back(std::move(surface));
        for (std::size_t p = 1; p < continuing.size(); ++p) {  // the other parts of a split, right after it
            const std::size_t j = freshIndex[continuing[p]];
            auto part =
                std::make_unique<SurfaceStructure>(renderer_->arena(), scene_.newId(), std::move(result.surfaces[j]),
                                                   std::move(result.footprints[j]), look.style().colour);
            copyLook(look, *part);
            next.push_back(std::move(part));
        }
    }
    for (std::size_t k : unmatched) {
        const std::size_t j = freshIndex[k];
        std::size_t colour = nextColour_++;
        if (result.method == ui::Method::Exhaustive && j == 0) {  // the exhaustive mesh keeps the first colour
            colour = 0;
            nextColour_ = std::max<std::size_t>(nextColour_ - 1, 1);
        }
        next.push_back(
            std::make_unique<SurfaceStructure>(renderer_->arena(), scene_.newId(), std::move(result.surfaces[j]),
                                               std::move(result.footprints[j]), render::surfaceColour(colour)));
    }
}

}  // namespace isotrack::viewer
