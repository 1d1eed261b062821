#!/usr/bin/python3
"""How low the mean dihedral angle of the CT skull goes when the data
themselves are smoothed, for docs/meshes.md (the goal of halving it with
`--smooth 20` while the enclosed volume stays within 1%).

Usage: /usr/bin/python3 bench/smoothing_floor.py [--isotrack build/app/isotrack]
       [--volume assets/ct/cranium.nhdr] [--sigma 0 0.5 0.75 1]

For each sigma (in units of the in-plane spacing, the same length in mm on
every axis), the volume is blurred with scipy's Gaussian filter and written as
float NRRD; the skull (iso 400, tracked from 122,122,160, capped, one thread) is
extracted from it with the consistent and snap tables, unsmoothed and with
`--smooth 20`. Prints, per mesh: triangles, the enclosed volume and the mean
dihedral angle (radians, per edge of two non-degenerate triangles, the measure
of tests/cli/mesh_processing.sh), each against the unsmoothed skull of the
same table from the data as they are (sigma 0).

A blurred volume has no slice terraces and rounder thin bone: its skull is
what a smoothing that knew the data could reach at this mesh resolution.
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np
from scipy.ndimage import gaussian_filter

from mesh_measures import enclosed_volume, read_ply
from smoothing_analysis import dihedral, edges_of_two

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_nhdr(path):
    """The CT's detached header: sizes, spacings, and its raw int16 samples."""
    head = dict(
        line.split(": ", 1) for line in open(path).read().splitlines() if ": " in line and not line.startswith("#")
    )
    if head["type"] != "short" or head["encoding"] != "raw" or head.get("endian", "little") != "little":
        sys.exit(f"{path}: expected raw little-endian short samples")
    sizes = [int(s) for s in head["sizes"].split()]
    spacings = [float(s) for s in head["spacings"].split()]
    raw = os.path.join(os.path.dirname(path), head["data file"])
    data = np.fromfile(raw, "<i2").reshape(sizes[::-1]).astype(np.float32)
    return data, spacings


def write_nhdr(path, data, spacings):
    data.astype("<f4").tofile(path + ".raw")
    with open(path, "w") as out:
        out.write(
            "NRRD0004\ntype: float\ndimension: 3\n"
            f"sizes: {' '.join(str(n) for n in data.shape[::-1])}\n"
            f"spacings: {' '.join(repr(s) for s in spacings)}\n"
            "kinds: domain domain domain\nencoding: raw\nendian: little\n"
            f"data file: {os.path.basename(path)}.raw\n"
        )


def measures(ply):
    v, f = read_ply(ply)
    _, a, b, _ = edges_of_two(f)
    return len(f), enclosed_volume(v, f), float(np.nanmean(dihedral(v, f, a, b)))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--isotrack", default=os.path.join(REPO, "build/app/isotrack"))
    parser.add_argument("--volume", default=os.path.join(REPO, "assets/ct/cranium.nhdr"))
    parser.add_argument("--sigma", type=float, nargs="+", default=[0, 0.5, 0.75, 1])
    args = parser.parse_args()
    data, spacings = read_nhdr(args.volume)
    print(f"{args.volume}: skull at iso 400, seed 122,122,160, --cap, one thread")
    print("| table | data blurred, sigma | --smooth | triangles | enclosed volume | mean dihedral (rad) |")
    print("|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        reference = {}
        for sigma in args.sigma:
            # sigma in in-plane voxels, as a length: the same in mm along every axis
            blurred = gaussian_filter(data, [sigma * spacings[0] / s for s in spacings[::-1]]) if sigma else data
            nhdr = os.path.join(work, f"blurred{sigma:g}.nhdr")
            write_nhdr(nhdr, blurred, spacings)
            for table in ("consistent", "snap"):
                for smooth in (0, 20):
                    ply = os.path.join(work, f"{table}{sigma:g}_{smooth}.ply")
                    subprocess.run(
                        [args.isotrack, "extract", "--volume", nhdr, "--iso", "400", "--method", "track",
                         "--seed", "122,122,160", "--table", table, "--cap", "--threads", "1", "--smooth",
                         str(smooth), "--out", ply],
                        check=True, stdout=subprocess.DEVNULL,
                    )
                    triangles, volume, angle = measures(ply)
                    reference.setdefault(table, (volume, angle))
                    v0, a0 = reference[table]
                    print(f"| {table} | {sigma:g} voxel ({sigma * spacings[0]:.2f} mm) | {smooth or 'no'} | "
                          f"{triangles:,} | {100 * (volume / v0 - 1):+.2f}% | {angle:.4f} ({100 * (angle / a0 - 1):+.1f}%) |")


if __name__ == "__main__":
    main()
