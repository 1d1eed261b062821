// Applying the worker's results so that surfaces keep who they are.
//
// Who each surface is, core decides (isotrack/follow.h: continueSurfaces,
// against the scene as it is when the result arrives); here its answer is
// mapped onto the scene's structures. A surface that continues one keeps that
// one's structure: its id (and so the selection), colour, visibility and
// offset; further parts of a split get new ids and the same look; new surfaces
// get new ids and fresh colours (the whole mesh of mc the first colour); the
// surfaces that ended are dropped. Tracked surfaces are updated first, then
// those with their own isovalue, then the others in list order, so the GPU
// arena fills as it always has.
#include <algorithm>
#include <cstdio>
#include <map>
#include <set>

#include "render/palette.h"
#include "ui/format.h"
#include "ui/method_labels.h"
#include "viewer/viewer.h"

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
    const std::optional<double> previousIso = extraction_.shownIso();  // of the surfaces in the scene
    if (!result.next.onlyOwnIsovalues) {  // otherwise the common isovalue shown is as it was
        extraction_.applied(result);
        // Room for the whole result in one page before its surfaces arrive one
        // by one: they then draw in one call, and no page is made halfway.
        std::size_t vertices = 0, indices = 0;
        for (const Surface& surface : result.next.surfaces) {
            vertices += surface.mesh.vertices.size();
            indices += surface.mesh.indices.size();
        }
        if (vertices > 0) renderer_->reserveSurfaces(vertices, indices);
    }
    const bool onlyOwnIsovalues = result.next.onlyOwnIsovalues;
    placeSurfaces(continueSurfaces(previousSurfaces(true), previousIso, std::move(result.next)), onlyOwnIsovalues);
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

// Core's answer on the scene: `next` in the order the list takes (isotrack/follow.h).
void Viewer::placeSurfaces(NextSurfaces next, bool onlyOwnIsovalues) {
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
            auto part = std::make_unique<SurfaceStructure>(renderer_->arena(), scene_.newId(), std::move(*n.surface),
                                                           std::move(n.footprint), look.style().colour);
            copyLook(look, *part);
            placed.push_back(std::move(part));
        } else {
            std::size_t colour = nextColour_++;
            if (n.wholeVolume) {  // the exhaustive mesh keeps the first colour
                colour = 0;
                nextColour_ = std::max<std::size_t>(nextColour_ - 1, 1);
            }
            placed.push_back(std::make_unique<SurfaceStructure>(renderer_->arena(), scene_.newId(),
                                                                std::move(*n.surface), std::move(n.footprint),
                                                                render::surfaceColour(colour)));
        }
    }
    for (auto& surface : placed) scene_.add(std::move(surface));
}

}  // namespace isotrack::viewer
