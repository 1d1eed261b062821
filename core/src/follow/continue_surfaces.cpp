// The identity side of following surfaces (isotrack/follow.h): tracked
// surfaces by their seeds, surfaces with their own isovalue by their arcs, the
// others by arc (method tree) or footprint; then the list in its next order.
#include <algorithm>
#include <map>

#include "isotrack/follow.h"

namespace isotrack {
namespace {

// Own isovalues live on the contour tree's arcs: with another method they lapse.
bool keepsOwnIsovalue(const PreviousSurface& surface, const NextExtraction& extraction) {
    if (extraction.nextStep) return false;  // another volume's arcs
    return surface.own.has_value() && (extraction.onlyOwnIsovalues || extraction.method == Method::Tree);
}

// The previous surfaces' arcs are on the extraction's tree: the same volume, method tree.
bool sameTree(std::optional<double> previousIso, const NextExtraction& extraction) {
    return extraction.tree && previousIso && extraction.method == Method::Tree && !extraction.nextStep;
}

// Kept in its place by its seed or its own isovalue, not matched by footprint or arc.
bool keepsPlace(const PreviousSurface& surface, const NextExtraction& extraction) {
    return surface.seed.has_value() || keepsOwnIsovalue(surface, extraction);
}

NextSurface unchangedSurface(const PreviousSurface& surface, const NextExtraction& extraction) {
    NextSurface next;
    next.continues = surface.id;
    next.unchanged = true;
    next.ownIsovalue = keepsOwnIsovalue(surface, extraction);
    return next;
}

// Tracked surfaces get their seed's surface (the first to claim it), or are Merged or Gone.
void placeTracked(const std::vector<PreviousSurface>& previous, NextExtraction& extraction,
                  std::vector<NextSurface>& placed, std::vector<bool>& claimed) {
    std::map<std::uint32_t, const NextExtraction::Seed*> seeds;
    for (const NextExtraction::Seed& seed : extraction.seeds) seeds[seed.id] = &seed;
    std::map<int, std::uint32_t> owner;  // extracted surface -> the tracked surface showing it
    for (std::size_t i = 0; i < previous.size(); ++i) {
        if (!previous[i].seed) continue;
        const auto found = seeds.find(previous[i].id);
        if (found == seeds.end()) continue;  // tracked since the request was made: unchanged
        const NextExtraction::Seed& seed = *found->second;
        NextSurface& next = placed[i];
        next.unchanged = false;
        if (!seed.seed || seed.surface < 0) {
            next.presence = Presence::Gone;
            continue;
        }
        next.seed = seed.seed;
        const auto taken = owner.find(seed.surface);
        if (taken != owner.end()) {
            next.presence = Presence::Merged;
            next.mergedInto = taken->second;
            continue;
        }
        owner[seed.surface] = previous[i].id;
        claimed[std::size_t(seed.surface)] = true;
        next.surface = std::move(extraction.surfaces[std::size_t(seed.surface)]);
        next.footprint = std::move(extraction.footprints[std::size_t(seed.surface)]);
    }
}

// Surfaces with their own isovalue get their mesh at it, or are Gone when their arc ended on the way.
void placeOwn(const std::vector<PreviousSurface>& previous, NextExtraction& extraction,
              std::vector<NextSurface>& placed) {
    for (NextExtraction::Own& own : extraction.own) {
        const auto found =
            std::find_if(previous.begin(), previous.end(), [&](const PreviousSurface& s) { return s.id == own.id; });
        if (found == previous.end() || !keepsOwnIsovalue(*found, extraction)) continue;  // deleted, or back
        NextSurface& next = placed[std::size_t(found - previous.begin())];
        next.unchanged = false;
        next.ownShown = own.iso;
        next.mergedInto = 0;
        if (own.surface) {
            next.presence = Presence::Shown;
            next.ownArc = own.surface->stats.arc.value_or(found->own->arc);
            next.surface = std::move(own.surface);
            next.footprint = std::move(own.footprint);
        } else {
            next.presence = Presence::Gone;
            next.surface.reset();
            next.footprint = SurfaceFootprint{};
        }
    }
}

std::size_t sharedBlocks(const SurfaceFootprint& a, const SurfaceFootprint& b) {
    std::size_t shared = 0;
    for (auto i = a.blocks.begin(), j = b.blocks.begin(); i != a.blocks.end() && j != b.blocks.end();) {
        if (*i < *j) {
            ++i;
        } else if (*j < *i) {
            ++j;
        } else {
            ++shared, ++i, ++j;
        }
    }
    return shared;
}

// The matching of the surfaces kept in place by neither seed nor own isovalue.
struct Untracked {
    std::vector<std::size_t> previous;  // indices into the previous list
    std::vector<std::size_t> fresh;     // indices into the extraction's surfaces
    std::vector<int> match;             // per fresh: index into `previous`, or -1
};

Untracked matchUntracked(const std::vector<PreviousSurface>& previous, std::optional<double> previousIso,
                         const NextExtraction& extraction, const std::vector<bool>& claimed) {
    Untracked u;
    std::vector<const SurfaceFootprint*> before, after;
    for (std::size_t i = 0; i < previous.size(); ++i) {
        if (keepsPlace(previous[i], extraction)) continue;
        u.previous.push_back(i);
        before.push_back(previous[i].footprint);
    }
    for (std::size_t j = 0; j < extraction.surfaces.size(); ++j) {
        if (claimed[j]) continue;
        u.fresh.push_back(j);
        after.push_back(&extraction.footprints[j]);
    }
    std::optional<std::vector<int>> byArc;  // method tree: exact, by the contour tree's arcs
    if (sameTree(previousIso, extraction)) {
        std::vector<std::optional<std::size_t>> oldArcs, newArcs;
        for (std::size_t i : u.previous) oldArcs.push_back(previous[i].arc);
        for (std::size_t j : u.fresh) newArcs.push_back(extraction.surfaces[j].stats.arc);
        byArc = matchSurfacesByArc(*extraction.tree, *previousIso, oldArcs, newArcs);
    }
    if (byArc) {
        u.match = std::move(*byArc);
    } else {
        const SurfaceFootprint none;
        for (const SurfaceFootprint*& f : before) f = f ? f : &none;
        u.match = matchSurfaces(before, after);
    }
    return u;
}

// Which previous surface the surface that ended merged into: the one whose
// continuation holds its arc (method tree) or most of its blocks.
std::optional<std::uint32_t> mergedInto(const PreviousSurface& ended, std::optional<double> previousIso,
                                        const NextExtraction& extraction, const Untracked& u,
                                        const std::vector<PreviousSurface>& previous) {
    int best = -1;
    if (sameTree(previousIso, extraction) && ended.arc) {
        const std::size_t arc = followArc(*extraction.tree, *ended.arc, extraction.iso);
        for (std::size_t k = 0; k < u.fresh.size() && best < 0; ++k) {
            if (extraction.surfaces[u.fresh[k]].stats.arc == arc && u.match[k] >= 0) best = static_cast<int>(k);
        }
    } else if (ended.footprint) {
        std::size_t most = 0;
        for (std::size_t k = 0; k < u.fresh.size(); ++k) {
            const std::size_t shared = sharedBlocks(*ended.footprint, extraction.footprints[u.fresh[k]]);
            if (shared > most && u.match[k] >= 0) most = shared, best = static_cast<int>(k);
        }
    }
    if (best < 0) return std::nullopt;
    return previous[u.previous[std::size_t(u.match[std::size_t(best)])]].id;
}

}  // namespace

NextSurfaces continueSurfaces(const std::vector<PreviousSurface>& previous, std::optional<double> previousIso,
                              NextExtraction extraction) {
    NextSurfaces out;
    out.iso = extraction.iso;
    std::vector<NextSurface> placed;
    placed.reserve(previous.size());
    for (const PreviousSurface& surface : previous) placed.push_back(unchangedSurface(surface, extraction));
    std::vector<bool> claimed(extraction.surfaces.size(), false);
    if (!extraction.onlyOwnIsovalues) placeTracked(previous, extraction, placed, claimed);
    placeOwn(previous, extraction, placed);
    if (extraction.onlyOwnIsovalues) {  // the others, and the common isovalue, are as they were
        out.surfaces = std::move(placed);
        return out;
    }

    const Untracked u = matchUntracked(previous, previousIso, extraction, claimed);
    // The parts continuing each previous surface, largest first.
    std::vector<std::vector<std::size_t>> parts(u.previous.size());
    std::vector<std::size_t> unmatched;
    for (std::size_t k = 0; k < u.fresh.size(); ++k) {
        if (u.match[k] >= 0) {
            parts[std::size_t(u.match[k])].push_back(k);
        } else {
            unmatched.push_back(k);
        }
    }
    for (auto& list : parts) {
        std::stable_sort(list.begin(), list.end(), [&](std::size_t a, std::size_t b) {
            return extraction.footprints[u.fresh[a]].triangles > extraction.footprints[u.fresh[b]].triangles;
        });
    }
    const auto fresh = [&](std::size_t k, std::optional<std::uint32_t> continues, bool split) {
        const std::size_t j = u.fresh[k];
        NextSurface next;
        next.continues = continues;
        next.split = split;
        next.surface = std::move(extraction.surfaces[j]);
        next.footprint = std::move(extraction.footprints[j]);
        next.wholeVolume = extraction.method == Method::Exhaustive && j == 0;
        return next;
    };
    for (std::size_t slot = 0; slot < u.previous.size(); ++slot) {  // before the meshes move
        const PreviousSurface& surface = previous[u.previous[slot]];
        if (parts[slot].empty())
            out.ended.push_back(EndedSurface{surface.id, mergedInto(surface, previousIso, extraction, u, previous)});
    }
    out.surfaces.reserve(previous.size() + u.fresh.size());
    std::size_t slot = 0;  // index into u.previous
    for (std::size_t i = 0; i < previous.size(); ++i) {
        if (keepsPlace(previous[i], extraction)) {
            out.surfaces.push_back(std::move(placed[i]));
            continue;
        }
        const std::vector<std::size_t>& continuing = parts[slot++];
        for (std::size_t p = 0; p < continuing.size(); ++p)
            out.surfaces.push_back(fresh(continuing[p], previous[i].id, p > 0));
    }
    for (std::size_t k : unmatched) out.surfaces.push_back(fresh(k, std::nullopt, false));
    return out;
}

}  // namespace isotrack
