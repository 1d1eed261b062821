#pragma once
// Meshes and figures the mesh-processing tests share: procedural balls (whole,
// or cut by the volume's border), and the mean dihedral angle of a mesh.
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include "isotrack/extract.h"
#include "isotrack/fields.h"
#include "isotrack/volume.h"

namespace isotrack::test {

// A float32 volume whose value is r minus the distance to `centre`: a ball
// (above iso 0) of radius r, cut by the border where it reaches past it.
inline Volume ballVolume(Dims dims, Vec3d centre, double r) {
    Volume v(dims, ScalarType::Float32);
    for (int z = 0; z < dims[2]; ++z)
        for (int y = 0; y < dims[1]; ++y)
            for (int x = 0; x < dims[0]; ++x)
                v.setValue(x, y, z, r - std::hypot(x - centre[0], y - centre[1], z - centre[2]));
    return v;
}

inline Surface exhaustive(const Volume& volume, double iso, bool cap = false) {
    ExtractRequest request;
    request.iso = iso;
    request.measure = true;
    request.cap = cap;
    return extract(volume, request).front();
}

// The mean angle (radians) between the normals of triangles sharing an edge.
inline double meanDihedralAngle(const Mesh& mesh) {
    auto normal = [&](std::size_t t) {
        const float* a = mesh.vertices[mesh.indices[3 * t]].position;
        const float* b = mesh.vertices[mesh.indices[3 * t + 1]].position;
        const float* c = mesh.vertices[mesh.indices[3 * t + 2]].position;
        const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
        const double w[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
        std::array<double, 3> n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (double& component : n) component = length > 0 ? component / length : 0.0;
        return std::make_pair(n, length > 0);
    };
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> firstFace;
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        for (int k = 0; k < 3; ++k) {
            std::uint32_t a = mesh.indices[3 * t + std::size_t(k)], b = mesh.indices[3 * t + std::size_t(k + 1) % 3];
            if (a > b) std::swap(a, b);
            const auto [it, fresh] = firstFace.emplace(std::make_pair(a, b), t);
            if (fresh) continue;
            const auto [n1, ok1] = normal(it->second);
            const auto [n2, ok2] = normal(t);
            if (!ok1 || !ok2) continue;
            const double d = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
            sum += std::acos(std::max(-1.0, std::min(1.0, d)));
            ++count;
        }
    return count ? sum / double(count) : 0.0;
}

}  // namespace isotrack::test
