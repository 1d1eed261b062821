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

struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise seen from below
    std::vector<GridEdge> vertexEdges;   // per vertex, the grid edge it was computed on

    std::size_t triangleCount() const { return indices.size() / 3; }
    std::size_t byteSize() const {
        return vertices.size() * sizeof(Vertex) + indices.size() * sizeof(std::uint32_t);
    }
};

}  // namespace isotrack
