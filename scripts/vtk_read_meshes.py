#!/usr/bin/python3
"""vtk_read_meshes.py -- read isotrack's mesh exports with VTK's own readers.

Usage: /usr/bin/python3 scripts/vtk_read_meshes.py [--triangles N] FILE...
  FILE is .ply (vtkPLYReader), .obj (vtkOBJReader) or .stl (vtkSTLReader).
  Prints, per file, the reader, points, triangles and whether normals came
  along; with --triangles N, exits 1 unless every file holds exactly N
  triangles (and nothing but triangles).

Needs Debian's python3-vtk9 (VTK 9.1), so run it with /usr/bin/python3.
"""
import argparse
import os
import sys

import vtk

READERS = {".ply": vtk.vtkPLYReader, ".obj": vtk.vtkOBJReader, ".stl": vtk.vtkSTLReader}


def read(path):
    ext = os.path.splitext(path)[1].lower()
    if ext not in READERS:
        sys.exit("vtk_read_meshes: %s: unsupported extension %r (supported: %s)" % (path, ext, ", ".join(READERS)))
    reader = READERS[ext]()
    reader.SetFileName(path)
    reader.Update()
    mesh = reader.GetOutput()
    polys = mesh.GetPolys()
    triangles = 0
    others = 0
    ids = vtk.vtkIdList()
    polys.InitTraversal()
    while polys.GetNextCell(ids):
        if ids.GetNumberOfIds() == 3:
            triangles += 1
        else:
            others += 1
    normals = mesh.GetPointData().GetNormals() is not None or mesh.GetCellData().GetNormals() is not None
    return reader.GetClassName(), mesh.GetNumberOfPoints(), triangles, others, normals


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--triangles", type=int, help="expected triangle count of every file")
    parser.add_argument("files", nargs="+")
    args = parser.parse_args()
    ok = True
    for path in args.files:
        name, points, triangles, others, normals = read(path)
        print("%-40s %-14s %9d points %9d triangles%s%s" % (
            path, name, points, triangles, " (+%d other cells)" % others if others else "",
            ", normals" if normals else ""))
        if args.triangles is not None and (triangles != args.triangles or others):
            print("  expected %d triangles" % args.triangles)
            ok = False
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
