#pragma once
// An indexed triangle mesh in world units, as the extractors emit it.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace isotrack {

struct Vertex {
    float position[3];
    float normal[3];  // unit, pointing from above the isovalue towards below it
};

// Identifies the grid edge a vertex lies on: the edge from sample (x, y, z)
// one step along `axis` (0 = x, 1 = y, 2 = z).
struct GridEdge {
    int x = 0, y = 0, z = 0;
    int axis = 0;
    friend bool operator==(const GridEdge& a, const GridEdge& b) {
        return a.x == b.x && a.y == b.y && a.z == b.z && a.axis == b.axis;
    }
};

// A GridEdge in 8 bytes (20 bits per coordinate, 2 for the axis), as meshes keep one per vertex.
class PackedGridEdge {
public:
    PackedGridEdge() = default;
    PackedGridEdge(const GridEdge& e)  // NOLINT(google-explicit-constructor): lossless for coordinates < 2^20
        : bits_(std::uint64_t(e.x) | std::uint64_t(e.y) << 20 | std::uint64_t(e.z) << 40 | std::uint64_t(e.axis) << 60) {}
    operator GridEdge() const {  // NOLINT(google-explicit-constructor)
        return GridEdge{int(bits_ & kMask), int(bits_ >> 20 & kMask), int(bits_ >> 40 & kMask), int(bits_ >> 60)};
    }

private:
    static constexpr std::uint64_t kMask = (std::uint64_t(1) << 20) - 1;
    std::uint64_t bits_ = 0;
};

struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;       // three per triangle, counter-clockwise seen from below
    std::vector<PackedGridEdge> vertexEdges;  // per vertex, the grid edge it was computed on

    std::size_t triangleCount() const { return indices.size() / 3; }
    // What a GPU holds of the mesh: vertices and indices.
    std::size_t drawByteSize() const { return vertices.size() * sizeof(Vertex) + indices.size() * sizeof(std::uint32_t); }
    // Everything, with the grid edge behind each vertex.
    std::size_t byteSize() const { return drawByteSize() + vertexEdges.size() * sizeof(PackedGridEdge); }
};

}  // namespace isotrack
