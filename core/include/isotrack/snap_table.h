#pragma once
// The 3-state table of SnapMC (Raman & Wenger, "Quality isosurface mesh
// generation using an extended marching cubes lookup table", EuroVis 2008).
//
// A sample is below, at or above the isovalue. Before a cube is looked up, a
// sample whose crossing on one of its six grid edges lies within
// kSnapDistance (a fraction of the edge) of it is snapped: it counts as at
// the isovalue, and the surface passes through its grid point instead of
// through crossings a sliver away from it. The table has an entry for each of
// the 3^8 = 6561 configurations.
//
// Loops that snapping leaves on one cube face are fanned from their corner
// first in the face's coordinates, so both cubes on the face draw the same
// triangles; other loops from a corner whose fan draws no triangle and no
// diagonal flat on a face, or, where none does, around their centre.
// Generated, never written by hand: a configuration refines the 2-state one
// in which "at" counts as above (VTK's rule, sample >= iso). Its triangles are
// the consistent table's triangles of that 2-state configuration, with every
// corner on an edge that has an "at" end moved onto that end (a crossed edge
// has at most one: its other end is below). Triangles that this collapses
// (two corners at one place) are dropped, and so are pairs over the same three
// corners (a sheet folded back onto itself, enclosing nothing). Each triangle
// keeps the piece of the 2-state configuration it came from, so tracking
// follows the consistent table's continuation over the 2-state configurations
// and visits the same cells as on a volume whose snapped samples equal the
// isovalue. The 2-state surface is closed, so its image is too; where a thin
// sheet of "at" samples has cells below on both sides, both cells draw the
// same triangles on their shared face, reversed, and the extractors cancel
// such pairs (detail::removeFins) over the surface.
#include <array>
#include <cstdint>

#include "isotrack/tables.h"

namespace isotrack {

constexpr int kSnapConfigCount = 6561;
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

enum class SampleState : std::uint8_t { Below = 0, At = 1, Above = 2 };

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

// The configuration index of eight states in cube vertex order: sum of state_v * 3^v.
int snapConfigIndex(const std::array<SampleState, 8>& states);
// The states of a configuration index.
std::array<SampleState, 8> snapConfigStates(int index);

const std::array<SnapCase, kSnapConfigCount>& snapTable();

// Whether a sample with value `value` snaps to `iso` given one of its grid
// neighbours' `neighbour`: the edge between them is crossed and the crossing
// lies within kSnapDistance of the sample. NaN never snaps.
inline bool snapsTowards(double value, double neighbour, double iso) {
    if (value >= iso) return neighbour < iso && (value - iso) < kSnapDistance * (value - neighbour);
    return neighbour >= iso && (iso - value) < kSnapDistance * (neighbour - value);
}

}  // namespace isotrack
