// mesh_distance A.ply B.ply: prints the sampled symmetric Hausdorff distance
// between two meshes (tests/core/mesh/mesh_distance.h), for the CLI tests;
// each direction's on stderr.
#include <algorithm>
#include <cstdio>
#include <exception>

#include "core/mesh/mesh_distance.h"
#include "isotrack/io.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: mesh_distance A.ply B.ply\n");
        return 2;
    }
    try {
        const isotrack::Mesh a = isotrack::readPly(argv[1]), b = isotrack::readPly(argv[2]);
        const double ab = isotrack::test::directedHausdorff(a, b), ba = isotrack::test::directedHausdorff(b, a);
        std::printf("%.9g\n", std::max(ab, ba));
        std::fprintf(stderr, "from %s: %.9g, from %s: %.9g\n", argv[1], ab, argv[2], ba);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "mesh_distance: %s\n", e.what());
        return 1;
    }
    return 0;
}
