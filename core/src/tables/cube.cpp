#include "isotrack/cube.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace isotrack::cube {
namespace {

using Matrix = std::array<std::array<int, 3>, 3>;
using IVec = std::array<int, 3>;

IVec centred(int vertex) {
    const auto& o = kVertexOffset[vertex];
    return {2 * o[0] - 1, 2 * o[1] - 1, 2 * o[2] - 1};
}

int vertexAtCentred(const IVec& c) {
    for (int v = 0; v < kVertexCount; ++v) {
        if (centred(v) == c) return v;
    }
    throw std::logic_error("cube: no vertex at rotated position");
}

int edgeBetween(int a, int b) {
    for (int e = 0; e < kEdgeCount; ++e) {
        const auto& ev = kEdgeVertices[e];
        if ((ev[0] == a && ev[1] == b) || (ev[0] == b && ev[1] == a)) return e;
    }
    throw std::logic_error("cube: vertices are not joined by an edge");
}

IVec apply(const Matrix& m, const IVec& p) {
    IVec r{};
    for (int i = 0; i < 3; ++i) r[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2];
    return r;
}

Matrix multiply(const Matrix& a, const Matrix& b) {
    Matrix r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) r[i][j] += a[i][k] * b[k][j];
    return r;
}

int faceOfNormal(const IVec& n) {
    for (int axis = 0; axis < 3; ++axis) {
        if (n[axis] != 0) return 2 * axis + (n[axis] > 0 ? 1 : 0);
    }
    throw std::logic_error("cube: zero face normal");
}

IVec faceNormal(int face) {
    IVec n{0, 0, 0};
    n[faceAxis(face)] = faceSide(face) ? 1 : -1;
    return n;
}

Rotation makeRotation(const Matrix& m) {
    Rotation r{};
    r.matrix = m;
    for (int v = 0; v < kVertexCount; ++v) r.vertex[v] = vertexAtCentred(apply(m, centred(v)));
    for (int e = 0; e < kEdgeCount; ++e) {
        r.edge[e] = edgeBetween(r.vertex[kEdgeVertices[e][0]], r.vertex[kEdgeVertices[e][1]]);
    }
    for (int f = 0; f < kFaceCount; ++f) r.face[f] = faceOfNormal(apply(m, faceNormal(f)));
    return r;
}

std::array<Rotation, 24> generateRotations() {
    const Matrix identity{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    const std::array<Matrix, 3> quarterTurns{{
        {{{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}},  // about x
        {{{0, 0, 1}, {0, 1, 0}, {-1, 0, 0}}},  // about y
        {{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}},  // about z
    }};
    std::vector<Matrix> group{identity};
    for (std::size_t i = 0; i < group.size(); ++i) {
        for (const Matrix& turn : quarterTurns) {
            Matrix next = multiply(turn, group[i]);
            if (std::find(group.begin(), group.end(), next) == group.end()) group.push_back(next);
        }
    }
    if (group.size() != 24) throw std::logic_error("cube: rotation closure is not of order 24");
    std::array<Rotation, 24> result{};
    for (std::size_t i = 0; i < group.size(); ++i) result[i] = makeRotation(group[i]);
    return result;
}

struct FaceTopology {
    std::array<std::array<int, 4>, 6> vertices{};
    std::array<std::array<int, 4>, 6> edges{};
};

FaceTopology buildFaces() {
    FaceTopology t;
    for (int f = 0; f < kFaceCount; ++f) {
        std::vector<int> onFace;
        for (int v = 0; v < kVertexCount; ++v) {
            if (kVertexOffset[v][faceAxis(f)] == faceSide(f)) onFace.push_back(v);
        }
        // Walk the face: each next vertex shares a cube edge with the previous one.
        std::array<int, 4> cycle{onFace[0], -1, -1, -1};
        std::vector<bool> used(8, false);
        used[onFace[0]] = true;
        for (int k = 1; k < 4; ++k) {
            for (int v : onFace) {
                if (used[v]) continue;
                bool adjacent = false;
                for (const auto& ev : kEdgeVertices) {
                    adjacent |= (ev[0] == v && ev[1] == cycle[k - 1]) || (ev[1] == v && ev[0] == cycle[k - 1]);
                }
                if (adjacent) {
                    cycle[k] = v;
                    used[v] = true;
                    break;
                }
            }
        }
        t.vertices[f] = cycle;
        for (int k = 0; k < 4; ++k) t.edges[f][k] = edgeBetween(cycle[k], cycle[(k + 1) % 4]);
    }
    return t;
}

const FaceTopology& faces() {
    static const FaceTopology topology = buildFaces();
    return topology;
}

}  // namespace

int edgeAxis(int edge) {
    const auto& a = kVertexOffset[kEdgeVertices[edge][0]];
    const auto& b = kVertexOffset[kEdgeVertices[edge][1]];
    for (int axis = 0; axis < 3; ++axis) {
        if (a[axis] != b[axis]) return axis;
    }
    throw std::logic_error("cube: degenerate edge");
}

const std::array<int, 3>& edgeOrigin(int edge) {
    static const std::array<std::array<int, 3>, 12> origins = [] {
        std::array<std::array<int, 3>, 12> o{};
        for (int e = 0; e < kEdgeCount; ++e) {
            const auto& a = kVertexOffset[kEdgeVertices[e][0]];
            const auto& b = kVertexOffset[kEdgeVertices[e][1]];
            for (int i = 0; i < 3; ++i) o[e][i] = std::min(a[i], b[i]);
        }
        return o;
    }();
    return origins[edge];
}

int edgeAt(const std::array<int, 3>& origin, int axis) {
    for (int e = 0; e < kEdgeCount; ++e) {
        if (edgeAxis(e) == axis && edgeOrigin(e) == origin) return e;
    }
    return -1;
}

const std::array<int, 4>& faceVertices(int face) { return faces().vertices[face]; }
const std::array<int, 4>& faceEdges(int face) { return faces().edges[face]; }

bool edgeOnFace(int edge, int face) {
    const auto& e = faceEdges(face);
    return std::find(e.begin(), e.end(), edge) != e.end();
}

int edgeAcrossFace(int edge, int face) {
    std::array<int, 3> origin = edgeOrigin(edge);
    const int axis = faceAxis(face);
    origin[axis] = 1 - origin[axis];
    return edgeAt(origin, edgeAxis(edge));
}

const std::array<Rotation, 24>& rotations() {
    static const std::array<Rotation, 24> group = generateRotations();
    return group;
}

std::uint8_t rotateConfig(std::uint8_t config, const Rotation& rotation) {
    unsigned rotated = 0;
    for (int v = 0; v < kVertexCount; ++v) {
        if (config & (1u << v)) rotated |= 1u << rotation.vertex[v];
    }
    return static_cast<std::uint8_t>(rotated);
}

}  // namespace isotrack::cube
