#pragma once
// Marching-cubes triangle tables, generated from the cube's rotation group.
//
// The only hand-written table data are Lorensen & Cline's 15 base cases (1987), as
// polygons over cube edges. From them:
//  - the classic table expands each base case by the 24 rotations and by
//    complement (a complemented case reuses the base case's triangles, wound the
//    other way). It is the 1987 table, with its holes on ambiguous faces.
//  - the consistent table (after Montani, Scateni & Scopigno 1994) expands by
//    rotation only. The 8 rotation classes that are complements of base cases are
//    triangulated by the same rule the base cases obey: on every face whose
//    diagonal corners alternate, the corners above the isovalue are kept apart.
//    Two cubes sharing a face therefore always cut it the same way, and the
//    surface has no holes.
// Triangles are wound counter-clockwise seen from the side below the isovalue, so
// their normals point the same way as isotrack's vertex normals (down the gradient).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace isotrack {

// Trilinear: the topology of the trilinear interpolant, decided per cube from its
// samples (isotrack/trilinear.h); it has no TriangleTable and no continuation
// table of its own. Snap: the 3-state table of SnapMC (isotrack/snap_table.h),
// 3^8 configurations refining the consistent table's, whose continuation it
// follows.
enum class TableKind : std::uint8_t { Consistent, Classic, Trilinear, Snap };
// Every table, in the order front ends list them.
inline constexpr std::array<TableKind, 4> kTableKinds{TableKind::Consistent, TableKind::Classic, TableKind::Trilinear,
                                                      TableKind::Snap};
// "consistent", "classic", "trilinear" or "snap".
const char* tableKindName(TableKind kind);
// "consistent", "classic", "trilinear" or "snap"; throws InputError naming the
// text and the valid names otherwise.
TableKind parseTableKind(const std::string& name);

constexpr int kMaxCaseTriangles = 12;

using EdgePolygon = std::vector<int>;  // cube edges in order around a piece of surface

struct CaseTriangles {
    std::uint8_t count = 0;
    std::array<std::array<std::int8_t, 3>, kMaxCaseTriangles> triangles{};
};

// How a configuration was derived: rotations()[rotation] applied to the base
// case's mask (complemented when `complemented`) gives the configuration.
struct CaseOrigin {
    std::uint8_t baseCase = 0;
    std::uint8_t rotation = 0;
    bool complemented = false;
};

class TriangleTable {
public:
    TriangleTable(TableKind kind, const std::array<CaseTriangles, 256>& cases,
                  const std::array<CaseOrigin, 256>& origins)
        : kind_(kind), cases_(cases), origins_(origins) {}

    TableKind kind() const { return kind_; }
    const CaseTriangles& operator[](std::uint8_t config) const { return cases_[config]; }
    const CaseOrigin& origin(std::uint8_t config) const { return origins_[config]; }
    int totalTriangles() const;

private:
    TableKind kind_;
    std::array<CaseTriangles, 256> cases_;
    std::array<CaseOrigin, 256> origins_;
};

// The consistent or classic table (the consistent one for TableKind::Trilinear,
// whose cubes outside its ambiguous cases it equals up to triangulation, and
// for TableKind::Snap, whose 2-state configurations it triangulates).
const TriangleTable& triangleTable(TableKind kind);

struct BaseCase {
    std::uint8_t mask;                  // vertices above the isovalue
    std::vector<EdgePolygon> polygons;  // as written, before orientation
};
// Lorensen & Cline's cases 0..14, in their numbering.
const std::array<BaseCase, 15>& lorensenClineBaseCases();

// The polygons of a configuration under the face rule: on each face the crossed
// edges are joined in pairs, cutting off the corners above the isovalue on
// ambiguous faces, and the pairs are chained into closed polygons.
std::vector<EdgePolygon> faceRulePolygons(std::uint8_t config);

// Reverses `polygon` if needed so it winds counter-clockwise seen from below.
void orientPolygon(std::uint8_t config, EdgePolygon& polygon);

}  // namespace isotrack
