#pragma once
// The 3-state table of SnapMC (Raman & Wenger, "Quality isosurface mesh
// generation using an extended marching cubes lookup table", EuroVis 2008).
//
// A sample is below, at or above the isovalue. Before a cube is looked up, a
// sample whose crossing on one of its six grid edges lies within
// kSnapDistance (a fraction of the edge) of it is snapped: it counts as at
// the isovalue, and the surface passes through its grid point instead of
// through crossings a sliver away from it. A sample at the isovalue keeps the
// side its value is on (at or above the isovalue is above, VTK's rule) for the
// surface's topology, so the table has an entry per 2-state configuration and
// set of samples at the isovalue: 2^8 x 2^8 = 65,536 entries, over the 3^8
// below/at/above states and, for each at sample, its side.
//
// Generated, never written by hand: an entry's triangles are the consistent
// table's polygons of its 2-state configuration, with every corner on an edge
// that has an at end moved onto that end (onto its end above the isovalue when
// both are at: a snap distance below one half lets only one end snap towards
// the edge's own crossing, and an end that equals the isovalue is above, where
// the crossing is exactly). Polygons are split where
// this makes them pass a corner twice; pieces of fewer than three corners go.
// A polygon left on one cube face is fanned from its corner first in the
// face's coordinates, so both cubes on the face draw the same triangles,
// reversed; any other from a corner whose fan lays no triangle and no diagonal
// flat on a face, or, where none does, around its centre. Triangles over the
// same three corners as another go, both (a sheet folded back on itself,
// enclosing nothing). Each triangle keeps the piece of the 2-state
// configuration it came from, so the extractors follow the consistent table's
// continuation and visit the same cells as with the consistent table. Where a
// sheet of at samples has samples below on both sides, both cubes draw the
// same triangles on their shared face, reversed; the extractors cancel such
// pairs (detail::removeFins) over the surface.
#include <array>
#include <cstdint>
#include <vector>

#include "isotrack/tables.h"

namespace isotrack {

// Entries: the 2-state configuration in the low byte, the samples at the isovalue in the high one.
constexpr int kSnapCaseCount = 65536;
constexpr int snapCaseIndex(std::uint8_t aboveMask, std::uint8_t atMask) { return aboveMask | atMask << 8; }
// Triangle corners 0..11 are crossings on cube edges; kSnapCornerVertex + v is
// cube vertex v (a sample at the isovalue); kSnapCornerCentre + i is the centre
// of the case's i-th centred loop: the mean of its corners (SnapCase::centres).
constexpr int kSnapCornerVertex = 12;
constexpr int kSnapCornerCentre = 20;
constexpr int kMaxSnapTriangles = 16;
constexpr int kMaxSnapCentres = 4;
// The snap distance: a crossing this close to a sample (as a fraction of the
// edge, from the sample) snaps the sample to the isovalue.
constexpr double kSnapDistance = 0.3;

// A sample's state: its side (bit 0: at or above the isovalue) and whether it is at the isovalue (bit 1).
enum class SampleState : std::uint8_t { Below = 0, Above = 1, AtFromBelow = 2, At = 3 };
constexpr bool isAt(SampleState s) { return std::uint8_t(s) & 2u; }
constexpr bool isAbove(SampleState s) { return std::uint8_t(s) & 1u; }

struct SnapCase {
    std::uint8_t count = 0;
    std::uint8_t aboveMask = 0;  // the 2-state configuration: samples at or above
    std::uint8_t atMask = 0;     // the samples at the isovalue
    std::array<std::array<std::int8_t, 3>, kMaxSnapTriangles> triangles{};
    std::array<std::int8_t, kMaxSnapTriangles> piece{};  // the 2-state piece (continuationTable) of each triangle
    // Loops fanned around their centre because every fan of their corners alone
    // would draw a diagonal on a cube face, which the cube across it may draw too:
    // their corners (edge or vertex corners), -1 after the last.
    std::uint8_t centreCount = 0;
    std::array<std::array<std::int8_t, 12>, kMaxSnapCentres> centres{};
};

// Indexed by snapCaseIndex.
const std::vector<SnapCase>& snapTable();

// Whether a sample with value `value` snaps to `iso` given one of its grid
// neighbours' `neighbour`: the edge between them is crossed and the crossing
// lies within kSnapDistance of the sample. NaN never snaps.
inline bool snapsTowards(double value, double neighbour, double iso) {
    if (value >= iso) return neighbour < iso && (value - iso) < kSnapDistance * (value - neighbour);
    return neighbour >= iso && (iso - value) < kSnapDistance * (neighbour - value);
}

}  // namespace isotrack
