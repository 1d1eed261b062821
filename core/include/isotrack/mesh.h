#pragma once
// An indexed triangle mesh in world units, as the extractors emit it.
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace isotrack {

// An allocator whose resize() leaves new elements of trivial types uninitialised
// (default-initialised), so an extractor can size its buffers once and let the
// threads that fill them be the first to touch their pages.
template <class T>
struct DefaultInitAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };
    DefaultInitAllocator() = default;
    template <class U>
    DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}  // NOLINT(google-explicit-constructor)

    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        std::allocator_traits<std::allocator<T>>::construct(static_cast<std::allocator<T>&>(*this), p,
                                                            std::forward<Args>(args)...);
    }
};

// The growable array meshes keep their buffers in.
template <class T>
using Buffer = std::vector<T, DefaultInitAllocator<T>>;

struct Vertex {
    float position[3];
    float normal[3];  // unit, pointing from above the isovalue towards below it
};

// The axis of a vertex inside cell (x, y, z) rather than on an edge: the
// trilinear table's interior vertices.
constexpr int kCellInterior = 3;

// Identifies the grid edge a vertex lies on: the edge from sample (x, y, z)
// one step along `axis` (0 = x, 1 = y, 2 = z; kCellInterior for a cell's
// interior vertex).
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
        : bits_(std::uint64_t(e.x) | std::uint64_t(e.y) << 20 | std::uint64_t(e.z) << 40 |
                std::uint64_t(e.axis) << 60) {}
    operator GridEdge() const {  // NOLINT(google-explicit-constructor)
        return GridEdge{int(bits_ & kMask), int(bits_ >> 20 & kMask), int(bits_ >> 40 & kMask), int(bits_ >> 60)};
    }

private:
    static constexpr std::uint64_t kMask = (std::uint64_t(1) << 20) - 1;
    std::uint64_t bits_;  // uninitialised when default-constructed, as Buffer's resize relies on
};

struct Mesh {
    Buffer<Vertex> vertices;
    Buffer<std::uint32_t> indices;       // three per triangle, counter-clockwise seen from below
    Buffer<PackedGridEdge> vertexEdges;  // per vertex, the grid edge it was computed on

    std::size_t triangleCount() const { return indices.size() / 3; }
    // What a GPU holds of the mesh: vertices and indices.
    std::size_t drawByteSize() const {
        return vertices.size() * sizeof(Vertex) + indices.size() * sizeof(std::uint32_t);
    }
    // Everything, with the grid edge behind each vertex.
    std::size_t byteSize() const { return drawByteSize() + vertexEdges.size() * sizeof(PackedGridEdge); }
};

}  // namespace isotrack
