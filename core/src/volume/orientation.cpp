// Direction matrices and frames: see isotrack/orientation.h.
#include "isotrack/orientation.h"

#include <algorithm>
#include <cmath>

#include "isotrack/errors.h"

namespace isotrack {

namespace {

constexpr double kMaxCosine = 1e-4;

double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

Vec3d cross(const Vec3d& a, const Vec3d& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The inverse by cofactors: rows of the inverse are the cross products of columns.
Mat3d inverse(const Mat3d& m) {
    const double det = determinant(m);
    const Vec3d r0 = cross(m[1], m[2]), r1 = cross(m[2], m[0]), r2 = cross(m[0], m[1]);
    Mat3d inv{};
    for (std::size_t c = 0; c < 3; ++c) inv[c] = {r0[c] / det, r1[c] / det, r2[c] / det};
    return inv;
}

Mat3d transpose(const Mat3d& m) {
    Mat3d t{};
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c) t[c][r] = m[r][c];
    return t;
}

}  // namespace

const char* worldFrameName(WorldFrame frame) {
    switch (frame) {
        case WorldFrame::Lps: return "lps";
        case WorldFrame::Ras: return "ras";
        case WorldFrame::Voxel: return "voxel";
    }
    return "lps";
}

WorldFrame parseWorldFrame(const std::string& name) {
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (lower == "lps") return WorldFrame::Lps;
    if (lower == "ras") return WorldFrame::Ras;
    if (lower == "voxel") return WorldFrame::Voxel;
    throw InputError("unknown frame \"" + name + "\" (expected lps, ras or voxel)");
}

std::optional<Mat3d> directionFromAxes(const Mat3d& axes, Vec3d* lengths) {
    Mat3d direction{};
    Vec3d length{};
    for (std::size_t a = 0; a < 3; ++a) {
        length[a] = std::sqrt(dot(axes[a], axes[a]));
        if (!(length[a] > 0) || !std::isfinite(length[a])) return std::nullopt;
        for (std::size_t r = 0; r < 3; ++r) direction[a][r] = axes[a][r] / length[a];
    }
    for (std::size_t a = 0; a < 3; ++a)
        if (std::fabs(dot(direction[a], direction[(a + 1) % 3])) > kMaxCosine) return std::nullopt;
    if (lengths) *lengths = length;
    return direction;
}

double determinant(const Mat3d& m) { return dot(m[0], cross(m[1], m[2])); }

Vec3d multiply(const Mat3d& m, const Vec3d& v) {
    Vec3d out{};
    for (std::size_t r = 0; r < 3; ++r) out[r] = m[0][r] * v[0] + m[1][r] * v[1] + m[2][r] * v[2];
    return out;
}

Mat3d multiply(const Mat3d& a, const Mat3d& b) {
    Mat3d out{};
    for (std::size_t c = 0; c < 3; ++c) out[c] = multiply(a, b[c]);
    return out;
}

bool isIdentity(const Mat3d& m) { return m == kIdentityDirection; }

Vec3d flipRasLps(const Vec3d& v) { return {-v[0], -v[1], v[2]}; }

Mat3d flipRasLps(const Mat3d& m) { return {flipRasLps(m[0]), flipRasLps(m[1]), flipRasLps(m[2])}; }

std::string orientationCode(const Mat3d& direction) {
    // LPS world axes, and the letter for each one's positive and negative side.
    const char positive[3] = {'L', 'P', 'S'}, negative[3] = {'R', 'A', 'I'};
    std::string code;
    for (const Vec3d& axis : direction) {
        std::size_t largest = 0;
        for (std::size_t r = 1; r < 3; ++r)
            if (std::fabs(axis[r]) > std::fabs(axis[largest])) largest = r;
        code += axis[largest] >= 0 ? positive[largest] : negative[largest];
    }
    return code;
}

Vec3d indexToWorld(const Volume& volume, const Vec3d& index) {
    const Vec3d& s = volume.spacing();
    const Vec3d grid{index[0] * s[0], index[1] * s[1], index[2] * s[2]};
    const Vec3d turned = multiply(volume.direction(), grid);
    return {volume.origin()[0] + turned[0], volume.origin()[1] + turned[1], volume.origin()[2] + turned[2]};
}

std::array<Vec3d, 2> worldBounds(const Volume& volume) {
    std::array<Vec3d, 2> bounds{};
    for (int corner = 0; corner < 8; ++corner) {
        Vec3d index{};
        for (std::size_t a = 0; a < 3; ++a)
            index[a] = (corner >> a & 1) ? double(std::max(volume.dims()[a] - 1, 0)) : 0.0;
        const Vec3d p = indexToWorld(volume, index);
        for (std::size_t a = 0; a < 3; ++a) {
            bounds[0][a] = corner == 0 ? p[a] : std::min(bounds[0][a], p[a]);
            bounds[1][a] = corner == 0 ? p[a] : std::max(bounds[1][a], p[a]);
        }
    }
    return bounds;
}

bool FrameTransform::identity() const { return isIdentity(linear) && offset == Vec3d{0, 0, 0}; }

Vec3d FrameTransform::apply(const Vec3d& grid) const {
    const Vec3d p = multiply(linear, grid);
    return {p[0] + offset[0], p[1] + offset[1], p[2] + offset[2]};
}

Vec3d FrameTransform::toGrid(const Vec3d& point) const {
    return multiply(inverse(linear), Vec3d{point[0] - offset[0], point[1] - offset[1], point[2] - offset[2]});
}

FrameTransform gridToFrame(const Volume& volume, WorldFrame frame) {
    // grid = origin + S * index; LPS = origin + D * (grid - origin).
    const Vec3d& o = volume.origin();
    FrameTransform t;
    if (frame == WorldFrame::Voxel) {
        const Vec3d& s = volume.spacing();
        t.linear = {Vec3d{1 / s[0], 0, 0}, Vec3d{0, 1 / s[1], 0}, Vec3d{0, 0, 1 / s[2]}};
    } else {
        t.linear = frame == WorldFrame::Ras ? flipRasLps(volume.direction()) : volume.direction();
    }
    // LPS with an identity direction is the grid itself: no arithmetic on the origin, so it
    // stays exact. Any other frame moves the origin even when its linear part is the
    // identity (RAS of a diag(-1,-1,1) direction, voxel indices at unit spacing).
    if (frame == WorldFrame::Lps && isIdentity(t.linear)) return t;
    const Vec3d turned = multiply(t.linear, o);
    const Vec3d base = frame == WorldFrame::Ras ? flipRasLps(o) : frame == WorldFrame::Voxel ? Vec3d{0, 0, 0} : o;
    t.offset = {base[0] - turned[0], base[1] - turned[1], base[2] - turned[2]};
    return t;
}

void transformMesh(Mesh& mesh, const FrameTransform& transform) {
    if (transform.identity()) return;
    // Normals are gradients: they turn by the inverse transpose.
    const Mat3d normalMatrix = transpose(inverse(transform.linear));
    for (Vertex& v : mesh.vertices) {
        const Vec3d p = transform.apply({double(v.position[0]), double(v.position[1]), double(v.position[2])});
        Vec3d n = multiply(normalMatrix, Vec3d{double(v.normal[0]), double(v.normal[1]), double(v.normal[2])});
        const double length = std::sqrt(dot(n, n));
        if (length > 0)
            for (double& c : n) c /= length;
        for (std::size_t a = 0; a < 3; ++a) {
            v.position[a] = float(p[a]);
            v.normal[a] = float(n[a]);
        }
    }
    if (transform.mirrors())
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
            std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
}

void transformSurface(Surface& surface, const FrameTransform& transform) {
    if (transform.identity()) return;
    transformMesh(surface.mesh, transform);
    SurfaceStats& stats = surface.stats;
    for (std::size_t v = 0; v < surface.mesh.vertices.size(); ++v)
        for (std::size_t a = 0; a < 3; ++a) {
            const double c = surface.mesh.vertices[v].position[a];
            stats.boundsMin[a] = v == 0 ? c : std::min(stats.boundsMin[a], c);
            stats.boundsMax[a] = v == 0 ? c : std::max(stats.boundsMax[a], c);
        }
}

}  // namespace isotrack
