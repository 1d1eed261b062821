#!/usr/bin/env python3
"""isotrack's Python module against scikit-image's marching cubes.

Times, as the median of --repeat runs (wall clock, time.perf_counter):
  * isotrack.marching_cubes on one thread and on every core,
  * skimage.measure.marching_cubes (method "lewiner", its default; "lorensen" with --lorensen),
  * isotrack.track of one surface (the skull of the CT, seeded at world x, y, z = 122, 122, 160),
  * numpy's copy of the volume: what a wrapper that copied its input would add (isotrack does not copy),
on the CT sample (scripts/get_ct.sh, iso 400) and a gyroid generated here (iso 0).
Prints a Markdown table. Not a test: figures vary with the machine and its load.

Usage: PYTHONPATH=build/python python3 python/bench_python.py [--repeat 5] [--gyroid 256] [--ct PATH]
"""
import argparse
import os
import pathlib
import statistics
import time

import numpy as np

import isotrack

try:
    from skimage import measure
except ImportError:  # the table then lacks the scikit-image rows
    measure = None

ROOT = pathlib.Path(__file__).resolve().parents[1]


def gyroid(n):
    """isotrack's gyroid field (4 periods across the volume), float32, indexed (z, y, x)."""
    a = 2 * np.pi * 4 * np.arange(n) / (n - 1) + 0.1
    s, c = np.sin(a), np.cos(a)
    z, y, x = s[:, None, None], s[None, :, None], s[None, None, :]
    cz, cy, cx = c[:, None, None], c[None, :, None], c[None, None, :]
    return (x * cy + y * cz + z * cx).astype(np.float32)


def timed(run, repeat):
    """(median seconds, last result) over `repeat` runs."""
    seconds, result = [], None
    for _ in range(repeat):
        result = None  # the previous run's mesh is freed first
        start = time.perf_counter()
        result = run()
        seconds.append(time.perf_counter() - start)
    return statistics.median(seconds), result


def triangles(result):
    if isinstance(result, isotrack.Surface):
        return result.triangle_count
    if isinstance(result, tuple):
        return len(result[1])
    return None


def bench_volume(name, volume, level, spacing, seed, args):
    threads = os.cpu_count() or 1
    cases = [
        ("isotrack.marching_cubes, 1 thread", lambda: isotrack.marching_cubes(volume, level, spacing=spacing, threads=1)),
        (f"isotrack.marching_cubes, {threads} threads", lambda: isotrack.marching_cubes(volume, level, spacing=spacing)),
    ]
    if measure is not None:
        cases.append(("skimage marching_cubes (lewiner)", lambda: measure.marching_cubes(volume, level, spacing=spacing)))
        if args.lorensen:
            cases.append(("skimage marching_cubes (lorensen)",
                          lambda: measure.marching_cubes(volume, level, spacing=spacing, method="lorensen")))
    if seed is not None:
        cases.append(("isotrack.track, 1 thread", lambda: isotrack.track(volume, level, seed=seed, spacing=spacing, threads=1)))
        cases.append((f"isotrack.track, {threads} threads", lambda: isotrack.track(volume, level, seed=seed, spacing=spacing)))
    cases.append(("numpy copy of the volume (not done)", lambda: volume.copy()))
    rows = []
    for label, run in cases:
        seconds, result = timed(run, args.repeat)
        rows.append((name, label, triangles(result), seconds))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeat", type=int, default=5, help="runs per case; the median is shown")
    parser.add_argument("--gyroid", type=int, default=256, help="gyroid size N (N^3 samples)")
    parser.add_argument("--ct", default=str(ROOT / "assets" / "ct" / "cranium.nrrd"), help="CT volume")
    parser.add_argument("--lorensen", action="store_true", help="also time scikit-image's lorensen method")
    args = parser.parse_args()

    rows = []
    if pathlib.Path(args.ct).exists():
        loaded = isotrack.load(args.ct)
        ct, spacing = loaded.samples, loaded.spacing[::-1]  # a raw array, spacing in (z, y, x)
        # The skull: world (x, y, z) = (122, 122, 160), given in (z, y, x).
        rows += bench_volume(f"CT {'x'.join(map(str, ct.shape[::-1]))} {ct.dtype}, iso 400", ct, 400.0, spacing,
                             (160.0, 122.0, 122.0), args)
    else:
        print(f"(no CT at {args.ct}: run scripts/get_ct.sh)")
    n = args.gyroid
    rows += bench_volume(f"gyroid {n}^3 float32, iso 0", gyroid(n), 0.0, (1.0, 1.0, 1.0), None, args)

    print(f"| volume | extraction | triangles | ms (median of {args.repeat}) |")
    print("|---|---|---:|---:|")
    for name, label, count, seconds in rows:
        print(f"| {name} | {label} | {'' if count is None else f'{count:,}'} | {seconds * 1e3:.1f} |")


if __name__ == "__main__":
    main()
