#!/usr/bin/python3
"""Dump how VTK's marching-cubes case table groups triangles into pieces.

For each of the 256 cube configurations (bit i set iff cube vertex i is ABOVE
the isovalue) build a 2x2x2 vtkImageData with 1.0 at the set vertices and 0.0
elsewhere, run vtkMarchingCubes at 0.5, map each output point to the cube edge
whose midpoint it is, union triangles that share a point, and record, for each
connected piece, the sorted set of cube edges its triangles use.

Run with Debian's interpreter (the one that has the VTK bindings):

    /usr/bin/python3 scripts/vtk_mc_pieces.py [OUTPUT]

OUTPUT defaults to tests/data/vtk_mc_pieces.txt relative to the repo root.

isotrack / VTK cube numbering:
  vertices 0:(0,0,0) 1:(1,0,0) 2:(1,1,0) 3:(0,1,0)
           4:(0,0,1) 5:(1,0,1) 6:(1,1,1) 7:(0,1,1)
  edges    0:(0,1) 1:(1,2) 2:(2,3) 3:(3,0) 4:(4,5) 5:(5,6) 6:(6,7) 7:(7,4)
           8:(0,4) 9:(1,5) 10:(2,6) 11:(3,7)
"""

import collections
import os
import sys

import vtk

VERTS = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
         (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
         (0, 4), (1, 5), (2, 6), (3, 7)]
MIDPOINTS = [tuple((VERTS[a][k] + VERTS[b][k]) / 2.0 for k in range(3))
             for a, b in EDGES]
TOL = 1e-4
# Faces as (4 corner vertices in cyclic order, the 4 edges between them):
# fe[i] joins fv[i] and fv[(i + 1) % 4].
FACES = [
    ((0, 1, 2, 3), (0, 1, 2, 3)),      # z = 0
    ((4, 5, 6, 7), (4, 5, 6, 7)),      # z = 1
    ((0, 1, 5, 4), (0, 9, 4, 8)),      # y = 0
    ((3, 2, 6, 7), (2, 10, 6, 11)),    # y = 1
    ((0, 3, 7, 4), (3, 11, 7, 8)),     # x = 0
    ((1, 2, 6, 5), (1, 10, 5, 9)),     # x = 1
]


def edge_of_point(p):
    best = None
    for e, m in enumerate(MIDPOINTS):
        if max(abs(p[k] - m[k]) for k in range(3)) <= TOL:
            if best is not None:
                raise RuntimeError("point %r matches two edges" % (p,))
            best = e
    if best is None:
        raise RuntimeError("point %r is not at an edge midpoint" % (p,))
    return best


def run_config(config):
    """Return (pieces, n_triangles, triangles).

    pieces = sorted list of sorted edge lists; triangles = list of edge-id
    triples as emitted by VTK.
    """
    img = vtk.vtkImageData()
    img.SetDimensions(2, 2, 2)
    img.SetSpacing(1.0, 1.0, 1.0)
    img.SetOrigin(0.0, 0.0, 0.0)
    img.AllocateScalars(vtk.VTK_FLOAT, 1)
    scalars = img.GetPointData().GetScalars()
    for i, (x, y, z) in enumerate(VERTS):
        pid = img.ComputePointId([x, y, z])
        scalars.SetValue(pid, 1.0 if (config >> i) & 1 else 0.0)

    mc = vtk.vtkMarchingCubes()
    mc.SetInputData(img)
    mc.SetValue(0, 0.5)
    mc.ComputeNormalsOff()
    mc.ComputeGradientsOff()
    mc.ComputeScalarsOff()
    mc.Update()
    out = mc.GetOutput()

    pt_edge = [edge_of_point(out.GetPoint(i))
               for i in range(out.GetNumberOfPoints())]

    tris = []
    polys = out.GetPolys()
    polys.InitTraversal()
    ids = vtk.vtkIdList()
    while polys.GetNextCell(ids):
        if ids.GetNumberOfIds() != 3:
            raise RuntimeError("non-triangle cell in config %d" % config)
        tris.append([pt_edge[ids.GetId(k)] for k in range(3)])
    if out.GetNumberOfCells() != len(tris):
        raise RuntimeError("unexpected non-poly cells in config %d" % config)

    # Union-find over triangles; triangles sharing a point (i.e. an edge
    # midpoint -- points are merged by the locator, and matching by edge id
    # is equivalent) are in the same piece.
    parent = list(range(len(tris)))

    def find(a):
        while parent[a] != a:
            parent[a] = parent[parent[a]]
            a = parent[a]
        return a

    owner = {}
    for t, tri in enumerate(tris):
        for e in tri:
            if e in owner:
                ra, rb = find(owner[e]), find(t)
                if ra != rb:
                    parent[ra] = rb
            else:
                owner[e] = t
    groups = {}
    for t, tri in enumerate(tris):
        groups.setdefault(find(t), set()).update(tri)
    pieces = sorted(sorted(g) for g in groups.values())
    return pieces, len(tris), tris


def format_line(config, pieces, ntri):
    body = " ".join(",".join(str(e) for e in p) for p in pieces)
    line = "%d:" % config
    if body:
        line += " " + body
    return line + " | %d" % ntri


def main():
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    out_path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        repo, "tests", "data", "vtk_mc_pieces.txt")

    full = [run_config(c) for c in range(256)]
    results = [(p, n) for p, n, _ in full]

    # Sanity checks.
    assert results[0] == ([], 0), results[0]
    assert results[255] == ([], 0), results[255]
    assert results[1][0] == [[0, 3, 8]], results[1]
    for c, (pieces, ntri) in enumerate(results):
        used = set(e for p in pieces for e in p)
        crossing = set(e for e, (a, b) in enumerate(EDGES)
                       if ((c >> a) & 1) != ((c >> b) & 1))
        assert used == crossing, (c, used, crossing)
        for i, p in enumerate(pieces):
            for q in pieces[i + 1:]:
                assert not set(p) & set(q), (c, pieces)

    # Face-level check over every ambiguous face of every configuration:
    # the face segments (triangle sides lying in the face) either cut off the
    # two ABOVE corners individually or the two BELOW corners.
    apart = {"above": 0, "below": 0}
    for c, (_, _, tris) in enumerate(full):
        for face, (fv, fe) in enumerate(FACES):
            bits = [(c >> v) & 1 for v in fv]
            if bits not in ([1, 0, 1, 0], [0, 1, 0, 1]):
                continue
            segs = set()
            for tri in tris:
                for k in range(3):
                    a, b = tri[k], tri[(k + 1) % 3]
                    if a in fe and b in fe:
                        segs.add(frozenset((a, b)))
            # Segment cutting off corner fv[i] joins its two face edges.
            cut = [i for i in range(4)
                   if frozenset((fe[(i - 1) % 4], fe[i])) in segs]
            assert len(cut) == 2 and len(segs) == 2, (c, face, segs)
            kind = "above" if bits[cut[0]] else "below"
            apart[kind] += 1

    version = vtk.vtkVersion.GetVTKVersion()
    header = [
        "# vtk_mc_pieces.txt -- connected pieces of VTK's marching-cubes case table",
        "# Produced by: /usr/bin/python3 scripts/vtk_mc_pieces.py",
        "# VTK version: %s (vtkMarchingCubes, isovalue 0.5 on a 2x2x2 float"
        " vtkImageData, spacing 1, origin 0," % version,
        "#   value 1.0 at vertices whose bit is set, 0.0 elsewhere)",
        "# Configuration index: bit i set iff cube vertex i is ABOVE the isovalue.",
        "# Vertices: 0:(0,0,0) 1:(1,0,0) 2:(1,1,0) 3:(0,1,0)"
        " 4:(0,0,1) 5:(1,0,1) 6:(1,1,1) 7:(0,1,1)",
        "# Edges: 0:(0,1) 1:(1,2) 2:(2,3) 3:(3,0) 4:(4,5) 5:(5,6) 6:(6,7)"
        " 7:(7,4) 8:(0,4) 9:(1,5) 10:(2,6) 11:(3,7)",
        "# Output points are mapped to the cube edge whose midpoint they are;"
        " triangles sharing a point",
        "#   form one piece.",
        "# Line format: CONFIG: PIECE PIECE ... | NTRIANGLES",
        "#   PIECE = the piece's sorted cube edge ids joined by ','; pieces"
        " sorted by smallest edge id;",
        "#   NTRIANGLES = number of triangles VTK emitted for the"
        " configuration. Empty config: 'CONFIG: | 0'.",
        "# Summary: %d triangles in total; pieces per config: %s." % (
            sum(n for _, n in results),
            ", ".join("%d:%d configs" % (k, v) for k, v in sorted(
                collections.Counter(len(p) for p, _ in results).items()))),
        "# Ambiguous faces (diagonal corners equal): on %d of %d the ABOVE"
        " corners are kept apart" % (apart["above"],
                                     apart["above"] + apart["below"]),
        "#   (e.g. config 5 -> two pieces; its complement 250 -> one piece"
        " whose face segments cut off corners 1 and 3).",
    ]
    lines = [format_line(c, p, n) for c, (p, n) in enumerate(results)]
    os.makedirs(os.path.dirname(os.path.abspath(out_path)), exist_ok=True)
    with open(out_path, "w") as f:
        f.write("\n".join(header + lines) + "\n")

    # Summary.
    total_tri = sum(n for _, n in results)
    hist = {}
    for p, _ in results:
        hist[len(p)] = hist.get(len(p), 0) + 1
    print("wrote %s (VTK %s)" % (out_path, version))
    print("total triangles over 256 configs: %d" % total_tri)
    for k in sorted(hist):
        print("configs with %d piece(s): %d" % (k, hist[k]))
    p5, p250 = results[5][0], results[250][0]
    print("config 5 (vertices 0,2 above; diagonal on face z=0): %d piece(s): %s"
          % (len(p5), " ".join(",".join(map(str, p)) for p in p5)))
    print("config 250 (vertices 0,2 below, 1,3 above): %d piece(s): %s"
          % (len(p250), " ".join(",".join(map(str, p)) for p in p250)))

    print("ambiguous faces over all 256 configs: ABOVE corners kept apart on"
          " %d, BELOW corners kept apart on %d" % (apart["above"],
                                                   apart["below"]))
    if apart["below"] == 0:
        print("=> VTK's table consistently keeps the ABOVE corners apart"
              " (joins the BELOW corners) on every ambiguous face")
    elif apart["above"] == 0:
        print("=> VTK's table consistently keeps the BELOW corners apart"
              " (joins the ABOVE corners) on every ambiguous face")
    else:
        print("=> VTK's table is INCONSISTENT on ambiguous faces")


if __name__ == "__main__":
    main()
