#!/usr/bin/python3
"""make_ct_variants.py -- the CT sample in every volume format isotrack reads.

Usage: /usr/bin/python3 scripts/make_ct_variants.py [CT_DIR]
  CT_DIR defaults to assets/ct (where scripts/get_ct.sh writes cranium.nhdr and
  cranium.raw). Writes CT_DIR/variants/:

    cranium_gzip.nrrd        attached NRRD, gzip encoding
    cranium.mhd + cranium_mhd.raw   MetaImage, detached data
    cranium.mha              MetaImage, LOCAL data
    cranium_zlib.mha         MetaImage, LOCAL data, CompressedData True
    cranium.vtk              VTK legacy STRUCTURED_POINTS, BINARY (big-endian)
    cranium_be.nii           NIfTI-1, big-endian int16
    cranium_be.nii.gz        the same, gzip-compressed

Sizes and spacing are copied as text from cranium.nhdr, so every header spells
them the same way (NIfTI stores float32 pixdim and is compared with its .nii.gz).
Standard library only; idempotent (does nothing when the outputs are newer than
the inputs). Prints the paths it made, or would have made.
"""
import array
import gzip
import os
import struct
import sys
import zlib

NAMES = ["cranium_gzip.nrrd", "cranium.mhd", "cranium_mhd.raw", "cranium.mha", "cranium_zlib.mha",
         "cranium.vtk", "cranium_be.nii", "cranium_be.nii.gz"]


def read_nhdr(path):
    fields = {}
    with open(path, encoding="ascii") as f:
        for line in f:
            line = line.rstrip("\n")
            if ": " in line and not line.startswith("#"):
                key, value = line.split(": ", 1)
                fields[key] = value.strip()
    if fields.get("type") != "short" or fields.get("endian") != "little" or fields.get("encoding") != "raw":
        sys.exit("make_ct_variants: %s: expected raw little-endian short data" % path)
    return fields["sizes"].split(), fields["spacings"].split()


def nrrd_gzip(sizes, spacings, raw):
    header = ("NRRD0004\n# InVesalius example \"Cranium\" CT, gzip encoding (scripts/make_ct_variants.py)\n"
              "type: short\ndimension: 3\nsizes: %s\nspacings: %s\nkinds: domain domain domain\n"
              "endian: little\nencoding: gzip\n\n" % (" ".join(sizes), " ".join(spacings)))
    return header.encode("ascii") + gzip.compress(raw, compresslevel=6, mtime=0)


def mhd_header(sizes, spacings, data_file, extra=""):
    return ("ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n%s"
            "TransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = 0 0 0\nCenterOfRotation = 0 0 0\n"
            "AnatomicalOrientation = RAI\nElementSpacing = %s\nDimSize = %s\nElementType = MET_SHORT\n"
            "ElementDataFile = %s\n" % (extra or "CompressedData = False\n", " ".join(spacings), " ".join(sizes),
                                        data_file)).encode("ascii")


def vtk_binary(sizes, spacings, raw):
    count = int(sizes[0]) * int(sizes[1]) * int(sizes[2])
    header = ("# vtk DataFile Version 3.0\nInVesalius Cranium CT (scripts/make_ct_variants.py)\nBINARY\n"
              "DATASET STRUCTURED_POINTS\nDIMENSIONS %s\nSPACING %s\nORIGIN 0 0 0\nPOINT_DATA %d\n"
              "SCALARS ct short 1\nLOOKUP_TABLE default\n" % (" ".join(sizes), " ".join(spacings), count))
    return header.encode("ascii") + big_endian_int16(raw) + b"\n"


def big_endian_int16(raw):
    samples = array.array("h")
    samples.frombytes(raw)
    if sys.byteorder == "little":
        samples.byteswap()
    return samples.tobytes()


def nifti_big_endian(sizes, spacings, raw):
    nx, ny, nz = (int(s) for s in sizes)
    sx, sy, sz = (float(s) for s in spacings)
    header = b"".join([
        struct.pack(">i", 348),                      # sizeof_hdr
        b"\0" * 10 + b"\0" * 18,                     # data_type, db_name
        struct.pack(">ihcc", 0, 0, b"r", b"\0"),     # extents, session_error, regular, dim_info
        struct.pack(">8h", 3, nx, ny, nz, 1, 1, 1, 1),
        struct.pack(">3fh", 0, 0, 0, 0),             # intent_p1..3, intent_code
        struct.pack(">hhh", 4, 16, 0),               # datatype int16, bitpix, slice_start
        struct.pack(">8f", 1, sx, sy, sz, 1, 1, 1, 1),
        struct.pack(">3f", 352, 0, 0),               # vox_offset, scl_slope, scl_inter
        struct.pack(">hcc", 0, b"\0", b"\x0a"),      # slice_end, slice_code, xyzt_units (mm, s)
        struct.pack(">4f2i", 0, 0, 0, 0, 0, 0),      # cal_max, cal_min, slice_duration, toffset, glmax, glmin
        b"InVesalius Cranium CT, big-endian (isotrack)".ljust(80, b"\0"),
        b"\0" * 24,                                  # aux_file
        struct.pack(">hh", 1, 1),                    # qform_code, sform_code
        struct.pack(">6f", 0, 0, 0, 0, 0, 0),        # quatern_b..d, qoffset_x..z
        struct.pack(">4f", -sx, 0, 0, 0),            # srow_x: NIfTI is RAS, so the NRRD's
        struct.pack(">4f", 0, -sy, 0, 0),            # srow_y  i and j (LPS) point to -x, -y
        struct.pack(">4f", 0, 0, sz, 0),             # srow_z
        b"\0" * 16,                                  # intent_name
        b"n+1\0",
    ])
    assert len(header) == 348, len(header)
    return header + b"\0\0\0\0" + big_endian_int16(raw)


def write(path, data):
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, path)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    ct = os.path.abspath(sys.argv[1]) if len(sys.argv) > 1 else os.path.join(here, "..", "assets", "ct")
    nhdr, raw_path = os.path.join(ct, "cranium.nhdr"), os.path.join(ct, "cranium.raw")
    for p in (nhdr, raw_path):
        if not os.path.isfile(p):
            sys.exit("make_ct_variants: %s is missing (run scripts/get_ct.sh first)" % p)
    out = os.path.join(ct, "variants")
    outputs = [os.path.join(out, n) for n in NAMES]
    newest_input = max(os.path.getmtime(p) for p in (nhdr, raw_path, os.path.abspath(__file__)))
    if all(os.path.isfile(p) and os.path.getmtime(p) > newest_input for p in outputs):
        print("\n".join(outputs))
        return
    os.makedirs(out, exist_ok=True)

    sizes, spacings = read_nhdr(nhdr)
    with open(raw_path, "rb") as f:
        raw = f.read()
    if len(raw) != int(sizes[0]) * int(sizes[1]) * int(sizes[2]) * 2:
        sys.exit("make_ct_variants: %s has %d bytes, not what %s describes" % (raw_path, len(raw), nhdr))

    write(os.path.join(out, "cranium_gzip.nrrd"), nrrd_gzip(sizes, spacings, raw))
    write(os.path.join(out, "cranium_mhd.raw"), raw)
    write(os.path.join(out, "cranium.mhd"), mhd_header(sizes, spacings, "cranium_mhd.raw"))
    write(os.path.join(out, "cranium.mha"), mhd_header(sizes, spacings, "LOCAL") + raw)
    packed = zlib.compress(raw, 6)
    write(os.path.join(out, "cranium_zlib.mha"),
          mhd_header(sizes, spacings, "LOCAL",
                     "CompressedData = True\nCompressedDataSize = %d\n" % len(packed)) + packed)
    write(os.path.join(out, "cranium.vtk"), vtk_binary(sizes, spacings, raw))
    nii = nifti_big_endian(sizes, spacings, raw)
    write(os.path.join(out, "cranium_be.nii"), nii)
    write(os.path.join(out, "cranium_be.nii.gz"), gzip.compress(nii, compresslevel=6, mtime=0))
    print("\n".join(outputs))


if __name__ == "__main__":
    main()
