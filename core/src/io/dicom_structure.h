#pragma once
// A walk over every element of a DICOM file before GDCM reads it.
//
// GDCM trusts declared lengths (it sizes buffers by them) and, as Debian builds
// it, asserts on streams that end early; so each file is first walked here:
// preamble and "DICM", the file meta group, then every element of the dataset
// in the transfer syntax the meta group names, into sequences, items and
// encapsulated pixel data, checking that every declared length fits in what
// holds it and that the file ends where its last element does.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace isotrack::detail {

struct DicomStructure {
    bool hasMagic = false;  // the 128-byte preamble and "DICM"
    std::string transferSyntax;
    bool hasPixelData = false;
    bool encapsulated = false;         // compressed: fragments in items
    std::uint64_t pixelDataBytes = 0;  // native: the value's length; encapsulated: the fragments'
    // Every element's tag and VR as an explicit-VR file spells it (none for implicit VR),
    // for checking against the dictionary GDCM reads them by.
    std::vector<std::pair<std::uint32_t, std::string>> explicitVrs;
};

// Returns the structure; a FormatError naming the file, the element and the
// problem when a length overruns, the file ends early, or the encoding is not
// one isotrack reads.
DicomStructure checkDicomStructure(const std::string& path);

// Whether the file starts with the preamble and "DICM" (false for short files).
bool hasDicomMagic(const std::string& path);

}  // namespace isotrack::detail
