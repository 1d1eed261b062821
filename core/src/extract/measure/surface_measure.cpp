// measureSurface: a whole mesh's figures, with the measuring the walks and the
// split of every surface do as they go (surface_measure.h), and the closing
// check of a mesh whose closedness its table does not promise (meshIsClosed).
#include "extract/measure/surface_measure.h"

#include <atomic>

#include "isotrack/surface.h"
#include "support/parallel.h"

namespace isotrack::detail {

// The directed sides are grouped by their first vertex (a counting sort) and
// each is looked for among its reverse's group, a handful of neighbours, rather
// than hashed: a large mesh's sides would fill a table far bigger than the caches.
//
// On several threads the vertices are cut into one range per thread, and a
// thread counts, places and checks the sides that start in its range: each
// reads every triangle but writes only its own groups, so no write is shared
// and a group holds its sides in triangle order, as on one thread. Three passes
// (count, place, check), each a parallelFor; the groups' offsets are running
// sums within a range plus the sizes of the ranges before it.
bool meshIsClosed(const Mesh& mesh, int threads) {
    if (mesh.indices.empty()) return false;
    const std::uint32_t* indices = mesh.indices.data();
    const std::size_t sideCount = mesh.indices.size(), vertexCount = mesh.vertices.size();
    const int ranges = int(std::clamp<std::size_t>(vertexCount, 1, std::size_t(std::max(threads, 1))));
    auto rangeBegin = [&](int r) { return vertexCount * std::size_t(r) / std::size_t(ranges); };
    // Vertex v's sides: to[first[v] .. first[v + 1]). The range [b, e) writes first[b + 1 .. e].
    std::vector<std::size_t> first(vertexCount + 1, 0), rangeSides(std::size_t(ranges), 0);
    parallelFor(ranges, threads, [&](int r) {
        const std::size_t b = rangeBegin(r), span = rangeBegin(r + 1) - b;
        std::size_t* sidesAfter = first.data() + 1;  // sidesAfter[v] = first[v + 1]
        for (std::size_t i = 0; i < sideCount; ++i) {
            if (std::size_t(indices[i]) - b < span) ++sidesAfter[indices[i]];  // wraps below b
        }
        std::size_t running = 0;
        for (std::size_t v = b; v < b + span; ++v) running = sidesAfter[v] += running;
        rangeSides[std::size_t(r)] = running;
    });
    std::vector<std::size_t> rangeOffset(std::size_t(ranges), 0);
    for (std::size_t r = 1; r < rangeOffset.size(); ++r) rangeOffset[r] = rangeOffset[r - 1] + rangeSides[r - 1];
    std::vector<std::uint32_t> to(sideCount);
    std::vector<std::size_t> end(vertexCount);
    parallelFor(ranges, threads, [&](int r) {
        const std::size_t b = rangeBegin(r), span = rangeBegin(r + 1) - b, offset = rangeOffset[std::size_t(r)];
        for (std::size_t v = b; v < b + span; ++v) first[v + 1] += offset;
        if (span > 0) end[b] = offset;  // first[b], which the range before writes
        for (std::size_t v = b + 1; v < b + span; ++v) end[v] = first[v];
        auto place = [&](std::uint32_t from, std::uint32_t next) {
            if (std::size_t(from) - b < span) to[end[from]++] = next;
        };
        for (std::size_t i = 0; i < sideCount; i += 3) {
            place(indices[i], indices[i + 1]);
            place(indices[i + 1], indices[i + 2]);
            place(indices[i + 2], indices[i]);
        }
    });
    std::atomic<bool> open{false};
    parallelFor(ranges, threads, [&](int r) {
        for (std::size_t v = rangeBegin(r); v < rangeBegin(r + 1); ++v) {
            if (open.load(std::memory_order_relaxed)) return;
            const auto group = to.begin() + std::ptrdiff_t(first[v]),
                       groupEnd = to.begin() + std::ptrdiff_t(first[v + 1]);
            for (auto a = group; a < groupEnd; ++a) {
                const std::uint32_t w = *a;
                const auto reverse = to.begin() + std::ptrdiff_t(first[w]),
                           reverseEnd = to.begin() + std::ptrdiff_t(first[w + 1]);
                // The side v -> w twice, or no side w -> v.
                if (std::find(a + 1, groupEnd, w) != groupEnd ||
                    std::find(reverse, reverseEnd, std::uint32_t(v)) == reverseEnd) {
                    open.store(true, std::memory_order_relaxed);
                    return;
                }
            }
        }
    });
    return !open.load();
}

SurfaceStats measureSurfaceOn(const Mesh& mesh, const Volume& volume, bool closedUnlessOnBorder, int threads) {
    SurfaceMeasure measure;
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        measure.addVertex(mesh.vertices[v], mesh.vertexEdges[v], volume.dims());
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        measure.addTriangle(mesh.vertices.data(), mesh.indices[3 * t], mesh.indices[3 * t + 1],
                            mesh.indices[3 * t + 2]);
    }
    return surfaceStats(mesh, measure, closedUnlessOnBorder, threads);
}

SurfaceStats measureSurfaceInRuns(const Mesh& mesh, const Volume& volume, int threads) {
    const int runs = std::max(threads, 1);
    const std::size_t vertexCount = mesh.vertices.size(), triangleCount = mesh.triangleCount();
    std::vector<SurfaceMeasure> measures(static_cast<std::size_t>(runs));
    parallelFor(runs, threads, [&](int r) {
        SurfaceMeasure& measure = measures[std::size_t(r)];
        const std::size_t vBegin = vertexCount * std::size_t(r) / std::size_t(runs),
                          vEnd = vertexCount * std::size_t(r + 1) / std::size_t(runs);
        measure.addBounds(mesh.vertices.data() + vBegin, vEnd - vBegin);
        for (std::size_t v = vBegin; v < vEnd && !measure.touchesBorder; ++v)
            measure.touchesBorder = edgeOnVolumeBorder(mesh.vertexEdges[v], volume.dims());
        const std::size_t tBegin = triangleCount * std::size_t(r) / std::size_t(runs),
                          tEnd = triangleCount * std::size_t(r + 1) / std::size_t(runs);
        TriangleLanes lanes;
        std::size_t t = tBegin;
        for (; t + 4 <= tEnd; t += 4) lanes.addFour(mesh.vertices.data(), mesh.indices.data() + 3 * t);
        for (; t < tEnd; ++t) {
            lanes.add(mesh.vertices[mesh.indices[3 * t]], mesh.vertices[mesh.indices[3 * t + 1]],
                      mesh.vertices[mesh.indices[3 * t + 2]]);
        }
        measure.triangles = lanes.total();
    });
    SurfaceMeasure measure;
    for (const SurfaceMeasure& part : measures) measure.merge(part);
    return surfaceStats(mesh, measure, false, threads);
}

}  // namespace isotrack::detail

namespace isotrack {

SurfaceStats measureSurface(const Mesh& mesh, const Volume& volume, bool closedUnlessOnBorder) {
    return detail::measureSurfaceOn(mesh, volume, closedUnlessOnBorder, 1);
}

}  // namespace isotrack
