#pragma once
// Reading and writing volumes (NRRD) and meshes (PLY).
//
// Loaders throw FormatError with a one-line message naming the file, the field and
// the value. They validate sizes against the bytes actually available before
// allocating, so hostile files fail fast instead of exhausting memory.
#include <cstdint>
#include <string>
#include <vector>

#include "isotrack/mesh.h"
#include "isotrack/volume.h"

namespace isotrack {

// 3D NRRD, attached (.nrrd) or detached (.nhdr + "data file:") header; raw or
// gzip encoding; either endian; any scalar type Volume can hold. Spacing comes
// from "spacings:" or the lengths of "space directions:" (orientation is dropped);
// origin from "space origin:".
Volume loadNrrd(const std::string& path);

// Attached header, raw, little endian; keeps spacing and origin exactly.
void writeNrrd(const Volume& volume, const std::string& path);

// Chooses a loader by extension (.nrrd, .nhdr, case-insensitive).
Volume loadVolume(const std::string& path);

// Binary little-endian PLY: float x y z nx ny nz per vertex, uchar/int index
// lists per face, plus an int "component" per face when faceComponent is given
// (it must then hold one entry per triangle). Throws InputError for an
// inconsistent mesh, FormatError when the file cannot be written.
void writePly(const std::string& path, const Mesh& mesh, const std::vector<std::int32_t>* faceComponent = nullptr);

// Reads exactly what writePly writes; anything else is a FormatError.
// vertexEdges is left empty (PLY does not store it). When faceComponent is given
// it receives the per-face components, or is cleared if the file has none.
Mesh readPly(const std::string& path, std::vector<std::int32_t>* faceComponent = nullptr);

}  // namespace isotrack
