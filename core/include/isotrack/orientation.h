#pragma once
// Where a volume lies in the patient: direction matrices, anatomical codes, and
// the frames isotrack writes meshes in.
//
// The world frame is LPS (x to the patient's Left, y to Posterior, z to Superior),
// as in DICOM and ITK. Loaders convert what a file declares into it (NIfTI's RAS
// by flipping x and y). A file that declares no anatomical space (VTK legacy,
// raw, a NRRD without "space", NIfTI without sform or qform) is taken as given.
//
// The extractors emit grid coordinates (see isotrack/volume.h); a FrameTransform
// carries them into LPS, RAS or voxel indices when a mesh leaves for a file.
#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "isotrack/mesh.h"
#include "isotrack/surface.h"
#include "isotrack/volume.h"

namespace isotrack {

enum class WorldFrame : std::uint8_t { Lps, Ras, Voxel };
// Every frame, in the order front ends list them.
inline constexpr std::array<WorldFrame, 3> kWorldFrames{WorldFrame::Lps, WorldFrame::Ras, WorldFrame::Voxel};

const char* worldFrameName(WorldFrame frame);  // "lps", "ras", "voxel"
// Throws InputError for anything but lps, ras or voxel (any case).
WorldFrame parseWorldFrame(const std::string& name);

// The direction matrix of three index-axis vectors (columns of `axes`, any
// lengths, e.g. NRRD's space directions or a NIfTI sform's columns); `lengths`
// receives their lengths (the spacing). nullopt when a vector is zero or not
// finite, or two are not orthogonal (cosine above 1e-4): isotrack has no shear.
std::optional<Mat3d> directionFromAxes(const Mat3d& axes, Vec3d* lengths = nullptr);

double determinant(const Mat3d& m);
Vec3d multiply(const Mat3d& m, const Vec3d& v);
Mat3d multiply(const Mat3d& a, const Mat3d& b);
bool isIdentity(const Mat3d& m);

// RAS <-> LPS: x and y change sign (its own inverse).
Vec3d flipRasLps(const Vec3d& v);
Mat3d flipRasLps(const Mat3d& m);

// For each index axis, the side of the patient it points towards, as nibabel
// and Slicer write it: "LPS" for an identity direction, "RAS" for a NIfTI with
// an identity sform, "LPI" when k runs towards the feet. An oblique axis takes
// its largest component.
std::string orientationCode(const Mat3d& direction);

// World (LPS) position of a continuous index (i, j, k).
Vec3d indexToWorld(const Volume& volume, const Vec3d& index);
// Smallest and largest world (LPS) coordinate of the grid's eight corners.
std::array<Vec3d, 2> worldBounds(const Volume& volume);

// out = linear * grid + offset: from grid coordinates into a frame.
struct FrameTransform {
    Mat3d linear = kIdentityDirection;  // columns
    Vec3d offset{0, 0, 0};

    bool identity() const;
    bool mirrors() const { return determinant(linear) < 0; }
    Vec3d apply(const Vec3d& grid) const;
    // A point given in the frame (e.g. a --seed) back in grid coordinates.
    Vec3d toGrid(const Vec3d& point) const;
};

FrameTransform gridToFrame(const Volume& volume, WorldFrame frame);

// Moves positions into the frame and turns normals with them (still unit, still
// pointing from above the isovalue towards below); when the transform mirrors,
// each triangle's last two corners swap so that its winding keeps agreeing with
// the normals. An identity transform leaves the mesh untouched, bit for bit.
void transformMesh(Mesh& mesh, const FrameTransform& transform);

// A surface in the frame: its mesh (transformMesh) and the bounds reported with
// it; area and enclosed volume stay in world units. Every front end that writes
// surfaces in a frame (extract --frame, --all-times, Python) calls this.
void transformSurface(Surface& surface, const FrameTransform& transform);

}  // namespace isotrack
