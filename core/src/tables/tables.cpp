#include "isotrack/tables.h"

#include <algorithm>
#include <stdexcept>

#include "isotrack/cube.h"
#include "isotrack/errors.h"

namespace isotrack {
namespace {

using Vec = std::array<double, 3>;

Vec edgeMidpoint(int edge) {
    const auto& a = cube::kVertexOffset[cube::kEdgeVertices[edge][0]];
    const auto& b = cube::kVertexOffset[cube::kEdgeVertices[edge][1]];
    return {(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0, (a[2] + b[2]) / 2.0};
}

bool above(std::uint8_t config, int vertex) { return (config >> vertex) & 1u; }

// Unit vector along `edge` from its end above the isovalue to its end below it.
Vec downhill(std::uint8_t config, int edge) {
    int from = cube::kEdgeVertices[edge][0];
    int to = cube::kEdgeVertices[edge][1];
    if (!above(config, from)) std::swap(from, to);
    Vec d{};
    for (int i = 0; i < 3; ++i) d[i] = cube::kVertexOffset[to][i] - cube::kVertexOffset[from][i];
    return d;
}

using Triangle = std::array<int, 3>;

bool sharesFace(const Triangle& t) {
    for (int f = 0; f < cube::kFaceCount; ++f) {
        if (cube::edgeOnFace(t[0], f) && cube::edgeOnFace(t[1], f) && cube::edgeOnFace(t[2], f)) return true;
    }
    return false;
}

double facing(std::uint8_t config, const Triangle& t) {
    const Vec a = edgeMidpoint(t[0]), b = edgeMidpoint(t[1]), c = edgeMidpoint(t[2]);
    const Vec u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const Vec v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const Vec n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double dot = 0.0;
    for (int corner : t) {
        const Vec d = downhill(config, corner);
        dot += n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
    }
    return dot;
}

// Fans an oriented polygon from the first corner whose fan has no triangle lying
// flat on a cube face (it would meet the neighbouring cube's surface there) and
// every triangle facing down the gradient.
std::vector<Triangle> triangulate(std::uint8_t config, const EdgePolygon& polygon) {
    const std::size_t n = polygon.size();
    for (std::size_t start = 0; start < n; ++start) {
        std::vector<Triangle> fan;
        bool good = true;
        for (std::size_t k = 1; k + 1 < n && good; ++k) {
            const Triangle t{polygon[start], polygon[(start + k) % n], polygon[(start + k + 1) % n]};
            good = !sharesFace(t) && facing(config, t) > 0.0;
            fan.push_back(t);
        }
        if (good) return fan;
    }
    throw std::logic_error("tables: polygon has no clean fan triangulation");
}

void appendTriangles(std::uint8_t config, const EdgePolygon& polygon, const cube::Rotation& rotation,
                     CaseTriangles& out) {
    for (const Triangle& t : triangulate(config, polygon)) {
        if (out.count >= kMaxCaseTriangles) throw std::logic_error("tables: too many triangles in a case");
        auto& slot = out.triangles[out.count++];
        for (int k = 0; k < 3; ++k) slot[k] = static_cast<std::int8_t>(rotation.edge[t[k]]);
    }
}

std::uint8_t complement(std::uint8_t config) { return static_cast<std::uint8_t>(~config); }

// Finds the base case and rotation that give `config`, without complement when
// `allowComplement` is false. Prefers the uncomplemented match.
bool findOrigin(std::uint8_t config, bool allowComplement, CaseOrigin& origin) {
    const auto& bases = lorensenClineBaseCases();
    const auto& group = cube::rotations();
    for (int pass = 0; pass < (allowComplement ? 2 : 1); ++pass) {
        for (std::size_t b = 0; b < bases.size(); ++b) {
            const std::uint8_t mask = pass == 0 ? bases[b].mask : complement(bases[b].mask);
            for (std::size_t r = 0; r < group.size(); ++r) {
                if (cube::rotateConfig(mask, group[r]) == config) {
                    origin = {static_cast<std::uint8_t>(b), static_cast<std::uint8_t>(r), pass == 1};
                    return true;
                }
            }
        }
    }
    return false;
}

TriangleTable buildClassic() {
    std::array<CaseTriangles, 256> cases{};
    std::array<CaseOrigin, 256> origins{};
    const auto& bases = lorensenClineBaseCases();
    for (int c = 0; c < 256; ++c) {
        const auto config = static_cast<std::uint8_t>(c);
        CaseOrigin origin;
        if (!findOrigin(config, true, origin)) throw std::logic_error("tables: configuration has no base case");
        origins[c] = origin;
        const BaseCase& base = bases[origin.baseCase];
        for (EdgePolygon polygon : base.polygons) {
            orientPolygon(base.mask, polygon);
            std::uint8_t frame = base.mask;
            if (origin.complemented) {
                // A complement swaps above and below: the same surface, facing the other way.
                std::reverse(polygon.begin(), polygon.end());
                frame = complement(frame);
            }
            appendTriangles(frame, polygon, cube::rotations()[origin.rotation], cases[c]);
        }
    }
    return TriangleTable(TableKind::Classic, cases, origins);
}

TriangleTable buildConsistent() {
    std::array<CaseTriangles, 256> cases{};
    std::array<CaseOrigin, 256> origins{};
    const auto& bases = lorensenClineBaseCases();
    const auto& group = cube::rotations();
    for (int c = 0; c < 256; ++c) {
        const auto config = static_cast<std::uint8_t>(c);
        CaseOrigin origin;
        if (findOrigin(config, false, origin)) {
            origins[c] = origin;
            const BaseCase& base = bases[origin.baseCase];
            for (EdgePolygon polygon : base.polygons) {
                orientPolygon(base.mask, polygon);
                appendTriangles(base.mask, polygon, group[origin.rotation], cases[c]);
            }
            continue;
        }
        // A complemented class: triangulate its representative by the face rule,
        // then turn it into place.
        if (!findOrigin(config, true, origin)) throw std::logic_error("tables: configuration has no base case");
        origins[c] = origin;
        const std::uint8_t representative = complement(bases[origin.baseCase].mask);
        for (EdgePolygon polygon : faceRulePolygons(representative)) {
            orientPolygon(representative, polygon);
            appendTriangles(representative, polygon, group[origin.rotation], cases[c]);
        }
    }
    return TriangleTable(TableKind::Consistent, cases, origins);
}

}  // namespace

const char* tableKindName(TableKind kind) {
    switch (kind) {
        case TableKind::Classic: return "classic";
        case TableKind::Trilinear: return "trilinear";
        case TableKind::Snap: return "snap";
        case TableKind::Consistent: break;
    }
    return "consistent";
}

TableKind parseTableKind(const std::string& name) {
    if (name == "consistent") return TableKind::Consistent;
    if (name == "classic") return TableKind::Classic;
    if (name == "trilinear") return TableKind::Trilinear;
    if (name == "snap") return TableKind::Snap;
    throw InputError("unknown table \"" + name + "\" (expected consistent, classic, trilinear or snap)");
}

int TriangleTable::totalTriangles() const {
    int total = 0;
    for (const auto& c : cases_) total += c.count;
    return total;
}

const TriangleTable& triangleTable(TableKind kind) {
    static const TriangleTable consistent = buildConsistent();
    static const TriangleTable classic = buildClassic();
    return kind == TableKind::Classic ? classic : consistent;
}

const std::array<BaseCase, 15>& lorensenClineBaseCases() {
    // Vertex masks and surface polygons of the 15 cases of Lorensen & Cline (1987),
    // in isotrack's cube numbering. Winding is set by orientPolygon.
    static const std::array<BaseCase, 15> cases{{
        {0x00, {}},                                              // 0
        {0x01, {{0, 3, 8}}},                                     // 1: one corner
        {0x03, {{3, 8, 9, 1}}},                                  // 2: an edge
        {0x05, {{0, 3, 8}, {1, 2, 10}}},                         // 3: two corners across a face
        {0x41, {{0, 3, 8}, {5, 6, 10}}},                         // 4: two corners across the cube
        {0x07, {{3, 8, 9, 10, 2}}},                              // 5: three corners of a face
        {0x43, {{3, 8, 9, 1}, {5, 6, 10}}},                      // 6: an edge and a far corner
        {0x4a, {{0, 1, 9}, {2, 3, 11}, {5, 6, 10}}},             // 7: three scattered corners
        {0x0f, {{8, 9, 10, 11}}},                                // 8: a whole face
        {0x8d, {{0, 1, 10, 6, 7, 8}}},                           // 9: a corner and its three neighbours
        {0x55, {{0, 3, 7, 4}, {1, 2, 6, 5}}},                    // 10: two opposite edges
        {0x71, {{0, 3, 7, 6, 10, 9}}},                           // 11: a twisted path of four
        {0x1e, {{0, 3, 11, 10, 9}, {8, 7, 4}}},                  // 12: three corners of a face and a far corner
        {0xa5, {{0, 3, 8}, {1, 2, 10}, {4, 5, 9}, {6, 7, 11}}},  // 13: alternate corners
        {0xb2, {{0, 1, 5, 6, 11, 8}}},                           // 14: the mirror image of 11
    }};
    return cases;
}

std::vector<EdgePolygon> faceRulePolygons(std::uint8_t config) {
    // partner[e] lists the (up to two) edges joined to e by a segment on some face.
    std::array<std::vector<int>, 12> partner;
    for (int f = 0; f < cube::kFaceCount; ++f) {
        const auto& fv = cube::faceVertices(f);
        const auto& fe = cube::faceEdges(f);  // fe[k] joins fv[k] and fv[k+1]
        std::vector<int> crossed;
        for (int k = 0; k < 4; ++k) {
            if (above(config, fv[k]) != above(config, fv[(k + 1) % 4])) crossed.push_back(k);
        }
        if (crossed.size() == 2) {
            partner[fe[crossed[0]]].push_back(fe[crossed[1]]);
            partner[fe[crossed[1]]].push_back(fe[crossed[0]]);
        } else if (crossed.size() == 4) {
            // Ambiguous face: cut off each corner above the isovalue on its own.
            for (int k = 0; k < 4; ++k) {
                if (!above(config, fv[k])) continue;
                const int before = fe[(k + 3) % 4];
                const int after = fe[k];
                partner[before].push_back(after);
                partner[after].push_back(before);
            }
        }
    }
    std::vector<EdgePolygon> polygons;
    std::array<bool, 12> used{};
    for (int start = 0; start < 12; ++start) {
        if (used[start] || partner[start].empty()) continue;
        if (partner[start].size() != 2) throw std::logic_error("tables: crossed edge without two segments");
        EdgePolygon polygon{start};
        used[start] = true;
        int previous = start;
        int current = partner[start][0];
        while (current != start) {
            polygon.push_back(current);
            used[current] = true;
            const int next = partner[current][0] == previous ? partner[current][1] : partner[current][0];
            previous = current;
            current = next;
        }
        polygons.push_back(polygon);
    }
    return polygons;
}

void orientPolygon(std::uint8_t config, EdgePolygon& polygon) {
    // Newell's normal of the polygon through the edge midpoints, against the sum of
    // the directions in which its edges run from above the isovalue to below it.
    Vec normal{0, 0, 0};
    Vec down{0, 0, 0};
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec a = edgeMidpoint(polygon[i]);
        const Vec b = edgeMidpoint(polygon[(i + 1) % polygon.size()]);
        normal[0] += (a[1] - b[1]) * (a[2] + b[2]);
        normal[1] += (a[2] - b[2]) * (a[0] + b[0]);
        normal[2] += (a[0] - b[0]) * (a[1] + b[1]);
        const Vec d = downhill(config, polygon[i]);
        for (int k = 0; k < 3; ++k) down[k] += d[k];
    }
    const double agreement = normal[0] * down[0] + normal[1] * down[1] + normal[2] * down[2];
    if (agreement == 0.0) throw std::logic_error("tables: polygon orientation is undetermined");
    if (agreement < 0.0) std::reverse(polygon.begin(), polygon.end());
}

}  // namespace isotrack
