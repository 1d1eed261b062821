"""Figures of a triangle mesh for the bench scripts, with numpy and scipy only:
reading a binary PLY as isotrack writes it (float x y z nx ny nz, uchar-int
faces), the enclosed volume, and a sampled symmetric Hausdorff distance."""
import numpy as np
from scipy.spatial import cKDTree


def read_ply(path):
    data = open(path, "rb").read()
    start = data.index(b"end_header\n") + len(b"end_header\n")
    head = data[:start].decode()
    nv = int(head.split("element vertex ")[1].split()[0])
    nf = int(head.split("element face ")[1].split()[0])
    v = np.frombuffer(data, "<f4", nv * 6, start).reshape(nv, 6)[:, :3].astype(np.float64)
    f = np.frombuffer(data, np.dtype([("n", "u1"), ("i", "<i4", 3)]), nf, start + nv * 24)["i"].astype(np.int64)
    return v, f


def enclosed_volume(v, f):
    return abs(np.einsum("ij,ij->i", v[f[:, 0]], np.cross(v[f[:, 1]], v[f[:, 2]])).sum() / 6)


def sampled_hausdorff(v, w, f):
    """Between two placements v and w of the same faces f: the vertices, the
    triangles' centres and their edges' midpoints of each, against the other's."""
    def samples(x):
        p = [x[f[:, i]] for i in range(3)]
        return np.vstack([x, (p[0] + p[1] + p[2]) / 3, (p[0] + p[1]) / 2, (p[1] + p[2]) / 2, (p[2] + p[0]) / 2])

    s, t = samples(v), samples(w)
    return max(cKDTree(t).query(s)[0].max(), cKDTree(s).query(t)[0].max())
