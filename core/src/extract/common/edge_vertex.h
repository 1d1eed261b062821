#pragma once
// Vertex placement shared by every extractor, so that an edge crossed by the
// surface yields the same vertex whichever algorithm visits it.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "isotrack/mesh.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

// A threshold in the samples' own type with (sample >= value) exactly when
// (double(sample) >= iso), so classification runs on native values in vector
// registers. `all`/`none` cover isovalues outside the type's range.
template <class T>
struct NativeThreshold {
    T value{};
    bool all = false, none = false;

    explicit NativeThreshold(double iso) {
        if constexpr (std::is_integral_v<T>) {
            const double c = std::ceil(iso);
            if (c <= double(std::numeric_limits<T>::min())) {
                all = true;
            } else if (c > double(std::numeric_limits<T>::max())) {
                none = true;
            } else {
                value = static_cast<T>(c);
            }
        } else if constexpr (std::is_same_v<T, float>) {
            float f = static_cast<float>(iso);
            if (double(f) < iso) f = std::nextafter(f, std::numeric_limits<float>::infinity());
            value = f;
        } else {
            value = static_cast<T>(iso);
        }
    }
};

template <class T>
class SampleGrid {
public:
    SampleGrid(const Volume& volume, const T* samples, double iso)
        : samples_(samples),
          nx_(volume.dims()[0]),
          ny_(volume.dims()[1]),
          nz_(volume.dims()[2]),
          strideY_(std::size_t(nx_)),
          strideZ_(std::size_t(nx_) * std::size_t(ny_)),
          spacing_(volume.spacing()),
          origin_(volume.origin()),
          iso_(iso),
          threshold_(iso) {
        for (int k = 0; k < 3; ++k) halfInverseSpacing_[k] = 0.5 / spacing_[k];
        strides_ = {1, strideY_, strideZ_};
        const int size[3] = {nx_, ny_, nz_};
        for (int a = 0; a < 3; ++a) {
            for (int k = 0; k < 3; ++k)
                interiorSpan_[std::size_t(a)][std::size_t(k)] = unsigned(std::max(0, size[k] - 2 - (a == k)));
        }
    }

    int nx() const { return nx_; }
    int ny() const { return ny_; }
    int nz() const { return nz_; }
    std::size_t strideY() const { return strideY_; }
    std::size_t strideZ() const { return strideZ_; }
    std::size_t index(int x, int y, int z) const {
        return std::size_t(x) + strideY_ * std::size_t(y) + strideZ_ * std::size_t(z);
    }
    double iso() const { return iso_; }
    double at(std::size_t i) const { return static_cast<double>(samples_[i]); }
    // The one classification rule of isotrack, VTK's: a sample at or above the
    // isovalue is above; everything else, NaN included, is below.
    // Compared in the samples' own type (NativeThreshold keeps the two equal).
    bool above(std::size_t i) const { return threshold_.all || (!threshold_.none && samples_[i] >= threshold_.value); }

    // The configuration of the cell whose first corner is sample i: bit k set
    // when the cube's corner k is above (corners in isotrack's cube order).
    std::uint8_t cellConfig(std::size_t i) const {
        if (threshold_.all || threshold_.none) return threshold_.all ? 255 : 0;
        const T* s = samples_ + i;
        const T t = threshold_.value;
        const std::size_t sy = strideY_, sz = strideZ_;
#if defined(__SSE2__)
        // The cell's four rows of two samples side by side in one register, in
        // cube order (the rows at y + 1 run from x + 1 back to x), compared at once.
        if constexpr (std::is_same_v<T, std::int16_t> || std::is_same_v<T, std::uint16_t>) {
            auto pair = [](const T* at) {
                std::int32_t bits;
                std::memcpy(&bits, at, sizeof bits);
                return bits;
            };
            __m128i v = _mm_setr_epi32(pair(s), pair(s + sy), pair(s + sz), pair(s + sy + sz));
            v = _mm_shufflehi_epi16(_mm_shufflelo_epi16(v, _MM_SHUFFLE(2, 3, 1, 0)), _MM_SHUFFLE(2, 3, 1, 0));
            // Unsigned samples compare as signed once both sides have their top bit flipped.
            const int flip = std::is_same_v<T, std::uint16_t> ? 0x8000 : 0;
            v = _mm_xor_si128(v, _mm_set1_epi16(static_cast<short>(flip)));
            // t > the type's lowest value (NativeThreshold sets `all` otherwise), so t - 1 does not wrap.
            const __m128i below = _mm_set1_epi16(static_cast<short>((int(t) - 1) ^ flip));
            const __m128i above = _mm_cmpgt_epi16(v, below);
            return static_cast<std::uint8_t>(_mm_movemask_epi8(_mm_packs_epi16(above, above)));
        } else if constexpr (std::is_same_v<T, float>) {
            // Two floats in the low half (an unaligned 64-bit load).
            auto row = [](const T* at) {
                return _mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(at)));
            };
            const __m128 lower = _mm_movelh_ps(row(s), row(s + sy)),
                         upper = _mm_movelh_ps(row(s + sz), row(s + sy + sz));
            const __m128 threshold = _mm_set1_ps(t);
            // x, x + 1, then x + 1, x at y + 1; NaN compares false, as below.
            const int low =
                _mm_movemask_ps(_mm_cmpge_ps(_mm_shuffle_ps(lower, lower, _MM_SHUFFLE(2, 3, 1, 0)), threshold));
            const int high =
                _mm_movemask_ps(_mm_cmpge_ps(_mm_shuffle_ps(upper, upper, _MM_SHUFFLE(2, 3, 1, 0)), threshold));
            return static_cast<std::uint8_t>(low | high << 4);
        }
#endif
        const unsigned c = unsigned(s[0] >= t) | unsigned(s[1] >= t) << 1 | unsigned(s[1 + sy] >= t) << 2 |
                           unsigned(s[sy] >= t) << 3 | unsigned(s[sz] >= t) << 4 | unsigned(s[1 + sz] >= t) << 5 |
                           unsigned(s[1 + sy + sz] >= t) << 6 | unsigned(s[sy + sz] >= t) << 7;
        return static_cast<std::uint8_t>(c);
    }

    // flags[i] = above(begin + i) for `count` samples.
    void classify(std::size_t begin, std::size_t count, std::uint8_t* flags) const {
        if (threshold_.all || threshold_.none) {
            std::fill(flags, flags + count, std::uint8_t(threshold_.all));
            return;
        }
        const T* samples = samples_ + begin;
        const T t = threshold_.value;
        for (std::size_t i = 0; i < count; ++i) flags[i] = samples[i] >= t;
    }

    // The vertex where the surface crosses the edge from sample (x, y, z) one
    // step along `axis`, written straight into `v` (a mesh's buffer: assembling
    // it elsewhere and copying it stalls on the partial stores).
    // (Out of line: inlined, it crowds the hot loops that call it, which make
    // most of their vertices inside through interiorEdgeVertex.)
    [[gnu::noinline]] void edgeVertex(int x, int y, int z, int axis, Vertex& v) const {
        switch (axis) {
            case 0: edgeVertexAlong<0>(x, y, z, v); return;
            case 1: edgeVertexAlong<1>(x, y, z, v); return;
            default: edgeVertexAlong<2>(x, y, z, v); return;
        }
    }

    // Whether both ends of the edge from (x, y, z) along `Axis` have their six
    // neighbours in the volume: one unsigned compare per axis.
    template <int Axis>
    bool edgeInterior(int x, int y, int z) const {
        const auto& span = interiorSpan_[Axis];
        return unsigned(x - 1) < span[0] && unsigned(y - 1) < span[1] && unsigned(z - 1) < span[2];
    }

    // edgeVertex for an edge along `Axis` from sample `a` = (x, y, z) whose two
    // ends have all six neighbours in the volume, without the tests on the axis
    // and the border. Trackers call it once they know the edge is inside.
    template <int Axis>
    void interiorEdgeVertex(std::size_t a, int x, int y, int z, Vertex& v) const {
        const std::size_t b = a + stride<Axis>();
        double ga[3], gb[3];
        interiorGradient(a, ga);
        interiorGradient(b, gb);
        vertexOnEdge<Axis>(x, y, z, a, b, ga, gb, v);
    }

    // edgeInterior and interiorEdgeVertex for an axis known only at run time:
    // one path for the three axes, without a branch on the axis that the walk
    // of a tracker, meeting edges of every axis in turn, mispredicts. The same
    // operations in the same order, so the same vertex.
    bool edgeInterior(int axis, int x, int y, int z) const {
        const auto& span = interiorSpan_[std::size_t(axis)];
        return unsigned(x - 1) < span[0] && unsigned(y - 1) < span[1] && unsigned(z - 1) < span[2];
    }
    void interiorEdgeVertex(int axis, std::size_t a, int x, int y, int z, Vertex& v) const {
        const std::size_t b = a + strides_[std::size_t(axis)];
        double ga[3], gb[3];
        interiorGradient(a, ga);
        interiorGradient(b, gb);
        vertexOnEdge(axis, x, y, z, a, b, ga, gb, v);
    }

    // Central-difference gradient in world units; one-sided on the border.
    void gradient(int x, int y, int z, double g[3]) const {
        if (x > 0 && y > 0 && z > 0 && x + 1 < nx_ && y + 1 < ny_ && z + 1 < nz_) {
            interiorGradient(index(x, y, z), g);
            return;
        }
        borderGradient(x, y, z, g);
    }

    [[gnu::always_inline]] void interiorGradient(std::size_t i, double g[3]) const {
        g[0] = difference(i + 1, i - 1) * halfInverseSpacing_[0];
        g[1] = difference(i + strideY_, i - strideY_) * halfInverseSpacing_[1];
        g[2] = difference(i + strideZ_, i - strideZ_) * halfInverseSpacing_[2];
    }

    void borderGradient(int x, int y, int z, double g[3]) const {
        const int p[3] = {x, y, z};
        const int n[3] = {nx_, ny_, nz_};
        const std::size_t stride[3] = {1, strideY_, strideZ_};
        const std::size_t i = index(x, y, z);
        for (int k = 0; k < 3; ++k) {
            if (n[k] < 2) {
                g[k] = 0.0;
                continue;
            }
            const std::size_t lo = p[k] > 0 ? i - stride[k] : i;
            const std::size_t hi = p[k] < n[k] - 1 ? i + stride[k] : i;
            const int span = (p[k] > 0) + (p[k] < n[k] - 1);
            g[k] = (at(hi) - at(lo)) / (span * spacing_[k]);
        }
    }

private:
    template <int Axis>
    std::size_t stride() const {
        return Axis == 0 ? 1 : Axis == 1 ? strideY_ : strideZ_;
    }

    // at(hi) - at(lo), exactly: samples of up to 32 bits are subtracted as
    // integers (their difference, below 2^33, is a double without rounding, as
    // the difference of the two doubles is), which saves converting both.
    [[gnu::always_inline]] double difference(std::size_t hi, std::size_t lo) const {
        if constexpr (std::is_integral_v<T> && sizeof(T) <= 4) {
            return static_cast<double>(std::int64_t(samples_[hi]) - std::int64_t(samples_[lo]));
        } else {
            return at(hi) - at(lo);
        }
    }

    template <int Axis>
    void edgeVertexAlong(int x, int y, int z, Vertex& v) const {
        const std::size_t a = index(x, y, z);
        const std::size_t b = a + stride<Axis>();
        const int ex = x + (Axis == 0), ey = y + (Axis == 1), ez = z + (Axis == 2);
        double ga[3], gb[3];
        if (edgeInterior<Axis>(x, y, z)) {
            interiorGradient(a, ga);
            interiorGradient(b, gb);
        } else {
            gradient(x, y, z, ga);
            gradient(ex, ey, ez, gb);
        }
        vertexOnEdge<Axis>(x, y, z, a, b, ga, gb, v);
    }

    // The vertex on the edge from sample a = (x, y, z) to sample b along `Axis`,
    // given the gradients at both ends: the one place vertex floats are made.
    template <int Axis>
    [[gnu::always_inline]] void vertexOnEdge(int x, int y, int z, std::size_t a, std::size_t b, const double ga[3],
                                             const double gb[3], Vertex& v) const {
        vertexOnEdge(Axis, x, y, z, a, b, ga, gb, v);
    }

    [[gnu::always_inline]] void vertexOnEdge(int axis, int x, int y, int z, std::size_t a, std::size_t b,
                                             const double ga[3], const double gb[3], Vertex& v) const {
        const double va = at(a), vb = at(b);
        double t = (iso_ - va) / (vb - va);
        if (!(t >= 0.0 && t <= 1.0)) t = 0.5;  // non-finite samples: keep the vertex on the edge

        double p[3] = {origin_[0] + x * spacing_[0], origin_[1] + y * spacing_[1], origin_[2] + z * spacing_[2]};
        p[axis] += t * spacing_[axis];
        const double n[3] = {-(ga[0] + t * (gb[0] - ga[0])), -(ga[1] + t * (gb[1] - ga[1])),
                             -(ga[2] + t * (gb[2] - ga[2]))};
        const double length2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
        for (int k = 0; k < 3; ++k) v.position[k] = static_cast<float>(p[k]);
        if (length2 > 0.0 && std::isfinite(length2)) {
            const double inverse = 1.0 / std::sqrt(length2);
            for (int k = 0; k < 3; ++k) v.normal[k] = static_cast<float>(n[k] * inverse);
        } else {
            // Flat or non-finite neighbourhood: point along the edge, from above to below.
            for (int k = 0; k < 3; ++k) v.normal[k] = 0.0f;
            v.normal[axis] = above(a) ? 1.0f : -1.0f;
        }
    }

    const T* samples_;
    int nx_, ny_, nz_;
    std::size_t strideY_, strideZ_;
    Vec3d spacing_, origin_;
    double halfInverseSpacing_[3];
    std::array<std::size_t, 3> strides_{};  // per axis, the step between samples
    double iso_;
    NativeThreshold<T> threshold_;
    // Per edge axis and coordinate, the count of origins p with 0 < p and p + 1
    // (p + 2 along the edge) < the volume's size (edgeInterior).
    std::array<std::array<unsigned, 3>, 3> interiorSpan_{};
};

}  // namespace isotrack::detail
