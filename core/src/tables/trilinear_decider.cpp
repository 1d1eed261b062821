// The trilinear table's classifier: which subcase a cube's samples make.
//
// Faces (Nielson & Hamann 1991, the asymptotic decider): on a face whose
// diagonal corners alternate, the bilinear interpolant's saddle lies above the
// isovalue, joining the corners above, exactly when the product of the values
// (minus the isovalue) at the corners above is at least the product at the
// corners below. The test reads only the face's four samples and is symmetric
// in them, so both cubes sharing a face decide it alike.
//
// Interior (the tunnels of Chernyaev's MC33 and Lewiner et al.'s interior
// test): whether two regions of one sign, apart on the cube's boundary, meet
// inside the cube. Planes z = t cut the trilinear interpolant into bilinear
// ones whose corner values are linear in t. Their topology changes only where
// a corner value or the saddle condition g0 g2 - g1 g3 crosses zero (at most
// four roots and two), so between those values of t one plane stands for all:
// its regions, each holding at least one of the plane's corners, carry on into
// the next interval through the corners they share. Joining the regions of
// successive intervals, and the cube's corners to the first and last, groups
// the cube's corners by the regions of the solid cube they lie in, exactly.
#include <algorithm>
#include <cmath>
#include <vector>

#include "isotrack/cube.h"
#include "isotrack/trilinear.h"

namespace isotrack {
namespace {

bool aboveBit(std::uint8_t config, int vertex) { return (config >> vertex) & 1u; }

// Inside the set of one sign: value >= 0 for the corners above, < 0 below.
bool inside(double value, bool sign) { return sign ? value >= 0.0 : value < 0.0; }

// Regions of a plane with corner values g (cyclic order) on the side `sign`,
// as masks of the corners they hold.
std::array<unsigned, 2> planeRegions(const double g[4], bool sign, int& count) {
    unsigned in = 0;
    for (int k = 0; k < 4; ++k) in |= unsigned(inside(g[k], sign)) << k;
    count = 0;
    std::array<unsigned, 2> regions{};
    if (in == 0) return regions;
    if (in == 5u || in == 10u) {
        // Opposite corners: joined when the saddle is on their side.
        const double products = g[0] * g[2] - g[1] * g[3];
        const bool joined = (in == 5u) == (products >= 0.0);
        if (joined) {
            regions[count++] = in;
        } else {
            regions[count++] = in & 3u ? in & 3u : in & 12u;
            regions[count++] = in & ~regions[0];
        }
        return regions;
    }
    regions[count++] = in;  // any other set of corners is connected along the square's sides
    return regions;
}

int root(std::array<int, 24>& parent, int v) {
    while (parent[std::size_t(v)] != v) v = parent[std::size_t(v)] = parent[std::size_t(parent[std::size_t(v)])];
    return v;
}

// The values of t in (0, 1) where the planes' topology may change, sorted, with 0 and 1.
std::vector<double> criticalHeights(const double f[8]) {
    std::vector<double> t{0.0, 1.0};
    auto add = [&](double r) {
        if (r > 0.0 && r < 1.0) t.push_back(r);
    };
    double a[4], d[4];
    for (int k = 0; k < 4; ++k) {
        a[k] = f[k];
        d[k] = f[k + 4] - f[k];
        if (d[k] != 0.0) add(-a[k] / d[k]);
    }
    // (a0 + d0 t)(a2 + d2 t) - (a1 + d1 t)(a3 + d3 t) = q2 t^2 + q1 t + q0
    const double q2 = d[0] * d[2] - d[1] * d[3];
    const double q1 = a[0] * d[2] + a[2] * d[0] - a[1] * d[3] - a[3] * d[1];
    const double q0 = a[0] * a[2] - a[1] * a[3];
    if (q2 == 0.0) {
        if (q1 != 0.0) add(-q0 / q1);
    } else {
        const double disc = q1 * q1 - 4.0 * q2 * q0;
        if (disc >= 0.0) {
            const double s = std::sqrt(disc);
            add((-q1 - s) / (2.0 * q2));
            add((-q1 + s) / (2.0 * q2));
        }
    }
    std::sort(t.begin(), t.end());
    t.erase(std::unique(t.begin(), t.end()), t.end());
    return t;
}

// Per corner, the smallest corner of the same sign in the same region of the solid cube.
std::array<int, 8> solidRegions(const double f[8], std::uint8_t config) {
    const std::vector<double> t = criticalHeights(f);
    std::array<int, 8> region{};
    for (bool sign : {true, false}) {
        // Nodes 0..7: the cube's corners; 8 + 2 * interval + r: plane regions.
        std::array<int, 24> parent{};
        for (int v = 0; v < 24; ++v) parent[std::size_t(v)] = v;
        auto join = [&](int a, int b) {
            const int ra = root(parent, a), rb = root(parent, b);
            parent[std::size_t(std::max(ra, rb))] = std::min(ra, rb);
        };
        std::array<unsigned, 2> previous{};
        int previousCount = 0, previousNode = 0;
        const int intervals = int(t.size()) - 1;
        for (int i = 0; i < intervals; ++i) {
            const double mid = 0.5 * (t[std::size_t(i)] + t[std::size_t(i) + 1]);
            double g[4];
            for (int k = 0; k < 4; ++k) g[k] = f[k] + mid * (f[k + 4] - f[k]);
            int count = 0;
            const std::array<unsigned, 2> regions = planeRegions(g, sign, count);
            const int node = 8 + 2 * i;
            for (int r = 0; r < count; ++r) {
                for (int p = 0; p < previousCount; ++p) {
                    if (regions[std::size_t(r)] & previous[std::size_t(p)]) join(node + r, previousNode + p);
                }
                for (int k = 0; k < 4; ++k) {
                    if (!(regions[std::size_t(r)] >> k & 1u)) continue;
                    if (i == 0 && aboveBit(config, k) == sign) join(k, node + r);
                    if (i + 1 == intervals && aboveBit(config, k + 4) == sign) join(k + 4, node + r);
                }
            }
            previous = regions;
            previousCount = count;
            previousNode = node;
        }
        for (int v = 0; v < 8; ++v) {
            if (aboveBit(config, v) == sign) region[std::size_t(v)] = root(parent, v);
        }
    }
    return region;
}

}  // namespace

std::uint8_t decideFaces(const double values[8], std::uint8_t config) {
    std::uint8_t joined = 0;
    const std::uint8_t ambiguous = ambiguousFaces(config);
    for (int f = 0; f < cube::kFaceCount; ++f) {
        if (!(ambiguous >> f & 1u)) continue;
        const auto& fv = cube::faceVertices(f);
        const int k = aboveBit(config, fv[0]) ? 0 : 1;  // fv[k], fv[k + 2] are above
        const double up = values[fv[k]] * values[fv[k + 2]], down = values[fv[k + 1]] * values[fv[(k + 3) % 4]];
        if (up >= down) joined = static_cast<std::uint8_t>(joined | 1u << f);
    }
    return joined;
}

const TrilinearCase& classifyTrilinear(const double values[8], std::uint8_t config) {
    const TrilinearTable& table = trilinearTable();
    const std::uint8_t joined = decideFaces(values, config);
    const TrilinearCase* subcases = table.begin(config, joined);
    const int count = table.count(config, joined);
    if (count == 1) return subcases[0];
    for (int k = 0; k < 8; ++k) {
        if (!std::isfinite(values[k])) return subcases[0];
    }
    const std::array<int, 8> solid = solidRegions(values, config);
    for (int s = 1; s < count; ++s) {
        const auto& tunnel = subcases[s].tunnel;
        if (solid[std::size_t(tunnel[0])] == solid[std::size_t(tunnel[1])]) return subcases[s];
    }
    return subcases[0];
}

}  // namespace isotrack
