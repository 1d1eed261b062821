#!/usr/bin/python3
"""Where the mean dihedral angle of a smoothed CT surface stays, and what two
other smoothings reach, for docs/meshes.md (the goal of halving it).

Usage: /usr/bin/python3 bench/smoothing_analysis.py VOLUME.nrrd UNSMOOTHED.ply SMOOTHED.ply
(VOLUME: an axis-aligned NRRD at the origin, for its sizes and spacings)

UNSMOOTHED.ply and SMOOTHED.ply are `isotrack extract --cap [--smooth 20] --threads 1
--out` of the same surface (the same vertex order). Prints:
1. the mean dihedral angle (radians, per edge of two non-degenerate triangles:
   the measure tests/cli/mesh_processing.sh uses), its length-weighted mean and
   median, before and after;
2. its split by edge: on the cap (outside the sample grid), near the volume's
   border, touching a sliver (smallest angle < 10 degrees before), and by the
   distance to the nearest vertex of an opposite-facing sheet (normals more than
   120 degrees apart: the other side of thin bone or of a small tunnel);
3. what other smoothings reach, computed here with numpy: the same windowed
   sinc (checked against SMOOTHED.ply), one normalized at 0 (a cut-off at the
   pass band, stronger), each with the enclosed volume restored by a uniform
   offset along the vertex normals (Desbrun et al. 1999), and each with every
   vertex bounded to a tolerance of where it was (0.5 and 1 voxel). Hausdorff
   distances here are between dense samples (vertices, edge midpoints, centres):
   an upper bound within about half an edge.
"""
import sys

import numpy as np
import scipy.sparse as sparse
from scipy.spatial import cKDTree

from mesh_measures import enclosed_volume as volume, read_ply, sampled_hausdorff as hausdorff


def read_nrrd_grid(path):
    head = open(path, "rb").read(4096).split(b"\n\n")[0].decode()

    def field(name):
        return np.array([float(s) for s in next(x for x in head.splitlines() if x.startswith(name)).split()[1:]])

    return field("sizes:"), field("spacings:")


def face_normals(v, f):
    n = np.cross(v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 0]])
    length = np.linalg.norm(n, axis=1)
    ok = length > 0
    n[ok] /= length[ok, None]
    return n, ok, length


def vertex_normals(v, f):
    n, _, length = face_normals(v, f)
    out = np.zeros_like(v)
    for i in range(3):
        np.add.at(out, f[:, i], n * length[:, None])
    return out / np.maximum(np.linalg.norm(out, axis=1), 1e-30)[:, None]


def edges_of_two(f):
    e = np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1)
    faces = np.tile(np.arange(len(f)), 3)
    order = np.lexsort((e[:, 1], e[:, 0]))
    e, faces = e[order], faces[order]
    starts = np.r_[0, np.nonzero(~(e[1:] == e[:-1]).all(axis=1))[0] + 1]
    counts = np.diff(np.r_[starts, len(e)])
    two = starts[counts == 2]
    return e[two], faces[two], faces[two + 1], e[starts[counts != 2]]


def dihedral(v, f, a, b):
    n, ok, _ = face_normals(v, f)
    d = np.arccos(np.clip((n[a] * n[b]).sum(axis=1), -1, 1))
    return np.where(ok[a] & ok[b], d, np.nan)


def umbrella(n, f, fixed_edges):
    """W (mean of the neighbours) over free vertices; vertices of border or non-manifold edges are fixed."""
    e = np.unique(np.sort(np.concatenate([f[:, [0, 1]], f[:, [1, 2]], f[:, [2, 0]]]), axis=1), axis=0)
    free = np.ones(n, bool)
    free[fixed_edges.ravel()] = False
    adjacency = sparse.coo_matrix((np.ones(2 * len(e)), (np.r_[e[:, 0], e[:, 1]], np.r_[e[:, 1], e[:, 0]])), (n, n))
    adjacency = sparse.diags(free.astype(float)) @ adjacency.tocsr()
    degree = np.asarray(adjacency.sum(axis=1)).ravel()
    return sparse.diags(np.where(degree > 0, 1 / np.maximum(degree, 1), 0)) @ adjacency, degree > 0


def windowed_sinc(v, W, movable, iterations=20, passband=0.1, at_passband=True):
    """core/src/mesh/smooth.cpp's filter; at_passband False: normalized at 0 instead (a sharper cut)."""
    i = np.arange(iterations + 1)
    window = (0.355768 + 0.487396 * np.cos(i * np.pi / (iterations + 1)) + 0.144232 * np.cos(2 * i * np.pi / (iterations + 1))
              + 0.012604 * np.cos(3 * i * np.pi / (iterations + 1)))
    theta_pass = np.arccos(1 - 0.5 * passband)

    def coefficients(theta):
        c = window * 2 * np.sin(i * theta) / np.maximum(i, 1) / np.pi
        c[0] = window[0] * theta / np.pi
        return c

    theta = theta_pass
    if at_passband:
        for _ in range(100):
            c = coefficients(theta)
            value = (c * np.cos(i * theta_pass)).sum()
            slope = window[0] / np.pi + (window[1:] * 2 * np.cos(i[1:] * theta) / np.pi * np.cos(i[1:] * theta_pass)).sum()
            if abs(value - 1) < 1e-12:
                break
            theta = np.clip(theta - (value - 1) / slope, 0, np.pi)
        c = coefficients(theta)
    else:
        c = coefficients(theta)
        c /= c.sum()
    lo, hi = v.min(axis=0), v.max(axis=0)
    centre, size = 0.5 * (lo + hi), np.linalg.norm(hi - lo)
    x0 = (v - centre) / size

    def K(x):
        return np.where(movable[:, None], x - W @ x, 0.0)

    x1 = x0 - 0.5 * K(x0)
    total = c[0] * x0 + c[1] * x1
    for k in range(2, iterations + 1):
        x0, x1 = x1, 2 * x1 - K(x1) - x0
        total += c[k] * x1
    return np.where(movable[:, None], total * size + centre, v)


def restore_volume(w, f, target, movable):
    for _ in range(5):
        _, _, length = face_normals(w, f)
        offset = (target - volume(w, f)) / (0.5 * length.sum())
        w = np.where(movable[:, None], w + offset * vertex_normals(w, f), w)
    return w


def bound(w, v, tolerance):
    move = w - v
    distance = np.linalg.norm(move, axis=1)
    scale = np.where(distance > tolerance, tolerance / np.maximum(distance, 1e-30), 1.0)
    return v + move * scale[:, None]


def main():
    dims, spacing = read_nrrd_grid(sys.argv[1])
    v, f = read_ply(sys.argv[2])
    smoothed, f2 = read_ply(sys.argv[3])
    assert np.array_equal(f, f2), "the two meshes must be the same extraction (--threads 1)"
    e, a, b, other = edges_of_two(f)
    before, after = dihedral(v, f, a, b), dihedral(smoothed, f, a, b)
    for name, d, x in (("unsmoothed", before, v), ("smoothed", after, smoothed)):
        length = np.linalg.norm(x[e[:, 0]] - x[e[:, 1]], axis=1)
        good = np.isfinite(d)
        print(f"{name}: mean dihedral {np.nanmean(d):.4f} rad, length-weighted {(d * length)[good].sum() / length[good].sum():.4f},"
              f" median {np.nanmedian(d):.4f}, 99th percentile {np.nanpercentile(d, 99):.3f}")

    # Edge classes, on the unsmoothed mesh.
    grid = v / spacing  # the PLYs are in the default LPS frame: an axis-aligned volume at the origin
    on_cap = ((grid < 0) | (grid > dims - 1)).any(axis=1)
    near_border = ((grid < 1.5) | (grid > dims - 2.5)).any(axis=1)
    p = [v[f[:, i]] for i in range(3)]
    angles = []
    for i in range(3):
        u, w = p[(i + 1) % 3] - p[i], p[(i + 2) % 3] - p[i]
        cos = (u * w).sum(axis=1) / np.maximum(np.linalg.norm(u, axis=1) * np.linalg.norm(w, axis=1), 1e-30)
        angles.append(np.degrees(np.arccos(np.clip(cos, -1, 1))))
    sliver = np.min(angles, axis=0) < 10
    normals = vertex_normals(smoothed, f)
    distance, index = cKDTree(smoothed).query(smoothed, k=64, distance_upper_bound=4.0)
    opposite = np.full(len(v), np.inf)
    for j in range(1, 64):
        found = np.isfinite(distance[:, j])
        near = np.where(found, index[:, j], 0)
        hit = found & ((normals[near] * normals).sum(axis=1) < -0.5)
        opposite = np.where(hit, np.minimum(opposite, distance[:, j]), opposite)
    edge_opposite = np.minimum(opposite[e[:, 0]], opposite[e[:, 1]])
    cap = on_cap[e].any(axis=1)
    border = ~cap & near_border[e].any(axis=1)
    rest = ~cap & ~border
    classes = [("on the cap", cap), ("near the border", border), ("touching a sliver", rest & (sliver[a] | sliver[b]))]
    for low, high in ((0, 1), (1, 2), (2, 4), (4, np.inf)):
        name = f"opposite sheet {low}-{high} mm" if np.isfinite(high) else f"no opposite sheet within {low} mm"
        classes.append((name, rest & (edge_opposite >= low) & ((edge_opposite < high) | np.isinf(high))))
    print(f"\n{len(e)} edges of two triangles, {len(other)} others (left out)")
    print("| edges | share of edges | mean before | mean after | change | share of the sum after |")
    print("|---|---|---|---|---|---|")
    for name, mask in classes:
        print(f"| {name} | {mask.mean():.1%} | {np.nanmean(before[mask]):.3f} | {np.nanmean(after[mask]):.3f} |"
              f" {np.nanmean(after[mask]) / np.nanmean(before[mask]) - 1:+.0%} | {np.nansum(after[mask]) / np.nansum(after):.1%} |")

    # Other smoothings.
    W, movable = umbrella(len(v), f, other)
    target, start = volume(v, f), np.nanmean(before)
    voxel = spacing.min()
    print(f"\nvoxel {voxel} mm; other smoothings, 20 iterations, pass band 0.1:")
    print("| smoothing | enclosed volume | mean dihedral | Hausdorff (sampled, mm) |")
    print("|---|---|---|---|")

    def row(name, w):
        print(f"| {name} | {volume(w, f) / target - 1:+.2%} | {np.nanmean(dihedral(w, f, a, b)) / start - 1:+.1%} |"
              f" {hausdorff(v, w, f):.2f} |", flush=True)

    for at_passband, filter_name in ((True, "windowed sinc (isotrack, VTK)"), (False, "normalized at 0 (sharper)")):
        w = windowed_sinc(v, W, movable, at_passband=at_passband)
        if at_passband:
            print(f"(numpy filter bounded to half a voxel against SMOOTHED.ply: largest difference"
                  f" {np.abs(bound(w, v, 0.5 * voxel * (1 - 1e-6)) - smoothed).max():.1e} mm)")
        row(filter_name, w)
        row(f"{filter_name}, volume restored", restore_volume(w, f, target, movable))
        for share in (0.5, 1.0):
            bounded = bound(w, v, share * voxel)
            row(f"{filter_name}, bounded to {share:g} voxel", bounded)
            row(f"{filter_name}, bounded to {share:g} voxel, volume restored", restore_volume(bounded, f, target, movable))


if __name__ == "__main__":
    main()
