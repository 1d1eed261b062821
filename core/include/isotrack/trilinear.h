#pragma once
// The trilinear table: the topology of the trilinear interpolant of a cube's
// eight samples, in the spirit of Chernyaev's Marching Cubes 33 (1995), Lewiner
// et al. (2003) and Custodio et al. (2013).
//
// A cube's surface is not a function of its configuration alone. Each ambiguous
// face (diagonal corners alternating) is decided by Nielson & Hamann's
// asymptotic decider from its four samples only, so two cubes sharing a face cut
// it the same way. The decided faces fix the loops the surface draws on the
// cube's boundary; inside the cube, the loops bound disks, or two of them bound
// a tunnel when two regions of one sign that are apart on the boundary meet in
// the interior (the interior test, made exactly by sweeping planes through the
// cube, see trilinear_decider.cpp).
//
// A subcase is (configuration, decided faces, tunnel). Its entry is generated,
// not written: loops from the decided faces, each disk fanned from a corner or,
// when every fan would lay a chord on a cube face, from a vertex inside the
// cell, and a tunnel as a band between its two loops (through a vertex inside
// the cell, or a ring of them, where the loops cannot be joined directly).
// Corner indices 0..11 are cube edges; kInteriorVertex + k is the cell's k-th
// interior vertex.
#include <array>
#include <cstdint>
#include <vector>

namespace isotrack {

constexpr int kInteriorVertex = 12;
constexpr int kMaxInteriorVertices = 6;
constexpr int kMaxTrilinearTriangles = 32;

// Where an interior vertex goes: the mean of the vertices on the cube edges in
// `around`, or, with an anchor edge, halfway from the anchor's vertex to that mean.
struct InteriorVertex {
    std::uint16_t around = 0;
    std::int8_t anchor = -1;
};

struct TrilinearCase {
    std::uint8_t config = 0;
    std::uint8_t faceJoined = 0;  // bit f: on ambiguous face f the corners above are joined
    // The smallest vertex of each of the two boundary regions the tunnel joins; -1 without one.
    std::array<std::int8_t, 2> tunnel{{-1, -1}};
    std::uint8_t pieceCount = 0;  // separate pieces of surface in the cube
    std::uint8_t loopCount = 0;
    std::uint8_t interiorCount = 0;
    std::array<InteriorVertex, kMaxInteriorVertices> interior{};
    std::uint8_t triangleCount = 0;
    std::array<std::array<std::int8_t, 3>, kMaxTrilinearTriangles> triangles{};
};

class TrilinearTable {
public:
    TrilinearTable();
    // The subcases of a configuration with the given decided faces: the first
    // has no tunnel, the others one tunnel each.
    const TrilinearCase* begin(std::uint8_t config, std::uint8_t faceJoined) const {
        return cases_.data() + first_[index(config, faceJoined)];
    }
    int count(std::uint8_t config, std::uint8_t faceJoined) const { return count_[index(config, faceJoined)]; }
    const std::vector<TrilinearCase>& cases() const { return cases_; }

private:
    static std::size_t index(std::uint8_t config, std::uint8_t faceJoined) {
        return std::size_t(config) << 6 | faceJoined;
    }
    std::vector<TrilinearCase> cases_;
    std::array<std::uint16_t, 256 * 64> first_{};
    std::array<std::uint8_t, 256 * 64> count_{};
};

const TrilinearTable& trilinearTable();

// The faces of `config` whose diagonal corners alternate, as a 6-bit mask.
std::uint8_t ambiguousFaces(std::uint8_t config);

// The asymptotic decider: bit f set when, on ambiguous face f, the corners
// above the isovalue are joined. `values` are the cube's samples minus the
// isovalue, in cube order; `config` is their classification (bit set: >= 0).
std::uint8_t decideFaces(const double values[8], std::uint8_t config);

// The subcase of the trilinear interpolant of `values` (samples minus the
// isovalue, in cube order) classified as `config`.
const TrilinearCase& classifyTrilinear(const double values[8], std::uint8_t config);

}  // namespace isotrack
