#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "isotrack/errors.h"
#include "isotrack/fields.h"

using namespace isotrack;

namespace {

struct Components {
    int count = 0;
    bool touchesBorder = false;
    std::vector<int> label;  // per sample, -1 when not above iso
};

// 6-connected components of the samples above iso.
Components aboveIsoComponents(const Volume& v, double iso) {
    const Dims d = v.dims();
    Components out;
    out.label.assign(v.sampleCount(), -1);
    std::vector<std::size_t> stack;
    for (int z = 0; z < d[2]; ++z)
        for (int y = 0; y < d[1]; ++y)
            for (int x = 0; x < d[0]; ++x) {
                const std::size_t start = v.index(x, y, z);
                if (out.label[start] >= 0 || !(v.value(x, y, z) > iso)) continue;
                out.label[start] = out.count;
                stack.push_back(start);
                while (!stack.empty()) {
                    const std::size_t i = stack.back();
                    stack.pop_back();
                    const int px = int(i % std::size_t(d[0]));
                    const int py = int(i / std::size_t(d[0]) % std::size_t(d[1]));
                    const int pz = int(i / (std::size_t(d[0]) * std::size_t(d[1])));
                    if (px == 0 || py == 0 || pz == 0 || px == d[0] - 1 || py == d[1] - 1 || pz == d[2] - 1)
                        out.touchesBorder = true;
                    const int nb[6][3] = {{-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
                    for (const auto& o : nb) {
                        const int qx = px + o[0], qy = py + o[1], qz = pz + o[2];
                        if (qx < 0 || qy < 0 || qz < 0 || qx >= d[0] || qy >= d[1] || qz >= d[2]) continue;
                        const std::size_t j = v.index(qx, qy, qz);
                        if (out.label[j] >= 0 || !(v.value(qx, qy, qz) > iso)) continue;
                        out.label[j] = out.count;
                        stack.push_back(j);
                    }
                }
                ++out.count;
            }
    return out;
}

double dist(const Vec3d& a, const Vec3d& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

}  // namespace

TEST_CASE("builtin field list", "[core][fields]") {
    std::vector<std::string> names;
    for (const FieldInfo& f : builtinFields()) {
        names.push_back(f.name);
        CHECK(f.defaultIso == fieldDefaultIso(f.name));
        CHECK(std::strlen(f.description) > 0);
    }
    CHECK(names == std::vector<std::string>{"sphere", "torus", "shells", "blobs", "gyroid", "marschner-lobb", "noise"});
    CHECK(fieldDefaultIso("ml") == 0.5);
    CHECK(fieldDefaultIso("noise") == 0.5);
    CHECK(fieldDefaultIso("sphere") == 0.0);
    CHECK_THROWS_AS(fieldDefaultIso("cube"), InputError);
}

TEST_CASE("parseFieldSpec", "[core][fields]") {
    CHECK(parseFieldSpec("sphere").size == 128);
    CHECK(parseFieldSpec("sphere").name == "sphere");
    CHECK(parseFieldSpec("marschner-lobb").size == 64);
    CHECK(parseFieldSpec("noise").size == 64);
    CHECK(parseFieldSpec("torus:40").size == 40);
    const FieldSpec ml = parseFieldSpec("ml:32");
    CHECK(ml.name == "marschner-lobb");
    CHECK(ml.size == 32);
    CHECK(parseFieldSpec("blobs:8").size == 8);
    CHECK(parseFieldSpec("blobs:1024").size == 1024);

    CHECK_THROWS_WITH(parseFieldSpec("cube:64"), Catch::Contains("\"cube\"") && Catch::Contains("sphere") &&
                                                     Catch::Contains("marschner-lobb") && Catch::Contains("noise"));
    CHECK_THROWS_AS(parseFieldSpec(""), InputError);
    CHECK_THROWS_AS(parseFieldSpec("Sphere"), InputError);
    CHECK_THROWS_AS(parseFieldSpec("sphere:"), InputError);
    CHECK_THROWS_AS(parseFieldSpec("sphere:abc"), InputError);
    CHECK_THROWS_AS(parseFieldSpec("sphere:64x"), InputError);
    CHECK_THROWS_AS(parseFieldSpec("sphere:-64"), InputError);
    CHECK_THROWS_AS(parseFieldSpec("sphere:64:2"), InputError);
    CHECK_THROWS_AS(parseFieldSpec("sphere:7"), InputError);
    CHECK_THROWS_AS(parseFieldSpec("sphere:1025"), InputError);
    CHECK_THROWS_AS(parseFieldSpec("sphere:99999999999999999999"), InputError);
    CHECK_THROWS_WITH(parseFieldSpec("sphere:7"), Catch::Contains("8..1024"));
    CHECK_THROWS_AS(makeField({"sphere", 4}), InputError);
    CHECK_THROWS_AS(makeField({"cube", 32}), InputError);
}

TEST_CASE("fields are float32 cubes, unit spacing, deterministic", "[core][fields]") {
    for (const FieldInfo& f : builtinFields()) {
        INFO(f.name);
        const Volume a = makeField({f.name, 24});
        const Volume b = makeField({f.name, 24});
        CHECK(a.type() == ScalarType::Float32);
        CHECK(a.dims() == Dims{24, 24, 24});
        CHECK(a.spacing() == Vec3d{1, 1, 1});
        CHECK(a.origin() == Vec3d{0, 0, 0});
        REQUIRE(a.byteSize() == b.byteSize());
        CHECK(std::memcmp(a.bytes(), b.bytes(), a.byteSize()) == 0);
        // Every field must straddle its default iso, or there is nothing to extract.
        const auto r = a.range();
        CHECK(r[0] < f.defaultIso);
        CHECK(r[1] > f.defaultIso);
    }
}

TEST_CASE("sphere field: positive inside, analytic radius", "[core][fields]") {
    const int n = 33;
    const Volume v = makeField({"sphere", n});
    const Vec3d c = sphereFieldCenter(n);
    const double r = sphereFieldRadius(n);
    CHECK(r == Approx(12.0));
    CHECK(c[0] == Approx(16.0371));
    CHECK(v.value(16, 16, 16) > 0);
    CHECK(v.value(16, 16, 16) == Approx(r - std::sqrt(3 * 0.0371 * 0.0371)).epsilon(1e-6));
    CHECK(v.value(0, 0, 0) < 0);
    CHECK(v.value(n - 1, n - 1, n - 1) < 0);
    for (int x = 0; x < n; ++x) CHECK(v.value(x, 16, 16) == Approx(r - dist({double(x), 16, 16}, c)).margin(1e-5));
}

TEST_CASE("torus field: inside the tube, not at its hole", "[core][fields]") {
    const int n = 65;
    const Volume v = makeField({"torus", n});
    const auto [ring, tube] = torusFieldRadii(n);
    CHECK(ring == Approx(0.28 * 64));
    CHECK(tube == Approx(0.1 * 64));
    const Vec3d c = sphereFieldCenter(n);
    CHECK(v.value(32, 32, 32) < 0);  // the hole
    const int onRing = int(std::lround(c[0] + ring));
    CHECK(v.value(onRing, 32, 32) > 0);
    CHECK(v.value(32, onRing, 32) > 0);
    CHECK(v.value(onRing, 32, 32 + int(tube) + 2) < 0);
    CHECK(v.value(0, 0, 0) < 0);
}

TEST_CASE("shells field: three nested surfaces", "[core][fields]") {
    const int n = 65;
    const Volume v = makeField({"shells", n});
    const auto radii = shellsFieldRadii(n);
    // Walk out from the centre along +x and count sign changes.
    int crossings = 0;
    for (int x = 33; x < n; ++x)
        if ((v.value(x - 1, 32, 32) > 0) != (v.value(x, 32, 32) > 0)) ++crossings;
    CHECK(crossings == 3);
    CHECK(v.value(32, 32, 32) > 0);
    CHECK(v.value(32 + int((radii[0] + radii[1]) / 2), 32, 32) < 0);
    CHECK(v.value(32 + int((radii[1] + radii[2]) / 2), 32, 32) > 0);
    const Components comps = aboveIsoComponents(v, 0.0);
    CHECK(comps.count == 2);  // the ball and the shell
    CHECK_FALSE(comps.touchesBorder);
}

TEST_CASE("blobs field: 125 separate blobs of distinct sizes", "[core][fields]") {
    REQUIRE(blobsFieldCount() == 125);
    for (int n : {64, 128}) {
        INFO("n = " << n);
        const std::vector<Blob> blobs = blobsFieldBlobs(n);
        REQUIRE(blobs.size() == 125);
        double smallest = 1e300, largest = 0;
        for (std::size_t i = 0; i < blobs.size(); ++i) {
            smallest = std::min(smallest, blobs[i].radius);
            largest = std::max(largest, blobs[i].radius);
            for (std::size_t j = i + 1; j < blobs.size(); ++j) {
                CHECK(blobs[i].radius != blobs[j].radius);
                // At least a 2-voxel gap between any two surfaces.
                CHECK(dist(blobs[i].centre, blobs[j].centre) - blobs[i].radius - blobs[j].radius >= 2.0);
            }
            for (double c : blobs[i].centre) {
                CHECK(c - blobs[i].radius >= 2.0);
                CHECK(n - 1 - c - blobs[i].radius >= 2.0);
            }
        }
        CHECK(largest / smallest == Approx(3.0).epsilon(0.05));
    }

    const int n = 64;
    const double iso = fieldDefaultIso("blobs");
    const Volume v = makeField({"blobs", n});
    const Components comps = aboveIsoComponents(v, iso);
    CHECK(comps.count == 125);
    CHECK_FALSE(comps.touchesBorder);
    // Each blob's surface is the sphere blobsFieldBlobs describes.
    const std::vector<Blob> blobs = blobsFieldBlobs(n);
    for (const Blob& b : blobs) {
        const int x = int(std::lround(b.centre[0])), y = int(std::lround(b.centre[1])),
                  z = int(std::lround(b.centre[2]));
        const double d = dist({double(x), double(y), double(z)}, b.centre);
        CHECK((v.value(x, y, z) > iso) == (d < b.radius));
        const int outside = int(std::ceil(b.centre[0] + b.radius + 0.01));
        CHECK(v.value(outside, y, z) < iso);
    }
}

TEST_CASE("gyroid, Marschner-Lobb and noise fields", "[core][fields]") {
    const Volume g = makeField({"gyroid", 33});
    CHECK(g.value(0, 0, 0) == Approx(3 * std::sin(0.1) * std::cos(0.1)).epsilon(1e-6));
    const auto gr = g.range();
    CHECK(gr[0] > -1.6);
    CHECK(gr[1] < 1.6);

    const Volume ml = makeField({"ml", 41});
    const auto mr = ml.range();
    CHECK(mr[0] >= 0.0);
    CHECK(mr[1] <= 1.0 + 1e-6);
    // At z = -1 sin term is -1; at x = y = 0, rho_r(0) = cos(2 pi 6) = 1: (1 + 1 + 0.25 * 2) / 2.5 = 1.
    CHECK(ml.value(20, 20, 0) == Approx(1.0).epsilon(1e-6));
    // At z = 1 and the same column: (1 - 1 + 0.5) / 2.5 = 0.2.
    CHECK(ml.value(20, 20, 40) == Approx(0.2).epsilon(1e-5));

    const Volume noise = makeField({"noise", 32});
    const float* s = noise.data<float>();
    double sum = 0;
    for (std::size_t i = 0; i < noise.sampleCount(); ++i) {
        REQUIRE(s[i] >= 0.0f);
        REQUIRE(s[i] < 1.0f);
        sum += s[i];
    }
    CHECK(sum / double(noise.sampleCount()) == Approx(0.5).margin(0.01));
    // Noise is a hash of the sample index alone, so sample 0 agrees across sizes.
    CHECK(makeField({"noise", 16}).value(0, 0, 0) == noise.value(0, 0, 0));
}
