// Hostile input: every malformed file is refused with a one-line FormatError or
// InputError naming it, quickly, and before any large allocation; NaN and
// infinite samples never reach a vertex.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <new>
#include <random>
#include <string>
#include <vector>

#include "dicom_test_files.h"
#include "io_test_files.h"
#include "isotrack/errors.h"
#include "isotrack/fields.h"
#include "isotrack/io.h"
#include "isotrack/marching_cubes.h"
#include "isotrack/tracking.h"

using namespace isotrack;
using namespace isotrack::testing;

// The largest single allocation since the last reset, seen through replaced
// global operator new: "refused before anything is allocated" becomes checkable.
namespace {
std::atomic<std::size_t> gLargestAllocation{0};

void* allocate(std::size_t n) {
    std::size_t seen = gLargestAllocation.load(std::memory_order_relaxed);
    while (n > seen && !gLargestAllocation.compare_exchange_weak(seen, n, std::memory_order_relaxed)) {
    }
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
}  // namespace

// Every non-aligned form is replaced, so that each pair (new, delete) stays
// malloc/free, also under AddressSanitizer, which would otherwise supply some.
void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    try {
        return allocate(n);
    } catch (const std::bad_alloc&) {
        return nullptr;
    }
}
void* operator new[](std::size_t n, const std::nothrow_t& tag) noexcept { return operator new(n, tag); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace {

// No refusal may allocate more than the loaders' own I/O buffers.
constexpr std::size_t kMaxRefusalAllocation = std::size_t(2) << 20;

std::string baseName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// Loads `path`, which must be refused: FormatError or InputError, one line that
// names the file and contains `expect`, without a large allocation. (A hang would
// be caught by CTest's timeout; speed belongs in benchmarks, not in test verdicts.)
void expectRefused(const std::string& path, const std::string& expect, const std::function<void()>& load) {
    CAPTURE(baseName(path), expect);
    gLargestAllocation = 0;
    std::string message;
    try {
        load();
    } catch (const FormatError& e) {
        message = e.what();
    } catch (const InputError& e) {
        message = e.what();
    }
    CAPTURE(message);
    REQUIRE_FALSE(message.empty());  // accepted, which it must not be
    CHECK(message.find(baseName(path)) != std::string::npos);
    CHECK(message.find(expect) != std::string::npos);
    CHECK(message.find('\n') == std::string::npos);
    CHECK(message.find('\r') == std::string::npos);
    CHECK(message.size() < 500);
    CHECK(gLargestAllocation.load() < kMaxRefusalAllocation);
}

void expectRefused(const std::string& path, const std::string& expect) {
    expectRefused(path, expect, [&] { loadVolume(path); });
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    REQUIRE(at != std::string::npos);
    return text.replace(at, from.size(), to);
}

std::string randomBytes(std::size_t n, unsigned seed) {
    std::mt19937 rng(seed);
    std::string out(n, '\0');
    for (char& c : out) c = char(rng() & 0xff);
    return out;
}

// A flipped run of bytes in the middle of a compressed stream.
std::string corrupted(std::string compressed) {
    for (std::size_t i = compressed.size() / 3; i < compressed.size() / 3 + 16 && i < compressed.size(); ++i)
        compressed[i] = char(~compressed[i]);
    return compressed;
}

const Volume kSmall = patterned(ScalarType::Int16, {4, 3, 2});
const std::string kSamples = sampleBytes(kSmall, false);  // 48 bytes

const std::string kNrrd = "NRRD0004\ntype: short\ndimension: 3\nsizes: 4 3 2\nendian: little\nencoding: raw\n";
const std::string kMeta =
    "ObjectType = Image\nNDims = 3\nDimSize = 4 3 2\nElementType = MET_SHORT\n"
    "ElementSpacing = 1 1 1\nElementDataFile = LOCAL\n";
const std::string kVtk =
    "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 4 3 2\n"
    "SPACING 1 1 1\nORIGIN 0 0 0\nPOINT_DATA 24\nSCALARS s short 1\nLOOKUP_TABLE default\n";

}  // namespace

TEST_CASE("hostile NRRD files are refused", "[core][io][hostile]") {
    TempDir dir;
    auto refuse = [&](const std::string& name, const std::string& bytes, const std::string& expect) {
        writeFile(dir.file(name), bytes);
        expectRefused(dir.file(name), expect);
    };
    refuse("truncated.nrrd", kNrrd + "\n" + kSamples.substr(0, 40), "has only 40");
    refuse("zero.nrrd", replaced(kNrrd, "4 3 2", "4 0 2") + "\n" + kSamples, "\"sizes\"");
    refuse("negative.nrrd", replaced(kNrrd, "4 3 2", "4 -3 2") + "\n" + kSamples, "\"sizes\"");
    refuse("overflow.nrrd", replaced(kNrrd, "4 3 2", "4294967296 4294967296 4294967296") + "\n" + kSamples, "sizes");
    refuse("absurd.nrrd", replaced(kNrrd, "4 3 2", "100000 100000 100000") + "\n" + kSamples, "volume limit");
    refuse("oversized.nrrd", replaced(kNrrd, "4 3 2", "1000 1000 1000") + "\n" + kSamples, "has only 48");
    refuse("type.nrrd", replaced(kNrrd, "short", "complex") + "\n" + kSamples, "\"type\"");
    refuse("encoding.nrrd", replaced(kNrrd, "raw", "bzip2") + "\n" + kSamples, "\"encoding\"");
    const std::string gz = replaced(kNrrd, "raw", "gzip") + "\n";
    refuse("corrupt.nrrd", gz + corrupted(gzipBytes(randomBytes(48, 1))), "gzip data");
    const std::string packed = gzipBytes(kSamples);
    refuse("cut.nrrd", gz + packed.substr(0, packed.size() - 10), "truncated");
    refuse("notgzip.nrrd", gz + kSamples, "gzip data is corrupt");
    // Claims 16 MiB that a few KiB of gzip could in principle hold: measured, then refused.
    refuse("bomb.nrrd", replaced(gz, "4 3 2", "256 256 128") + gzipBytes(std::string(4 << 20, '\0')), "truncated");
    refuse("ratio.nrrd", replaced(gz, "4 3 2", "1000 1000 500") + packed, "cannot hold");
    refuse("missing.nhdr", kNrrd + "data file: nothere.raw\n", "nothere.raw");
    refuse("directory.nhdr", kNrrd + "data file: .\n", "cannot open");
    refuse("device.nhdr", kNrrd + "data file: /dev/zero\n", "not a regular file");
    refuse("noblank.nrrd", kNrrd, "blank line");
    refuse("longheader.nrrd", "NRRD0004\n" + std::string(std::size_t(2) << 20, 'a'), "longer than");
    refuse("random.nrrd", randomBytes(4096, 2), "not a NRRD file");
    refuse("empty.nrrd", "", "not a NRRD file");
}

TEST_CASE("hostile NIfTI-1 files are refused", "[core][io][hostile]") {
    TempDir dir;
    const NiftiHeader good = niftiHeaderFor(kSmall, false);
    auto refuse = [&](const std::string& name, const std::string& bytes, const std::string& expect) {
        writeFile(dir.file(name), bytes);
        expectRefused(dir.file(name), expect);
    };
    auto refuseHeader = [&](const std::string& name, const std::function<void(NiftiHeader&)>& edit,
                            const std::string& expect, const std::string& gzipExpect = "") {
        NiftiHeader h = good;
        edit(h);
        std::string bytes = h.bytes() + std::string(4, '\0') + kSamples;
        refuse(name, bytes, expect);
        refuse(name + ".gz", gzipBytes(bytes), gzipExpect.empty() ? expect : gzipExpect);
    };
    const std::string file = niftiFile(good, kSamples);
    refuse("short.nii", file.substr(0, 100), "shorter than the 348-byte header");
    refuseHeader(
        "sizeof.nii", [](NiftiHeader& h) { h.sizeofHdr = 1234; }, "sizeof_hdr");
    refuseHeader(
        "nifti2.nii", [](NiftiHeader& h) { h.sizeofHdr = 540; }, "NIfTI-2");
    refuseHeader(
        "pair.nii", [](NiftiHeader& h) { h.magic = std::string("ni1\0", 4); }, ".hdr/.img");
    refuseHeader(
        "magic.nii", [](NiftiHeader& h) { h.magic = "abc"; }, "\"magic\"");
    refuseHeader(
        "2d.nii", [](NiftiHeader& h) { h.dim[0] = 2; }, "\"dim\"");
    refuseHeader(
        "5d.nii", [](NiftiHeader& h) { h.dim[0] = 5, h.dim[4] = 7, h.dim[5] = 2; }, "only 3D");
    refuseHeader(
        "dim0.nii", [](NiftiHeader& h) { h.dim[0] = -3; }, "\"dim\"");
    refuseHeader(
        "zero.nii", [](NiftiHeader& h) { h.dim[2] = 0; }, "must be positive");
    refuseHeader(
        "negative.nii", [](NiftiHeader& h) { h.dim[1] = -4; }, "must be positive");
    refuseHeader(
        "absurd.nii", [](NiftiHeader& h) { h.dim[1] = h.dim[2] = h.dim[3] = 32767; }, "volume limit");
    refuseHeader(
        "large.nii", [](NiftiHeader& h) { h.dim[1] = h.dim[2] = 1000; }, "\"dim\"");
    refuseHeader(
        "datatype.nii", [](NiftiHeader& h) { h.datatype = 999; }, "unknown datatype 999");
    refuseHeader(
        "complex.nii", [](NiftiHeader& h) { h.datatype = 32, h.bitpix = 64; }, "complex64");
    refuseHeader(
        "bitpix.nii", [](NiftiHeader& h) { h.bitpix = 8; }, "\"bitpix\"");
    // pixdim is the spacing of a qform (with a sform, the sform's columns are).
    const auto qform = [](NiftiHeader& h) { h.sformCode = 0, h.qformCode = 1; };
    refuseHeader(
        "pixdim.nii", [&](NiftiHeader& h) { qform(h), h.pixdim[2] = 0; }, "\"pixdim\"");
    refuseHeader(
        "pixnan.nii", [&](NiftiHeader& h) { qform(h), h.pixdim[3] = std::nanf(""); }, "\"pixdim\"");
    refuseHeader(
        "pixneg.nii", [&](NiftiHeader& h) { qform(h), h.pixdim[1] = -1; }, "\"pixdim\"");
    refuseHeader(
        "srow0.nii", [](NiftiHeader& h) { h.srow[0][0] = h.srow[1][0] = h.srow[2][0] = 0; }, "\"srow\"");
    refuseHeader(
        "srownan.nii", [](NiftiHeader& h) { h.srow[1][1] = std::nanf(""); }, "\"srow\"");
    refuseHeader(
        "quatern.nii", [&](NiftiHeader& h) { qform(h), h.quatern[0] = 2; }, "\"quatern_b\"");
    refuseHeader(
        "voxoffset.nii", [](NiftiHeader& h) { h.voxOffset = 100; }, "\"vox_offset\"");
    refuseHeader(
        "voxfraction.nii", [](NiftiHeader& h) { h.voxOffset = 352.5f; }, "\"vox_offset\"");
    refuseHeader(
        "voxinf.nii", [](NiftiHeader& h) { h.voxOffset = INFINITY; }, "\"vox_offset\"");
    refuseHeader(
        "voxfar.nii", [](NiftiHeader& h) { h.voxOffset = 1e6f; }, "\"vox_offset\"", "cannot hold");
    refuseHeader(
        "slope.nii", [](NiftiHeader& h) { h.sclSlope = INFINITY; }, "\"scl_slope\"");
    refuseHeader(
        "inter.nii", [](NiftiHeader& h) { h.sclSlope = 2, h.sclInter = NAN; }, "\"scl_inter\"");
    refuseHeader(
        "far.nii", [](NiftiHeader& h) { h.srow[0][3] = 1e38f; }, "beyond float range");
    refuseHeader(
        "spread.nii", [](NiftiHeader& h) { h.srow[0][0] = -1e37f; }, "beyond float range");
    refuse("truncated.nii", file.substr(0, file.size() - 8), "has only 40");
    const std::string packed = gzipBytes(file);
    refuse("corrupt.nii.gz", corrupted(packed), "gzip data");
    refuse("cut.nii.gz", packed.substr(0, packed.size() - 30), "truncated");
    refuse("short.nii.gz", gzipBytes(file.substr(0, file.size() - 8)), "truncated");
    refuse("plain.nii.gz", file, "gzip data is corrupt");
    NiftiHeader bomb = good;
    bomb.dim[1] = bomb.dim[2] = 256, bomb.dim[3] = 128;
    refuse("bomb.nii.gz", gzipBytes(bomb.bytes() + std::string(4 << 20, '\0')), "truncated");
    bomb.dim[3] = 4096;
    refuse("ratio.nii.gz", gzipBytes(bomb.bytes() + std::string(4, '\0')), "cannot hold");
    refuse("random.nii", randomBytes(4096, 3), "sizeof_hdr");
    refuse("random.nii.gz", randomBytes(4096, 4), "gzip data");
    refuse("empty.nii", "", "shorter than");
    refuse("empty.nii.gz", "", "gzip data is truncated");
}

TEST_CASE("hostile MetaImage files are refused", "[core][io][hostile]") {
    TempDir dir;
    auto refuse = [&](const std::string& name, const std::string& bytes, const std::string& expect) {
        writeFile(dir.file(name), bytes);
        expectRefused(dir.file(name), expect);
    };
    refuse("nodata.mhd", replaced(kMeta, "ElementDataFile = LOCAL\n", ""), "ElementDataFile");
    refuse("missing.mhd", replaced(kMeta, "LOCAL", "gone.raw"), "gone.raw");
    refuse("device.mhd", replaced(kMeta, "LOCAL", "/dev/urandom"), "not a regular file");
    refuse("short.mha", kMeta + kSamples.substr(0, 40), "has only 40");
    refuse("long.mha", kMeta + kSamples + "0123456789ab", "has 60");
    refuse("ndims.mha", replaced(kMeta, "NDims = 3", "NDims = 2") + kSamples, "\"NDims\"");
    refuse("dims.mha", replaced(kMeta, "4 3 2", "4 3") + kSamples, "\"DimSize\"");
    refuse("zero.mha", replaced(kMeta, "4 3 2", "4 0 2") + kSamples, "\"DimSize\"");
    refuse("absurd.mha", replaced(kMeta, "4 3 2", "2000000000 2000000000 2000000000") + kSamples, "volume limit");
    refuse("oversized.mha", replaced(kMeta, "4 3 2", "1000 1000 1000") + kSamples, "has only 48");
    refuse("type.mha", replaced(kMeta, "MET_SHORT", "MET_LONG") + kSamples, "MET_LONG");
    refuse("channels.mha", replaced(kMeta, "NDims = 3\n", "NDims = 3\nElementNumberOfChannels = 3\n") + kSamples,
           "ElementNumberOfChannels");
    refuse("zlib.mha", replaced(kMeta, "NDims = 3\n", "NDims = 3\nCompressedData = True\n") + randomBytes(64, 5),
           "zlib data");
    refuse(
        "zcorrupt.mha",
        replaced(kMeta, "NDims = 3\n", "NDims = 3\nCompressedData = True\n") + corrupted(zlibBytes(randomBytes(48, 6))),
        "zlib data");
    refuse("zsize.mha",
           replaced(kMeta, "NDims = 3\n", "NDims = 3\nCompressedData = True\nCompressedDataSize = 7\n") +
               zlibBytes(kSamples),
           "CompressedDataSize");
    refuse("ascii.mha", replaced(kMeta, "NDims = 3\n", "NDims = 3\nBinaryData = False\n") + "1 2 3", "ASCII");
    refuse("spacing.mha", replaced(kMeta, "ElementSpacing = 1 1 1", "ElementSpacing = 1 0 1") + kSamples,
           "\"ElementSpacing\"");
    refuse("spacingnan.mha", replaced(kMeta, "ElementSpacing = 1 1 1", "ElementSpacing = 1 nan 1") + kSamples,
           "\"ElementSpacing\"");
    refuse("list.mhd", replaced(kMeta, "LOCAL", "LIST"), "multi-file");
    refuse("pattern.mhd", replaced(kMeta, "LOCAL", "slice%03d.raw 1 10 1"), "multi-file");
    refuse("twice.mha", replaced(kMeta, "NDims = 3\n", "NDims = 3\nNDims = 3\n") + kSamples, "twice");
    refuse("noequals.mha", replaced(kMeta, "NDims = 3\n", "NDims = 3\nthis is not a field\n") + kSamples,
           "Key = Value");
    refuse("headersize.mhd", replaced(kMeta, "ElementDataFile = LOCAL", "HeaderSize = -7\nElementDataFile = x.raw"),
           "\"HeaderSize\"");
    refuse("huge.mha", "NDims = " + std::string(std::size_t(2) << 20, '3'), "longer than 1 MiB");
    refuse("random.mha", randomBytes(4096, 7), "random.mha");
    refuse("empty.mhd", "", "ElementDataFile");
}

TEST_CASE("hostile VTK legacy files are refused", "[core][io][hostile]") {
    TempDir dir;
    auto refuse = [&](const std::string& name, const std::string& bytes, const std::string& expect) {
        writeFile(dir.file(name), bytes);
        expectRefused(dir.file(name), expect);
    };
    const std::string big = sampleBytes(kSmall, true);
    const std::string ascii = replaced(kVtk, "BINARY", "ASCII");
    refuse("version.vtk", replaced(kVtk, "# vtk DataFile Version 3.0", "hello") + big, "not a VTK legacy file");
    refuse("encoding.vtk", replaced(kVtk, "BINARY", "HEX") + big, "ASCII or BINARY");
    refuse("poly.vtk", replaced(kVtk, "STRUCTURED_POINTS", "POLYDATA") + big, "STRUCTURED_POINTS");
    refuse("zero.vtk", replaced(kVtk, "DIMENSIONS 4 3 2", "DIMENSIONS 4 0 2") + big, "\"DIMENSIONS\"");
    refuse("nodims.vtk", replaced(kVtk, "DIMENSIONS 4 3 2\n", "") + big, "DIMENSIONS");
    refuse(
        "absurd.vtk",
        replaced(replaced(kVtk, "4 3 2", "100000 100000 100000"), "POINT_DATA 24", "POINT_DATA 1000000000000000") + big,
        "volume limit");
    refuse("oversized.vtk",
           replaced(replaced(kVtk, "4 3 2", "1000 1000 100"), "POINT_DATA 24", "POINT_DATA 100000000") + big,
           "has only 48");
    refuse("count.vtk", replaced(kVtk, "POINT_DATA 24", "POINT_DATA 23") + big, "\"POINT_DATA\"");
    refuse("bit.vtk", replaced(kVtk, "short 1", "bit 1") + big, "\"bit\"");
    refuse("long.vtk", replaced(kVtk, "short 1", "long") + big, "\"long\"");
    refuse("components.vtk", replaced(kVtk, "short 1", "short 3") + big, "1 component");
    refuse("nolut.vtk", replaced(kVtk, "LOOKUP_TABLE default\n", "") + big, "LOOKUP_TABLE");
    refuse("cell.vtk", replaced(kVtk, "POINT_DATA 24", "CELL_DATA 6") + big, "CELL_DATA");
    refuse("field.vtk", replaced(kVtk, "SCALARS s short 1", "FIELD f 1") + big, "FIELD");
    refuse("truncated.vtk", kVtk + big.substr(0, 40), "has only 40");
    refuse("spacing.vtk", replaced(kVtk, "SPACING 1 1 1", "SPACING 1 -1 1") + big, "\"SPACING\"");
    refuse("origin.vtk", replaced(kVtk, "ORIGIN 0 0 0", "ORIGIN 0 inf 0") + big, "\"ORIGIN\"");
    refuse("far.vtk", replaced(kVtk, "ORIGIN 0 0 0", "ORIGIN 0 1e300 0") + big, "beyond float range");
    refuse("ascii_short.vtk", ascii + "1 2 3 4 5", "truncated");
    std::string ones;
    for (int i = 0; i < 23; ++i) ones += " 1";
    refuse("ascii_word.vtk", ascii + "1 2 abc" + ones, "\"abc\"");
    refuse("ascii_range.vtk", replaced(ascii, "short", "unsigned_char") + "300" + ones, "\"300\"");
    refuse("ascii_big.vtk",
           replaced(replaced(ascii, "4 3 2", "1000 1000 100"), "POINT_DATA 24", "POINT_DATA 100000000") + "1 2 3",
           "ASCII numbers");
    refuse("token.vtk", replaced(kVtk, "DATASET", std::string(1000, 'D')), "longer than");
    refuse("random.vtk", randomBytes(4096, 8), "not a VTK legacy file");
    refuse("empty.vtk", "", "not a VTK legacy file");
}

TEST_CASE("raw files whose layout disagrees with their size are refused", "[core][io][hostile]") {
    TempDir dir;
    writeFile(dir.file("v.raw"), kSamples);
    auto refuse = [&](Dims dims, ScalarType type, const std::string& expect, const std::string& name = "v.raw") {
        RawLayout layout;
        layout.dims = dims;
        layout.type = type;
        expectRefused(dir.file(name), expect, [&] { loadRaw(dir.file(name), layout); });
    };
    refuse({4, 3, 3}, ScalarType::Int16, "has only 48");
    refuse({4, 3, 1}, ScalarType::Int16, "sizes disagree");
    refuse({4, 3, 2}, ScalarType::Float64, "has only 48");
    refuse({4, 0, 2}, ScalarType::Int16, "must be positive");
    refuse({-4, 3, 2}, ScalarType::Int16, "must be positive");
    refuse({100000, 100000, 100000}, ScalarType::UInt8, "volume limit");
    refuse({2000, 2000, 2000}, ScalarType::UInt8, "has only 48");
    refuse({4, 3, 2}, ScalarType::Int16, "cannot open", "absent.raw");
    RawLayout flat;
    flat.dims = {4, 3, 2};
    flat.type = ScalarType::Int16;
    flat.spacing = {1, 0, 1};
    expectRefused(dir.file("v.raw"), "spacing", [&] { loadRaw(dir.file("v.raw"), flat); });
    // Without a layout a .raw file is a request loadVolume cannot serve.
    expectRefused(dir.file("v.raw"), "dims and type");
}

TEST_CASE("every loader refuses missing files, directories, empty files and noise", "[core][io][hostile]") {
    TempDir dir;
    for (const std::string ext : {".nrrd", ".nhdr", ".nii", ".nii.gz", ".mhd", ".mha", ".vtk"}) {
        expectRefused(dir.file("absent" + ext), "cannot open");
        std::filesystem::create_directories(dir.file("folder" + ext));
        expectRefused(dir.file("folder" + ext), "cannot open");
        writeFile(dir.file("empty" + ext), "");
        expectRefused(dir.file("empty" + ext), "");
        for (unsigned seed = 10; seed < 30; ++seed) {
            writeFile(dir.file("noise" + ext), randomBytes(1 + seed * 37, seed));
            expectRefused(dir.file("noise" + ext), "");
        }
    }
    writeFile(dir.file("scan.dcm"), kSamples);
    expectRefused(dir.file("scan.dcm"), "not a DICOM file");
    writeFile(dir.file("scan.img"), kSamples);
    expectRefused(dir.file("scan.img"), "unsupported volume file extension \".img\"");
}

TEST_CASE("hostile DICOM files are refused", "[core][io][hostile][dicom]") {
    TempDir dir;
    const std::string good = DicomSlice(16, 12, 0).bytes();
    writeFile(dir.file("good.dcm"), good);
    REQUIRE(loadVolume(dir.file("good.dcm")).dims() == Dims{16, 12, 1});

    expectRefused(dir.file("absent.dcm"), "cannot open");
    writeFile(dir.file("empty.dcm"), "");
    expectRefused(dir.file("empty.dcm"), "not a DICOM file");
    for (unsigned seed = 40; seed < 60; ++seed) {
        writeFile(dir.file("noise.dcm"), std::string(128, '\0') + "DICM" + randomBytes(1 + seed * 37, seed));
        expectRefused(dir.file("noise.dcm"), "");
    }
    // Cut anywhere: in the header, in an element, in the pixel data.
    for (std::size_t keep :
         {std::size_t(100), std::size_t(200), std::size_t(300), good.size() - 200, good.size() - 1}) {
        CAPTURE(keep);
        writeFile(dir.file("truncated.dcm"), good.substr(0, keep));
        expectRefused(dir.file("truncated.dcm"), "");
    }
    DicomSlice lying(16, 12, 0);
    lying.raw(0x7fe0, 0x0010, "OW", std::string(64, '\1'), 0xfffffff0u);
    writeFile(dir.file("lying_pixels.dcm"), lying.bytes());
    expectRefused(dir.file("lying_pixels.dcm"), "");
    DicomSlice lyingHeader(16, 12, 0);
    lyingHeader.raw(0x0009, 0x1010, "OB", std::string(8, '\1'), 0x7ffffff0u);
    writeFile(dir.file("lying_header.dcm"), lyingHeader.bytes());
    expectRefused(dir.file("lying_header.dcm"), "");
    // A standard element with a VR the dictionary does not allow (GDCM would assert on it).
    DicomSlice wrongVr(16, 12, 0);
    wrongVr.text(0x0028, 0x0009, "AS", "0018");  // FrameIncrementPointer is AT
    writeFile(dir.file("wrong_vr.dcm"), wrongVr.bytes());
    expectRefused(dir.file("wrong_vr.dcm"), "(0028,0009) has VR AS");
    // Encapsulated pixel data whose closing delimiter claims 2.3 GB (GDCM would allocate them).
    DicomSlice delimiter(16, 12, 0);
    const auto item = [](std::uint16_t element, std::uint32_t length) {
        return encode(std::uint16_t(0xfffe), false) + encode(element, false) + encode(length, false);
    };
    delimiter.raw(0x7fe0, 0x0010, "OB", item(0xe000, 0) + item(0xe000, 4) + "abcd" + item(0xe0dd, 0x89000000u),
                  0xffffffffu);
    writeFile(dir.file("delimiter.dcm"), delimiter.bytes());
    expectRefused(dir.file("delimiter.dcm"), "delimitation item declares 2298478592 bytes");
    // RLE frames whose headers lie about their segments (GDCM's decoder seeks to the offsets unchecked).
    const auto rleFrame = [](std::uint32_t segments, std::uint32_t first, std::uint32_t length) {
        std::string header = encode(segments, false) + encode(first, false);
        header += std::string(64 - header.size(), '\0');
        return header + std::string(length - 64, '\x7f');
    };
    for (const auto& [frame, problem] :
         std::vector<std::pair<std::string, std::string>>{{rleFrame(2, 0x40b90000u, 130), "segment 1 starts at byte"},
                                                          {rleFrame(0, 64, 130), "declares 0 segments"},
                                                          {rleFrame(16, 64, 130), "declares 16 segments"},
                                                          {std::string(40, '\0'), "has no 64-byte header"}}) {
        DicomSlice rle(16, 12, 0);
        rle.transferSyntax = "1.2.840.10008.1.2.5";
        const std::string items = item(0xe000, 0) + item(0xe000, std::uint32_t(frame.size())) + frame + item(0xe0dd, 0);
        rle.raw(0x7fe0, 0x0010, "OB", items, 0xffffffffu);
        writeFile(dir.file("rle_lying.dcm"), rle.bytes());
        expectRefused(dir.file("rle_lying.dcm"), problem);
    }
    DicomSlice noPixels(16, 12, 0);
    noPixels.erase(0x7fe0, 0x0010);
    writeFile(dir.file("no_pixels.dcm"), noPixels.bytes());
    expectRefused(dir.file("no_pixels.dcm"), "no pixel data");
    DicomSlice absurd(16, 12, 0);
    absurd.us(0x0028, 0x0010, 65535);
    absurd.us(0x0028, 0x0011, 65535);
    writeFile(dir.file("absurd.dcm"), absurd.bytes());
    expectRefused(dir.file("absurd.dcm"), "pixel data holds 384");
    DicomSlice colour(16, 12, 0);
    colour.us(0x0028, 0x0002, 3);
    writeFile(dir.file("colour.dcm"), colour.bytes());
    expectRefused(dir.file("colour.dcm"), "SamplesPerPixel");
    DicomSlice badOrientation(16, 12, 0);
    badOrientation.text(0x0020, 0x0037, "DS", "1\\1\\0\\0\\1\\0");
    writeFile(dir.file("bad_orientation.dcm"), badOrientation.bytes());
    expectRefused(dir.file("bad_orientation.dcm"), "ImageOrientationPatient");

    // Folders: mixed sizes within one series, nothing DICOM at all.
    std::filesystem::create_directories(dir.file("mixed_sizes"));
    writeFile(dir.file("mixed_sizes/a.dcm"), DicomSlice(16, 12, 0).bytes());
    writeFile(dir.file("mixed_sizes/b.dcm"), DicomSlice(16, 13, 1).bytes());
    expectRefused(dir.file("mixed_sizes"), "mixed sizes");
    std::filesystem::create_directories(dir.file("not_dicom"));
    writeFile(dir.file("not_dicom/x.txt"), "hello");
    expectRefused(dir.file("not_dicom"), "no DICOM images");
    writeFile(dir.file("DICOMDIR"), randomBytes(500, 3));
    expectRefused(dir.file("DICOMDIR"), "DICOMDIR");
}

namespace {

bool finiteMesh(const Mesh& mesh) {
    for (const Vertex& v : mesh.vertices)
        for (std::size_t k = 0; k < 3; ++k)
            if (!std::isfinite(v.position[k]) || !std::isfinite(v.normal[k])) return false;
    return true;
}

template <class T>
Volume sphereWithHoles(ScalarType type) {
    const Volume sphere = makeField({"sphere", 24});
    Volume v(sphere.dims(), type);
    std::mt19937 rng(99);
    const T specials[] = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                          -std::numeric_limits<T>::infinity()};
    for (std::size_t i = 0; i < v.sampleCount(); ++i) {
        v.data<T>()[i] = T(sphere.data<float>()[i]);
        if (rng() % 7 == 0) v.data<T>()[i] = specials[rng() % 3];
    }
    return v;
}

}  // namespace

TEST_CASE("an all-NaN volume gives empty meshes; its range is empty", "[core][io][hostile][nan]") {
    for (ScalarType type : {ScalarType::Float32, ScalarType::Float64}) {
        Volume v({9, 8, 7}, type);
        for (int z = 0; z < 7; ++z)
            for (int y = 0; y < 8; ++y)
                for (int x = 0; x < 9; ++x) v.setValue(x, y, z, std::nan(""));
        CHECK_FALSE(std::isfinite(v.range()[0]));
        for (double iso : {0.0, -1e30, 1e30}) {
            CHECK(marchingCubes(v, iso).triangleCount() == 0);
            CHECK(marchingCubes(v, iso, TableKind::Classic).triangleCount() == 0);
            CHECK(extractAllSurfaces(v, iso).empty());
            CHECK(countCrossedEdges(v, iso) == 0);
        }
    }
}

TEST_CASE("scattered NaN and infinite samples give only finite vertices", "[core][io][hostile][nan]") {
    for (const Volume& v :
         {sphereWithHoles<float>(ScalarType::Float32), sphereWithHoles<double>(ScalarType::Float64)}) {
        CAPTURE(scalarTypeName(v.type()));
        const double iso = fieldDefaultIso("sphere");
        for (TableKind table : {TableKind::Consistent, TableKind::Classic}) {
            const Mesh mesh = marchingCubes(v, iso, table);
            CHECK(mesh.triangleCount() > 0);
            CHECK(finiteMesh(mesh));
            std::size_t triangles = 0;
            for (const Surface& s : extractAllSurfaces(v, iso, table)) {
                CHECK(finiteMesh(s.mesh));
                CHECK(std::isfinite(s.stats.area));
                triangles += s.mesh.triangleCount();
            }
            CHECK(triangles == mesh.triangleCount());
        }
    }
}
