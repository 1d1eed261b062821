#pragma once
// Room extract/measure: the figures of surfaces (isotrack/surface.h): area,
// bounds, enclosed volume and closedness as the walks and the split of every
// surface measure them (this file, and measureSurface in surface_measure.cpp),
// topology (surface_topology.cpp), and the counts over every sample that an
// extraction is measured against (sample_counts.cpp, isotrack/marching_cubes.h).
// Uses extract/common, support/ and the public headers.
//
// Measuring surfaces, shared by the tracker and by the labelled exhaustive pass.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "isotrack/mesh.h"
#include "isotrack/surface.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

// True when the grid edge lies in one of the volume's boundary planes: a surface
// through it is cut open by the border.
inline bool edgeOnVolumeBorder(const GridEdge& e, const Dims& dims) {
    if (e.axis == kCellInterior) return false;  // the trilinear table's vertex inside a cell
    const int p[3] = {e.x, e.y, e.z};
    for (int k = 0; k < 3; ++k) {
        if (k != e.axis && (p[k] == 0 || p[k] == dims[k] - 1)) return true;
    }
    return false;
}

// Grid edges in memory order, to break ties between surfaces the same way everywhere.
inline std::uint64_t edgeOrder(const GridEdge& e, const Dims& dims) {
    return ((std::uint64_t(e.z) * std::uint64_t(dims[1]) + std::uint64_t(e.y)) * std::uint64_t(dims[0]) +
            std::uint64_t(e.x)) *
               3 +
           std::uint64_t(e.axis);
}

// A surface's first grid edge in memory order: equal-sized surfaces are ordered by it.
inline std::uint64_t firstEdgeOrder(const Mesh& mesh, const Dims& dims) {
    std::uint64_t first = std::numeric_limits<std::uint64_t>::max();
    for (const GridEdge e : mesh.vertexEdges) first = std::min(first, edgeOrder(e, dims));
    return first;
}

// Area and signed enclosed volume (divergence theorem), triangle by triangle,
// kept as twice the area and six times the volume so that a triangle costs no
// division.
struct TriangleMeasure {
    friend class TriangleLanes;
    double doubleArea = 0.0, sixfoldVolume = 0.0;

    double area() const { return 0.5 * doubleArea; }
    double signedVolume() const { return sixfoldVolume / 6.0; }
    void merge(const TriangleMeasure& other) {
        doubleArea += other.doubleArea;
        sixfoldVolume += other.sixfoldVolume;
    }

    void add(const Vertex& a, const Vertex& b, const Vertex& c) { addTo(doubleArea, sixfoldVolume, a, b, c); }
    // add, into sums of the caller's own: a loop over many triangles keeps them
    // in registers (in a struct, they go through memory, a store and a load a triangle).
    static void addTo(double& doubledArea, double& sixfoldSignedVolume, const Vertex& a, const Vertex& b,
                      const Vertex& c) {
        float area, volume;
        measure(a, b, c, area, volume);
        doubledArea += double(area);
        sixfoldSignedVolume += double(volume);
    }

    // addTo for the four triangles at indices[0..11], one after the other, in
    // one pass of 4-wide arithmetic: per triangle the same float operations in
    // the same order, so the sums are those of four addTo calls.
    static void addFourTo(double& doubledArea, double& sixfoldSignedVolume, const Vertex* vertices,
                          const std::uint32_t* indices) {
#if defined(__SSE2__)
        __m128 areas4, volumes4;
        measureFour(vertices, indices, areas4, volumes4);
        alignas(16) float areas[4], volumes[4];
        _mm_store_ps(areas, areas4);
        _mm_store_ps(volumes, volumes4);
        for (int i = 0; i < 4; ++i) {
            doubledArea += double(areas[i]);
            sixfoldSignedVolume += double(volumes[i]);
        }
#else
        for (int i = 0; i < 4; ++i) {
            addTo(doubledArea, sixfoldSignedVolume, vertices[indices[3 * i]], vertices[indices[3 * i + 1]],
                  vertices[indices[3 * i + 2]]);
        }
#endif
    }

private:
    // One triangle's twice area and six times signed volume.
    static void measure(const Vertex& a, const Vertex& b, const Vertex& c, float& doubledArea,
                        float& sixfoldSignedVolume) {
#if defined(__SSE2__)
        // A corner's x, y, z and, unused, its normal's x: the same float
        // operations in the same order as below, in half the instructions.
        const __m128 pa = _mm_loadu_ps(a.position), pb = _mm_loadu_ps(b.position), pc = _mm_loadu_ps(c.position);
        const __m128 u = _mm_sub_ps(pb, pa), v = _mm_sub_ps(pc, pa);
        const __m128 n = _mm_sub_ps(_mm_mul_ps(yzx(u), zxy(v)), _mm_mul_ps(zxy(u), yzx(v)));
        doubledArea = _mm_cvtss_f32(_mm_sqrt_ss(_mm_set_ss(sum3(_mm_mul_ps(n, n)))));  // std::sqrt would test for errno
        sixfoldSignedVolume = sum3(_mm_mul_ps(pa, n));
#else
        const float* pa = a.position;
        const float u[3] = {b.position[0] - pa[0], b.position[1] - pa[1], b.position[2] - pa[2]};
        const float v[3] = {c.position[0] - pa[0], c.position[1] - pa[1], c.position[2] - pa[2]};
        const float n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        doubledArea = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        sixfoldSignedVolume = pa[0] * n[0] + pa[1] * n[1] + pa[2] * n[2];
#endif
    }

#if defined(__SSE2__)
    // Lane i: twice the area and six times the signed volume of triangle i of
    // the four at indices[0..11], by measure's float operations.
    static void measureFour(const Vertex* vertices, const std::uint32_t* indices, __m128& doubledAreas,
                            __m128& sixfoldSignedVolumes) {
        // Lane i: triangle i's corner k, as x, y, z rows.
        __m128 x[3], y[3], z[3];
        for (int k = 0; k < 3; ++k) {
            __m128 p0 = _mm_loadu_ps(vertices[indices[k]].position),
                   p1 = _mm_loadu_ps(vertices[indices[3 + k]].position);
            __m128 p2 = _mm_loadu_ps(vertices[indices[6 + k]].position),
                   p3 = _mm_loadu_ps(vertices[indices[9 + k]].position);
            _MM_TRANSPOSE4_PS(p0, p1, p2, p3);
            x[k] = p0, y[k] = p1, z[k] = p2;
        }
        const __m128 ux = _mm_sub_ps(x[1], x[0]), uy = _mm_sub_ps(y[1], y[0]), uz = _mm_sub_ps(z[1], z[0]);
        const __m128 vx = _mm_sub_ps(x[2], x[0]), vy = _mm_sub_ps(y[2], y[0]), vz = _mm_sub_ps(z[2], z[0]);
        const __m128 nx = _mm_sub_ps(_mm_mul_ps(uy, vz), _mm_mul_ps(uz, vy));
        const __m128 ny = _mm_sub_ps(_mm_mul_ps(uz, vx), _mm_mul_ps(ux, vz));
        const __m128 nz = _mm_sub_ps(_mm_mul_ps(ux, vy), _mm_mul_ps(uy, vx));
        const __m128 squared = _mm_add_ps(_mm_add_ps(_mm_mul_ps(nx, nx), _mm_mul_ps(ny, ny)), _mm_mul_ps(nz, nz));
        doubledAreas = _mm_sqrt_ps(squared);
        sixfoldSignedVolumes = _mm_add_ps(_mm_add_ps(_mm_mul_ps(x[0], nx), _mm_mul_ps(y[0], ny)), _mm_mul_ps(z[0], nz));
    }
    static __m128 yzx(__m128 p) { return _mm_shuffle_ps(p, p, _MM_SHUFFLE(3, 0, 2, 1)); }
    static __m128 zxy(__m128 p) { return _mm_shuffle_ps(p, p, _MM_SHUFFLE(3, 1, 0, 2)); }
    // (p0 + p1) + p2.
    static float sum3(__m128 p) {
        const __m128 p1 = _mm_shuffle_ps(p, p, _MM_SHUFFLE(1, 1, 1, 1));
        return _mm_cvtss_f32(_mm_add_ss(_mm_add_ss(p, p1), _mm_movehl_ps(p, p)));
    }
#endif
};

// TriangleMeasure's sums over a run of triangles, with four running sums each,
// one per lane of the four triangles measured at once: consecutive groups' adds
// do not wait on each other, as they do on one running sum (a double add's
// latency per triangle, which bounded splitting every surface). The totals' last
// bits depend on how the triangles were grouped.
class TriangleLanes {
public:
    void addFour(const Vertex* vertices, const std::uint32_t* indices) {
#if defined(__SSE2__)
        __m128 areas, volumes;
        TriangleMeasure::measureFour(vertices, indices, areas, volumes);
        area01_ = _mm_add_pd(area01_, _mm_cvtps_pd(areas));
        area23_ = _mm_add_pd(area23_, _mm_cvtps_pd(_mm_movehl_ps(areas, areas)));
        volume01_ = _mm_add_pd(volume01_, _mm_cvtps_pd(volumes));
        volume23_ = _mm_add_pd(volume23_, _mm_cvtps_pd(_mm_movehl_ps(volumes, volumes)));
#else
        for (int i = 0; i < 4; ++i) {
            float area, volume;
            TriangleMeasure::measure(vertices[indices[3 * i]], vertices[indices[3 * i + 1]],
                                     vertices[indices[3 * i + 2]], area, volume);
            area_[i] += double(area);
            volume_[i] += double(volume);
        }
#endif
    }
    // One triangle, into the first lane.
    void add(const Vertex& a, const Vertex& b, const Vertex& c) {
        float area, volume;
        TriangleMeasure::measure(a, b, c, area, volume);
#if defined(__SSE2__)
        area01_ = _mm_add_sd(area01_, _mm_set_sd(double(area)));
        volume01_ = _mm_add_sd(volume01_, _mm_set_sd(double(volume)));
#else
        area_[0] += double(area);
        volume_[0] += double(volume);
#endif
    }
    // The lanes added up: (0 + 1) + (2 + 3).
    TriangleMeasure total() const {
        double area[4], volume[4];
#if defined(__SSE2__)
        _mm_storeu_pd(area, area01_);
        _mm_storeu_pd(area + 2, area23_);
        _mm_storeu_pd(volume, volume01_);
        _mm_storeu_pd(volume + 2, volume23_);
#else
        std::copy(area_, area_ + 4, area);
        std::copy(volume_, volume_ + 4, volume);
#endif
        TriangleMeasure sums;
        sums.doubleArea = (area[0] + area[1]) + (area[2] + area[3]);
        sums.sixfoldVolume = (volume[0] + volume[1]) + (volume[2] + volume[3]);
        return sums;
    }

private:
#if defined(__SSE2__)
    __m128d area01_ = _mm_setzero_pd(), area23_ = _mm_setzero_pd();
    __m128d volume01_ = _mm_setzero_pd(), volume23_ = _mm_setzero_pd();
#else
    double area_[4] = {}, volume_[4] = {};
#endif
};

// A surface's figures, accumulated vertex by vertex and triangle by triangle.
struct SurfaceMeasure {
    TriangleMeasure triangles;
    float boundsMin[3] = {INFINITY, INFINITY, INFINITY}, boundsMax[3] = {-INFINITY, -INFINITY, -INFINITY};
    bool touchesBorder = false;

    void addVertex(const Vertex& v, const GridEdge& e, const Dims& dims) {
        addBounds(v);
        if (!touchesBorder) touchesBorder = edgeOnVolumeBorder(e, dims);
    }
    // The bounds only, for a tracker that learns touchesBorder otherwise.
    void addBounds(const Vertex& v) {
        for (int k = 0; k < 3; ++k) {
            boundsMin[k] = std::min(boundsMin[k], v.position[k]);
            boundsMax[k] = std::max(boundsMax[k], v.position[k]);
        }
    }
    // addBounds for `count` vertices, in vector registers.
    void addBounds(const Vertex* vertices, std::size_t count) {
#if defined(__SSE2__)
        // A vertex's x, y, z and, ignored, its normal's x. minps(p, lo) is
        // std::min(lo, p) exactly (lo unless p < lo), and maxps likewise.
        __m128 lo = _mm_setr_ps(boundsMin[0], boundsMin[1], boundsMin[2], 0.0f),
               hi = _mm_setr_ps(boundsMax[0], boundsMax[1], boundsMax[2], 0.0f);
        for (std::size_t v = 0; v < count; ++v) {
            const __m128 p = _mm_loadu_ps(vertices[v].position);
            lo = _mm_min_ps(p, lo);
            hi = _mm_max_ps(p, hi);
        }
        alignas(16) float l[4], h[4];
        _mm_store_ps(l, lo);
        _mm_store_ps(h, hi);
        for (int k = 0; k < 3; ++k) boundsMin[k] = l[k], boundsMax[k] = h[k];
#else
        for (std::size_t v = 0; v < count; ++v) addBounds(vertices[v]);
#endif
    }
    void addTriangle(const Vertex* vertices, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        triangles.add(vertices[a], vertices[b], vertices[c]);
    }
    // Adds what another part of the same surface measured.
    void merge(const SurfaceMeasure& other) {
        triangles.merge(other.triangles);
        for (int k = 0; k < 3; ++k) {
            boundsMin[k] = std::min(boundsMin[k], other.boundsMin[k]);
            boundsMax[k] = std::max(boundsMax[k], other.boundsMax[k]);
        }
        touchesBorder = touchesBorder || other.touchesBorder;
    }
};

// Every directed side appears once and so does its reverse: no holes, no
// non-manifold edges, consistent winding (surface_measure.cpp). On `threads`
// threads each takes the sides from a range of vertices; the answer is the same.
bool meshIsClosed(const Mesh& mesh, int threads = 1);

// The figures of a surface from its measure, but for cells visited, time, and
// whether it is closed (known once it is finished: settleClosed).
inline SurfaceStats measuredStats(const Mesh& mesh, const SurfaceMeasure& measure) {
    SurfaceStats stats;
    stats.triangles = mesh.triangleCount();
    stats.vertices = mesh.vertices.size();
    stats.bytes = mesh.byteSize();
    if (!mesh.vertices.empty()) {
        for (int k = 0; k < 3; ++k) {
            stats.boundsMin[k] = measure.boundsMin[k];
            stats.boundsMax[k] = measure.boundsMax[k];
        }
    }
    stats.area = measure.triangles.area();
    stats.touchesBorder = measure.touchesBorder;
    return stats;
}

// Whether a finished surface is closed, and then the volume it encloses. With
// `closedUnlessOnBorder` (the consistent table leaves no holes) a surface is
// closed exactly when the border does not cut it; otherwise every edge is checked.
inline void settleClosed(SurfaceStats& stats, const Mesh& mesh, const SurfaceMeasure& measure,
                         bool closedUnlessOnBorder, int threads = 1) {
    stats.closed = closedUnlessOnBorder ? !stats.touchesBorder && !mesh.indices.empty() : meshIsClosed(mesh, threads);
    if (stats.closed) stats.enclosedVolume = std::abs(measure.triangles.signedVolume());
}

// measuredStats and settleClosed of a finished surface.
inline SurfaceStats surfaceStats(const Mesh& mesh, const SurfaceMeasure& measure, bool closedUnlessOnBorder,
                                 int threads = 1) {
    SurfaceStats stats = measuredStats(mesh, measure);
    settleClosed(stats, mesh, measure, closedUnlessOnBorder, threads);
    return stats;
}

// measureSurface (isotrack/surface.h), its closing check on `threads` threads.
SurfaceStats measureSurfaceOn(const Mesh& mesh, const Volume& volume, bool closedUnlessOnBorder, int threads);
// measureSurfaceOn's figures (no closedUnlessOnBorder) with the vertices and
// triangles cut into one run per thread, measured at once (TriangleLanes) and
// added up in run order: the bounds and closedness are measureSurface's, the
// area's and volume's last bits depend on the number of threads. For a walk on
// several threads, whose triangle order varies anyway.
SurfaceStats measureSurfaceInRuns(const Mesh& mesh, const Volume& volume, int threads);

}  // namespace isotrack::detail
