// Windowed-sinc smoothing: G. Taubin, T. Zhang and G. Golub, "Optimal surface
// smoothing as filter design" (IBM RC-20404, 1996), as VTK's
// vtkWindowedSincPolyDataFilter documents it.
//
// With K = I - W, W the umbrella operator (each free vertex moved to the mean
// of its neighbours), a mesh's coordinates are filtered by a polynomial f(K)
// of degree N (the iterations). In the variable k in [0, 2] the ideal low-pass
// filter is 1 below the pass band k_pb and 0 above; with k = 1 - cos(theta) it is
// a step in theta at theta_pb = acos(1 - k_pb / 2), whose cosine series has the
// Chebyshev coefficients
//     c_0 = (theta_pb + s) / pi,  c_i = 2 sin(i (theta_pb + s)) / (i pi)
// (s an offset, below), windowed (Nuttall, VTK's default window) to damp the
// Gibbs ripple. The polynomial is evaluated by the Chebyshev recurrence in
// x = 1 - k / 2, one application of K per step:
//   1. adjacency: the mesh's edges; vertices on edges of one triangle (the
//      border) or of more than two (non-manifold) are fixed.
//   2. normalize: centre the coordinates on their bounds and divide by the
//      bounds' diagonal (VTK's NormalizeCoordinates), in double precision.
//   3. coefficients: c_i w_i, with the offset s found by Newton's method so that
//      f(k_pb) = 1: the pass band, the overall shape and its volume, goes
//      through unscaled (a window alone would shrink or swell it slightly).
//   4. iterate: x_1 = x_0 - K x_0 / 2, x_{n+1} = 2 x_n - K x_n - x_{n-1};
//      the result is sum c_i w_i x_i.
//   5. restore the coordinates, put the fixed vertices back.
//   6. bound: a vertex that moved farther than the tolerance from where it was
//      is pulled back along its move to that distance (the idea of Gibson's
//      constrained elastic surface nets, 1998: a smoothed surface from a volume
//      should stay within the data's resolution). Each smoothed triangle is
//      then the original triangle's corners each moved at most that far, so
//      every point of either mesh lies within the tolerance of the other (the
//      Hausdorff distance is at most the tolerance). Normals are recomputed.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "isotrack/errors.h"
#include "isotrack/mesh_processing.h"
#include "mesh/mesh_edges.h"

namespace isotrack {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Each vertex's neighbours in compressed rows; a fixed vertex has none.
struct Neighbours {
    std::vector<std::uint32_t> first;  // vertex v's: ids[first[v] .. first[v + 1])
    std::vector<std::uint32_t> ids;
};

Neighbours freeNeighbours(const Mesh& mesh) {
    const std::size_t n = mesh.vertices.size();
    const std::vector<detail::EdgeUse> edges = detail::meshEdges(mesh.indices.data(), mesh.triangleCount());
    std::vector<char> fixed(n, 0);
    for (const detail::EdgeUse& e : edges)
        if (e.triangles != 2) fixed[e.a] = fixed[e.b] = 1;
    Neighbours out;
    out.first.assign(n + 1, 0);
    for (const detail::EdgeUse& e : edges) {
        if (!fixed[e.a]) ++out.first[e.a + 1];
        if (!fixed[e.b]) ++out.first[e.b + 1];
    }
    for (std::size_t v = 0; v < n; ++v) out.first[v + 1] += out.first[v];
    out.ids.resize(out.first[n]);
    std::vector<std::uint32_t> fill(out.first.begin(), out.first.end() - 1);
    for (const detail::EdgeUse& e : edges) {
        if (!fixed[e.a]) out.ids[fill[e.a]++] = e.b;
        if (!fixed[e.b]) out.ids[fill[e.b]++] = e.a;
    }
    return out;
}

// The windowed coefficients c_i w_i, i = 0 .. iterations.
std::vector<double> filterCoefficients(int iterations, double passband) {
    const int n = iterations;
    std::vector<double> window(std::size_t(n) + 1), c(std::size_t(n) + 1);
    for (int i = 0; i <= n; ++i) {
        const double a = double(i) * kPi / double(n + 1);
        window[std::size_t(i)] =
            0.355768 + 0.487396 * std::cos(a) + 0.144232 * std::cos(2 * a) + 0.012604 * std::cos(3 * a);
    }
    const double thetaPass = std::acos(1.0 - 0.5 * passband);
    auto coefficients = [&](double theta) {
        c[0] = window[0] * theta / kPi;
        for (int i = 1; i <= n; ++i) c[std::size_t(i)] = window[std::size_t(i)] * 2.0 * std::sin(i * theta) / (i * kPi);
    };
    // f(k_pb) = sum c_i cos(i theta_pb), and its derivative in the cut-off theta.
    double theta = thetaPass;
    for (int step = 0; step < 100; ++step) {
        coefficients(theta);
        double f = 0.0, slope = window[0] / kPi;
        for (int i = 0; i <= n; ++i) f += c[std::size_t(i)] * std::cos(i * thetaPass);
        for (int i = 1; i <= n; ++i)
            slope += window[std::size_t(i)] * 2.0 * std::cos(i * theta) / kPi * std::cos(i * thetaPass);
        if (std::abs(f - 1.0) < 1e-12 || slope == 0.0) break;
        theta = std::clamp(theta - (f - 1.0) / slope, 0.0, kPi);
    }
    coefficients(theta);
    return c;
}

using Points = std::vector<std::array<double, 3>>;

// out = 2 x - K x - previous for free vertices (out = x_1's form when previous is null).
void chebyshevStep(const Neighbours& nb, const Points& x, const Points* previous, Points& out) {
    for (std::size_t v = 0; v + 1 < nb.first.size(); ++v) {
        const std::uint32_t begin = nb.first[v], end = nb.first[v + 1];
        std::array<double, 3> mean{0, 0, 0};
        for (std::uint32_t j = begin; j < end; ++j)
            for (int a = 0; a < 3; ++a) mean[a] += x[nb.ids[j]][a];
        for (int a = 0; a < 3; ++a) {
            const double laplacian = begin == end ? 0.0 : x[v][a] - mean[a] / double(end - begin);  // K x
            out[v][a] = previous ? 2.0 * x[v][a] - laplacian - (*previous)[v][a] : x[v][a] - 0.5 * laplacian;
        }
    }
}

}  // namespace

void smoothMesh(Mesh& mesh, int iterations, double passband, double tolerance) {
    if (iterations < 1) throw InputError("smooth: iterations " + std::to_string(iterations) + " is not positive");
    if (!(passband > 0.0 && passband < 2.0))
        throw InputError("smooth: pass band " + std::to_string(passband) + " is outside (0, 2)");
    if (!(tolerance > 0.0)) throw InputError("smooth: tolerance " + std::to_string(tolerance) + " is not positive");
    const std::size_t n = mesh.vertices.size();
    if (n == 0) return;
    const Neighbours nb = freeNeighbours(mesh);

    std::array<double, 3> lo{}, hi{};
    for (int a = 0; a < 3; ++a) lo[a] = hi[a] = mesh.vertices[0].position[a];
    for (const Vertex& v : mesh.vertices)
        for (int a = 0; a < 3; ++a)
            lo[a] = std::min(lo[a], double(v.position[a])), hi[a] = std::max(hi[a], double(v.position[a]));
    const std::array<double, 3> centre{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
    double length = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                              (hi[2] - lo[2]) * (hi[2] - lo[2]));
    if (length == 0.0) length = 1.0;

    Points x0(n), x1(n), x2(n), sum(n);
    for (std::size_t v = 0; v < n; ++v)
        for (int a = 0; a < 3; ++a) x0[v][a] = (double(mesh.vertices[v].position[a]) - centre[a]) / length;
    const std::vector<double> c = filterCoefficients(iterations, passband);
    chebyshevStep(nb, x0, nullptr, x1);
    for (std::size_t v = 0; v < n; ++v)
        for (int a = 0; a < 3; ++a) sum[v][a] = c[0] * x0[v][a] + c[1] * x1[v][a];
    for (int i = 2; i <= iterations; ++i) {
        chebyshevStep(nb, x1, &x0, x2);
        for (std::size_t v = 0; v < n; ++v)
            for (int a = 0; a < 3; ++a) sum[v][a] += c[std::size_t(i)] * x2[v][a];
        std::swap(x0, x1);
        std::swap(x1, x2);
    }
    for (std::size_t v = 0; v < n; ++v) {
        if (nb.first[v] == nb.first[v + 1]) continue;  // fixed, or on no edge
        float* p = mesh.vertices[v].position;
        std::array<double, 3> target{}, move{};
        for (int a = 0; a < 3; ++a) {
            target[a] = sum[v][a] * length + centre[a];
            move[a] = target[a] - double(p[a]);
        }
        const double distance = std::sqrt(move[0] * move[0] + move[1] * move[1] + move[2] * move[2]);
        // Pulled back a little inside, so that float rounding cannot carry it past.
        if (distance > tolerance)
            for (int a = 0; a < 3; ++a) target[a] = double(p[a]) + tolerance * (1.0 - 1e-6) / distance * move[a];
        for (int a = 0; a < 3; ++a) p[a] = float(target[a]);
    }
    recomputeNormals(mesh);
}

void recomputeNormals(Mesh& mesh) {
    std::vector<std::array<double, 3>> sums(mesh.vertices.size(), {0, 0, 0});
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const std::uint32_t* corner = &mesh.indices[3 * t];
        const float* p = mesh.vertices[corner[0]].position;
        const float* q = mesh.vertices[corner[1]].position;
        const float* r = mesh.vertices[corner[2]].position;
        const double u[3] = {double(q[0]) - p[0], double(q[1]) - p[1], double(q[2]) - p[2]};
        const double w[3] = {double(r[0]) - p[0], double(r[1]) - p[1], double(r[2]) - p[2]};
        // Counter-clockwise seen from below: the cross product points below,
        // twice the triangle's area long.
        const double normal[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) sums[corner[k]][a] += normal[a];
    }
    for (std::size_t v = 0; v < sums.size(); ++v) {
        const double norm = std::sqrt(sums[v][0] * sums[v][0] + sums[v][1] * sums[v][1] + sums[v][2] * sums[v][2]);
        if (norm == 0.0) continue;  // only degenerate triangles here: the old normal stays
        for (int a = 0; a < 3; ++a) mesh.vertices[v].normal[a] = float(sums[v][a] / norm);
    }
}

}  // namespace isotrack
