// Every surface at once: the exhaustive pass, labelled, then split.
//
// extractAllSurfaces runs the (parallel) exhaustive pass, which labels the
// connected surfaces on the way (labelled_march.h), tallies each cell piece
// and its triangles at one of its vertices, and lists the vertices on the
// volume's border. The mesh is then split in parallel over ranges of chunks:
// the surfaces are numbered, each range counts its share of every surface's
// vertices, triangles and cell pieces (one pass over its vertices), which gives
// it its place in every surface's buffers, the listed vertices mark the surfaces
// the border cuts, and the triangles, then the vertices, are copied there and
// measured. The largest surface is not copied but compacted in place, keeping
// the exhaustive pass's buffers (and their pages, already touched); its part
// below the first vertex of any other surface is in place already, and is only
// measured. It yields exactly the surfaces trackAllSurfaces finds by tracking
// one surface at a time (the tests hold them equal), with no per-voxel memory.
//
// The passes, over one Split: numberSurfaces, placeShares, splitTriangles,
// splitVertices, compactLargest, measureSurfaces, then sortedBySize.
#include <algorithm>
#include <numeric>
#include <type_traits>

#include "extract/common/cancel.h"
#include "extract/marching_cubes/labelled_march.h"
#include "extract/measure/surface_measure.h"
#include "extract/snap/snap_march.h"
#include "extract/surfaces/all_surfaces.h"
#include "extract/trilinear/trilinear_march.h"
#include "isotrack/tracking.h"
#include "support/huge_pages.h"
#include "support/parallel.h"

namespace isotrack {
namespace {

constexpr std::uint32_t kNone = ~std::uint32_t(0);  // no root or surface yet

// One thread's share of one surface.
struct Share {
    std::uint32_t vertices = 0, triangles = 0, pieces = 0;
    std::size_t vertexBase = 0, triangleBase = 0;  // where the share starts in the surface's buffers
    detail::SurfaceMeasure measure;
};

// Consecutive chunks of the exhaustive pass, one range per thread: splitting
// keeps one Share per surface per range.
struct Range {
    std::size_t vertexBegin = 0, vertexEnd = 0;
    std::size_t triangleBegin = 0, triangleEnd = 0;
    std::size_t chunkBegin = 0, chunkEnd = 0;
};

// Ranges end at the chunk boundaries nearest to equal shares of the triangles.
std::vector<Range> ranges(const std::vector<detail::MarchedChunk>& chunks, int threads) {
    if (chunks.empty()) return {};
    const std::size_t count = std::min(chunks.size(), std::size_t(std::max(1, threads)));
    const std::size_t triangles = chunks.back().triangleEnd;
    std::vector<Range> out(count);
    std::size_t begin = 0;
    for (std::size_t r = 0; r < count; ++r) {
        // At least one chunk each, ending where the running count is nearest the target.
        const std::size_t target = triangles * (r + 1) / count, limit = chunks.size() - (count - r - 1);
        std::size_t end = begin + 1;
        while (end < limit) {
            const std::size_t here = chunks[end - 1].triangleEnd, next = chunks[end].triangleEnd;
            if (here >= target || (next >= target && next - target >= target - here)) break;
            ++end;
        }
        if (r + 1 == count) end = chunks.size();
        out[r] = {chunks[begin].vertexBegin,
                  chunks[end - 1].vertexEnd,
                  chunks[begin].triangleBegin,
                  chunks[end - 1].triangleEnd,
                  begin,
                  end};
        begin = end;
    }
    return out;
}

// Adds the bounds of a run of one surface's vertices, kept in registers by the
// caller (values, not references: a lambda capturing them would keep them in memory).
void addVertexRun(detail::SurfaceMeasure& measure, float x0, float y0, float z0, float x1, float y1, float z1) {
    detail::SurfaceMeasure run;
    run.boundsMin[0] = x0, run.boundsMin[1] = y0, run.boundsMin[2] = z0;
    run.boundsMax[0] = x1, run.boundsMax[1] = y1, run.boundsMax[2] = z1;
    measure.merge(run);
}

// Per vertex, its surface and its index in its range's share, side by side:
// splitting the triangles looks both up for each corner.
struct Label {
    std::uint32_t surface, local;
};

// What the passes of the split share: the labelled mesh, its ranges, and what
// each pass leaves for the next.
struct Split {
    Split(detail::LabelledMesh& labelledMesh, const Volume& volume, TableKind tableKind, int threadCount)
        : labelled(labelledMesh),
          mesh(labelledMesh.mesh),
          parts(ranges(labelledMesh.chunks, threadCount)),
          dims(volume.dims()),
          table(tableKind),
          threads(threadCount) {}

    detail::LabelledMesh& labelled;
    Mesh& mesh;
    const std::vector<Range> parts;
    const Dims dims;
    const TableKind table;
    const int threads;

    std::vector<std::uint32_t> roots;        // numberSurfaces: each surface's root, in order
    Buffer<Label> labels;                    // numberSurfaces: per vertex
    std::vector<std::vector<Share>> shares;  // per range, per surface
    std::size_t count = 0;                   // surfaces
    std::vector<Surface> surfaces;           // placeShares: sized, but for the largest
    std::size_t largest = 0;
    bool compact = false;  // the largest surface is compacted in the mesh's buffers (it is not alone)
    // Every vertex below the first vertex of another surface (its root) is the
    // largest surface's, at its final place: those vertices, and the triangles
    // with only such corners, stay as they are, and are only measured. With one
    // surface far larger than the rest, which start late, that is most of the mesh.
    std::size_t settled = 0;

    template <class Fn>
    void forParts(Fn&& fn) {
        detail::parallelFor(int(parts.size()), threads, [&](int r) { fn(parts[std::size_t(r)], std::size_t(r)); });
    }
};

// Each vertex gets its surface's number (its label's `surface`): its parent's when
// the parent is in the same range (below it, so numbered already), else by a
// walk to its root. It gets its index in its range's share of that surface
// (`local`), and the share adds up the cell pieces and triangles tallied at
// its vertices. Ranges only read the forest, so they run at once. One range
// (one thread) has every root, and numbers each surface as its root comes.
// Runs of vertices on one surface are common: the run's surface and counters
// stay in registers.
template <bool OneRange>
void numberRange(Split& s, const Range& part, std::size_t r) {
    const std::uint32_t* parent = s.labelled.parent.data();
    std::vector<std::uint32_t>& roots = s.roots;
    Label* const labels = s.labels.data();
    const std::uint8_t* const tallies = s.labelled.tally.data();
    auto numberOf = [&](std::uint32_t root) {
        return static_cast<std::uint32_t>(std::lower_bound(roots.begin(), roots.end(), root) - roots.begin());
    };
    std::vector<Share>& share = s.shares[r];
    std::uint32_t k = kNone, counter = 0, triangles = 0, pieces = 0;
    // The last walk's start and its surface: vertices in a row often share a
    // parent below the range.
    std::uint32_t walkedFrom = kNone, walkedTo = kNone;
    for (std::size_t v = part.vertexBegin; v < part.vertexEnd; ++v) {
        const std::uint32_t up = parent[v];
        std::uint32_t surface;
        if constexpr (OneRange) {
            if (up == v) {
                surface = static_cast<std::uint32_t>(roots.size());
                roots.push_back(up);
                share.emplace_back();
            } else {
                surface = labels[up].surface;
            }
        } else if (up != v && up >= part.vertexBegin) {
            surface = labels[up].surface;
        } else if (up == walkedFrom) {
            surface = walkedTo;
        } else {
            std::uint32_t root = up;
            while (parent[root] != root) root = parent[root];
            surface = numberOf(root);
            walkedFrom = up, walkedTo = surface;
        }
        if (surface != k) {
            if (k != kNone) share[k].vertices = counter, share[k].triangles = triangles, share[k].pieces = pieces;
            k = surface;
            counter = share[k].vertices, triangles = share[k].triangles, pieces = share[k].pieces;
        }
        labels[v] = {k, counter++};
        const unsigned tally = tallies[v];
        triangles += tally & detail::kTalliedTriangles;
        pieces += tally / detail::kTalliedPiece;
    }
    if (k != kNone) share[k].vertices = counter, share[k].triangles = triangles, share[k].pieces = pieces;
    // The surfaces the border cuts: the exhaustive pass listed their vertices on it.
    for (std::size_t c = part.chunkBegin; c < part.chunkEnd; ++c) {
        for (const std::uint32_t v : s.labelled.chunks[c].borderVertices)
            share[labels[v].surface].measure.touchesBorder = true;
    }
}

// Surfaces numbered in order of their roots (their first vertices): each
// range lists its roots, and the lists one after the other are in order. Then
// every range numbers its vertices (numberRange). The forest is freed after.
void numberSurfaces(Split& s) {
    const std::uint32_t* parent = s.labelled.parent.data();
    if (s.parts.size() > 1) {
        std::vector<std::vector<std::uint32_t>> rootsOf(s.parts.size());
        s.forParts([&](const Range& part, std::size_t r) {
            for (std::size_t v = part.vertexBegin; v < part.vertexEnd; ++v) {
                if (parent[v] == v) rootsOf[r].push_back(static_cast<std::uint32_t>(v));
            }
        });
        for (const std::vector<std::uint32_t>& some : rootsOf) s.roots.insert(s.roots.end(), some.begin(), some.end());
    }
    detail::resizeOnHugePages(s.labels, s.mesh.vertices.size());
    s.shares.assign(s.parts.size(), std::vector<Share>(s.roots.size()));
    if (s.parts.size() == 1) {
        numberRange<true>(s, s.parts[0], 0);
    } else {
        s.forParts([&](const Range& part, std::size_t r) { numberRange<false>(s, part, r); });
    }
    s.count = s.roots.size();
    Buffer<std::uint32_t>().swap(s.labelled.parent);
}

// Each share's place in its surface's buffers, the largest surface, and the
// other surfaces' buffers sized once; the largest keeps the mesh's.
void placeShares(Split& s) {
    const std::size_t count = s.count;
    s.surfaces.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        std::size_t vertices = 0, triangles = 0;
        for (std::vector<Share>& share : s.shares) {
            share[k].vertexBase = vertices;
            share[k].triangleBase = triangles;
            vertices += share[k].vertices;
            triangles += share[k].triangles;
        }
        s.surfaces[k].stats.vertices = vertices;
        s.surfaces[k].stats.triangles = triangles;
        if (triangles > s.surfaces[s.largest].stats.triangles) s.largest = k;
    }
    for (std::size_t k = 0; k < count; ++k) {
        if (k == s.largest) continue;  // it keeps the mesh's buffers
        Surface& surface = s.surfaces[k];
        detail::resizeOnHugePages(surface.mesh.vertices, surface.stats.vertices);
        detail::resizeOnHugePages(surface.mesh.vertexEdges, surface.stats.vertices);
        detail::resizeOnHugePages(surface.mesh.indices, 3 * surface.stats.triangles);
    }
    // The largest surface is compacted in the mesh's own buffers: each range's
    // share moves to the start of the range (every element moves down, within the
    // range), then the shares next to each other. A lone surface stays as it is.
    s.compact = count > 0 && s.surfaces[s.largest].stats.vertices != s.mesh.vertices.size();
    s.settled = s.mesh.vertices.size();
    for (std::size_t k = 0; k < std::min<std::size_t>(count, 2); ++k) {
        if (k != s.largest) s.settled = std::min<std::size_t>(s.settled, s.roots[k]);
    }
}

// The range's first triangles while their corners are settled, measured into
// `sums` and left in place; returns the first triangle after them.
std::size_t measureSettledTriangles(const Split& s, const Range& part, detail::TriangleLanes& sums) {
    const std::uint32_t* indices = s.mesh.indices.data();
    const Vertex* vertices = s.mesh.vertices.data();
    const std::size_t settled = s.settled, triangleEnd = part.triangleEnd;
    auto isSettled = [&](const std::uint32_t* v, std::size_t corners) {
        std::uint32_t top = 0;
        for (std::size_t i = 0; i < corners; ++i) top = std::max(top, v[i]);
        return top < settled;
    };
    std::size_t t = part.triangleBegin;
    while (t + 4 <= triangleEnd && isSettled(indices + 3 * t, 12)) {
        sums.addFour(vertices, indices + 3 * t);
        t += 4;
    }
    while (t < triangleEnd && isSettled(indices + 3 * t, 3)) {
        const std::uint32_t* v = indices + 3 * t++;
        sums.add(vertices[v[0]], vertices[v[1]], vertices[v[2]]);
    }
    return t;
}

// A range's triangles out to their surfaces, measured on the way, while the
// vertices are still in place. A range's triangles use the next range's
// vertices too. One range (one thread) has all of every surface: indices are
// then the vertices' own.
template <bool OneRange>
void splitRangeTriangles(Split& s, const Range& part, std::size_t r) {
    const std::size_t count = s.count, largest = s.largest;
    std::vector<Share>& share = s.shares[r];
    std::vector<std::size_t> cursor(count);
    // Per surface, where this range's and the next range's vertices start in it.
    std::vector<std::uint32_t> base(count), nextBase(count, 0);
    for (std::size_t k = 0; k < count; ++k) {
        cursor[k] = 3 * share[k].triangleBase;
        base[k] = static_cast<std::uint32_t>(share[k].vertexBase);
        if (r + 1 < s.parts.size()) nextBase[k] = static_cast<std::uint32_t>(s.shares[r + 1][k].vertexBase);
    }
    std::uint32_t* indices = s.mesh.indices.data();
    const Label* label = s.labels.data();
    const Vertex* vertices = s.mesh.vertices.data();
    std::vector<Surface>& surfaces = s.surfaces;
    const bool compact = s.compact;
    const std::size_t vertexEnd = part.vertexEnd, triangleEnd = part.triangleEnd;
    std::size_t to = 3 * part.triangleBegin;  // where the largest surface's next triangle goes
    // Consecutive triangles mostly lie on one surface: such a run keeps its
    // sums, bases and output in registers, and is measured four triangles at a
    // time where four in a row are on it.
    std::uint32_t runSurface = kNone, own = 0, next = 0;
    std::uint32_t* out = nullptr;  // null for a lone surface, whose triangles stay as they are
    detail::TriangleLanes runSums;
    // A run of surface k begins: its bases, and where its triangles go.
    auto startRun = [&](std::uint32_t k) {
        runSurface = k;
        own = base[k];
        next = nextBase[k];
        if (k != largest) {
            out = surfaces[k].mesh.indices.data() + cursor[k];
        } else {
            out = compact ? indices + to : nullptr;
        }
    };
    auto endRun = [&] {
        share[runSurface].measure.triangles.merge(runSums.total());
        if (runSurface == largest) {
            if (out) to = std::size_t(out - indices);
        } else {
            cursor[runSurface] = std::size_t(out - surfaces[runSurface].mesh.indices.data());
        }
    };
    // The run of the largest surface begins with the settled triangles, in place.
    std::size_t t = measureSettledTriangles(s, part, runSums);
    if (t != part.triangleBegin) {
        to = 3 * t;
        startRun(static_cast<std::uint32_t>(largest));
    }
    while (t < triangleEnd) {
        const std::uint32_t* v = indices + 3 * t;
        const std::uint32_t k = label[v[0]].surface;
        if (k != runSurface) {
            if (runSurface != kNone) endRun();
            runSums = {};
            startRun(k);
        }
        std::size_t run = 1;
        if (t + 4 <= triangleEnd && label[v[3]].surface == k && label[v[6]].surface == k && label[v[9]].surface == k) {
            runSums.addFour(vertices, v);
            run = 4;
        } else {
            runSums.add(vertices[v[0]], vertices[v[1]], vertices[v[2]]);
        }
        if (out) {
            // Read before writing: a compacted triangle may land on its own corners.
            auto remap = [&](auto corners) {
                for (std::size_t i = 0; i < decltype(corners)::value; ++i) {
                    if constexpr (OneRange) {
                        out[i] = label[v[i]].local;
                    } else {
                        out[i] = label[v[i]].local + (v[i] < vertexEnd ? own : next);
                    }
                }
            };
            if (run == 4) {
                remap(std::integral_constant<std::size_t, 12>{});
            } else {
                remap(std::integral_constant<std::size_t, 3>{});
            }
            out += 3 * run;
        }
        t += run;
    }
    if (runSurface != kNone) endRun();
}

void splitTriangles(Split& s) {
    if (s.parts.size() == 1) {
        splitRangeTriangles<true>(s, s.parts[0], 0);
    } else {
        s.forParts([&](const Range& part, std::size_t r) { splitRangeTriangles<false>(s, part, r); });
    }
}

// A range's vertices out to their surfaces, their bounds measured on the way; a
// run of one surface's vertices keeps its bounds in registers (locals, see
// addVertexRun).
void splitRangeVertices(Split& s, const Range& part, std::size_t r) {
    std::vector<Share>& share = s.shares[r];
    std::vector<Surface>& surfaces = s.surfaces;
    const std::size_t largest = s.largest;
    const bool compact = s.compact;
    const Label* const labels = s.labels.data();
    std::size_t to = part.vertexBegin;
    std::uint32_t runSurface = kNone;
    float x0 = 0, y0 = 0, z0 = 0, x1 = 0, y1 = 0, z1 = 0;
    // Where the run's vertices and grid edges go, one after the other (a run's
    // locals are consecutive); null for a lone surface, which stays as it is.
    Vertex* const vertices = s.mesh.vertices.data();
    PackedGridEdge* const edges = s.mesh.vertexEdges.data();
    Vertex* outVertex = nullptr;
    PackedGridEdge* outEdge = nullptr;
    // A run of surface k begins at its vertex `local`: where its vertices go.
    auto startRun = [&](std::uint32_t k, std::uint32_t local) {
        runSurface = k;
        if (k != largest) {
            const std::size_t at = local + share[k].vertexBase;
            outVertex = surfaces[k].mesh.vertices.data() + at;
            outEdge = surfaces[k].mesh.vertexEdges.data() + at;
        } else {
            outVertex = compact ? vertices + to : nullptr;
            outEdge = compact ? edges + to : nullptr;
        }
    };
    auto endRun = [&] {
        addVertexRun(share[runSurface].measure, x0, y0, z0, x1, y1, z1);
        if (runSurface == largest && outVertex) to = std::size_t(outVertex - vertices);
    };
    // Settled vertices stay; the largest surface's run begins with their bounds.
    std::size_t v = part.vertexBegin;
    const std::size_t settledEnd = std::clamp(s.settled, part.vertexBegin, part.vertexEnd);
    if (settledEnd > v) {
        detail::SurfaceMeasure run;
        run.addBounds(vertices + v, settledEnd - v);
        x0 = run.boundsMin[0], y0 = run.boundsMin[1], z0 = run.boundsMin[2];
        x1 = run.boundsMax[0], y1 = run.boundsMax[1], z1 = run.boundsMax[2];
        v = to = settledEnd;
        startRun(static_cast<std::uint32_t>(largest), 0);
    }
    for (; v < part.vertexEnd; ++v) {
        const auto [k, local] = labels[v];
        const Vertex& vertex = vertices[v];
        const PackedGridEdge edge = edges[v];
        const float x = vertex.position[0], y = vertex.position[1], z = vertex.position[2];
        if (k != runSurface) {
            if (runSurface != kNone) endRun();
            startRun(k, local);
            x0 = x1 = x, y0 = y1 = y, z0 = z1 = z;
        }
        x0 = std::min(x0, x), y0 = std::min(y0, y), z0 = std::min(z0, z);
        x1 = std::max(x1, x), y1 = std::max(y1, y), z1 = std::max(z1, z);
        if (outVertex) {
            *outVertex++ = vertex;
            *outEdge++ = edge;
        }
    }
    if (runSurface != kNone) endRun();
}

void splitVertices(Split& s) {
    s.forParts([&](const Range& part, std::size_t r) { splitRangeVertices(s, part, r); });
}

// The largest surface's shares moved next to each other, range by range (a
// share may land on the previous one's old place), the three buffers at once;
// then the mesh is the largest surface's. A lone surface is the mesh as it is.
void compactLargest(Split& s) {
    Mesh& mesh = s.mesh;
    if (s.compact) {
        const SurfaceStats& largest = s.surfaces[s.largest].stats;
        auto moveShares = [&](auto& buffer, bool byTriangle) {
            const std::size_t per = byTriangle ? 3 : 1;  // elements per vertex or triangle
            for (std::size_t r = 1; r < s.parts.size(); ++r) {
                const Share& share = s.shares[r][s.largest];
                const std::size_t from = byTriangle ? s.parts[r].triangleBegin : s.parts[r].vertexBegin;
                const std::size_t to = byTriangle ? share.triangleBase : share.vertexBase;
                const std::size_t moved = byTriangle ? share.triangles : share.vertices;
                if (from == to) continue;  // nothing below it left the largest surface
                std::copy_n(buffer.begin() + std::ptrdiff_t(per * from), per * moved,
                            buffer.begin() + std::ptrdiff_t(per * to));
            }
        };
        detail::parallelFor(3, s.threads, [&](int buffer) {
            if (buffer == 0) moveShares(mesh.vertices, false);
            if (buffer == 1) moveShares(mesh.vertexEdges, false);
            if (buffer == 2) moveShares(mesh.indices, true);
        });
        mesh.vertices.resize(largest.vertices);
        mesh.vertexEdges.resize(largest.vertices);
        mesh.indices.resize(3 * largest.triangles);
    }
    if (s.count > 0) s.surfaces[s.largest].mesh = std::move(mesh);
}

// The shares' measures merged in range order, and every surface's figures.
void measureSurfaces(Split& s) {
    detail::parallelFor(int(s.count), s.threads, [&](int index) {
        const std::size_t k = std::size_t(index);
        detail::SurfaceMeasure measure;
        std::size_t pieces = 0;
        for (const std::vector<Share>& share : s.shares) {
            measure.merge(share[k].measure);
            pieces += share[k].pieces;
        }
        s.surfaces[k].stats = detail::surfaceStats(s.surfaces[k].mesh, measure, s.table == TableKind::Consistent);
        s.surfaces[k].stats.cellsVisited = pieces;
    });
}

// Largest first; equal sizes by their first grid edge in memory order, as trackAllSurfaces.
std::vector<Surface> sortedBySize(Split& s) {
    const std::size_t count = s.count;
    std::vector<Surface>& surfaces = s.surfaces;
    std::vector<std::size_t> triangles(count);
    for (std::size_t k = 0; k < count; ++k) triangles[k] = surfaces[k].stats.triangles;
    std::vector<std::size_t> order(count);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return triangles[a] > triangles[b]; });
    for (std::size_t i = 0; i < count;) {
        std::size_t j = i + 1;
        while (j < count && triangles[order[j]] == triangles[order[i]]) ++j;
        if (j - i > 1) {
            std::vector<std::pair<std::uint64_t, std::size_t>> keyed;
            for (std::size_t k = i; k < j; ++k)
                keyed.push_back({detail::firstEdgeOrder(surfaces[order[k]].mesh, s.dims), order[k]});
            std::sort(keyed.begin(), keyed.end());
            for (std::size_t k = i; k < j; ++k) order[k] = keyed[k - i].second;
        }
        i = j;
    }
    std::vector<Surface> sorted;
    sorted.reserve(count);
    for (std::size_t c : order) sorted.push_back(std::move(surfaces[c]));
    return sorted;
}

}  // namespace

std::vector<Surface> extractAllSurfaces(const Volume& volume, double iso, TableKind table, int threads) {
    std::vector<Surface> surfaces = detail::extractAllSurfaces(volume, iso, table, threads, nullptr);
    volume.throwIfDamaged();  // a mapped file that shrank meanwhile read as zeros
    return surfaces;
}

std::vector<Surface> detail::extractAllSurfaces(const Volume& volume, double iso, TableKind table, int threads,
                                                const std::atomic<bool>* cancel, ExtractProgress* progress) {
    if (table == TableKind::Trilinear) return detail::allTrilinear(volume, iso, threads);
    if (table == TableKind::Snap) return detail::allSnap(volume, iso, threads);
    detail::LabelledMesh labelled = detail::marchLabelled(volume, iso, table, threads, progress);
    if (detail::cancelled(cancel)) return {};
    Split split(labelled, volume, table, threads);
    numberSurfaces(split);
    placeShares(split);
    splitTriangles(split);
    splitVertices(split);
    compactLargest(split);
    measureSurfaces(split);
    return sortedBySize(split);
}

}  // namespace isotrack
