#!/usr/bin/python3
"""VTK's vtkWindowedSincPolyDataFilter on a PLY isotrack wrote, for docs/meshes.md.

Usage: /usr/bin/python3 bench/vtk_smoothing.py MESH.ply [ITERATIONS] [PASSBAND]

Smooths the mesh with Debian's VTK (python3-vtk9; 9.1 windows with Hamming)
as `isotrack extract --smooth` is documented to (boundary vertices fixed, no
feature edges, coordinates normalized), and prints the enclosed volume and the
mean dihedral angle (radians, between the normals of triangles sharing an edge)
before and after, and the Hausdorff distance between the two, sampled at the
vertices, edge midpoints and centres (an upper bound within about half an edge).
"""
import sys

import numpy as np
import vtk
from vtk.util import numpy_support

from mesh_measures import enclosed_volume, read_ply, sampled_hausdorff


def mean_dihedral(v, f):
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    length = np.linalg.norm(n, axis=1)
    ok = length > 0
    n[ok] /= length[ok, None]
    edges = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    faces = np.tile(np.arange(len(f)), 3)
    order = np.lexsort((edges[:, 1], edges[:, 0]))
    edges, faces = edges[order], faces[order]
    pair = (edges[1:] == edges[:-1]).all(axis=1)
    a, b = faces[:-1][pair], faces[1:][pair]
    keep = ok[a] & ok[b]
    return np.arccos(np.clip((n[a[keep]] * n[b[keep]]).sum(axis=1), -1, 1)).mean()


def main():
    v, f = read_ply(sys.argv[1])
    iterations = int(sys.argv[2]) if len(sys.argv) > 2 else 20
    passband = float(sys.argv[3]) if len(sys.argv) > 3 else 0.1
    mesh = vtk.vtkPolyData()
    points = vtk.vtkPoints()
    points.SetData(numpy_support.numpy_to_vtk(v, deep=1))
    mesh.SetPoints(points)
    cells = np.hstack([np.full((len(f), 1), 3), f]).ravel()
    polys = vtk.vtkCellArray()
    polys.SetCells(len(f), numpy_support.numpy_to_vtkIdTypeArray(cells, deep=1))
    mesh.SetPolys(polys)
    smoother = vtk.vtkWindowedSincPolyDataFilter()
    smoother.SetInputData(mesh)
    smoother.SetNumberOfIterations(iterations)
    smoother.SetPassBand(passband)
    smoother.BoundarySmoothingOff()
    smoother.FeatureEdgeSmoothingOff()
    smoother.NonManifoldSmoothingOn()
    smoother.NormalizeCoordinatesOn()
    smoother.Update()
    out = numpy_support.vtk_to_numpy(smoother.GetOutput().GetPoints().GetData()).astype(np.float64)
    print(f"VTK {vtk.vtkVersion.GetVTKVersion()}, {iterations} iterations, pass band {passband}")
    print(f"enclosed volume {enclosed_volume(v, f):.1f} -> {enclosed_volume(out, f):.1f}")
    print(f"mean dihedral angle {mean_dihedral(v, f):.4f} -> {mean_dihedral(out, f):.4f} rad")
    print(f"Hausdorff distance (sampled) {sampled_hausdorff(v, out, f):.3f}")


if __name__ == "__main__":
    main()
