#!/usr/bin/python3
"""The plots and tables of docs/performance.md, measured afresh in one run.

  (a) time to track one surface against the surface's size: surfaces of the CT
      sample, of the blobs field and of the gyroid, and spheres of several sizes
      (`isotrack bench --methods track`, one thread), with the exhaustive pass on
      the same volumes for reference;
  (b) time of the exhaustive pass (`mc`) against the volume's size: the sphere and
      gyroid fields at N = 64 .. 320, on one and two threads, and one read of every
      sample (`stream`) as the floor;
  (c) isotrack's exhaustive pass against VTK's vtkFlyingEdges3D (one and two
      threads, as in bench/compare_vtk.py) and scikit-image's
      measure.marching_cubes (one thread) on the same volumes.

Times are extraction only (loading excluded). Each figure is the fastest of its
runs: --repeat runs within a process, and for (c) over --rounds rounds that run
isotrack, VTK and scikit-image in turn. On a machine shared with other work the
fastest run is the least disturbed one, the closest to what the work itself
costs; the medians are kept in the JSON file too.

Writes docs/img/track_vs_surface.png, mc_vs_volume.png and vs_vtk_skimage.png,
prints the tables as markdown, and keeps the raw figures in
build/bench-data/make_plots.json.

Usage: /usr/bin/python3 bench/make_plots.py [--quick] [--replot] [--repeat 5] [--rounds 3]
Needs Debian's python3-vtk9, python3-matplotlib, python3-skimage and python3-numpy
(run it with /usr/bin/python3) and, for the CT, assets/ct/cranium.nrrd from
scripts/get_ct.sh.
"""
import argparse
import json
import os
import statistics
import struct
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import skimage  # noqa: E402
from skimage import measure  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import compare_vtk  # noqa: E402
from compare_vtk import vtk  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(REPO, "build", "bench-data")
IMG = os.path.join(REPO, "docs", "img")
CT = os.path.join(REPO, "assets", "ct", "cranium.nrrd")


def run_json(cmd):
    return json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)


def bench(binary, source, iso, methods, threads, repeat, seed=None):
    """`isotrack bench --json`: {(method, threads): run report, with "fastest" added}."""
    cmd = [binary, "bench", *source, "--methods", ",".join(methods), "--threads", ",".join(map(str, threads)),
           "--repeat", str(repeat), "--json"]
    if iso is not None:
        cmd += ["--iso", repr(iso)]
    if seed is not None:
        cmd += ["--seed", ",".join(repr(float(v)) for v in seed)]
    runs = run_json(cmd)["runs"]
    for r in runs:
        r["fastest"] = min(r["seconds_all"])
    return {(r["method"], r["threads"]): r for r in runs}


def read_nrrd_numpy(path):
    """The samples of an attached-header raw NRRD (what `isotrack field` and get_ct.sh write), z-y-x."""
    types = {"float": "<f4", "double": "<f8", "short": "<i2", "ushort": "<u2", "uchar": "u1", "int": "<i4"}
    with open(path, "rb") as f:
        blob = f.read()
    end = blob.index(b"\n\n") + 2
    header = dict(line.split(": ", 1) for line in blob[:end].decode().splitlines()[1:] if ": " in line)
    if header.get("encoding") != "raw" or header.get("endian", "little") != "little":
        raise ValueError(f"{path}: only raw little-endian NRRD is read here")
    nx, ny, nz = (int(v) for v in header["sizes"].split())
    return np.frombuffer(blob, dtype=types[header["type"]], offset=end).reshape(nz, ny, nx)


def surface_seeds(binary, path, iso, directory, count):
    """A point on each of about `count` surfaces of the volume, spread over their sizes (log-spaced
    ranks): the first vertex of each surface, from `isotrack extract --method all --out-dir`."""
    os.makedirs(directory, exist_ok=True)
    report = run_json([binary, "extract", "--volume", path, "--iso", repr(iso), "--method", "all", "--threads", "2",
                       "--out-dir", directory, "--out-format", "ply", "--json"])
    surfaces = report["surfaces"]
    n = len(surfaces)
    ranks = sorted({min(n - 1, int(round(x))) for x in np.geomspace(1, n, num=min(count, n)) - 1})
    seeds = []
    for rank in ranks:
        with open(os.path.join(directory, f"surface_{rank:03d}.ply"), "rb") as f:
            head = f.read(4096)
            start = head.index(b"end_header\n") + len(b"end_header\n")
            x, y, z = struct.unpack_from("<3f", head, start)
        seeds.append((rank, [x, y, z]))
    return seeds


def ensure_field(binary, spec):
    return compare_vtk.ensure_field(binary, spec, DATA)


# ---- (a) tracking against surface size -----------------------------------------------------------

def track_against_size(args):
    cases = []
    if os.path.exists(CT):
        cases.append(("CT, iso 400.5", CT, 400.5, 24 if not args.quick else 10))
    blobs = "blobs:128" if args.quick else "blobs:256"
    cases.append((f"blobs {blobs.split(':')[1]}³", ensure_field(args.isotrack, blobs), 0.25, 12 if not args.quick else 6))
    gyroid = "gyroid:128" if args.quick else "gyroid:192"
    cases.append((f"gyroid {gyroid.split(':')[1]}³", ensure_field(args.isotrack, gyroid), 0.0, 6 if not args.quick else 4))
    results = {}
    for name, path, iso, count in cases:
        seeds = surface_seeds(args.isotrack, path, iso, os.path.join(DATA, "surfaces", os.path.basename(path)), count)
        points = []
        for rank, seed in seeds:
            run = bench(args.isotrack, ["--volume", path], iso, ["track"], [1], args.repeat, seed)[("track", 1)]
            points.append({"rank": rank, "triangles": run["triangles"], "seconds": run["fastest"],
                           "median": run["seconds"]})
        mc = bench(args.isotrack, ["--volume", path], iso, ["mc"], [1], args.repeat)[("mc", 1)]
        results[name] = {"points": points, "mc_seconds": mc["fastest"], "mc_triangles": mc["triangles"]}
        print(f"  (a) {name}: {len(points)} surfaces tracked", file=sys.stderr)
    # One closed surface that grows with the volume: the sphere at several sizes.
    points = []
    for n in ([32, 64, 128] if args.quick else [32, 64, 128, 192, 256]):
        c = (n - 1) / 2
        seed = [c + 0.375 * (n - 1), c, c]
        run = bench(args.isotrack, ["--field", f"sphere:{n}"], None, ["track"], [1], args.repeat, seed)[("track", 1)]
        points.append({"n": n, "triangles": run["triangles"], "seconds": run["fastest"], "median": run["seconds"]})
    results["sphere N³"] = {"points": points}
    print("  (a) spheres tracked", file=sys.stderr)
    return results


def plot_track(results, path):
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=100)
    markers = iter("osD^v")
    for name, r in results.items():
        tri = [p["triangles"] for p in r["points"]]
        ms = [p["seconds"] * 1e3 for p in r["points"]]
        line = ax.loglog(tri, ms, marker=next(markers), linestyle="-" if name.startswith("sphere") else "none",
                         label=f"track, {name}", alpha=0.85)[0]
        if "mc_seconds" in r:
            ax.axhline(r["mc_seconds"] * 1e3, color=line.get_color(), linestyle=":", linewidth=1,
                       label=f"mc on the whole volume, {name}")
    all_tri = np.array([p["triangles"] for r in results.values() for p in r["points"]], dtype=float)
    all_ms = np.array([p["seconds"] * 1e3 for r in results.values() for p in r["points"]])
    per = np.median(all_ms / all_tri)
    xs = np.geomspace(all_tri.min(), all_tri.max(), 20)
    ax.loglog(xs, xs * per, color="grey", linewidth=0.8, linestyle="--",
              label=f"{per * 1e6:.0f} ns per triangle (the points' median)")
    ax.set_xlabel("triangles in the tracked surface")
    ax.set_ylabel("ms, one thread (fastest run)")
    ax.set_title("Tracking one surface: time follows the surface, not the volume")
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def track_table(results):
    lines = ["| volume | surface | triangles | track ms | ns / triangle | mc ms (whole volume) |",
             "|---|---|---|---|---|---|"]
    for name, r in results.items():
        pts = sorted(r["points"], key=lambda p: p["triangles"])
        if len(pts) > 2:
            picks, labels = [pts[0], pts[len(pts) // 2], pts[-1]], ["smallest", "middle", "largest"]
        else:
            picks, labels = pts, ["smallest", "largest"][-len(pts):]
        for label, p in zip(labels, picks):
            what = f"N = {p['n']}" if "n" in p else f"{label} of {len(pts)} tracked"
            mc = f"{r['mc_seconds'] * 1e3:.2f}" if "mc_seconds" in r else ""
            lines.append(f"| {name} | {what} | {p['triangles']:,} | {p['seconds'] * 1e3:.3f} |"
                         f" {p['seconds'] * 1e9 / p['triangles']:.0f} | {mc} |")
    return "\n".join(lines)


# ---- (b) the exhaustive pass against volume size -------------------------------------------------

def mc_against_size(args):
    sizes = [64, 128, 192] if args.quick else [64, 96, 128, 160, 192, 224, 256, 288, 320]
    results = {}
    for field in ("sphere", "gyroid"):
        rows = []
        for n in sizes:
            runs = bench(args.isotrack, ["--field", f"{field}:{n}"], None, ["mc", "stream"], [1, 2], args.repeat)
            rows.append({"n": n, "triangles": runs[("mc", 1)]["triangles"],
                         **{f"{m}_{t}": runs[(m, t)]["fastest"] for m in ("mc", "stream") for t in (1, 2)},
                         **{f"{m}_{t}_median": runs[(m, t)]["seconds"] for m in ("mc", "stream") for t in (1, 2)}})
        results[field] = rows
        print(f"  (b) {field}: N = {sizes[0]} .. {sizes[-1]}", file=sys.stderr)
    return results


def plot_mc(results, path):
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=100)
    styles = {"sphere": "o", "gyroid": "s"}
    for field, rows in results.items():
        mvox = [r["n"] ** 3 / 1e6 for r in rows]
        for threads, ls in ((1, "-"), (2, "--")):
            ax.plot(mvox, [r[f"mc_{threads}"] * 1e3 for r in rows], marker=styles[field], linestyle=ls,
                    label=f"mc, {field}, {threads} thread{'s' if threads > 1 else ''}")
    rows = results["sphere"]
    ax.plot([r["n"] ** 3 / 1e6 for r in rows], [r["stream_1"] * 1e3 for r in rows], color="grey", linestyle=":",
            marker=".", label="one read of every sample, 1 thread")
    ax.set_xlabel("million voxels (N³, N = %d .. %d)" % (rows[0]["n"], rows[-1]["n"]))
    ax.set_ylabel("ms (fastest run)")
    ax.set_title("The exhaustive pass: time against volume size")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def mc_table(results):
    lines = ["| N | sphere triangles | sphere mc ms, 1T / 2T | gyroid triangles | gyroid mc ms, 1T / 2T |"
             " one read ms, 1T | gyroid Mvoxels/s, 1T |",
             "|---|---|---|---|---|---|---|"]
    for s, g in zip(results["sphere"], results["gyroid"]):
        lines.append(f"| {s['n']} | {s['triangles']:,} | {s['mc_1'] * 1e3:.1f} / {s['mc_2'] * 1e3:.1f} |"
                     f" {g['triangles']:,} | {g['mc_1'] * 1e3:.1f} / {g['mc_2'] * 1e3:.1f} |"
                     f" {s['stream_1'] * 1e3:.2f} | {g['n'] ** 3 / g['mc_1'] / 1e6:.0f} |")
    return "\n".join(lines)


# ---- (c) against VTK and scikit-image ------------------------------------------------------------

def timed(run, repeat):
    """Every run's seconds, and the last run's result."""
    times, result = [], None
    for _ in range(repeat):
        start = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - start)
    return times, result


def flying_edges_seconds(image, iso, threads, repeat):
    vtk.vtkSMPTools.SetBackend("TBB")
    vtk.vtkSMPTools.Initialize(threads)
    fe = vtk.vtkFlyingEdges3D()
    fe.SetInputData(image)
    fe.SetValue(0, iso)
    fe.ComputeNormalsOn()

    def run():
        fe.Modified()
        fe.Update()
        return fe.GetOutput().GetNumberOfCells()

    return timed(run, repeat)


def skimage_seconds(volume, iso, spacing, repeat):
    def run():
        _, faces, _, _ = measure.marching_cubes(volume, level=iso, spacing=spacing)
        return len(faces)

    return timed(run, repeat)


def against_others(args):
    cases = []
    if os.path.exists(CT):
        cases.append(("CT, iso 400.5", CT, 400.5, (1.5, 0.957, 0.957)))
    n = 128 if args.quick else 256
    for field, iso in (("sphere", 0.0), ("blobs", 0.25), ("gyroid", 0.0)):
        cases.append((f"{field} {n}³", ensure_field(args.isotrack, f"{field}:{n}"), iso, (1.0, 1.0, 1.0)))
    results = {}
    for name, path, iso, spacing in cases:
        image = compare_vtk.read_nrrd(path)
        volume = read_nrrd_numpy(path).astype(np.float32)  # the type marching_cubes works in; converted untimed
        rounds = {"mc_1": [], "mc_2": [], "fe_1": [], "fe_2": [], "skimage": []}
        counts = {}
        for round_ in range(args.rounds):
            order = ["isotrack", "vtk", "skimage"]
            for who in order[round_ % 3:] + order[:round_ % 3]:
                if who == "isotrack":
                    runs = bench(args.isotrack, ["--volume", path], iso, ["mc"], [1, 2], args.repeat)
                    rounds["mc_1"] += runs[("mc", 1)]["seconds_all"]
                    rounds["mc_2"] += runs[("mc", 2)]["seconds_all"]
                    counts["isotrack"] = runs[("mc", 1)]["triangles"]
                elif who == "vtk":
                    for threads in (1, 2):
                        seconds, counts["vtk"] = flying_edges_seconds(image, iso, threads, args.repeat)
                        rounds[f"fe_{threads}"] += seconds
                else:
                    seconds, counts["skimage"] = skimage_seconds(volume, iso, spacing, args.skimage_repeat)
                    rounds["skimage"] += seconds
        fastest = {key: min(values) for key, values in rounds.items()}
        med = {key: statistics.median(values) for key, values in rounds.items()}
        results[name] = {"seconds": fastest, "median_seconds": med, "runs": rounds, "triangles": counts}
        print(f"  (c) {name}: done", file=sys.stderr)
    return results


def plot_others(results, path):
    names = list(results)
    bars = [("isotrack mc, 1 thread", "mc_1"), ("isotrack mc, 2 threads", "mc_2"),
            ("VTK Flying Edges, 1 thread", "fe_1"), ("VTK Flying Edges, 2 threads", "fe_2"),
            ("scikit-image marching_cubes", "skimage")]
    fig, ax = plt.subplots(figsize=(7.5, 5.2), dpi=100)
    width = 0.16
    x = np.arange(len(names))
    for i, (label, key) in enumerate(bars):
        ax.bar(x + (i - 2) * width, [results[n]["seconds"][key] * 1e3 for n in names], width, label=label)
    ax.set_yscale("log")
    ax.set_xticks(x)
    ax.set_xticklabels(names)
    ax.set_ylabel("ms, fastest run (log scale)")
    ax.set_title("One exhaustive extraction, same volume and isovalue")
    ax.grid(True, axis="y", which="major", alpha=0.3)
    ax.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.08), ncol=3, frameon=False)
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def others_table(results):
    lines = ["| volume | triangles (isotrack / VTK / scikit-image) | isotrack mc ms, 1T / 2T |"
             " VTK Flying Edges ms, 1T / 2T | scikit-image ms, 1T | Flying Edges ÷ mc, 1T | scikit-image ÷ mc, 1T |",
             "|---|---|---|---|---|---|---|"]
    for name, r in results.items():
        s, c = r["seconds"], r["triangles"]
        lines.append(f"| {name} | {c['isotrack']:,} / {c['vtk']:,} / {c['skimage']:,} |"
                     f" {s['mc_1'] * 1e3:.1f} / {s['mc_2'] * 1e3:.1f} | {s['fe_1'] * 1e3:.1f} / {s['fe_2'] * 1e3:.1f} |"
                     f" {s['skimage'] * 1e3:.0f} | {s['fe_1'] / s['mc_1']:.2f} | {s['skimage'] / s['mc_1']:.1f} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--isotrack", default=os.path.join(REPO, "build", "app", "isotrack"))
    parser.add_argument("--repeat", type=int, default=5, help="runs per figure within a process")
    parser.add_argument("--rounds", type=int, default=3, help="rounds of isotrack, VTK and scikit-image in turn, for (c)")
    parser.add_argument("--skimage-repeat", type=int, default=2, help="scikit-image runs per round")
    parser.add_argument("--quick", action="store_true", help="smaller volumes and fewer surfaces, for a smoke run")
    parser.add_argument("--replot", action="store_true",
                        help="measure nothing: plots and tables from the last run's build/bench-data/make_plots.json")
    args = parser.parse_args()
    if args.quick:
        args.repeat = min(args.repeat, 3)
    os.makedirs(DATA, exist_ok=True)
    os.makedirs(IMG, exist_ok=True)
    if not os.path.exists(CT):
        print("CT skipped: run scripts/get_ct.sh", file=sys.stderr)

    saved = os.path.join(DATA, "make_plots.json")
    if args.replot:
        with open(saved) as f:
            run = json.load(f)
    else:
        load_before = os.getloadavg()[0]
        start = time.perf_counter()
        run = {"track": track_against_size(args), "mc": mc_against_size(args), "others": against_others(args)}
        run["about"] = (f"bench/make_plots.py{' --quick' if args.quick else ''}: VTK {vtk.vtkVersion.GetVTKVersion()},"
                        f" scikit-image {skimage.__version__}, {os.cpu_count()} cores,"
                        f" {time.perf_counter() - start:.0f} s, load average {load_before:.1f} at the start,"
                        f" {os.getloadavg()[0]:.1f} at the end")
        with open(saved, "w") as f:
            json.dump(run, f, indent=1)
    track, mc, others = run["track"], run["mc"], run["others"]
    plot_track(track, os.path.join(IMG, "track_vs_surface.png"))
    plot_mc(mc, os.path.join(IMG, "mc_vs_volume.png"))
    plot_others(others, os.path.join(IMG, "vs_vtk_skimage.png"))
    print(f"<!-- {run.get('about', '')} -->\n")
    print("Tracking one surface (one thread; `docs/img/track_vs_surface.png`):\n")
    print(track_table(track) + "\n")
    print("The exhaustive pass against volume size (`docs/img/mc_vs_volume.png`):\n")
    print(mc_table(mc) + "\n")
    print("Against VTK and scikit-image (`docs/img/vs_vtk_skimage.png`):\n")
    print(others_table(others))


if __name__ == "__main__":
    main()
