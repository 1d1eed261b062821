// Index-to-world transforms: what each loader keeps, and meshes written in the
// LPS, RAS and voxel frames (positions, normals, winding).
#include <catch2/catch.hpp>

#include <cctype>
#include <cmath>
#include <set>
#include <sstream>
#include <string>

#include "core/io/io_test_files.h"
#include "isotrack/errors.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/orientation.h"

using namespace isotrack;
using isotrack::testing::niftiFile;
using isotrack::testing::NiftiHeader;
using isotrack::testing::niftiHeaderFor;
using isotrack::testing::sampleBytes;
using isotrack::testing::TempDir;
using isotrack::testing::writeFile;

namespace {

using Affine = std::array<std::array<double, 4>, 3>;  // rows, as NIfTI's srow_x..z

constexpr int kN = 18;
const Vec3d kCentre{8.5, 9.25, 7.75};  // in voxel indices, off the grid's symmetry

// A ball (value >= 0 inside) in a kN^3 float volume with unit geometry.
Volume ball() {
    Volume v({kN, kN, kN}, ScalarType::Float32);
    for (int z = 0; z < kN; ++z)
        for (int y = 0; y < kN; ++y)
            for (int x = 0; x < kN; ++x)
                v.setValue(x, y, z, 6.0 - std::hypot(x - kCentre[0], y - kCentre[1], z - kCentre[2]));
    return v;
}

Vec3d apply(const Affine& m, const Vec3d& p) {
    Vec3d out{};
    for (std::size_t r = 0; r < 3; ++r) out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3];
    return out;
}

// The ball as a NIfTI whose sform is `sform` (float, as the file stores it).
Volume loadWithSform(const TempDir& dir, const Affine& sform, const std::string& name) {
    const Volume v = ball();
    NiftiHeader h = niftiHeaderFor(v, false);
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 4; ++c) h.srow[r][c] = float(sform[r][c]);
    writeFile(dir.file(name), niftiFile(h, sampleBytes(v, false)));
    return loadNifti(dir.file(name));
}

Affine floatRounded(Affine m) {
    for (auto& row : m)
        for (double& c : row) c = double(float(c));
    return m;
}

// The most common NIfTI: axis-aligned in RAS with an origin off zero. Its LPS
// direction is diag(-1,-1,1), so RAS is the identity and only the origin moves.
Affine alignedRasSform() { return {{{2, 0, 0, -64}, {0, 2, 0, -64}, {0, 0, 3, -96}}}; }

// A flip of x (the mirrored case), and an oblique one: turned 30 degrees
// about an axis, anisotropic, with i mirrored (det -1).
Affine flippedSform() { return floatRounded({{{-0.9, 0, 0, 40.5}, {0, 1.1, 0, -20.25}, {0, 0, 1.3, 7}}}); }

Affine obliqueSform() {
    const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
    const Vec3d spacing{0.8, 1.2, 1.5};
    // Columns: rotation about z by 30 degrees, then about x by 30 degrees; i reversed.
    const double r[3][3] = {{c, -s, 0}, {s * c, c * c, -s}, {s * s, c * s, c}};
    Affine m{};
    for (std::size_t row = 0; row < 3; ++row)
        for (std::size_t col = 0; col < 3; ++col) m[row][col] = r[row][col] * spacing[col] * (col == 0 ? -1 : 1);
    m[0][3] = -100.25, m[1][3] = 55.5, m[2][3] = 12.125;
    return floatRounded(m);
}

double dot(const Vec3d& a, const Vec3d& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3d sub(const float* a, const float* b) { return {double(a[0]) - b[0], double(a[1]) - b[1], double(a[2]) - b[2]}; }
Vec3d cross(const Vec3d& a, const Vec3d& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Normals point away from `centre` (out of the ball) and every triangle's
// winding agrees with its corners' normals.
void requireOutward(const Mesh& mesh, const Vec3d& centre) {
    REQUIRE(mesh.triangleCount() > 200);
    std::size_t inward = 0, against = 0;
    for (const Vertex& v : mesh.vertices) {
        const Vec3d out{v.position[0] - centre[0], v.position[1] - centre[1], v.position[2] - centre[2]};
        if (dot(out, {v.normal[0], v.normal[1], v.normal[2]}) <= 0) ++inward;
    }
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const Vertex& a = mesh.vertices[mesh.indices[t]];
        const Vertex& b = mesh.vertices[mesh.indices[t + 1]];
        const Vertex& c = mesh.vertices[mesh.indices[t + 2]];
        const Vec3d n = cross(sub(b.position, a.position), sub(c.position, a.position));
        if (dot(n, n) < 1e-12) continue;
        const Vec3d sum{double(a.normal[0]) + b.normal[0] + c.normal[0],
                        double(a.normal[1]) + b.normal[1] + c.normal[1],
                        double(a.normal[2]) + b.normal[2] + c.normal[2]};
        if (dot(n, sum) <= 0) ++against;
    }
    CHECK(inward == 0);
    CHECK(against == 0);
}

Mesh inFrame(const Volume& v, WorldFrame frame) {
    Mesh mesh = marchingCubes(v, 0.0);
    transformMesh(mesh, gridToFrame(v, frame));
    return mesh;
}

}  // namespace

TEST_CASE("a NIfTI sform, axis-aligned, flipped or oblique: exported vertices are the sform applied to voxel positions",
          "[core][orientation]") {
    TempDir dir;
    for (const auto& [name, sform] : {std::pair<std::string, Affine>{"ras.nii", alignedRasSform()},
                                      {"flipped.nii", flippedSform()},
                                      {"oblique.nii", obliqueSform()}}) {
        INFO(name);
        const Volume v = loadWithSform(dir, sform, name);
        const Mesh voxel = inFrame(v, WorldFrame::Voxel);
        writePly(dir.file("ras.ply"), inFrame(v, WorldFrame::Ras));
        const Mesh ras = readPly(dir.file("ras.ply"));
        REQUIRE(ras.vertices.size() == voxel.vertices.size());
        REQUIRE(ras.indices.size() == voxel.indices.size());
        double worst = 0;
        for (std::size_t i = 0; i < ras.vertices.size(); ++i) {
            const float* q = voxel.vertices[i].position;
            const Vec3d expected = apply(sform, {q[0], q[1], q[2]});
            for (std::size_t a = 0; a < 3; ++a)
                worst = std::max(worst, std::fabs(ras.vertices[i].position[a] - expected[a]));
        }
        CHECK(worst < 1e-4);
        // Voxel positions are indices: the ball's own, whatever the sform.
        requireOutward(voxel, kCentre);
        requireOutward(ras, apply(sform, kCentre));
        // LPS is RAS with x and y negated, same triangles.
        const Mesh lps = inFrame(v, WorldFrame::Lps);
        const Vec3d centreRas = apply(sform, kCentre);
        requireOutward(lps, {-centreRas[0], -centreRas[1], centreRas[2]});
        CHECK(lps.indices == ras.indices);
    }
}

TEST_CASE("the direction's determinant decides whether triangles are rewound", "[core][orientation]") {
    TempDir dir;
    const Mesh plain = marchingCubes(ball(), 0.0);
    const Volume flipped = loadWithSform(dir, flippedSform(), "f.nii");
    CHECK(determinant(flipped.direction()) == Approx(-1.0));
    const Mesh mirrored = inFrame(flipped, WorldFrame::Lps);
    REQUIRE(mirrored.indices.size() == plain.indices.size());
    CHECK(mirrored.indices[0] == plain.indices[0]);
    CHECK(mirrored.indices[1] == plain.indices[2]);
    CHECK(mirrored.indices[2] == plain.indices[1]);
}

TEST_CASE("an axis-aligned volume's meshes are untouched in the default frame", "[core][orientation]") {
    Volume v = ball();
    v.setSpacing({0.5, 0.75, 2.0});
    v.setOrigin({-3.25, 10, 4});
    const Mesh plain = marchingCubes(v, 0.0);
    const Mesh lps = inFrame(v, WorldFrame::Lps);
    REQUIRE(plain.vertices.size() == lps.vertices.size());
    CHECK(std::memcmp(plain.vertices.data(), lps.vertices.data(), plain.vertices.size() * sizeof(Vertex)) == 0);
    CHECK(plain.indices == lps.indices);
    CHECK(gridToFrame(v, WorldFrame::Lps).identity());
    // RAS negates x and y of positions and normals and keeps the winding.
    const Mesh ras = inFrame(v, WorldFrame::Ras);
    CHECK(ras.indices == plain.indices);
    CHECK(ras.vertices[7].position[0] == Approx(-plain.vertices[7].position[0]));
    CHECK(ras.vertices[7].normal[1] == Approx(-plain.vertices[7].normal[1]));
    CHECK(ras.vertices[7].position[2] == plain.vertices[7].position[2]);
}

TEST_CASE("a seed in a frame comes back to the grid point it names", "[core][orientation]") {
    TempDir dir;
    const Volume v = loadWithSform(dir, obliqueSform(), "o.nii");
    for (WorldFrame frame : {WorldFrame::Lps, WorldFrame::Ras, WorldFrame::Voxel}) {
        const FrameTransform t = gridToFrame(v, frame);
        const Vec3d grid{v.origin()[0] + 3.5 * v.spacing()[0], v.origin()[1] + 2 * v.spacing()[1],
                         v.origin()[2] + 9 * v.spacing()[2]};
        const Vec3d back = t.toGrid(t.apply(grid));
        for (std::size_t a = 0; a < 3; ++a) CHECK(back[a] == Approx(grid[a]).margin(1e-9));
    }
    const Vec3d index =
        gridToFrame(v, WorldFrame::Voxel).apply({v.origin()[0] + 3.5 * v.spacing()[0], v.origin()[1], v.origin()[2]});
    CHECK(index[0] == Approx(3.5));
    // LPS from the loader's transform equals the sform, flipped.
    const Vec3d lps = indexToWorld(v, {3, 4, 5});
    const Vec3d ras = apply(obliqueSform(), {3, 4, 5});
    CHECK(lps[0] == Approx(-ras[0]).margin(1e-5));
    CHECK(lps[1] == Approx(-ras[1]).margin(1e-5));
    CHECK(lps[2] == Approx(ras[2]).margin(1e-5));
}

TEST_CASE("NIfTI: sform first, then qform (quaternion and qfac), then pixdim", "[core][orientation][nifti]") {
    TempDir dir;
    const Volume v = ball();
    NiftiHeader h = niftiHeaderFor(v, false);
    const std::string samples = sampleBytes(v, false);
    // qform: 90 degrees about z (b = c = 0, d = sin 45), qfac -1 mirrors k.
    h.sformCode = 0;
    h.qformCode = 1;
    h.pixdim[0] = -1;
    h.pixdim[1] = 2, h.pixdim[2] = 3, h.pixdim[3] = 4;
    h.quatern[2] = float(std::sqrt(0.5));
    h.qoffset[0] = 10, h.qoffset[1] = 20, h.qoffset[2] = 30;
    writeFile(dir.file("q.nii"), niftiFile(h, samples));
    const Volume qv = loadNifti(dir.file("q.nii"));
    // RAS: i -> +y, j -> -x, k -> -z; in LPS: i -> -y, j -> +x, k -> -z.
    const Mat3d expected{{{0, -1, 0}, {1, 0, 0}, {0, 0, -1}}};
    for (std::size_t a = 0; a < 3; ++a)
        for (std::size_t r = 0; r < 3; ++r) CHECK(qv.direction()[a][r] == Approx(expected[a][r]).margin(1e-6));
    CHECK(qv.spacing() == Vec3d{2, 3, 4});
    CHECK(qv.origin() == Vec3d{-10, -20, 30});
    CHECK(orientationCode(qv.direction()) == "ALI");
    // The sform wins over the qform, its spacing over pixdim.
    h.sformCode = 2;
    for (std::size_t r = 0; r < 3; ++r)
        for (std::size_t c = 0; c < 3; ++c) h.srow[r][c] = r == c ? 1.0f : 0.0f;
    writeFile(dir.file("s.nii"), niftiFile(h, samples));
    const Volume sv = loadNifti(dir.file("s.nii"));
    CHECK(orientationCode(sv.direction()) == "RAS");
    CHECK(sv.spacing() == Vec3d{1, 1, 1});
    // Neither: the grid as given.
    h.sformCode = 0, h.qformCode = 0;
    writeFile(dir.file("none.nii"), niftiFile(h, samples));
    CHECK(isIdentity(loadNifti(dir.file("none.nii")).direction()));
    // A sheared sform is refused by name.
    h.sformCode = 1;
    h.srow[0][1] = 0.5f;
    writeFile(dir.file("shear.nii"), niftiFile(h, samples));
    CHECK_THROWS_WITH(loadNifti(dir.file("shear.nii")),
                      Catch::Contains("shear.nii") && Catch::Contains("srow") && Catch::Contains("orthogonal"));
}

TEST_CASE("NRRD space and space directions; writeNrrd keeps a turned volume", "[core][orientation][nrrd]") {
    TempDir dir;
    const std::string samples(8, '\1');
    const std::string header =
        "NRRD0005\ntype: uint8\ndimension: 3\nspace: right-anterior-superior\nsizes: 2 2 2\n"
        "space directions: (0,2,0) (-3,0,0) (0,0,-0.5)\nspace origin: (1,2,3)\nencoding: raw\n\n";
    writeFile(dir.file("ras.nrrd"), header + samples);
    const Volume v = loadNrrd(dir.file("ras.nrrd"));
    CHECK(v.spacing() == Vec3d{2, 3, 0.5});
    CHECK(v.direction() == Mat3d{{{0, -1, 0}, {3.0 / 3, 0, 0}, {0, 0, -1}}});
    CHECK(v.origin() == Vec3d{-1, -2, 3});
    CHECK(orientationCode(v.direction()) == "ALI");
    writeNrrd(v, dir.file("back.nrrd"));
    const Volume back = loadNrrd(dir.file("back.nrrd"));
    CHECK(back.direction() == v.direction());
    CHECK(back.spacing() == v.spacing());
    CHECK(back.origin() == v.origin());
    // Not orthogonal: refused, naming the field.
    writeFile(dir.file("skew.nrrd"),
              "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\n"
              "space directions: (1,0,0) (1,1,0) (0,0,1)\nencoding: raw\n\n" +
                  samples);
    CHECK_THROWS_WITH(loadNrrd(dir.file("skew.nrrd")),
                      Catch::Contains("space directions") && Catch::Contains("orthogonal"));
}

TEST_CASE("MetaImage TransformMatrix, else AnatomicalOrientation", "[core][orientation][metaimage]") {
    TempDir dir;
    const std::string samples(8, '\1');
    const std::string base =
        "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\nOffset = 1 2 3\n";
    writeFile(dir.file("tm.mha"), base +
                                      "TransformMatrix = 0 1 0 -1 0 0 0 0 1\nAnatomicalOrientation = RAI\n"
                                      "ElementDataFile = LOCAL\n" +
                                      samples);
    const Volume tm = loadMetaImage(dir.file("tm.mha"));
    CHECK(tm.direction() == Mat3d{{{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}});
    CHECK(tm.origin() == Vec3d{1, 2, 3});
    writeFile(dir.file("ao.mha"), base + "AnatomicalOrientation = LPS\nElementDataFile = LOCAL\n" + samples);
    CHECK(orientationCode(loadMetaImage(dir.file("ao.mha")).direction()) == "RAI");
    writeFile(dir.file("rai.mha"), base + "AnatomicalOrientation = RAI\nElementDataFile = LOCAL\n" + samples);
    CHECK(isIdentity(loadMetaImage(dir.file("rai.mha")).direction()));
    writeFile(dir.file("bad.mha"), base + "AnatomicalOrientation = RRI\nElementDataFile = LOCAL\n" + samples);
    CHECK_THROWS_WITH(loadMetaImage(dir.file("bad.mha")), Catch::Contains("AnatomicalOrientation"));
}

TEST_CASE("orientation codes and world bounds", "[core][orientation]") {
    CHECK(orientationCode(kIdentityDirection) == "LPS");
    CHECK(orientationCode(flipRasLps(kIdentityDirection)) == "RAS");
    CHECK(orientationCode({{{1, 0, 0}, {0, 1, 0}, {0, 0, -1}}}) == "LPI");
    Volume v({3, 5, 2}, ScalarType::UInt8, {2, 1, 4}, {10, 0, 0});
    v.setDirection({{{0, 1, 0}, {-1, 0, 0}, {0, 0, 1}}});
    const auto box = worldBounds(v);
    CHECK(box[0] == Vec3d{6, 0, 0});
    CHECK(box[1] == Vec3d{10, 4, 4});
    CHECK_THROWS_AS(parseWorldFrame("xyz"), InputError);
    CHECK(parseWorldFrame("RAS") == WorldFrame::Ras);
}

TEST_CASE("frames by name, in any case", "[core][orientation]") {
    std::set<std::string> names;
    for (const WorldFrame frame : kWorldFrames) {
        const std::string name = worldFrameName(frame);
        CHECK(parseWorldFrame(name) == frame);
        std::string upper = name;
        for (char& c : upper) c = char(std::toupper(static_cast<unsigned char>(c)));
        CHECK(parseWorldFrame(upper) == frame);
        names.insert(name);
    }
    CHECK(names == std::set<std::string>{"lps", "ras", "voxel"});
    try {
        parseWorldFrame("xyz");
        FAIL("xyz was accepted");
    } catch (const InputError& error) {
        const std::string message = error.what();
        CHECK(message.find('\n') == std::string::npos);
        CHECK(message.find("\"xyz\"") != std::string::npos);
        for (const WorldFrame frame : kWorldFrames) CHECK(message.find(worldFrameName(frame)) != std::string::npos);
    }
}
