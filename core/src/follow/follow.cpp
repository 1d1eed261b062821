// Following seeds and surfaces across isovalues: seeds, footprints and the
// match by footprint (the rules are in isotrack/follow.h).
#include "isotrack/follow.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace isotrack {
namespace {

constexpr double kWalkStep = 0.25;  // voxels
constexpr double kMergeShare = 0.25;
// A footprint looks at most this many vertices, evenly spread: enough to cover a
// large surface's blocks well, while a whole skull costs under a millisecond.
constexpr std::size_t kFootprintSamples = 1 << 14;

// The trilinear interpolant at grid coordinates g (clamped into the grid).
double trilinear(const Volume& volume, const Vec3d& g) {
    const Dims& n = volume.dims();
    int base[3];
    double t[3];
    for (int k = 0; k < 3; ++k) {
        const double c = std::clamp(g[k], 0.0, double(n[k] - 1));
        base[k] = std::min(static_cast<int>(std::floor(c)), std::max(n[k] - 2, 0));
        t[k] = n[k] > 1 ? c - base[k] : 0.0;
    }
    double sum = 0.0;
    for (int corner = 0; corner < 8; ++corner) {
        const int d[3] = {corner & 1, corner >> 1 & 1, corner >> 2 & 1};
        double w = 1.0;
        int q[3];
        for (int k = 0; k < 3; ++k) {
            w *= d[k] ? t[k] : 1.0 - t[k];
            q[k] = std::min(base[k] + d[k], n[k] - 1);
        }
        if (w != 0.0) sum += w * volume.value(q[0], q[1], q[2]);
    }
    return sum;
}

Vec3d gradient(const Volume& volume, const Vec3d& g) {
    Vec3d out{};
    for (int k = 0; k < 3; ++k) {
        Vec3d a = g, b = g;
        a[k] -= 0.5;
        b[k] += 0.5;
        out[k] = trilinear(volume, b) - trilinear(volume, a);
    }
    return out;
}

bool above(double value, double iso) { return value >= iso; }

bool crossed(const Volume& volume, double iso, const GridEdge& e) {
    const Dims& n = volume.dims();
    const int x1 = e.x + (e.axis == 0), y1 = e.y + (e.axis == 1), z1 = e.z + (e.axis == 2);
    if (e.x < 0 || e.y < 0 || e.z < 0 || x1 >= n[0] || y1 >= n[1] || z1 >= n[2]) return false;
    return above(volume.value(e.x, e.y, e.z), iso) != above(volume.value(x1, y1, z1), iso);
}

Vec3d gridToWorld(const Volume& volume, const Vec3d& g) {
    return {volume.origin()[0] + g[0] * volume.spacing()[0], volume.origin()[1] + g[1] * volume.spacing()[1],
            volume.origin()[2] + g[2] * volume.spacing()[2]};
}

double squaredDistance(const Vec3d& a, const Vec3d& b) {
    double d = 0.0;
    for (int k = 0; k < 3; ++k) d += (a[k] - b[k]) * (a[k] - b[k]);
    return d;
}

// The crossed edge within `radius` cells of world point `world` whose crossing is nearest it.
std::optional<FollowedSeed> nearestCrossingWithin(const Volume& volume, double iso, const Vec3d& world, int radius) {
    const Dims& n = volume.dims();
    int centre[3];
    for (int k = 0; k < 3; ++k) {
        const double g = (world[k] - volume.origin()[k]) / volume.spacing()[k];
        centre[k] = static_cast<int>(std::lround(std::clamp(std::isfinite(g) ? g : 0.0, 0.0, double(n[k] - 1))));
    }
    std::optional<FollowedSeed> best;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (int z = std::max(centre[2] - radius, 0); z <= std::min(centre[2] + radius, n[2] - 1); ++z) {
        for (int y = std::max(centre[1] - radius, 0); y <= std::min(centre[1] + radius, n[1] - 1); ++y) {
            for (int x = std::max(centre[0] - radius, 0); x <= std::min(centre[0] + radius, n[0] - 1); ++x) {
                for (int axis = 0; axis < 3; ++axis) {
                    const GridEdge e{x, y, z, axis};
                    if (!crossed(volume, iso, e)) continue;
                    const Vec3d point = edgeCrossing(volume, iso, e);
                    const double d = squaredDistance(point, world);
                    if (d < bestDistance) {
                        bestDistance = d;
                        best = FollowedSeed{e, point};
                    }
                }
            }
        }
    }
    return best;
}

// Walks from grid point g along the gradient towards `iso`; the world point where it crosses, if it does.
std::optional<Vec3d> walkToIsovalue(const Volume& volume, double iso, Vec3d g) {
    const double start = trilinear(volume, g);
    if (!std::isfinite(start)) return std::nullopt;
    const double direction = start < iso ? 1.0 : -1.0;  // up the gradient to reach a higher isovalue
    double previous = start;
    for (double walked = 0.0; walked < kFollowWalkVoxels; walked += kWalkStep) {
        const Vec3d grad = gradient(volume, g);
        const double length = std::sqrt(grad[0] * grad[0] + grad[1] * grad[1] + grad[2] * grad[2]);
        if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
        Vec3d next = g;
        for (int k = 0; k < 3; ++k) next[k] += direction * kWalkStep * grad[k] / length;
        const double value = trilinear(volume, next);
        if (above(value, iso) != above(previous, iso)) return gridToWorld(volume, next);
        if ((value - previous) * direction <= 0.0) return std::nullopt;  // an extremum short of the isovalue
        previous = value;
        g = next;
    }
    return std::nullopt;
}

std::uint64_t blockKey(const GridEdge& e) {
    return std::uint64_t(e.x >> kFootprintBlockShift) | std::uint64_t(e.y >> kFootprintBlockShift) << 20 |
           std::uint64_t(e.z >> kFootprintBlockShift) << 40;
}

bool containsCentreOf(const SurfaceFootprint& box, const SurfaceFootprint& other) {
    for (int k = 0; k < 3; ++k) {
        const double centre = 0.5 * (other.boundsMin[k] + other.boundsMax[k]);
        if (centre < box.boundsMin[k] || centre > box.boundsMax[k]) return false;
    }
    return true;
}

double overlapVolume(const SurfaceFootprint& a, const SurfaceFootprint& b) {
    double v = 1.0;
    for (int k = 0; k < 3; ++k)
        v *= std::max(0.0, std::min(a.boundsMax[k], b.boundsMax[k]) - std::max(a.boundsMin[k], b.boundsMin[k]));
    return v;
}

// Boxes that hold each other's centres: the same surface, moved further than a block.
int matchByBounds(const std::vector<const SurfaceFootprint*>& previous, const SurfaceFootprint& surface) {
    int best = -1;
    double bestOverlap = -1.0;
    for (std::size_t i = 0; i < previous.size(); ++i) {
        if (!containsCentreOf(*previous[i], surface) || !containsCentreOf(surface, *previous[i])) continue;
        const double overlap = overlapVolume(*previous[i], surface);
        if (overlap > bestOverlap) {
            bestOverlap = overlap;
            best = static_cast<int>(i);
        }
    }
    return best;
}

}  // namespace

Vec3d edgeCrossing(const Volume& volume, double iso, const GridEdge& e) {
    const int x1 = e.x + (e.axis == 0), y1 = e.y + (e.axis == 1), z1 = e.z + (e.axis == 2);
    const double a = volume.value(e.x, e.y, e.z), b = volume.value(x1, y1, z1);
    const double t = b != a ? std::clamp((iso - a) / (b - a), 0.0, 1.0) : 0.5;
    Vec3d g{double(e.x), double(e.y), double(e.z)};
    g[std::size_t(e.axis)] += t;
    return gridToWorld(volume, g);
}

std::optional<FollowedSeed> followSeed(const Volume& volume, double iso, const Vec3d& point) {
    const Dims& n = volume.dims();
    if (n[0] < 2 || n[1] < 2 || n[2] < 2) return std::nullopt;
    Vec3d g{};
    for (int k = 0; k < 3; ++k) {
        g[k] = (point[k] - volume.origin()[k]) / volume.spacing()[k];
        if (!std::isfinite(g[k])) return std::nullopt;
        g[k] = std::clamp(g[k], 0.0, double(n[k] - 1));
    }
    if (const std::optional<Vec3d> crossing = walkToIsovalue(volume, iso, g)) {
        if (auto seed = nearestCrossingWithin(volume, iso, *crossing, 1)) return seed;
    }
    return nearestCrossingWithin(volume, iso, point, kFollowNeighbourhood);
}

SurfaceFootprint footprintOf(const Mesh& mesh) {
    SurfaceFootprint footprint;
    footprint.triangles = mesh.triangleCount();
    const std::size_t count = mesh.vertexEdges.size();
    const std::size_t stride = std::max<std::size_t>(1, (count + kFootprintSamples - 1) / kFootprintSamples);
    footprint.blocks.reserve(count / stride + 1);
    for (std::size_t i = 0; i < count; i += stride) footprint.blocks.push_back(blockKey(mesh.vertexEdges[i]));
    std::sort(footprint.blocks.begin(), footprint.blocks.end());
    footprint.blocks.erase(std::unique(footprint.blocks.begin(), footprint.blocks.end()), footprint.blocks.end());
    footprint.blocks.shrink_to_fit();
    if (!mesh.vertices.empty()) {
        footprint.boundsMin = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                               std::numeric_limits<double>::infinity()};
        footprint.boundsMax = {-footprint.boundsMin[0], -footprint.boundsMin[1], -footprint.boundsMin[2]};
        for (const Vertex& v : mesh.vertices) {
            for (int k = 0; k < 3; ++k) {
                footprint.boundsMin[k] = std::min(footprint.boundsMin[k], double(v.position[k]));
                footprint.boundsMax[k] = std::max(footprint.boundsMax[k], double(v.position[k]));
            }
        }
    }
    return footprint;
}

std::vector<int> matchSurfaces(const std::vector<const SurfaceFootprint*>& previous,
                               const std::vector<const SurfaceFootprint*>& next) {
    std::unordered_map<std::uint64_t, std::vector<int>> owners;
    for (std::size_t i = 0; i < previous.size(); ++i) {
        for (std::uint64_t block : previous[i]->blocks) owners[block].push_back(static_cast<int>(i));
    }
    std::vector<int> match(next.size(), -1);
    std::vector<std::size_t> votes(previous.size(), 0);
    std::vector<int> voted;
    for (std::size_t j = 0; j < next.size(); ++j) {
        voted.clear();
        for (std::uint64_t block : next[j]->blocks) {
            const auto found = owners.find(block);
            if (found == owners.end()) continue;
            for (int i : found->second) {
                if (votes[std::size_t(i)]++ == 0) voted.push_back(i);
            }
        }
        if (voted.empty()) {
            if (next[j]->triangles > 0) match[j] = matchByBounds(previous, *next[j]);
            continue;
        }
        std::size_t most = 0;
        for (int i : voted) most = std::max(most, votes[std::size_t(i)]);
        int best = -1;
        for (int i : voted) {
            if (double(votes[std::size_t(i)]) < kMergeShare * double(most)) continue;
            if (best < 0 || previous[std::size_t(i)]->triangles > previous[std::size_t(best)]->triangles ||
                (previous[std::size_t(i)]->triangles == previous[std::size_t(best)]->triangles && i < best)) {
                best = i;
            }
        }
        match[j] = best;
        for (int i : voted) votes[std::size_t(i)] = 0;
    }
    return match;
}

const char* presenceName(Presence presence) {
    switch (presence) {
        case Presence::Shown: return "shown";
        case Presence::Gone: return "gone";
        case Presence::Merged: return "merged";
    }
    return "shown";
}

}  // namespace isotrack
