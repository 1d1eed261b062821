#pragma once
// Reading volumes (NRRD, NIfTI-1, MetaImage, VTK legacy, raw) and writing them
// (NRRD); writing meshes (PLY, OBJ, STL) and reading PLY back.
//
// Loaders throw FormatError with a one-line message naming the file, the field and
// the value. They validate sizes against the bytes actually available (for
// compressed data, the inflated size, measured first) before allocating, so
// hostile files fail fast instead of exhausting memory. Samples keep their
// native type; spacing, origin and direction are kept, in the LPS world frame
// (isotrack/orientation.h; docs/formats.md lists what each format declares).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/volume.h"

namespace isotrack {

// ---- Volumes ---------------------------------------------------------------

enum class VolumeFormat : std::uint8_t { Nrrd, Nifti, MetaImage, VtkLegacy, Raw, Dicom, VtkImageData, VtkCollection };

const char* volumeFormatName(VolumeFormat format);

// The format loadVolume reads `path` as, from its extension (case-insensitive):
// .nrrd .nhdr, .nii .nii.gz, .mhd .mha, .vtk, .vti, .pvd, .raw; DICOM (isotrack/dicom.h) for
// a folder, a file named DICOMDIR, .dcm or .dicom; nullopt for anything else.
std::optional<VolumeFormat> volumeFormatOf(const std::string& path);

// Chooses a loader by extension; a time series (.pvd, 4D NIfTI) gives its first
// step (isotrack/time_series.h reads the others). A .raw file (or any other) needs loadRaw and
// its layout; asking loadVolume for one is a FormatError listing the formats.
// DICOM gives the largest series (loadDicom picks another).
Volume loadVolume(const std::string& path);

// 3D NRRD, attached (.nrrd) or detached (.nhdr + "data file:") header; raw or
// gzip encoding; either endian; any scalar type Volume can hold. Spacing comes
// from "spacings:" or the lengths of "space directions:", the direction from the
// vectors themselves; origin from "space origin:". "space:" RAS or LAS is turned
// into LPS; LPS, a space without anatomical meaning, or none is taken as given.
// "dimension: 4" is a 3D time series, the time axis last (kinds, when given:
// three domain or space, then time, list or domain; "space directions" ends in
// none): `step` picks the 3D volume, the t-th after the data's start.
Volume loadNrrd(const std::string& path, std::size_t step = 0);
// The fourth axis's size, 1 for a 3D file.
std::size_t nrrdSteps(const std::string& path);

// Attached header, raw, little endian; keeps spacing and origin exactly. A volume
// with a direction other than the identity is written with "space:
// left-posterior-superior" and its turned "space directions".
void writeNrrd(const Volume& volume, const std::string& path);

// NIfTI-1 single file (.nii, or gzip-compressed .nii.gz), either endian (told by
// sizeof_hdr), datatypes uint8/int8/int16/uint16/int32/uint32/float32/float64.
// 3D, or a 3D time series: dim[0] == 3, or 4 with dim[4] steps (dim[0] up to 7
// with every further dimension 1); `step` picks the 3D volume. The transform is
// the sform when sform_code > 0 (spacing from its columns' lengths; a sheared
// sform is refused), else the qform when qform_code > 0 (quaternion, qfac,
// pixdim, qoffset), else pixdim alone, taken as given; NIfTI's RAS becomes LPS.
// When scl_slope is non-zero and (slope, inter) is not (1, 0) the samples become
// float32 slope * v + inter; otherwise they stay native.
Volume loadNifti(const std::string& path, std::size_t step = 0);
// The time of each step: toffset + t * pixdim[4] (t when pixdim[4] is 0); one
// entry, 0, for a 3D file.
std::vector<double> niftiStepTimes(const std::string& path);

// MetaImage: .mhd with a detached ElementDataFile (relative to the header) or
// .mha with LOCAL data; MET_UCHAR/CHAR/SHORT/USHORT/INT/UINT/FLOAT/DOUBLE, one
// channel; BinaryDataByteOrderMSB; ElementSpacing; Offset (or Origin, Position);
// HeaderSize; CompressedData True (a zlib stream). The direction comes from
// TransformMatrix (each axis's LPS vector in turn, as ITK writes it), else from
// AnatomicalOrientation (ITK's letters: "RAI" is the identity).
Volume loadMetaImage(const std::string& path);

// VTK legacy STRUCTURED_POINTS, BINARY (big-endian, per the VTK spec) or ASCII:
// DIMENSIONS, SPACING (or ASPECT_RATIO), ORIGIN, POINT_DATA n, and the first
// SCALARS name type [1] (LOOKUP_TABLE optional) as the samples.
Volume loadVtkLegacy(const std::string& path);

// VTK XML ImageData (.vti): one Piece; a PointData DataArray of one component,
// `array` by Name or else the first such, in format ascii, binary (base64) or
// appended (raw or base64), uncompressed or vtkZLibDataCompressor, UInt32 or
// UInt64 header_type, either byte_order; types Int8..Float64 (Int64 and UInt64
// are refused). WholeExtent, Origin, Spacing and Direction (VTK 9), taken as
// given; the volume's origin is the WholeExtent's first point.
Volume loadVti(const std::string& path, const std::string& array = "");

// A headerless file of samples, x fastest, nothing before or after them.
struct RawLayout {
    Dims dims{0, 0, 0};
    ScalarType type = ScalarType::UInt8;
    Vec3d spacing{1, 1, 1};
    Vec3d origin{0, 0, 0};
    bool bigEndian = false;
};

// The file must hold exactly dims * sizeof(type) bytes.
Volume loadRaw(const std::string& path, const RawLayout& layout);

// ---- Meshes ----------------------------------------------------------------

enum class MeshFormat : std::uint8_t { Ply, Obj, Stl };

// The format writeMesh writes `path` as (.ply, .obj, .stl, case-insensitive).
// Throws InputError naming the extension and the supported ones.
MeshFormat meshFormatOf(const std::string& path);
const char* meshFormatExtension(MeshFormat format);  // ".ply", ".obj", ".stl"

// Writes PLY, OBJ or STL by extension. faceComponent (one entry per triangle)
// becomes PLY's per-face "component" and OBJ's groups; STL has no place for it.
void writeMesh(const std::string& path, const Mesh& mesh, const std::vector<std::int32_t>* faceComponent = nullptr);

// Binary little-endian PLY: float x y z nx ny nz per vertex, uchar/int index
// lists per face, plus an int "component" per face when faceComponent is given
// (it must then hold one entry per triangle). Throws InputError for an
// inconsistent mesh, FormatError when the file cannot be written.
void writePly(const std::string& path, const Mesh& mesh, const std::vector<std::int32_t>* faceComponent = nullptr);

// Reads exactly what writePly writes; anything else is a FormatError.
// vertexEdges is left empty (PLY does not store it). When faceComponent is given
// it receives the per-face components, or is cleared if the file has none.
Mesh readPly(const std::string& path, std::vector<std::int32_t>* faceComponent = nullptr);

// Wavefront OBJ: "v x y z", "vn nx ny nz" per vertex, "f a//a b//b c//c" per
// triangle (1-based), and "g component_N" before each run of faces of one
// component when faceComponent is given.
void writeObj(const std::string& path, const Mesh& mesh, const std::vector<std::int32_t>* faceComponent = nullptr);

// Binary STL: one facet per triangle with the normal of the triangle itself
// (right-handed, so it agrees with the vertex normals; zero for a degenerate one).
void writeStl(const std::string& path, const Mesh& mesh);

}  // namespace isotrack
