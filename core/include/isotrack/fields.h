#pragma once
// Deterministic built-in scalar fields for demos, tests and benchmarks.
//
// Every field is a float32 N x N x N volume with spacing 1 and origin 0, so world
// and voxel coordinates coincide. The object is where value >= iso ("above").
// Values depend only on the name and N: same bytes on every platform and run.
#include <array>
#include <string>
#include <vector>

#include "isotrack/volume.h"

namespace isotrack {

struct FieldInfo {
    const char* name;
    int defaultSize;
    double defaultIso;
    const char* description;
};

// In display order. Aliases (e.g. "ml") are accepted by parseFieldSpec but not listed.
const std::vector<FieldInfo>& builtinFields();

struct FieldSpec {
    std::string name;  // canonical name, aliases resolved
    int size = 0;      // samples per axis
};

inline constexpr int kMinFieldSize = 8;
inline constexpr int kMaxFieldSize = 1024;

// Parses "NAME" or "NAME:N". Throws InputError on an unknown name, a size that is
// not a plain integer, or N outside [kMinFieldSize, kMaxFieldSize].
FieldSpec parseFieldSpec(const std::string& spec);

// Throws InputError for an unknown name or an out-of-range size.
Volume makeField(const FieldSpec& spec);

// Accepts aliases. Throws InputError for an unknown name.
double fieldDefaultIso(const std::string& name);

// Analytic geometry, in voxel units, for tests to compare against.
double sphereFieldRadius(int n);
Vec3d sphereFieldCenter(int n);                 // also the centre of "torus" and "shells"
std::array<double, 2> torusFieldRadii(int n);   // {ring radius, tube radius}
std::array<double, 3> shellsFieldRadii(int n);  // {ball, shell inner wall, shell outer wall}

struct Blob {
    Vec3d centre;
    double radius;  // of its isosurface at the default iso; the surface is an exact sphere
};
int blobsFieldCount();
// All radii are distinct, so exactly one blob is the smallest.
std::vector<Blob> blobsFieldBlobs(int n);

}  // namespace isotrack
