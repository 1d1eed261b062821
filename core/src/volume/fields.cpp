#include "isotrack/fields.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "isotrack/errors.h"

namespace isotrack {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Keeps the sphere-like fields' centres off the lattice so samples rarely sit on the iso exactly.
constexpr double kCentreOffset = 0.0371;
constexpr double kBlobsIso = 0.25;
constexpr int kBlobsPerAxis = 5;

// splitmix64: a fixed, well-mixed hash, because std:: distributions differ between platforms.
std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

double unitDouble(std::uint64_t h) { return double(h >> 11) * 0x1.0p-53; }

const std::vector<FieldInfo> kFields = {
    {"sphere", 128, 0.0, "a ball of radius 0.375*(N-1); value is the signed distance to its surface"},
    {"torus", 128, 0.0, "a torus around z, ring radius 0.28*(N-1), tube radius 0.1*(N-1)"},
    {"shells", 128, 0.0, "a ball inside a hollow spherical shell: three nested closed surfaces"},
    {"blobs", 128, kBlobsIso, "125 separate metaballs of distinct sizes on a jittered 5x5x5 lattice"},
    {"gyroid", 128, 0.0, "a gyroid with 4 periods across the volume: one large connected surface"},
    {"marschner-lobb", 64, 0.5, "the Marschner-Lobb test signal (fM = 6, alpha = 0.25) on [-1,1]^3"},
    {"noise", 64, 0.5, "white noise uniform in [0,1): a worst case for extraction"},
};

std::string printable(const std::string& s) {
    std::string out;
    for (char c : s.substr(0, 80)) out += (c >= 0x20 && c < 0x7f) ? c : '?';
    if (s.size() > 80) out += "...";
    return out;
}

std::string validNames() {
    std::string names;
    for (const FieldInfo& f : kFields) {
        if (!names.empty()) names += ", ";
        names += f.name;
        if (std::string(f.name) == "marschner-lobb") names += " (alias ml)";
    }
    return names;
}

const FieldInfo* findField(const std::string& name) {
    const std::string canonical = name == "ml" ? "marschner-lobb" : name;
    for (const FieldInfo& f : kFields)
        if (canonical == f.name) return &f;
    return nullptr;
}

const FieldInfo& requireField(const std::string& name, const std::string& context) {
    const FieldInfo* f = findField(name);
    if (!f) throw InputError(context + ": unknown field \"" + printable(name) + "\" (valid: " + validNames() + ")");
    return *f;
}

// Squared distance to the centre along one axis, per sample.
std::vector<double> axisSquares(int n, double centre) {
    std::vector<double> sq(std::size_t(n), 0.0);
    for (int i = 0; i < n; ++i) sq[std::size_t(i)] = (i - centre) * (i - centre);
    return sq;
}

Volume makeVolume(int n) { return Volume({n, n, n}, ScalarType::Float32); }

// Calls fn(distance to centre) for each sample, writing its result.
template <class Fn>
Volume radialField(int n, Fn fn) {
    Volume vol = makeVolume(n);
    const std::vector<double> sq = axisSquares(n, sphereFieldCenter(n)[0]);
    float* out = vol.data<float>();
    std::size_t i = 0;
    for (int z = 0; z < n; ++z)
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x)
                out[i++] = float(fn(std::sqrt(sq[std::size_t(x)] + sq[std::size_t(y)] + sq[std::size_t(z)])));
    return vol;
}

Volume sphereField(int n) {
    const double r = sphereFieldRadius(n);
    return radialField(n, [r](double d) { return r - d; });
}

Volume shellsField(int n) {
    const auto [r1, r2, r3] = shellsFieldRadii(n);
    return radialField(n, [r1 = r1, r2 = r2, r3 = r3](double d) { return std::max(r1 - d, std::min(d - r2, r3 - d)); });
}

Volume torusField(int n) {
    Volume vol = makeVolume(n);
    const auto [ring, tube] = torusFieldRadii(n);
    const std::vector<double> sq = axisSquares(n, sphereFieldCenter(n)[0]);
    // Squared distance from the ring circle within the (x,y) plane, per column.
    std::vector<double> ringSq(std::size_t(n) * std::size_t(n));
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double q = std::sqrt(sq[std::size_t(x)] + sq[std::size_t(y)]) - ring;
            ringSq[std::size_t(x) + std::size_t(n) * std::size_t(y)] = q * q;
        }
    float* out = vol.data<float>();
    const std::size_t slice = ringSq.size();
    for (int z = 0; z < n; ++z)
        for (std::size_t j = 0; j < slice; ++j)
            out[std::size_t(z) * slice + j] = float(tube - std::sqrt(ringSq[j] + sq[std::size_t(z)]));
    return vol;
}

Volume gyroidField(int n) {
    Volume vol = makeVolume(n);
    std::vector<double> s(static_cast<std::size_t>(n)), c(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * kPi * 4.0 * i / (n - 1) + 0.1;
        s[std::size_t(i)] = std::sin(a);
        c[std::size_t(i)] = std::cos(a);
    }
    float* out = vol.data<float>();
    std::size_t i = 0;
    for (std::size_t z = 0; z < std::size_t(n); ++z)
        for (std::size_t y = 0; y < std::size_t(n); ++y)
            for (std::size_t x = 0; x < std::size_t(n); ++x) out[i++] = float(s[x] * c[y] + s[y] * c[z] + s[z] * c[x]);
    return vol;
}

Volume marschnerLobbField(int n) {
    constexpr double fM = 6.0, alpha = 0.25;
    Volume vol = makeVolume(n);
    auto coord = [n](int i) { return -1.0 + 2.0 * i / (n - 1); };
    // The signal separates into a z term and a radial (x,y) term.
    std::vector<double> radial(std::size_t(n) * std::size_t(n));
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const double r = std::sqrt(coord(x) * coord(x) + coord(y) * coord(y));
            radial[std::size_t(x) + std::size_t(n) * std::size_t(y)] =
                alpha * (1.0 + std::cos(2.0 * kPi * fM * std::cos(kPi * r / 2.0)));
        }
    float* out = vol.data<float>();
    const std::size_t slice = radial.size();
    for (int z = 0; z < n; ++z) {
        const double zTerm = 1.0 - std::sin(kPi * coord(z) / 2.0);
        for (std::size_t j = 0; j < slice; ++j)
            out[std::size_t(z) * slice + j] = float((zTerm + radial[j]) / (2.0 * (1.0 + alpha)));
    }
    return vol;
}

Volume noiseField(int n) {
    constexpr std::uint64_t kSeed = 0x15070AC4ull;
    Volume vol = makeVolume(n);
    float* out = vol.data<float>();
    // 24 bits so the float is exact and never rounds up to 1.
    for (std::size_t i = 0; i < vol.sampleCount(); ++i) out[i] = float(double(splitmix64(kSeed + i) >> 40) * 0x1.0p-24);
    return vol;
}

// Each blob's kernel support radius, alongside its public description.
struct BlobLayout {
    std::vector<Blob> blobs;
    std::vector<double> supports;
};

BlobLayout blobLayout(int n) {
    const int count = blobsFieldCount();
    const double cell = (n - 1) / double(kBlobsPerAxis);
    // Jitter and supports are sized so neighbouring supports cannot overlap
    // (2 * 0.05 + 2 * 0.444 < 1) and stay inside the volume (0.444 < 0.5 - 0.05).
    const double jitter = 0.05 * cell;
    const double minSupport = 0.148 * cell, maxSupport = 0.444 * cell;
    // A shuffled ramp rather than random draws: distinct radii with an exact 3x spread.
    std::vector<int> rank(std::size_t(count), 0);
    for (int i = 0; i < count; ++i) rank[std::size_t(i)] = i;
    for (int i = count - 1; i > 0; --i) {
        const auto j = int(splitmix64(0xB10B5ull + std::uint64_t(i)) % std::uint64_t(i + 1));
        std::swap(rank[std::size_t(i)], rank[std::size_t(j)]);
    }
    const double isoFraction = std::sqrt(1.0 - std::cbrt(kBlobsIso));  // where (1-t^2)^3 == iso
    BlobLayout layout;
    for (int k = 0; k < count; ++k) {
        const int cellIndex[3] = {k % kBlobsPerAxis, (k / kBlobsPerAxis) % kBlobsPerAxis,
                                  k / (kBlobsPerAxis * kBlobsPerAxis)};
        Vec3d centre{};
        for (int a = 0; a < 3; ++a) {
            const double u = unitDouble(splitmix64(0x1EA5Eull + std::uint64_t(3 * k + a)));
            centre[std::size_t(a)] = (cellIndex[a] + 0.5) * cell + jitter * (2.0 * u - 1.0);
        }
        const double support = minSupport + (maxSupport - minSupport) * rank[std::size_t(k)] / (count - 1);
        layout.blobs.push_back({centre, support * isoFraction});
        layout.supports.push_back(support);
    }
    return layout;
}

Volume blobsField(int n) {
    Volume vol = makeVolume(n);
    const BlobLayout layout = blobLayout(n);
    float* out = vol.data<float>();
    for (std::size_t b = 0; b < layout.blobs.size(); ++b) {
        const Vec3d& c = layout.blobs[b].centre;
        const double s = layout.supports[b];
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::max(0, int(std::floor(c[std::size_t(a)] - s)));
            hi[a] = std::min(n - 1, int(std::ceil(c[std::size_t(a)] + s)));
        }
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y)
                for (int x = lo[0]; x <= hi[0]; ++x) {
                    const double dx = x - c[0], dy = y - c[1], dz = z - c[2];
                    const double t2 = (dx * dx + dy * dy + dz * dz) / (s * s);
                    if (t2 >= 1.0) continue;
                    const double w = (1.0 - t2) * (1.0 - t2) * (1.0 - t2);
                    float& v = out[vol.index(x, y, z)];
                    v = float(double(v) + w);
                }
    }
    return vol;
}

}  // namespace

const std::vector<FieldInfo>& builtinFields() { return kFields; }

FieldSpec parseFieldSpec(const std::string& spec) {
    const std::string context = "field spec \"" + printable(spec) + "\"";
    const std::size_t colon = spec.find(':');
    const FieldInfo& info = requireField(spec.substr(0, colon), context);
    FieldSpec result{info.name, info.defaultSize};
    if (colon == std::string::npos) return result;
    const std::string sizeText = spec.substr(colon + 1);
    const bool allDigits =
        !sizeText.empty() && std::all_of(sizeText.begin(), sizeText.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!allDigits) throw InputError(context + ": size \"" + printable(sizeText) + "\" is not a positive integer");
    // More than four digits is out of range anyway, and keeps stoi from overflowing.
    if (sizeText.size() > 4 || std::stoi(sizeText) < kMinFieldSize || std::stoi(sizeText) > kMaxFieldSize)
        throw InputError(context + ": size " + printable(sizeText) + " is outside " + std::to_string(kMinFieldSize) +
                         ".." + std::to_string(kMaxFieldSize));
    result.size = std::stoi(sizeText);
    return result;
}

Volume makeField(const FieldSpec& spec) {
    const std::string context = "field \"" + printable(spec.name) + "\"";
    const std::string name = requireField(spec.name, context).name;
    if (spec.size < kMinFieldSize || spec.size > kMaxFieldSize)
        throw InputError(context + ": size " + std::to_string(spec.size) + " is outside " +
                         std::to_string(kMinFieldSize) + ".." + std::to_string(kMaxFieldSize));
    const int n = spec.size;
    if (name == "sphere") return sphereField(n);
    if (name == "torus") return torusField(n);
    if (name == "shells") return shellsField(n);
    if (name == "blobs") return blobsField(n);
    if (name == "gyroid") return gyroidField(n);
    if (name == "marschner-lobb") return marschnerLobbField(n);
    return noiseField(n);
}

double fieldDefaultIso(const std::string& name) {
    return requireField(name, "field \"" + printable(name) + "\"").defaultIso;
}

double sphereFieldRadius(int n) { return 0.375 * (n - 1); }

Vec3d sphereFieldCenter(int n) {
    const double c = (n - 1) / 2.0 + kCentreOffset;
    return {c, c, c};
}

std::array<double, 2> torusFieldRadii(int n) { return {0.28 * (n - 1), 0.1 * (n - 1)}; }

std::array<double, 3> shellsFieldRadii(int n) { return {0.15 * (n - 1), 0.28 * (n - 1), 0.42 * (n - 1)}; }

int blobsFieldCount() { return kBlobsPerAxis * kBlobsPerAxis * kBlobsPerAxis; }

std::vector<Blob> blobsFieldBlobs(int n) { return blobLayout(n).blobs; }

}  // namespace isotrack
