#pragma once
// The unit cube of marching cubes, numbered once for all of isotrack.
//
//            7 -------- 6          vertices (x, y, z offsets)      edges (vertex pairs)
//           /|         /|          0 (0,0,0)   4 (0,0,1)           0: 0-1   4: 4-5   8: 0-4
//          / |        / |          1 (1,0,0)   5 (1,0,1)           1: 1-2   5: 5-6   9: 1-5
//         4 -------- 5  |          2 (1,1,0)   6 (1,1,1)           2: 2-3   6: 6-7  10: 2-6
//         |  3 ------|- 2          3 (0,1,0)   7 (0,1,1)           3: 3-0   7: 7-4  11: 3-7
//         | /        | /
//         |/         |/     z      faces (outward normal): 0 -x, 1 +x, 2 -y, 3 +y, 4 -z, 5 +z
//         0 -------- 1      | y
//                           |/__ x
//
// A configuration is an 8-bit mask whose bit i is set when vertex i is above the
// isovalue (sample >= iso, VTK's rule). This is the numbering of VTK's marching-cubes cases.
#include <array>
#include <cstdint>

namespace isotrack::cube {

constexpr int kVertexCount = 8;
constexpr int kEdgeCount = 12;
constexpr int kFaceCount = 6;

constexpr std::array<std::array<int, 3>, 8> kVertexOffset = {{
    {0, 0, 0},
    {1, 0, 0},
    {1, 1, 0},
    {0, 1, 0},
    {0, 0, 1},
    {1, 0, 1},
    {1, 1, 1},
    {0, 1, 1},
}};

constexpr std::array<std::array<int, 2>, 12> kEdgeVertices = {{
    {0, 1},
    {1, 2},
    {2, 3},
    {3, 0},
    {4, 5},
    {5, 6},
    {6, 7},
    {7, 4},
    {0, 4},
    {1, 5},
    {2, 6},
    {3, 7},
}};

// Face f is perpendicular to axis f / 2, on the low side when f is even.
constexpr int faceAxis(int face) { return face / 2; }
constexpr int faceSide(int face) { return face % 2; }

// The axis an edge runs along, and the offset of its lower end within the cube.
int edgeAxis(int edge);
const std::array<int, 3>& edgeOrigin(int edge);
// The edge with the given lower-end offset and axis.
int edgeAt(const std::array<int, 3>& origin, int axis);

// The four vertices of a face in cyclic order, and its four edges (edge k joins
// vertex k and vertex k+1 of that order).
const std::array<int, 4>& faceVertices(int face);
const std::array<int, 4>& faceEdges(int face);
bool edgeOnFace(int edge, int face);

// The same grid edge seen from the cube across `face` (e.g. edge 1 on the +x face
// is edge 3 of the cube at x + 1). `edge` must lie on `face`.
int edgeAcrossFace(int edge, int face);
constexpr int oppositeFace(int face) { return face ^ 1; }

// A rotation of the cube as permutations of its vertices, edges and faces.
struct Rotation {
    std::array<std::array<int, 3>, 3> matrix;  // acts on centred coordinates 2*offset-1
    std::array<int, 8> vertex;                 // vertex v moves to vertex[v]
    std::array<int, 12> edge;
    std::array<int, 6> face;
};

// The 24 proper rotations, generated as the closure of 90-degree turns about x, y
// and z; element 0 is the identity.
const std::array<Rotation, 24>& rotations();

// The configuration obtained by moving every vertex of `config` with `rotation`.
std::uint8_t rotateConfig(std::uint8_t config, const Rotation& rotation);

}  // namespace isotrack::cube
