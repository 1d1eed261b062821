// Generation of the trilinear table (isotrack/trilinear.h).
//
// For each configuration and each way of deciding its ambiguous faces:
//  1. segments: on every face, the crossed edges are joined in pairs. On an
//     ambiguous face the corners on the side the decision keeps apart are cut
//     off one by one (the corners above when they are separated, the corners
//     below when those above are joined). Each segment is oriented so that,
//     seen from outside the cube, the corners above lie on its right; the
//     segments then chain into oriented loops, and a triangle that follows a
//     loop faces down the gradient, as every isotrack table does.
//  2. regions: the cube's corners grouped by sign and by connection over the
//     decided faces; each loop separates a region above from one below.
//  3. subcases: without a tunnel, each loop bounds a disk. For two regions of
//     one sign next to the same region of the other sign, one subcase joins
//     them with a tunnel bounded by the two loops between them.
//  4. triangles: a disk is fanned from the first corner whose fan draws no chord
//     between two edges of one cube face (the cube across the face could draw it
//     too, and the edge would then have four triangles), preferring fans that
//     face down the gradient; failing that, from the interior vertex. A tunnel is
//     the shortest band between its loops with no such chord (a dynamic
//     programme over the two loops, as in contour stitching).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "isotrack/cube.h"
#include "isotrack/trilinear.h"

namespace isotrack {
namespace {

using Vec = std::array<double, 3>;
using Loop = std::vector<int>;
using Triangle = std::array<int, 3>;

bool above(std::uint8_t config, int vertex) { return (config >> vertex) & 1u; }

Vec edgeMidpoint(int edge) {
    if (edge >= kInteriorVertex) return {0.5, 0.5, 0.5};  // a vertex inside the cube, roughly
    const auto& a = cube::kVertexOffset[cube::kEdgeVertices[edge][0]];
    const auto& b = cube::kVertexOffset[cube::kEdgeVertices[edge][1]];
    return {(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0, (a[2] + b[2]) / 2.0};
}

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& u, const Vec& v) {
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}
double dot(const Vec& u, const Vec& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

bool shareFace(int a, int b) {
    if (a >= kInteriorVertex || b >= kInteriorVertex) return false;
    for (int f = 0; f < cube::kFaceCount; ++f) {
        if (cube::edgeOnFace(a, f) && cube::edgeOnFace(b, f)) return true;
    }
    return false;
}

// The segment from edge a to edge b on `face`, cutting off `corner` (or, for a
// segment across the face, any corner), turned so the corners above lie on its
// right seen from outside.
std::pair<int, int> orientSegment(std::uint8_t config, int face, int a, int b, int corner) {
    Vec normal{0, 0, 0};
    normal[std::size_t(cube::faceAxis(face))] = cube::faceSide(face) ? 1.0 : -1.0;
    const Vec from = edgeMidpoint(a);
    const Vec left = cross(normal, sub(edgeMidpoint(b), from));
    Vec p{};
    for (int k = 0; k < 3; ++k) p[std::size_t(k)] = cube::kVertexOffset[std::size_t(corner)][std::size_t(k)];
    const double side = dot(left, sub(p, from));
    if (side == 0.0) throw std::logic_error("trilinear: a face corner lies on a segment");
    return (side < 0.0) == above(config, corner) ? std::make_pair(a, b) : std::make_pair(b, a);
}

std::vector<std::pair<int, int>> faceSegments(std::uint8_t config, std::uint8_t faceJoined, int face) {
    const auto& fv = cube::faceVertices(face);
    const auto& fe = cube::faceEdges(face);  // fe[k] joins fv[k] and fv[k+1]
    std::vector<int> crossed;
    for (int k = 0; k < 4; ++k) {
        if (above(config, fv[k]) != above(config, fv[(k + 1) % 4])) crossed.push_back(k);
    }
    std::vector<std::pair<int, int>> segments;
    if (crossed.size() == 2) {
        const int k0 = crossed[0], k1 = crossed[1];
        // Adjacent crossed edges cut off the corner between them.
        int corner = fv[0];
        if ((k0 + 1) % 4 == k1) corner = fv[k1];
        if ((k1 + 1) % 4 == k0) corner = fv[k0];
        segments.push_back(orientSegment(config, face, fe[k0], fe[k1], corner));
    } else if (crossed.size() == 4) {
        const bool cutAbove = !(faceJoined >> face & 1u);
        for (int k = 0; k < 4; ++k) {
            if (above(config, fv[k]) != cutAbove) continue;
            segments.push_back(orientSegment(config, face, fe[(k + 3) % 4], fe[k], fv[k]));
        }
    }
    return segments;
}

std::vector<Loop> boundaryLoops(std::uint8_t config, std::uint8_t faceJoined) {
    std::array<int, 12> next;
    next.fill(-1);
    for (int f = 0; f < cube::kFaceCount; ++f) {
        for (const auto& [a, b] : faceSegments(config, faceJoined, f)) {
            if (next[a] != -1) throw std::logic_error("trilinear: an edge starts two segments");
            next[a] = b;
        }
    }
    std::vector<Loop> loops;
    std::array<bool, 12> used{};
    for (int start = 0; start < 12; ++start) {
        if (used[start] || next[start] < 0) continue;
        Loop loop;
        for (int e = start; !used[e]; e = next[e]) {
            if (next[e] < 0) throw std::logic_error("trilinear: an open loop");
            used[e] = true;
            loop.push_back(e);
        }
        loops.push_back(loop);
    }
    return loops;
}

int findRoot(std::array<int, 8>& parent, int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

// Per corner, the smallest corner of its region on the cube's boundary.
std::array<int, 8> boundaryRegions(std::uint8_t config, std::uint8_t faceJoined) {
    std::array<int, 8> parent{};
    for (int v = 0; v < 8; ++v) parent[v] = v;
    auto join = [&](int a, int b) {
        const int ra = findRoot(parent, a), rb = findRoot(parent, b);
        parent[std::max(ra, rb)] = std::min(ra, rb);
    };
    for (int f = 0; f < cube::kFaceCount; ++f) {
        const auto& fv = cube::faceVertices(f);
        int changes = 0;
        for (int k = 0; k < 4; ++k) {
            if (above(config, fv[k]) == above(config, fv[(k + 1) % 4])) {
                join(fv[k], fv[(k + 1) % 4]);
            } else {
                ++changes;
            }
        }
        if (changes == 4) {
            // The diagonal whose corners are above joins when the face says so; the other otherwise.
            const bool joinAbove = faceJoined >> f & 1u;
            const int k = above(config, fv[0]) == joinAbove ? 0 : 1;
            join(fv[k], fv[k + 2]);
        }
    }
    std::array<int, 8> region{};
    for (int v = 0; v < 8; ++v) region[v] = findRoot(parent, v);
    return region;
}

// The regions above and below on either side of a loop.
std::pair<int, int> loopSides(std::uint8_t config, const std::array<int, 8>& region, const Loop& loop) {
    int up = -1, down = -1;
    for (int e : loop) {
        int a = cube::kEdgeVertices[e][0], b = cube::kEdgeVertices[e][1];
        if (!above(config, a)) std::swap(a, b);
        if (up >= 0 && (up != region[a] || down != region[b]))
            throw std::logic_error("trilinear: a loop between several regions");
        up = region[a];
        down = region[b];
    }
    return {up, down};
}

double facing(std::uint8_t config, const Triangle& t) {
    const Vec a = edgeMidpoint(t[0]);
    const Vec n = cross(sub(edgeMidpoint(t[1]), a), sub(edgeMidpoint(t[2]), a));
    double sum = 0.0;
    for (int corner : t) {
        int from = cube::kEdgeVertices[corner][0], to = cube::kEdgeVertices[corner][1];
        if (!above(config, from)) std::swap(from, to);
        Vec d{};
        for (int k = 0; k < 3; ++k)
            d[std::size_t(k)] = cube::kVertexOffset[to][std::size_t(k)] - cube::kVertexOffset[from][std::size_t(k)];
        sum += dot(n, d);
    }
    return sum;
}

// A fan of the loop from a corner, or none when every fan draws a chord on a face.
std::vector<Triangle> diskFan(std::uint8_t config, const Loop& loop) {
    const std::size_t n = loop.size();
    std::vector<Triangle> fallback;
    for (std::size_t start = 0; start < n; ++start) {
        std::vector<Triangle> fan;
        bool clean = true, facingDown = true;
        for (std::size_t k = 1; k + 1 < n && clean; ++k) {
            if (k >= 2) clean = !shareFace(loop[start], loop[(start + k) % n]);
            const Triangle t{loop[start], loop[(start + k) % n], loop[(start + k + 1) % n]};
            facingDown = facingDown && facing(config, t) > 0.0;
            fan.push_back(t);
        }
        if (clean && facingDown) return fan;
        if (clean && fallback.empty()) fallback = fan;
    }
    return fallback;
}

// A band between loops a and b, the tunnel: a chain of chords (a_i, b_j), b walked
// backwards, each step a triangle that advances along one loop. A chord may not
// join two edges of one face; where the loops cannot be joined without one, a
// run of the chain passes through the interior vertex instead (a chord a_i - c -
// b_j). The run is one, and the chain starts and ends on a direct chord, so the
// interior vertex is a manifold vertex of the band.
class TunnelBand {
public:
    TunnelBand(const Loop& a, const Loop& b, int aStart, int bStart, int centre)
        : a_(a), b_(b), aStart_(aStart), bStart_(bStart), centre_(centre) {}

    // The cheapest band, or an empty one when there is none; sets usesInterior.
    std::vector<Triangle> build(bool& usesInterior) {
        const int na = int(a_.size()), nb = int(b_.size());
        const std::size_t states = std::size_t(3 * (na + 1) * (nb + 1));
        cost_.assign(states, kNone);
        from_.assign(states, -1);
        if (!direct(0, 0)) return {};
        cost_[state(0, 0, 0)] = length(0, 0);
        for (int i = 0; i <= na; ++i) {
            for (int j = 0; j <= nb; ++j) {
                for (int mode = 0; mode < 3; ++mode) relaxFrom(mode, i, j);
            }
        }
        int end = state(0, na, nb);
        if (cost_[std::size_t(state(2, na, nb))] < cost_[std::size_t(end)]) end = state(2, na, nb);
        if (cost_[std::size_t(end)] == kNone) return {};
        bestCost_ = cost_[std::size_t(end)];
        std::vector<Triangle> triangles;
        usesInterior = false;
        for (int s = end; from_[std::size_t(s)] >= 0; s = from_[std::size_t(s)]) {
            emitStep(from_[std::size_t(s)], s, triangles);
            usesInterior = usesInterior || modeOf(s) != 0 || modeOf(from_[std::size_t(s)]) != 0;
        }
        return triangles;
    }

    double cost() const { return bestCost_; }

private:
    static constexpr double kNone = std::numeric_limits<double>::infinity();

    int ea(int i) const { return a_[std::size_t((aStart_ + i) % int(a_.size()))]; }
    int eb(int j) const {
        const int nb = int(b_.size());
        return b_[std::size_t(((bStart_ - j) % nb + nb) % nb)];
    }
    bool direct(int i, int j) const { return !shareFace(ea(i), eb(j)); }
    double length(int i, int j) const {
        const Vec d = sub(edgeMidpoint(ea(i)), edgeMidpoint(eb(j)));
        return std::sqrt(dot(d, d));
    }
    double through(int i, int j) const {
        const Vec centre{0.5, 0.5, 0.5};
        const Vec u = sub(edgeMidpoint(ea(i)), centre), v = sub(edgeMidpoint(eb(j)), centre);
        return std::sqrt(dot(u, u)) + std::sqrt(dot(v, v)) + 1.0;  // direct chords are preferred
    }
    int state(int mode, int i, int j) const { return (mode * (int(a_.size()) + 1) + i) * (int(b_.size()) + 1) + j; }
    int modeOf(int s) const { return s / ((int(a_.size()) + 1) * (int(b_.size()) + 1)); }
    int iOf(int s) const { return s / (int(b_.size()) + 1) % (int(a_.size()) + 1); }
    int jOf(int s) const { return s % (int(b_.size()) + 1); }

    void relax(int from, int to, double step) {
        const double c = cost_[std::size_t(from)] + step;
        if (c < cost_[std::size_t(to)]) {
            cost_[std::size_t(to)] = c;
            from_[std::size_t(to)] = from;
        }
    }

    // A chain that runs once round a loop against a single corner of the other
    // meets its first chord again: the chain leaves its first chord along a and
    // reaches its last along b, and never stands at (a's end, b's start). Any
    // band can be started where it does so.
    void relaxFrom(int mode, int i, int j) {
        const int s = state(mode, i, j);
        if (cost_[std::size_t(s)] == kNone) return;
        const int na = int(a_.size()), nb = int(b_.size());
        const bool moreA = i < na && !(i + 1 == na && (j == 0 || j == nb)), moreB = j < nb && !(i == 0 && j == 0);
        if (mode != 1) {
            if (moreA && direct(i + 1, j)) relax(s, state(mode, i + 1, j), length(i + 1, j));
            if (moreB && direct(i, j + 1)) relax(s, state(mode, i, j + 1), length(i, j + 1));
        }
        // Into (or along) the run through the interior vertex. It neither leaves
        // the first chord nor comes back at a loop's end, so it never meets a
        // corner twice.
        if (mode == 1 || (mode == 0 && (i > 0 || j > 0))) {
            if (moreA) relax(s, state(1, i + 1, j), through(i + 1, j));
            if (moreB) relax(s, state(1, i, j + 1), through(i, j + 1));
        }
        if (mode == 1 && i < na && j < nb && direct(i, j)) relax(s, state(2, i, j), length(i, j));
    }

    void emitStep(int from, int to, std::vector<Triangle>& out) const {
        const int fm = modeOf(from), tm = modeOf(to), i = iOf(from), j = jOf(from);
        if (fm == 1 && tm == 2) {
            out.push_back({ea(i), eb(j), centre_});  // back to a direct chord
            return;
        }
        if (fm != 1 && tm == 1) out.push_back({eb(j), ea(i), centre_});  // into the run
        const int far = tm == 1 ? centre_ : -1;
        if (iOf(to) > i) {
            out.push_back({ea(i), ea(i + 1), far >= 0 ? far : eb(j)});
        } else {
            out.push_back({eb(j + 1), eb(j), far >= 0 ? far : ea(i)});
        }
    }

    const Loop& a_;
    const Loop& b_;
    int aStart_, bStart_, centre_;
    std::vector<double> cost_;
    std::vector<int> from_;
    double bestCost_ = kNone;
};

// The cheapest band over every pair of starting corners.
std::vector<Triangle> tunnelBand(const Loop& a, const Loop& b, int centre, bool& usesInterior) {
    std::vector<Triangle> best;
    double bestCost = std::numeric_limits<double>::infinity();
    for (int i = 0; i < int(a.size()); ++i) {
        for (int j = 0; j < int(b.size()); ++j) {
            bool interior = false;
            TunnelBand band(a, b, i, j, centre);
            std::vector<Triangle> triangles = band.build(interior);
            if (!triangles.empty() && band.cost() < bestCost) {
                best = triangles;
                bestCost = band.cost();
                usesInterior = interior;
            }
        }
    }
    return best;
}

void addTriangles(const std::vector<Triangle>& triangles, TrilinearCase& out) {
    for (const Triangle& t : triangles) {
        if (out.triangleCount >= kMaxTrilinearTriangles)
            throw std::logic_error("trilinear: too many triangles in a subcase");
        auto& slot = out.triangles[out.triangleCount++];
        for (int k = 0; k < 3; ++k) slot[std::size_t(k)] = static_cast<std::int8_t>(t[std::size_t(k)]);
    }
}

std::uint16_t edgeMask(const Loop& loop) {
    std::uint16_t mask = 0;
    for (int e : loop) mask = static_cast<std::uint16_t>(mask | 1u << e);
    return mask;
}

// A new interior vertex of the subcase, as its corner index.
int addInterior(TrilinearCase& out, std::uint16_t around, int anchor) {
    if (out.interiorCount >= kMaxInteriorVertices) throw std::logic_error("trilinear: too many interior vertices");
    out.interior[out.interiorCount] = {around, static_cast<std::int8_t>(anchor)};
    return kInteriorVertex + out.interiorCount++;
}

void addDisk(std::uint8_t config, const Loop& loop, TrilinearCase& out) {
    std::vector<Triangle> fan = diskFan(config, loop);
    if (fan.empty()) {
        const int centre = addInterior(out, edgeMask(loop), -1);
        for (std::size_t k = 0; k < loop.size(); ++k) fan.push_back({loop[k], loop[(k + 1) % loop.size()], centre});
    }
    addTriangles(fan, out);
}

// A tunnel between loops a and b: a direct band, or one through an interior
// vertex, or else a ring of interior vertices, one per corner of a, halfway
// between a and the tunnel's middle: a band from a to the ring, then one from
// the ring (whose chords never lie on a face) to b.
void addTunnel(const Loop& a, const Loop& b, TrilinearCase& out) {
    const std::uint16_t both = static_cast<std::uint16_t>(edgeMask(a) | edgeMask(b));
    bool interior = false;
    std::vector<Triangle> band = tunnelBand(a, b, kInteriorVertex + out.interiorCount, interior);
    if (!band.empty()) {
        if (interior) addInterior(out, both, -1);
        addTriangles(band, out);
        return;
    }
    Loop ring;
    for (int e : a) ring.push_back(addInterior(out, both, e));
    const std::size_t n = a.size();
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t next = (i + 1) % n;
        band.push_back({a[i], a[next], ring[next]});
        band.push_back({a[i], ring[next], ring[i]});
    }
    const std::vector<Triangle> rest = tunnelBand(ring, b, -1, interior);
    if (rest.empty() || interior) throw std::logic_error("trilinear: no band from a ring to a loop");
    band.insert(band.end(), rest.begin(), rest.end());
    addTriangles(band, out);
}

TrilinearCase buildSubcase(std::uint8_t config, std::uint8_t faceJoined, const std::vector<Loop>& loops, int tunnelA,
                           int tunnelB) {
    TrilinearCase out;
    out.config = config;
    out.faceJoined = faceJoined;
    out.loopCount = static_cast<std::uint8_t>(loops.size());
    out.pieceCount = static_cast<std::uint8_t>(loops.size() - (tunnelA >= 0 ? 1 : 0));
    if (tunnelA >= 0) {
        // The ring, if any, goes round the shorter loop.
        const Loop& a = loops[std::size_t(tunnelA)];
        const Loop& b = loops[std::size_t(tunnelB)];
        if (a.size() <= b.size()) {
            addTunnel(a, b, out);
        } else {
            addTunnel(b, a, out);
        }
    }
    for (std::size_t l = 0; l < loops.size(); ++l) {
        if (int(l) != tunnelA && int(l) != tunnelB) addDisk(config, loops[l], out);
    }
    return out;
}

// The subcases of one configuration with its faces decided: no tunnel first.
std::vector<TrilinearCase> subcases(std::uint8_t config, std::uint8_t faceJoined) {
    const std::vector<Loop> loops = boundaryLoops(config, faceJoined);
    std::vector<TrilinearCase> out{buildSubcase(config, faceJoined, loops, -1, -1)};
    const std::array<int, 8> region = boundaryRegions(config, faceJoined);
    std::vector<std::pair<int, int>> sides;
    for (const Loop& loop : loops) sides.push_back(loopSides(config, region, loop));
    for (std::size_t i = 0; i < loops.size(); ++i) {
        for (std::size_t j = i + 1; j < loops.size(); ++j) {
            // Two loops around one region: the regions beyond them may meet inside.
            int first = -1, second = -1;
            if (sides[i].first == sides[j].first) first = sides[i].second, second = sides[j].second;
            if (sides[i].second == sides[j].second) first = sides[i].first, second = sides[j].first;
            if (first < 0 || first == second) continue;
            TrilinearCase subcase;
            try {
                subcase = buildSubcase(config, faceJoined, loops, int(i), int(j));
            } catch (const std::logic_error&) {
                continue;  // no tunnel can be drawn between these loops: the subcase is left out (the tests show none
                           // is met)
            }
            subcase.tunnel = {static_cast<std::int8_t>(std::min(first, second)),
                              static_cast<std::int8_t>(std::max(first, second))};
            out.push_back(subcase);
        }
    }
    return out;
}

}  // namespace

std::uint8_t ambiguousFaces(std::uint8_t config) {
    std::uint8_t mask = 0;
    for (int f = 0; f < cube::kFaceCount; ++f) {
        const auto& fv = cube::faceVertices(f);
        const bool a = above(config, fv[0]);
        if (above(config, fv[1]) != a && above(config, fv[2]) == a && above(config, fv[3]) != a)
            mask = static_cast<std::uint8_t>(mask | 1u << f);
    }
    return mask;
}

TrilinearTable::TrilinearTable() {
    for (int c = 0; c < 256; ++c) {
        const auto config = static_cast<std::uint8_t>(c);
        const std::uint8_t ambiguous = ambiguousFaces(config);
        for (int joined = 0; joined < 64; ++joined) {
            if (joined & ~ambiguous) continue;
            const std::size_t at = index(config, static_cast<std::uint8_t>(joined));
            const std::vector<TrilinearCase> found = subcases(config, static_cast<std::uint8_t>(joined));
            first_[at] = static_cast<std::uint16_t>(cases_.size());
            count_[at] = static_cast<std::uint8_t>(found.size());
            cases_.insert(cases_.end(), found.begin(), found.end());
        }
    }
}

const TrilinearTable& trilinearTable() {
    static const TrilinearTable table;
    return table;
}

}  // namespace isotrack
