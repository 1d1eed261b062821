"""VTK XML ImageData (.vti) that VTK itself writes reads back as the same samples.

A 64^3 gyroid (`isotrack field gyroid:64 --out`, its samples read with numpy from
the raw NRRD, plus a ramp along x so that no axis swap or flip goes unseen) is written by vtkXMLImageDataWriter as ASCII, inline base64,
appended raw and appended base64, uncompressed and zlib, with UInt32 and UInt64
headers, as int16 and float64, and in sizes of one short zlib block and of a
partial last block, and at 128^3 (zlib appended, base64, ASCII: the size a
ParaView user writes); `isotrack extract --method all --json` must
give the same triangles, vertices and exported PLY bytes as the NRRD of the same samples. A second
array chosen with --array is checked against its NRRD, and VTK 9's Direction
with a WholeExtent not starting at 0 against VTK's own index-to-world transform.

Usage: /usr/bin/python3 vti_files.py ISOTRACK WORK_DIR  (exit 77 without VTK)
"""
import json
import os
import shutil
import subprocess
import sys

import numpy as np

try:
    import vtk
    from vtk.util import numpy_support
except ImportError:
    print("python3-vtk9 is missing: skipped")
    sys.exit(77)

ISOTRACK, WORK = sys.argv[1], sys.argv[2]
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(WORK)
os.chdir(WORK)
failures = []


def run(*args):
    done = subprocess.run([ISOTRACK, *args], capture_output=True, text=True)
    if done.returncode != 0:
        failures.append(f"isotrack {' '.join(args)}: exit {done.returncode}: {done.stderr.strip()}")
        return None
    return done.stdout


def counts(path, *extra, iso="0.25"):
    """(triangles, vertices, the exported PLY's bytes) of every surface at `iso`."""
    ply = os.path.basename(path) + ".ply"
    out = run("extract", "--volume", path, "--iso", iso, "--method", "all", "--json", "--out", ply, *extra)
    if out is None:
        return None
    j = json.loads(out)
    with open(ply, "rb") as f:
        return j["triangles"], j["vertices"], f.read()


def read_nrrd(path):
    data = open(path, "rb").read()
    head, body = data.split(b"\n\n", 1)
    fields = dict(line.split(": ", 1) for line in head.decode().splitlines()[1:] if ": " in line)
    assert fields["type"] == "float" and fields["encoding"] == "raw", fields
    nx, ny, nz = (int(v) for v in fields["sizes"].split())
    return np.frombuffer(body, dtype="<f4").reshape(nz, ny, nx)


def write_nrrd(path, samples):
    nz, ny, nx = samples.shape
    kind = {np.dtype("float32"): "float", np.dtype("float64"): "double", np.dtype("int16"): "short"}[samples.dtype]
    header = f"NRRD0004\ntype: {kind}\ndimension: 3\nsizes: {nx} {ny} {nz}\nendian: little\nencoding: raw\n\n"
    with open(path, "wb") as f:
        f.write(header.encode() + samples.astype(samples.dtype.newbyteorder("<")).tobytes())


def image(arrays, extent_start=(0, 0, 0), direction=None):
    nz, ny, nx = arrays[0][1].shape[:3]
    img = vtk.vtkImageData()
    x0, y0, z0 = extent_start
    img.SetExtent(x0, x0 + nx - 1, y0, y0 + ny - 1, z0, z0 + nz - 1)
    img.SetSpacing(1.0, 1.0, 1.0)
    if direction is not None:
        img.SetDirectionMatrix(*direction)
    for name, samples in arrays:
        flat = np.ascontiguousarray(samples).reshape(nx * ny * nz, -1)
        array = numpy_support.numpy_to_vtk(flat if flat.shape[1] > 1 else flat.ravel(), deep=True)
        array.SetName(name)
        img.GetPointData().AddArray(array)
    return img


def write_vti(path, img, mode, zlib=False, header64=False, encode=True):
    w = vtk.vtkXMLImageDataWriter()
    w.SetFileName(path)
    w.SetInputData(img)
    {"ascii": w.SetDataModeToAscii, "binary": w.SetDataModeToBinary, "appended": w.SetDataModeToAppended}[mode]()
    if zlib:
        w.SetCompressorTypeToZLib()
    else:
        w.SetCompressorTypeToNone()
    if header64:
        w.SetHeaderTypeToUInt64()
    w.SetEncodeAppendedData(encode)
    assert w.Write() == 1, path


run("field", "gyroid:64", "--out", "g.nrrd")
# A ramp along x makes the surface differ under any swap or flip of the axes.
gyroid = read_nrrd("g.nrrd") + np.linspace(0.0, 0.4, 64, dtype=np.float32)[None, None, :]
write_nrrd("g_ramp.nrrd", gyroid)
reference = counts("g_ramp.nrrd")
print("NRRD reference (triangles, vertices):", reference[:2])

cases = [
    ("ascii", dict(mode="ascii")),
    ("base64", dict(mode="binary")),
    ("base64_zlib", dict(mode="binary", zlib=True)),
    ("raw", dict(mode="appended", encode=False)),
    ("raw_zlib", dict(mode="appended", zlib=True, encode=False)),
    ("raw_zlib_uint64", dict(mode="appended", zlib=True, encode=False, header64=True)),
    ("appended_base64", dict(mode="appended")),
    ("appended_base64_zlib", dict(mode="appended", zlib=True)),
]
img = image([("g", gyroid)])
for name, how in cases:
    write_vti(f"{name}.vti", img, **how)
    got = counts(f"{name}.vti")
    print(f"{name}.vti:", got and got[:2])
    if got != reference:
        failures.append(f"{name}.vti: {got and got[:2]}, the NRRD gives {reference[:2]} (or the meshes differ)")

# The size a ParaView user writes: 128^3, zlib-compressed appended, inline
# base64 and ASCII, each against the NRRD of the same samples.
run("field", "gyroid:128", "--out", "g128.nrrd")
big = read_nrrd("g128.nrrd") + np.linspace(0.0, 0.4, 128, dtype=np.float32)[None, None, :]
write_nrrd("g128_ramp.nrrd", big)
big_reference = counts("g128_ramp.nrrd")
for name, how in (("raw_zlib", dict(mode="appended", zlib=True, encode=False)),
                  ("base64", dict(mode="binary")), ("ascii", dict(mode="ascii"))):
    write_vti(f"g128_{name}.vti", image([("g", big)]), **how)
    got = counts(f"g128_{name}.vti")
    print(f"g128_{name}.vti:", got and got[:2])
    if big_reference is None or got != big_reference:
        failures.append(f"g128_{name}.vti: {got and got[:2]}, the NRRD gives {big_reference and big_reference[:2]}")

# Other sample types, each against the NRRD of the same samples.
for dtype, scale in (("int16", 1000.0), ("float64", 1.0)):
    samples = (gyroid * scale).astype(dtype)
    write_nrrd(f"{dtype}.nrrd", samples)
    iso = str(0.25 * scale)
    want = counts(f"{dtype}.nrrd", iso=iso)
    write_vti(f"{dtype}.vti", image([("g", samples)]), "appended", zlib=True, encode=False)
    if want is None or counts(f"{dtype}.vti", iso=iso) != want:
        failures.append(f"{dtype}.vti: the mesh differs from {dtype}.nrrd's")

# zlib blocks of VTK's 32 KiB: a volume within one short block, and one whose last
# block is partial.
for nz, ny, nx in ((20, 20, 20), (30, 40, 50)):
    part = np.ascontiguousarray(gyroid[:nz, :ny, :nx])
    name = f"part_{nx}x{ny}x{nz}"
    write_nrrd(f"{name}.nrrd", part)
    want = counts(f"{name}.nrrd")
    for mode, encode in (("binary", True), ("appended", False)):
        write_vti(f"{name}_{mode}.vti", image([("g", part)]), mode, zlib=True, encode=encode)
        if want is None or counts(f"{name}_{mode}.vti") != want:
            failures.append(f"{name}_{mode}.vti: the mesh differs from {name}.nrrd's")

# Two arrays: the first scalar one by default, the other by --array; a 3-component
# array first is passed over.
vectors = np.stack([gyroid, gyroid, gyroid], axis=-1)
two = image([("v", vectors), ("g", gyroid), ("neg", -gyroid)])
write_vti("two.vti", two, "appended", zlib=True, encode=False)
if counts("two.vti") != reference:
    failures.append(f"two.vti: the first scalar array gives {counts('two.vti')}, not {reference}")
write_nrrd("neg.nrrd", -gyroid)
if counts("two.vti", "--array", "neg") != counts("neg.nrrd"):
    failures.append("two.vti --array neg: differs from neg.nrrd")
bad = subprocess.run([ISOTRACK, "extract", "--volume", "two.vti", "--array", "nope"], capture_output=True, text=True)
if bad.returncode != 1 or "no PointData array \"nope\"" not in bad.stderr or bad.stderr.count("\n") != 1:
    failures.append(f"--array nope: exit {bad.returncode}: {bad.stderr.strip()}")

# Geometry: VTK's own index-to-physical transform of the extent's first point is
# the volume's origin, and Direction's columns its axes (`info --json`).
rotation = (0.0, -1.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)  # row major
turned = image([("g", gyroid)], extent_start=(3, 4, 5), direction=rotation)
turned.SetSpacing(0.5, 2.0, 1.5)
turned.SetOrigin(10.0, -20.0, 7.25)
write_vti("turned.vti", turned, "binary")
first = [0.0, 0.0, 0.0]
turned.TransformIndexToPhysicalPoint(3, 4, 5, first)
out = run("info", "--volume", "turned.vti", "--json")
if out is not None:
    info = json.loads(out)
    axes = [[rotation[a], rotation[3 + a], rotation[6 + a]] for a in range(3)]
    if not np.allclose(info["origin"], first) or not np.allclose(info["direction"], axes):
        failures.append(f"turned.vti: origin {info['origin']} direction {info['direction']}, VTK says {first} {axes}")
    if not np.allclose(info["spacing"], [0.5, 2.0, 1.5]):
        failures.append(f"turned.vti: spacing {info['spacing']}")

if failures:
    print("\n".join("FAIL " + f for f in failures))
    sys.exit(1)
print("all .vti files read as VTK wrote them")
