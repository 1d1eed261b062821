#!/usr/bin/python3
"""VTK reference numbers for an isosurface: triangles, points, components.

Usage (Debian's interpreter, which has the VTK bindings):

    /usr/bin/python3 scripts/vtk_components.py FILE.nrrd ISO [--json]
    /usr/bin/python3 scripts/vtk_components.py --sphere [--json]

For FILE.nrrd at isovalue ISO, runs vtkMarchingCubes and vtkFlyingEdges3D
(ComputeNormals on for both) and, on each output, vtkPolyDataConnectivityFilter
(SetExtractionModeToAllRegions, ColorRegionsOn). Prints JSON with, per
algorithm: triangles, points, regions (GetNumberOfExtractedRegions), the
largest / smallest region size in triangles (cells counted per RegionId), and
the wall-clock seconds of each filter's Update(). Default output is indented
JSON; --json prints it compactly on one line.

Reading: vtkNrrdReader (the serial one) is used for raw-encoded files,
attached or detached header; raw files it reads are spot-checked against the
file bytes. The header is also parsed here, and a small pure-Python NRRD
reader is used instead when vtkNrrdReader would misread the file: it fails,
the encoding is not raw (gzip is unsupported and the ascii path misreads data
in VTK 9.1), it uses "byte skip"/"line skip", its space is left-handed (VTK
9.1 then flips y), or the first axis has <= 9 samples (VTK 9.1 then treats
that axis as vector components). Orientation in "space directions" is
ignored (only the axis lengths become spacing), as vtkNrrdReader does. The
"input" section of the JSON says which reader was used.

--sphere: built-in check. Writes a float distance-to-centre volume as NRRD
(attached raw, detached raw, gzip, and with "space directions"/"space
origin"), reads each back through the same code path, and checks that both
algorithms give exactly one closed component (Euler characteristic 2, no
boundary edges) with the expected area. Exits non-zero on failure.
"""

import gzip
import json
import math
import os
import struct
import sys
import tempfile
import time

import vtk

# Debian's VTK is built with MPI: vtk.vtkNrrdReader() is overridden through
# the object factory by vtkPNrrdReader, which fails without an MPI controller
# ("No MPI Controller available"). Use the serial reader.
vtk.vtkObjectFactory.SetAllEnableFlags(False, "vtkNrrdReader",
                                       "vtkPNrrdReader")

# NRRD type name -> (struct code, VTK type)
_NRRD_TYPES = {}
for _names, _code, _vtype in [
        (("signed char", "int8", "int8_t"), "b", vtk.VTK_SIGNED_CHAR),
        (("uchar", "unsigned char", "uint8", "uint8_t"), "B",
         vtk.VTK_UNSIGNED_CHAR),
        (("short", "short int", "signed short", "signed short int", "int16",
          "int16_t"), "h", vtk.VTK_SHORT),
        (("ushort", "unsigned short", "unsigned short int", "uint16",
          "uint16_t"), "H", vtk.VTK_UNSIGNED_SHORT),
        (("int", "signed int", "int32", "int32_t"), "i", vtk.VTK_INT),
        (("uint", "unsigned int", "uint32", "uint32_t"), "I",
         vtk.VTK_UNSIGNED_INT),
        (("longlong", "long long", "long long int", "signed long long",
          "signed long long int", "int64", "int64_t"), "q",
         vtk.VTK_LONG_LONG),
        (("ulonglong", "unsigned long long", "unsigned long long int",
          "uint64", "uint64_t"), "Q", vtk.VTK_UNSIGNED_LONG_LONG),
        (("float",), "f", vtk.VTK_FLOAT),
        (("double",), "d", vtk.VTK_DOUBLE)]:
    for _n in _names:
        _NRRD_TYPES[_n] = (_code, _vtype)


# --------------------------------------------------------------------------
# NRRD header parsing and fallback reader
# --------------------------------------------------------------------------

def parse_nrrd_header(path):
    """Return (fields dict, byte offset of attached data)."""
    fields = {}
    with open(path, "rb") as f:
        magic = f.readline()
        if not magic.startswith(b"NRRD"):
            raise ValueError("%s: not a NRRD file" % path)
        while True:
            line = f.readline()
            if not line or line in (b"\n", b"\r\n"):
                break
            text = line.decode("latin-1").rstrip("\r\n")
            if text.startswith("#"):
                continue
            if ":=" in text:          # key/value pair, not a field
                continue
            if ":" not in text:
                raise ValueError("%s: bad header line %r" % (path, text))
            key, val = text.split(":", 1)
            fields[key.strip().lower()] = val.strip()
        offset = f.tell()
    return fields, offset


def _vec(s):
    s = s.strip()
    if s == "none":
        return None
    return [float(v) for v in s.strip("()").split(",")]


def header_geometry(fields):
    """(dims, spacing, origin) implied by the header (axis-aligned view)."""
    if int(fields["dimension"]) != 3:
        raise ValueError("only 3-D NRRDs are supported (dimension: %s)"
                         % fields["dimension"])
    dims = [int(v) for v in fields["sizes"].split()]
    spacing = [1.0, 1.0, 1.0]
    origin = [0.0, 0.0, 0.0]
    if "space directions" in fields:
        dirs = [_vec(t + ")") for t in fields["space directions"].split(")")
                if t.strip()]
        dirs = [d for d in dirs if d is not None]
        spacing = [math.sqrt(sum(c * c for c in d)) for d in dirs[:3]]
    elif "spacings" in fields:
        spacing = [float(v) if v.lower() != "nan" else 1.0
                   for v in fields["spacings"].split()]
    if "space origin" in fields:
        origin = _vec(fields["space origin"])
    elif "axis mins" in fields:
        origin = [float(v) if v.lower() != "nan" else 0.0
                  for v in fields["axis mins"].split()]
    return dims, spacing, origin


def read_nrrd_python(path, fields, offset):
    """Pure-Python fallback reader -> vtkImageData."""
    dims, spacing, origin = header_geometry(fields)
    code, vtype = _NRRD_TYPES[fields["type"].lower()]
    n = dims[0] * dims[1] * dims[2]
    enc = fields.get("encoding", "raw").lower()
    datafile = fields.get("data file", fields.get("datafile"))
    if datafile:
        if datafile.startswith("LIST") or " " in datafile.strip():
            raise ValueError("multi-file 'data file' not supported")
        src = os.path.join(os.path.dirname(os.path.abspath(path)), datafile)
        skip = 0
    else:
        src, skip = path, offset
    with open(src, "rb") as f:
        f.seek(skip)
        payload = f.read()
    if enc in ("gzip", "gz"):
        payload = gzip.decompress(payload)
    elif enc in ("raw",):
        pass
    elif enc in ("ascii", "text", "txt"):
        vals = payload.split()[:n]
        conv = float if code in "fd" else int
        payload = struct.pack("<%d%s" % (n, code), *[conv(v) for v in vals])
        fields = dict(fields, endian="little")
    else:
        raise ValueError("unsupported NRRD encoding %r" % enc)
    bskip = int(fields.get("byte skip", "0"))
    size = n * struct.calcsize(code)
    if bskip == -1:
        payload = payload[-size:]
    else:
        payload = payload[bskip:bskip + size]
    if len(payload) != size:
        raise ValueError("NRRD data too short: %d bytes, need %d"
                         % (len(payload), size))
    if struct.calcsize(code) > 1 and \
            fields.get("endian", "little").lower() != sys.byteorder:
        import array
        a = array.array(code)
        a.frombytes(payload)
        a.byteswap()
        payload = a.tobytes()

    imp = vtk.vtkImageImport()
    imp.CopyImportVoidPointer(payload, len(payload))
    imp.SetDataScalarType(vtype)
    imp.SetNumberOfScalarComponents(1)
    imp.SetWholeExtent(0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1)
    imp.SetDataExtentToWholeExtent()
    imp.SetDataSpacing(*spacing)
    imp.SetDataOrigin(*origin)
    imp.Update()
    img = vtk.vtkImageData()
    img.DeepCopy(imp.GetOutput())
    return img


def _spot_check(path, fields, offset, dims, img):
    """Compare a few voxels of img with the raw bytes of the NRRD."""
    code = _NRRD_TYPES[fields["type"].lower()][0]
    size = struct.calcsize(code)
    endian = "<" if fields.get("endian", "little").lower() == "little" else ">"
    datafile = fields.get("data file", fields.get("datafile"))
    if datafile:
        src = os.path.join(os.path.dirname(os.path.abspath(path)), datafile)
        offset = 0
    else:
        src = path
    n = dims[0] * dims[1] * dims[2]
    scalars = img.GetPointData().GetScalars()
    with open(src, "rb") as f:
        for k in range(65):
            i = (k * (n - 1)) // 64
            f.seek(offset + i * size)
            (v,) = struct.unpack(endian + code, f.read(size))
            w = scalars.GetTuple1(i)
            if not (v == w or (v != v and w != w)):
                return False
    return True


class _ErrorCatcher(object):
    def __init__(self, obj):
        self.messages = []
        obj.AddObserver("ErrorEvent", self)

    def __call__(self, obj, event):
        self.messages.append(event)


def load_nrrd(path):
    """Return (vtkImageData, info dict)."""
    fields, offset = parse_nrrd_header(path)
    dims, spacing, origin = header_geometry(fields)
    info = {"file": path, "type": fields.get("type"),
            "encoding": fields.get("encoding"), "dims": dims,
            "header_spacing": spacing, "header_origin": origin}

    img = None
    enc = fields.get("encoding", "raw").lower()
    vtk_ok = (enc == "raw"
              and int(fields.get("byte skip", fields.get("byteskip", "0"))) == 0
              and int(fields.get("line skip", fields.get("lineskip", "0"))) == 0
              and fields.get("space", "") not in (
                  "left-anterior-superior", "LAS", "3D-left-handed")
              and dims[0] > 9)
    if vtk_ok:
        # vtkNrrdReader reports problems through the error stream; silence
        # it and detect failure ourselves.
        prev = vtk.vtkObject.GetGlobalWarningDisplay()
        vtk.vtkObject.GlobalWarningDisplayOff()
        try:
            rd = vtk.vtkNrrdReader()
            catcher = _ErrorCatcher(rd)
            if rd.CanReadFile(path):
                rd.SetFileName(path)
                t0 = time.perf_counter()
                rd.Update()
                info["read_seconds"] = round(time.perf_counter() - t0, 4)
                out = rd.GetOutput()
                if not catcher.messages and out is not None and \
                        list(out.GetDimensions()) == dims and \
                        out.GetNumberOfScalarComponents() == 1 and \
                        out.GetPointData().GetScalars() is not None and \
                        _spot_check(path, fields, offset, dims, out):
                    img = out
                    info["reader"] = "vtkNrrdReader"
        finally:
            vtk.vtkObject.SetGlobalWarningDisplay(prev)
    if img is None:
        t0 = time.perf_counter()
        img = read_nrrd_python(path, fields, offset)
        info["read_seconds"] = round(time.perf_counter() - t0, 4)
        info["reader"] = "python-fallback"
    else:
        notes = []
        if any(abs(a - b) > 1e-6 * max(1.0, abs(b))
               for a, b in zip(img.GetSpacing(), spacing)):
            notes.append("vtkNrrdReader spacing %r != header %r; using header"
                         % (list(img.GetSpacing()), spacing))
            img.SetSpacing(*spacing)
        if any(abs(a - b) > 1e-6 * max(1.0, abs(b))
               for a, b in zip(img.GetOrigin(), origin)):
            notes.append("vtkNrrdReader origin %r != header %r; using header"
                         % (list(img.GetOrigin()), origin))
            img.SetOrigin(*origin)
        if notes:
            info["notes"] = notes
    info["spacing"] = list(img.GetSpacing())
    info["origin"] = list(img.GetOrigin())
    info["scalar_range"] = list(img.GetScalarRange())
    return img, info


# --------------------------------------------------------------------------
# Isosurface + connectivity
# --------------------------------------------------------------------------

def run_algorithm(img, iso, algo):
    if algo == "vtkMarchingCubes":
        f = vtk.vtkMarchingCubes()
    elif algo == "vtkFlyingEdges3D":
        f = vtk.vtkFlyingEdges3D()
    else:
        raise ValueError(algo)
    f.SetInputData(img)
    f.SetValue(0, iso)
    f.ComputeNormalsOn()
    t0 = time.perf_counter()
    f.Update()
    t_iso = time.perf_counter() - t0
    surf = f.GetOutput()

    conn = vtk.vtkPolyDataConnectivityFilter()
    conn.SetInputData(surf)
    conn.SetExtractionModeToAllRegions()
    conn.ColorRegionsOn()
    t0 = time.perf_counter()
    conn.Update()
    t_conn = time.perf_counter() - t0
    nreg = conn.GetNumberOfExtractedRegions()

    # Count cells per RegionId. VTK 9.1 puts RegionId on the points only
    # (newer VTK also on the cells); a cell's region is that of its points.
    out = conn.GetOutput()
    counts = [0] * nreg
    cell_rid = out.GetCellData().GetArray("RegionId")
    if cell_rid is not None:
        for r in _ints(cell_rid):
            counts[r] += 1
    else:
        prid = _ints(out.GetPointData().GetArray("RegionId"))
        polys = out.GetPolys()
        conn_ids = _ints(polys.GetConnectivityArray())
        offs = _ints(polys.GetOffsetsArray())
        for c in range(polys.GetNumberOfCells()):
            counts[prid[conn_ids[offs[c]]]] += 1
        if polys.GetNumberOfCells() != out.GetNumberOfCells():
            raise RuntimeError("connectivity output has non-polygon cells")
    # Cross-check with the filter's own per-region cell counts.
    sizes = conn.GetRegionSizes()
    sizes = [int(sizes.GetValue(i)) for i in range(sizes.GetNumberOfTuples())]
    if sizes[:nreg] != counts or sum(counts) != surf.GetNumberOfCells():
        raise RuntimeError("RegionId counts disagree with GetRegionSizes")

    return {
        "triangles": surf.GetNumberOfCells(),
        "points": surf.GetNumberOfPoints(),
        "regions": nreg,
        "largest_region_triangles": max(counts) if counts else 0,
        "smallest_region_triangles": min(counts) if counts else 0,
        "seconds": {algo: round(t_iso, 4),
                    "vtkPolyDataConnectivityFilter": round(t_conn, 4)},
        "_surface": surf,
    }


def _ints(arr):
    """Fast read-only integer sequence view of a vtk integer array."""
    try:
        return memoryview(arr).cast("B").cast(
            {4: "i", 8: "q"}[arr.GetDataTypeSize()])
    except (TypeError, KeyError, ValueError):
        return [int(arr.GetTuple1(i)) for i in range(arr.GetNumberOfTuples())]


def analyse(img, iso):
    res = {}
    for algo in ("vtkMarchingCubes", "vtkFlyingEdges3D"):
        res[algo] = run_algorithm(img, iso, algo)
    return res


def public(res):
    return {k: {kk: vv for kk, vv in v.items() if not kk.startswith("_")}
            for k, v in res.items()}


# --------------------------------------------------------------------------
# Built-in sphere check
# --------------------------------------------------------------------------

def write_nrrd(path, dims, spacing, origin, values, variant):
    """Write a float volume (values: flat list, x fastest) as NRRD."""
    raw = struct.pack("<%df" % len(values), *values)
    hdr = ["NRRD0004", "# vtk_components.py sphere check (%s)" % variant,
           "type: float", "dimension: 3",
           "sizes: %d %d %d" % tuple(dims)]
    if variant == "space":
        hdr += ["space: left-posterior-superior",
                "space directions: (%r,0,0) (0,%r,0) (0,0,%r)"
                % tuple(spacing),
                "space origin: (%r,%r,%r)" % tuple(origin)]
    else:
        hdr += ["spacings: %r %r %r" % tuple(spacing)]
    hdr += ["endian: little"]
    if variant == "gzip":
        hdr += ["encoding: gzip"]
        raw = gzip.compress(raw)
    else:
        hdr += ["encoding: raw"]
    if variant == "detached":
        hdr += ["data file: %s" % (os.path.basename(path) + ".raw")]
        with open(path + ".raw", "wb") as f:
            f.write(raw)
        with open(path, "w") as f:
            f.write("\n".join(hdr) + "\n")
    else:
        with open(path, "wb") as f:
            f.write(("\n".join(hdr) + "\n\n").encode())
            f.write(raw)


def surface_topology(poly):
    """(euler characteristic, boundary edge count, area)."""
    edges = {}
    polys = poly.GetPolys()
    polys.InitTraversal()
    ids = vtk.vtkIdList()
    while polys.GetNextCell(ids):
        n = ids.GetNumberOfIds()
        for k in range(n):
            a, b = ids.GetId(k), ids.GetId((k + 1) % n)
            key = (a, b) if a < b else (b, a)
            edges[key] = edges.get(key, 0) + 1
    boundary = sum(1 for c in edges.values() if c == 1)
    mass = vtk.vtkMassProperties()
    tri = vtk.vtkTriangleFilter()
    tri.SetInputData(poly)
    mass.SetInputConnection(tri.GetOutputPort())
    mass.Update()
    euler = poly.GetNumberOfPoints() - len(edges) + poly.GetNumberOfCells()
    return euler, boundary, mass.GetSurfaceArea()


def sphere_check():
    n, radius = 40, 12.3
    spacing = [0.9, 1.0, 1.1]
    origin = [-5.0, 2.0, 7.5]
    centre = [origin[k] + spacing[k] * (n - 1) / 2.0 for k in range(3)]
    dims = [n, n, n]
    vals = []
    for z in range(n):
        for y in range(n):
            for x in range(n):
                p = (origin[0] + spacing[0] * x, origin[1] + spacing[1] * y,
                     origin[2] + spacing[2] * z)
                # value decreases outward: "inside" = above the isovalue
                vals.append(-math.sqrt(sum((p[k] - centre[k]) ** 2
                                           for k in range(3))))
    iso = -radius
    expected_area = 4.0 * math.pi * radius * radius
    report = {"sphere": {"dims": dims, "spacing": spacing, "origin": origin,
                         "radius": radius, "iso": iso,
                         "expected_area": round(expected_area, 3)},
              "variants": {}}
    ok = True
    ref_counts = None
    with tempfile.TemporaryDirectory() as tmp:
        for variant in ("attached", "detached", "gzip", "space"):
            path = os.path.join(tmp, "sphere_%s.nrrd" % variant)
            write_nrrd(path, dims, spacing, origin, vals, variant)
            img, info = load_nrrd(path)
            res = analyse(img, iso)
            v = {"reader": info["reader"], "spacing": info["spacing"],
                 "origin": info["origin"]}
            if info.get("notes"):
                v["notes"] = info["notes"]
            problems = []
            if any(abs(a - b) > 1e-5 for a, b in zip(info["spacing"],
                                                      spacing)):
                problems.append("spacing")
            want_origin = origin if variant == "space" else [0.0, 0.0, 0.0]
            if any(abs(a - b) > 1e-5 for a, b in zip(info["origin"],
                                                      want_origin)):
                problems.append("origin")
            for algo, r in res.items():
                euler, boundary, area = surface_topology(r["_surface"])
                r["euler"], r["boundary_edges"] = euler, boundary
                r["area"] = round(area, 3)
                if r["regions"] != 1:
                    problems.append("%s regions=%d" % (algo, r["regions"]))
                if euler != 2 or boundary != 0:
                    problems.append("%s euler=%d boundary=%d"
                                    % (algo, euler, boundary))
                if abs(area - expected_area) > 0.02 * expected_area:
                    problems.append("%s area=%.2f" % (algo, area))
            counts = {a: (r["triangles"], r["points"]) for a, r in res.items()}
            if ref_counts is None:
                ref_counts = counts
            elif counts != ref_counts:
                problems.append("counts differ between NRRD variants")
            v.update(public(res))
            v["ok"] = not problems
            if problems:
                v["problems"] = problems
                ok = False
            report["variants"][variant] = v
    report["ok"] = ok
    return report, ok


# --------------------------------------------------------------------------

def main(argv):
    args = [a for a in argv if a != "--json"]
    compact = "--json" in argv
    dump = (lambda o: json.dumps(o, separators=(",", ":"))) if compact else \
        (lambda o: json.dumps(o, indent=2))
    if args == ["--sphere"]:
        report, ok = sphere_check()
        report["vtk_version"] = vtk.vtkVersion.GetVTKVersion()
        print(dump(report))
        return 0 if ok else 1
    if len(args) != 2 or args[0].startswith("-"):
        sys.stderr.write(__doc__)
        return 2
    path, iso = args[0], float(args[1])
    img, info = load_nrrd(path)
    res = analyse(img, iso)
    report = {"vtk_version": vtk.vtkVersion.GetVTKVersion(),
              "input": info, "iso": iso}
    report.update(public(res))
    print(dump(report))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
