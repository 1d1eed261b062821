// Decimation through meshoptimizer (Debian's libmeshoptimizer-dev, 0.18):
// meshopt_simplify collapses edges in order of their quadric error (Garland and
// Heckbert) until the index count reaches the target or the next collapse would
// exceed the error bound; vertices at equal positions are collapsed together, so
// the seams of coincident vertices isotrack's zero-area triangles leave do not
// open. meshopt_SimplifyLockBorder keeps the vertices on the mesh's border
// where they are, so a surface the volume cut keeps its outline and a closed
// one stays closed. The kept triangles index a subset of the vertices; the
// unused ones are dropped, the rest keep their order and grid edges. Collapses
// can leave a triangle over three vertices on one line (the snap table's grid
// points); it is flipped away (flip.h).
#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "isotrack/errors.h"
#include "isotrack/mesh_processing.h"
#include "mesh/flip.h"
#include "mesh/manifold.h"
#include "mesh/near_surface.h"
#include "mesh/weld.h"

namespace isotrack {
namespace {

// Rounds of meshopt_simplify: its quadric error underestimates how far a thin
// bone's rim or spike moves when collapsed (the planes around it barely
// change), so after each round the result is checked against the input both
// ways (holdStrayTriangles), and the input's triangles where it fails are held
// back; the next round starts again from the input. meshoptimizer 0.18 locks
// border vertices only, so holding a triangle back locks its corners: they
// are then on the simplified part's border, kept, and the triangle fits back
// unchanged. Rounds go on until one holds back nothing new, when the result
// stands checked: each round holds at least one more triangle, so they end.
// The skull takes 3 to 6 rounds, the Marschner-Lobb field 12; past
// kMaxRounds the input is kept as it is rather than a result that strays.
constexpr int kMaxRounds = 64;

// meshoptimizer's bound, as a share of the error bound the check holds: its
// collapses then stop short of the bound in most places, so the triangles held
// back for the rest do not push them further in the next round (with the
// whole bound, each round strayed elsewhere: 25% of the snapped skull after 8
// rounds, against 10.7% here).
constexpr double kQuadricShare = 0.72;

std::vector<std::uint32_t> simplifyRound(const Mesh& mesh, const std::vector<char>& held, std::size_t targetTriangles,
                                         float relativeError) {
    std::vector<std::uint32_t> free, kept;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t* corner = &mesh.indices[3 * t];
        (held[t] ? kept : free).insert((held[t] ? kept : free).end(), corner, corner + 3);
    }
    const std::size_t heldTriangles = kept.size() / 3;
    const std::size_t target = targetTriangles > heldTriangles ? 3 * (targetTriangles - heldTriangles) : 0;
    std::vector<std::uint32_t> simplified(free.size());
    simplified.resize(meshopt_simplify(simplified.data(), free.data(), free.size(), mesh.vertices.front().position,
                                       mesh.vertices.size(), sizeof(Vertex), target, relativeError,
                                       meshopt_SimplifyLockBorder, nullptr));
    kept.insert(kept.end(), simplified.begin(), simplified.end());
    return kept;
}

double length(const float* p, const float* q) {
    double sum = 0.0;
    for (int a = 0; a < 3; ++a) sum += (double(p[a]) - q[a]) * (double(p[a]) - q[a]);
    return std::sqrt(sum);
}

struct Corner {
    float p[3];
    double distance;  // an upper bound of its distance to the other surface
};

// Whether triangle abc lies within `bound` of `other`. The distance to a
// surface changes no faster than the point moves, and every point of a
// triangle lies within its longest side over sqrt(3) of a corner (some side
// subtends at least 120 degrees there), so the triangle passes when its
// farthest corner plus that is within the bound; otherwise it is split in four
// at its sides' midpoints (each midpoint's distance the first found within
// half the bound, or the exact one), down to sides of a 64th of the bound,
// where one that still cannot pass fails: within the bound, perhaps, but not
// shown to be. So does one that has taken kPieceBudget pieces: a bound small
// against the triangle would take (side / bound)^2 of them (at a hundredth of
// a voxel, minutes for a small sphere), where a triangle within a bound of
// its own size needs tens, along the places where it comes near the bound.
constexpr int kPieceBudget = 1024;
bool withinBound(const Corner& a, const Corner& b, const Corner& c, const detail::NearSurface& other, double bound,
                 int& budget) {
    const double farthest = std::max({a.distance, b.distance, c.distance});
    if (farthest > bound) return false;
    const double side = std::max({length(a.p, b.p), length(b.p, c.p), length(c.p, a.p)});
    if (farthest + side / std::sqrt(3.0) <= bound) return true;
    if (side < bound / 64.0 || --budget < 0) return false;
    auto middle = [&](const Corner& p, const Corner& q) {
        Corner m{};
        for (int k = 0; k < 3; ++k) m.p[k] = 0.5f * (p.p[k] + q.p[k]);
        m.distance = other.distanceBound(m.p, bound / 2.0);
        return m;
    };
    const Corner ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
    if (std::max({ab.distance, bc.distance, ca.distance}) > bound) return false;  // before any piece
    return withinBound(a, ab, ca, other, bound, budget) && withinBound(ab, b, bc, other, bound, budget) &&
           withinBound(ca, bc, c, other, bound, budget) && withinBound(ab, bc, ca, other, bound, budget);
}
bool withinBound(const Corner& a, const Corner& b, const Corner& c, const detail::NearSurface& other, double bound) {
    int budget = kPieceBudget;
    return withinBound(a, b, c, other, bound, budget);
}

// Triangles by corner: the triangles of vertex v at list[first[v] ..
// first[v + 1]).
struct Fans {
    Fans(const std::uint32_t* indices, std::size_t count, std::size_t vertices)
        : corners(indices), first(vertices + 1, 0), list(count) {
        for (std::size_t i = 0; i < count; ++i) ++first[indices[i] + 1];
        for (std::size_t v = 0; v + 1 < first.size(); ++v) first[v + 1] += first[v];
        std::vector<std::uint32_t> fill(first.begin(), first.end() - 1);
        for (std::size_t i = 0; i < count; ++i) list[fill[indices[i]]++] = std::uint32_t(i / 3);
    }
    // Whether one of the triangles has the corners of `triangle` (in any order).
    bool holds(const std::uint32_t* triangle) const {
        std::array<std::uint32_t, 3> want{triangle[0], triangle[1], triangle[2]};
        std::sort(want.begin(), want.end());
        for (std::uint32_t i = first[triangle[0]]; i < first[triangle[0] + 1]; ++i) {
            const std::uint32_t* t = corners + 3 * std::size_t(list[i]);
            std::array<std::uint32_t, 3> have{t[0], t[1], t[2]};
            std::sort(have.begin(), have.end());
            if (have == want) return true;
        }
        return false;
    }
    const std::uint32_t* corners;  // the triangles' (kept by the caller)
    std::vector<std::uint32_t> first, list;
};

// Holds back the input's triangles where the result strays farther than
// maxError from the input. An input triangle with a point too far from the
// result (withinBound: a bound on every point, not a sample) is held itself:
// it stays, and its corners with it, while the rest of its corners' fans may
// still collapse. A result triangle not shown within maxError of the input
// (withinBound again; its corners are the input's vertices, on it) holds the
// input's triangles around its corners: holding the corners alone would leave
// the same triangle. False when none: the result stands.
bool holdStrayTriangles(const Mesh& mesh, const std::vector<std::uint32_t>& kept, const detail::NearSurface& original,
                        const Fans& fans, double maxError, std::vector<char>& held) {
    bool holding = false;
    const detail::NearSurface result(mesh.vertices, kept, maxError);
    auto at = [&](std::uint32_t v) { return mesh.vertices[v].position; };
    std::vector<double> toResult(mesh.vertices.size(), -1.0);
    auto corner = [&](std::uint32_t v) {
        if (toResult[v] < 0.0) toResult[v] = result.distanceBound(at(v), maxError / 4.0);
        Corner c{};
        std::copy(at(v), at(v) + 3, c.p);
        c.distance = toResult[v];
        return c;
    };
    // First, cheaply: a vertex within maxError less its fan's longest side over
    // sqrt(3) of the result clears its fan's triangles (withinBound's test).
    std::vector<double> fanSide(mesh.vertices.size(), 0.0);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        const double side =
            std::max({length(at(v[0]), at(v[1])), length(at(v[1]), at(v[2])), length(at(v[2]), at(v[0]))});
        for (int k = 0; k < 3; ++k) fanSide[v[k]] = std::max(fanSide[v[k]], side);
    }
    std::vector<char> clear(mesh.vertices.size(), 0);
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        const double radius = maxError - fanSide[v] / std::sqrt(3.0);
        clear[v] = radius > 0.0 && result.near(at(std::uint32_t(v)), radius);
    }
    // A triangle in both lies within any bound of the other mesh: with a small
    // bound, proving it point by point would take (side / bound)^2 pieces.
    const Fans resultFans(kept.data(), kept.size(), mesh.vertices.size());
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        if (held[t] || (clear[v[0]] && clear[v[1]] && clear[v[2]]) || resultFans.holds(v)) continue;
        if (withinBound(corner(v[0]), corner(v[1]), corner(v[2]), result, maxError)) continue;
        held[t] = 1;
        holding = true;
    }
    for (std::size_t t = 0; t < kept.size() / 3; ++t) {
        const std::uint32_t* v = &kept[3 * t];
        auto onInput = [&](std::uint32_t i) {  // a vertex of the input's triangles: at distance 0
            Corner c{};
            std::copy(at(i), at(i) + 3, c.p);
            return c;
        };
        if (fans.holds(v) || withinBound(onInput(v[0]), onInput(v[1]), onInput(v[2]), original, maxError)) continue;
        for (int k = 0; k < 3; ++k)
            for (std::uint32_t i = fans.first[v[k]]; i < fans.first[v[k] + 1]; ++i) {
                holding = holding || !held[fans.list[i]];
                held[fans.list[i]] = 1;
            }
    }
    return holding;
}

}  // namespace

void decimateMesh(Mesh& mesh, double ratio, std::optional<double> maxError) {
    if (!(ratio >= 0.0 && ratio <= 1.0))
        throw InputError("decimate: ratio " + std::to_string(ratio) + " is outside [0, 1]");
    if (ratio == 0.0 && !maxError) throw InputError("decimate: ratio 0 needs an error bound");
    if (maxError && !(*maxError >= 0.0))
        throw InputError("decimate: error " + std::to_string(*maxError) + " is negative");
    detail::weldCoincidentVertices(mesh);
    if (mesh.indices.empty()) return;
    const float* positions = mesh.vertices.front().position;
    const std::size_t target = std::size_t(double(mesh.triangleCount()) * ratio);
    // meshoptimizer's error is relative to the mesh's extent.
    float relativeError = std::numeric_limits<float>::max();
    if (maxError) {
        const float scale = meshopt_simplifyScale(positions, mesh.vertices.size(), sizeof(Vertex));
        relativeError = scale > 0.0f ? float(kQuadricShare * *maxError / double(scale)) : 0.0f;
    }
    std::vector<char> held(mesh.triangleCount(), 0);
    std::vector<std::uint32_t> kept;
    const std::vector<std::uint32_t> input(mesh.indices.begin(), mesh.indices.end());
    std::optional<detail::NearSurface> original;
    std::optional<Fans> fans;
    if (maxError) {
        original.emplace(mesh.vertices, input, *maxError);
        fans.emplace(input.data(), input.size(), mesh.vertices.size());
    }
    bool strays = false;
    for (int round = 0; round < kMaxRounds; ++round) {
        kept = simplifyRound(mesh, held, target, relativeError);
        detail::removeFins(kept);  // a thin part collapsed into fins is gone: hold it too
        strays = maxError && holdStrayTriangles(mesh, kept, *original, *fans, *maxError, held);
        if (!strays) break;
    }
    if (strays) kept = input;  // never checked within the bound
    mesh.indices.assign(kept.begin(), kept.end());
    detail::dropUnusedVertices(mesh);
    detail::removeFinsAndSplitPinches(mesh);
    detail::flipZeroAreaTriangles(mesh);
    recomputeNormals(mesh);
}

}  // namespace isotrack
