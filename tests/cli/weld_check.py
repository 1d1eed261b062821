#!/usr/bin/python3
"""Independent quality figures of a binary little-endian PLY as isotrack writes
it (float x y z nx ny nz, uchar-int faces), with numpy only: vertices welded by
exact position, zero-area triangles, edges of one and of more than two
triangles after welding, fractions of triangles whose smallest angle is below
1, 10 and 20 degrees. Prints one JSON object.
Usage: weld_check.py MESH.ply"""
import json
import sys

import numpy as np


def read_ply(path):
    with open(path, "rb") as f:
        vertices = faces = floats = 0
        while True:
            line = f.readline().decode("ascii").strip()
            if line.startswith("element vertex"):
                vertices = int(line.split()[2])
            elif line.startswith("element face"):
                faces = int(line.split()[2])
            elif line.startswith("property float"):
                floats += 1
            elif line == "end_header":
                break
        v = np.frombuffer(f.read(vertices * 4 * floats), dtype="<f4").reshape(vertices, floats)[:, :3]
        record = np.dtype([("n", "u1"), ("i", "<i4", 3)])
        t = np.frombuffer(f.read(faces * record.itemsize), dtype=record)
        assert (t["n"] == 3).all(), "not a triangle mesh"
        return np.ascontiguousarray(v), t["i"].astype(np.int64)


def main(path):
    v, t = read_ply(path)
    p = v.astype(np.float64)[t]
    doubled = np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
    _, weld = np.unique(v.view("V12").ravel(), return_inverse=True)
    w = weld.ravel()[t]
    kept = w[(w[:, 0] != w[:, 1]) & (w[:, 1] != w[:, 2]) & (w[:, 2] != w[:, 0])]
    edges = np.sort(np.concatenate([kept[:, [0, 1]], kept[:, [1, 2]], kept[:, [2, 0]]]), axis=1)
    _, uses = np.unique(edges, axis=0, return_counts=True)

    def angle(a, b, c):
        u, x = b - a, c - a
        cos = (u * x).sum(1) / np.maximum(np.linalg.norm(u, axis=1) * np.linalg.norm(x, axis=1), 1e-300)
        return np.degrees(np.arccos(np.clip(cos, -1.0, 1.0)))

    smallest = np.minimum(np.minimum(angle(p[:, 0], p[:, 1], p[:, 2]), angle(p[:, 1], p[:, 2], p[:, 0])),
                          angle(p[:, 2], p[:, 0], p[:, 1]))
    smallest[doubled == 0] = 0.0
    print(json.dumps({"triangles": int(len(t)), "zero_area": int((doubled == 0).sum()),
                      "boundary_edges": int((uses == 1).sum()), "non_manifold_edges": int((uses > 2).sum()),
                      "below_1": float((smallest < 1).mean()), "below_10": float((smallest < 10).mean()),
                      "below_20": float((smallest < 20).mean())}))


if __name__ == "__main__":
    main(sys.argv[1])
