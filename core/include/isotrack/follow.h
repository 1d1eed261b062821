#pragma once
// Following surfaces while the isovalue changes: the viewer re-extracts at each
// new isovalue and must tell which new surface continues which old one, so
// that a surface keeps its colour, visibility, offset and selection, and a
// tracked surface keeps its seed.
//
// Seeds. A tracked surface remembers a world point on it. At a new isovalue
// the surface has moved along its gradient (up the gradient when the
// isovalue rose, down when it fell), so followSeed walks from the point along
// the gradient of the trilinear interpolant until it crosses the new
// isovalue, then takes the crossed grid edge nearest that crossing. When the
// walk finds no crossing within kFollowWalkVoxels, the crossed edge nearest
// the point itself within kFollowNeighbourhood voxels is taken; when there is
// none, the surface is gone at this isovalue (nullopt), and the seed is kept
// for when it comes back.
//
// Surfaces without seeds. Each surface's footprint is the set of 4x4x4-cell
// blocks its vertices lie in (at most 16,384 vertices looked at, evenly
// spread, so that a large surface costs little). A new surface continues the old surface with
// which it shares the most blocks; when it shares blocks with several old
// surfaces that each have at least a quarter of the best one's share (old
// surfaces that merged), the largest of those (by triangles) is the one it
// continues. A new surface sharing no block continues the old one whose
// bounding box holds its centre while its own box holds the old one's (the
// same surface, moved further than a block), the most overlapping if several
// do. Several new surfaces may continue the same old one (it split).
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/volume.h"

namespace isotrack {

inline constexpr double kFollowWalkVoxels = 24.0;
inline constexpr int kFollowNeighbourhood = 3;
inline constexpr int kFootprintBlockShift = 2;  // 4x4x4 cells a block

struct FollowedSeed {
    GridEdge edge;
    Vec3d point{0, 0, 0};  // where the surface crosses `edge`, in world units
};

// The crossed edge of the surface through `point` at isovalue `iso` (see above).
std::optional<FollowedSeed> followSeed(const Volume& volume, double iso, const Vec3d& point);

// Where the surface crosses `edge` (which must be crossed), in world units.
Vec3d edgeCrossing(const Volume& volume, double iso, const GridEdge& edge);

struct SurfaceFootprint {
    std::vector<std::uint64_t> blocks;  // sorted, unique
    std::size_t triangles = 0;
    Vec3d boundsMin{0, 0, 0}, boundsMax{0, 0, 0};
};

// From the mesh's vertex grid edges (a mesh without them has an empty block set).
SurfaceFootprint footprintOf(const Mesh& mesh);

// For each new surface, the index of the old surface it continues, or -1.
std::vector<int> matchSurfaces(const std::vector<const SurfaceFootprint*>& previous,
                               const std::vector<const SurfaceFootprint*>& next);

}  // namespace isotrack
