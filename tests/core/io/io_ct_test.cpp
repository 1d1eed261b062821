// Acceptance: the CT sample in every format gives the same surface.
// assets/ct comes from scripts/get_ct.sh (which also runs make_ct_variants.py).
#include <catch2/catch.hpp>

#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"

using namespace isotrack;

namespace {

constexpr double kSkullIso = 400.5;

bool sameMesh(const Mesh& a, const Mesh& b) {
    return a.vertices.size() == b.vertices.size() && a.indices == b.indices &&
           std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vertex)) == 0;
}

bool sameSamples(const Volume& a, const Volume& b) {
    return a.dims() == b.dims() && a.type() == b.type() && a.byteSize() == b.byteSize() &&
           std::memcmp(a.bytes(), b.bytes(), a.byteSize()) == 0;
}

// The existing paths, or none (with a warning) when the CT has not been made.
std::vector<std::string> ctFiles(const std::vector<std::string>& names) {
    const std::string dir = std::string(ISOTRACK_SOURCE_DIR) + "/assets/ct/";
    std::vector<std::string> paths;
    for (const std::string& name : names) {
        if (!std::filesystem::exists(dir + name)) {
            WARN("skipped: " << dir + name << " is missing (scripts/get_ct.sh makes it)");
            return {};
        }
        paths.push_back(dir + name);
    }
    return paths;
}

}  // namespace

TEST_CASE("the CT as attached, detached and gzip NRRD, MetaImage and VTK legacy gives one identical surface",
          "[core][io][ct]") {
    const auto paths = ctFiles({"cranium.nrrd", "cranium.nhdr", "variants/cranium_gzip.nrrd", "variants/cranium.mhd",
                                "variants/cranium.mha", "variants/cranium_zlib.mha", "variants/cranium.vtk"});
    if (paths.empty()) return;
    const Volume reference = loadVolume(paths[0]);
    REQUIRE(reference.dims() == Dims{256, 256, 108});
    REQUIRE(reference.type() == ScalarType::Int16);
    const Mesh referenceMesh = marchingCubes(reference, kSkullIso);
    REQUIRE(referenceMesh.triangleCount() > 100000);
    for (std::size_t i = 1; i < paths.size(); ++i) {
        CAPTURE(paths[i]);
        const Volume v = loadVolume(paths[i]);
        REQUIRE(sameSamples(v, reference));
        CHECK(v.spacing() == reference.spacing());
        CHECK(v.origin() == reference.origin());
        CHECK(v.direction() == reference.direction());
        const Mesh mesh = marchingCubes(v, kSkullIso);
        CHECK(mesh.triangleCount() == referenceMesh.triangleCount());
        CHECK(sameMesh(mesh, referenceMesh));
    }
}

TEST_CASE("the CT as big-endian NIfTI and its .nii.gz gives one identical surface, on the NRRD's samples",
          "[core][io][ct]") {
    const auto paths = ctFiles({"variants/cranium_be.nii", "variants/cranium_be.nii.gz", "cranium.nrrd"});
    if (paths.empty()) return;
    const Volume nii = loadVolume(paths[0]);
    const Volume gz = loadVolume(paths[1]);
    const Volume nrrd = loadVolume(paths[2]);
    REQUIRE(sameSamples(nii, nrrd));
    REQUIRE(sameSamples(gz, nrrd));
    CHECK(nii.spacing() == gz.spacing());
    // The NIfTI's sform is the NRRD's grid in RAS: the same LPS direction and origin.
    CHECK(nii.direction() == nrrd.direction());
    CHECK(nii.origin() == nrrd.origin());
    // pixdim is float32: the NRRD's spacing, rounded.
    for (std::size_t a = 0; a < 3; ++a) CHECK(nii.spacing()[a] == double(float(nrrd.spacing()[a])));
    const Mesh fromNii = marchingCubes(nii, kSkullIso);
    const Mesh fromGz = marchingCubes(gz, kSkullIso);
    CHECK(fromNii.triangleCount() == marchingCubes(nrrd, kSkullIso).triangleCount());
    CHECK(sameMesh(fromNii, fromGz));
}
