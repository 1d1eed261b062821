// Edge flips that remove zero-area triangles (flip.h).
#include "mesh/flip.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace isotrack::detail {
namespace {

std::uint64_t edgeKey(std::uint32_t from, std::uint32_t to) { return (std::uint64_t(from) << 32) | to; }

double length2(const float* p, const float* q) {
    double sum = 0.0;
    for (int a = 0; a < 3; ++a) sum += (double(q[a]) - double(p[a])) * (double(q[a]) - double(p[a]));
    return sum;
}

// Directed edges to the triangle that holds them; an edge in more than one
// triangle maps to kCrowded.
constexpr std::uint32_t kCrowded = UINT32_MAX;

std::unordered_map<std::uint64_t, std::uint32_t> edgeTriangles(const Mesh& mesh) {
    std::unordered_map<std::uint64_t, std::uint32_t> edges;
    edges.reserve(mesh.indices.size());
    for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) {
            const auto [it, added] =
                edges.emplace(edgeKey(mesh.indices[3 * t + k], mesh.indices[3 * t + (k + 1) % 3]), t);
            if (!added) it->second = kCrowded;
        }
    return edges;
}

}  // namespace

bool zeroArea(const float* p, const float* q, const float* r) {
    double u[3], v[3];
    for (int a = 0; a < 3; ++a) {
        u[a] = double(q[a]) - double(p[a]);
        v[a] = double(r[a]) - double(p[a]);
    }
    const double cross[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double doubleArea = std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]);
    const double longest2 = std::max({length2(p, q), length2(q, r), length2(r, p)});
    return doubleArea <= kZeroAreaFraction * longest2;
}

void flipZeroAreaTriangles(Mesh& mesh) {
    auto position = [&](std::uint32_t v) { return mesh.vertices[v].position; };
    for (bool flipped = true; flipped;) {
        flipped = false;
        const auto edges = edgeTriangles(mesh);
        std::vector<char> touched(mesh.triangleCount(), 0);
        for (std::uint32_t t = 0; t < mesh.triangleCount(); ++t) {
            std::uint32_t* corner = &mesh.indices[3 * t];
            if (touched[t] || !zeroArea(position(corner[0]), position(corner[1]), position(corner[2]))) continue;
            // The longest side a -> b, and c opposite it.
            int longest = 0;
            double best = -1.0;
            for (int k = 0; k < 3; ++k) {
                const double l = length2(position(corner[k]), position(corner[(k + 1) % 3]));
                if (l > best) {
                    best = l;
                    longest = k;
                }
            }
            const std::uint32_t a = corner[longest], b = corner[(longest + 1) % 3], c = corner[(longest + 2) % 3];
            if (edges.at(edgeKey(a, b)) == kCrowded) continue;
            const auto across = edges.find(edgeKey(b, a));
            if (across == edges.end() || across->second == kCrowded || touched[across->second]) continue;
            std::uint32_t* other = &mesh.indices[3 * across->second];
            std::uint32_t d = other[0];
            for (int k = 0; k < 3; ++k)
                if (other[k] != a && other[k] != b) d = other[k];
            if (d == c || edges.count(edgeKey(c, d)) || edges.count(edgeKey(d, c))) continue;
            if (zeroArea(position(a), position(b), position(d))) continue;
            const std::uint32_t flippedT[3] = {c, a, d}, flippedOther[3] = {c, d, b};
            std::copy(flippedT, flippedT + 3, corner);
            std::copy(flippedOther, flippedOther + 3, other);
            touched[t] = touched[across->second] = 1;
            flipped = true;
        }
    }
}

}  // namespace isotrack::detail
