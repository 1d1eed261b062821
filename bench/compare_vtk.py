#!/usr/bin/python3
"""isotrack against VTK on the same volumes, in one run.

For each volume: isotrack's exhaustive pass (mc), every surface (all) and one
surface (track), at 1 and 2 threads, against VTK 9's vtkFlyingEdges3D (with
normals) at 1 and 2 threads through vtkSMPTools, followed by
vtkPolyDataConnectivityFilter in all-regions and closest-point modes. Times are
extraction only (reading excluded), medians of --repeat runs.

The runs come in --rounds rounds, each running everything once: VTK at 1 then
2 threads, and one `isotrack bench` process that times mc, all and track at 1
and 2 threads interleaved (every other round isotrack goes first). On a virtual
machine the same work can run 30% faster or slower from one minute to the next,
and from one process to the next by where its memory landed. So each time is
the median of its rounds' medians, and each ratio is the median of its rounds'
ratios: both sides of a round's ratio are measured minutes apart at most, and
isotrack's all / mc and two threads against one come from one process.
Prints a table of times and ratios (VTK time / isotrack time: above 1 means
isotrack is faster).

Usage: /usr/bin/python3 bench/compare_vtk.py [--isotrack build/app/isotrack] [--repeat 5] [--rounds 3] [--quick]
Needs Debian's python3-vtk9 (run it with /usr/bin/python3) and, for the CT rows,
assets/ct/cranium.nrrd from scripts/get_ct.sh.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

import vtk

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_nrrd(path):
    """Reads a NRRD with VTK's serial reader (Debian's factory would hand out the MPI one)."""
    vtk.vtkObjectFactory.SetAllEnableFlags(False, "vtkNrrdReader", "vtkPNrrdReader")
    reader = vtk.vtkNrrdReader()
    reader.SetFileName(path)
    reader.Update()
    image = vtk.vtkImageData()
    image.DeepCopy(reader.GetOutput())
    return image


def median_time(run, repeat):
    times = []
    result = None
    for _ in range(repeat):
        start = time.perf_counter()
        result = run()
        times.append(time.perf_counter() - start)
    return statistics.median(times), result


def vtk_times(image, iso, seed, threads, repeat):
    vtk.vtkSMPTools.SetBackend("TBB")
    vtk.vtkSMPTools.Initialize(threads)
    fe = vtk.vtkFlyingEdges3D()
    fe.SetInputData(image)
    fe.SetValue(0, iso)
    fe.ComputeNormalsOn()

    def flying_edges():
        fe.Modified()
        fe.Update()
        return fe.GetOutput().GetNumberOfCells()

    t_fe, triangles = median_time(flying_edges, repeat)
    surface = vtk.vtkPolyData()
    surface.DeepCopy(fe.GetOutput())

    def connectivity(mode):
        conn = vtk.vtkPolyDataConnectivityFilter()
        conn.SetInputData(surface)
        if mode == "all":
            conn.SetExtractionModeToAllRegions()
            conn.ColorRegionsOn()
        else:
            conn.SetExtractionModeToClosestPointRegion()
            conn.SetClosestPoint(*seed)
        conn.Update()
        return conn.GetNumberOfExtractedRegions() if mode == "all" else conn.GetOutput().GetNumberOfCells()

    t_all, regions = median_time(lambda: connectivity("all"), repeat)
    t_one, one = median_time(lambda: connectivity("closest"), repeat)
    return {"fe": t_fe, "fe_all": t_fe + t_all, "fe_one": t_fe + t_one, "triangles": triangles,
            "regions": regions, "one_triangles": one}


def isotrack_bench(binary, path, iso, seed, repeat):
    """mc, all, track and stream (every sample read once) at 1 and 2 threads, interleaved in
    one `isotrack bench` process: {threads: {method: run report}}."""
    cmd = [binary, "bench", "--volume", path, "--iso", repr(iso), "--methods", "mc,all,track,stream", "--threads", "1,2",
           "--seed", ",".join(repr(v) for v in seed), "--repeat", str(repeat), "--json"]
    report = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    out = {1: {}, 2: {}}
    for run in report["runs"]:
        out[run["threads"]][run["method"]] = run
    return out


def paired_ratio(tops, bottoms):
    """The median of the rounds' ratios, each round's top over the same round's bottom."""
    return statistics.median(t / b for t, b in zip(tops, bottoms))


def smallest_surface_seed(binary, path, iso):
    """A world point on the smallest surface (from `isotrack extract --method all --json`), to track."""
    cmd = [binary, "extract", "--volume", path, "--iso", repr(iso), "--method", "all", "--threads", "2", "--json"]
    report = json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)
    smallest = report["surfaces"][-1]
    lo, hi = smallest["bounds"]
    return [lo[0], (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2]


def ensure_field(binary, spec, directory):
    path = os.path.join(directory, spec.replace(":", "_") + ".nrrd")
    if not os.path.exists(path):
        subprocess.run([binary, "field", spec, "--out", path], check=True, capture_output=True)
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--isotrack", default=os.path.join(REPO, "build", "app", "isotrack"))
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--rounds", type=int, default=3, help="rounds of every run, VTK and isotrack in turn (median of their medians)")
    parser.add_argument("--quick", action="store_true", help="smaller volumes, for a smoke run")
    args = parser.parse_args()
    data = os.path.join(REPO, "build", "bench-data")
    os.makedirs(data, exist_ok=True)

    cases = []
    ct = os.path.join(REPO, "assets", "ct", "cranium.nrrd")
    if os.path.exists(ct):
        # The skull, seeded near the top of the head; at -400 the skin.
        cases.append(("CT iso 400", ct, 400.0, [122.0, 122.0, 160.0]))
        cases.append(("CT iso -400", ct, -400.0, [122.0, 122.0, 160.0]))
    else:
        print("CT skipped: run scripts/get_ct.sh", file=sys.stderr)
    n = 128 if args.quick else 256
    cases.append((f"gyroid {n}^3", ensure_field(args.isotrack, f"gyroid:{n}", data), 0.0, None))
    cases.append((f"blobs {n}^3", ensure_field(args.isotrack, f"blobs:{n}", data), 0.25, None))
    m = 256 if args.quick else 512
    cases.append((f"sphere {m}^3", ensure_field(args.isotrack, f"sphere:{m}", data), 0.0, None))

    print(f"isotrack vs VTK {vtk.vtkVersion.GetVTKVersion()}: medians of {args.rounds} rounds' medians of {args.repeat} runs"
          f" (isotrack: one process per round, its methods and threads interleaved), extraction only;")
    print("ratio = VTK time / isotrack time (above 1: isotrack faster), the median of the rounds' ratios\n")
    header = f"{'volume':<16} {'what':<34} {'isotrack ms':>12} {'VTK ms':>10} {'ratio':>7}"
    print(header)
    print("-" * len(header))
    rows = []
    for name, path, iso, seed in cases:
        image = read_nrrd(path)
        if seed is None:
            seed = smallest_surface_seed(args.isotrack, path, iso)
        methods = ("mc", "all", "track", "stream")
        ours = {threads: {method: [] for method in methods} for threads in (1, 2)}
        theirs = {1: [], 2: []}
        for round_ in range(args.rounds):
            def run_isotrack():
                runs = isotrack_bench(args.isotrack, path, iso, seed, args.repeat)
                for threads in (1, 2):
                    for method in methods:
                        ours[threads][method].append(runs[threads][method])
            if round_ % 2:
                run_isotrack()
            for threads in (1, 2):
                theirs[threads].append(vtk_times(image, iso, seed, threads, args.repeat))
            if not round_ % 2:
                run_isotrack()
        for threads in (1, 2):
            vtk_runs, mine = theirs[threads], ours[threads]
            times = {key: [r[key] for r in vtk_runs] for key in ("fe", "fe_all", "fe_one")}
            times.update({method: [r["seconds"] for r in mine[method]] for method in methods})
            med = {key: statistics.median(values) for key, values in times.items()}
            mc, al, tr = mine["mc"][0], mine["all"][0], mine["track"][0]  # the counts, the same in every round
            v = vtk_runs[0]
            lines = [
                (f"mc vs FlyingEdges, {threads}T", "mc", "fe"),
                (f"all vs FE+connectivity, {threads}T", "all", "fe_all"),
                (f"track vs FE+closest point, {threads}T", "track", "fe_one"),
            ]
            for what, ours_key, vtk_key in lines:
                print(f"{name:<16} {what:<34} {med[ours_key] * 1e3:12.2f} {med[vtk_key] * 1e3:10.2f}"
                      f" {paired_ratio(times[vtk_key], times[ours_key]):7.2f}")
            all_over_mc = paired_ratio(times["all"], times["mc"])
            print(f"{'':<16} {'(all / mc, same threads)':<34} {all_over_mc:12.2f}")
            # Against reading every sample once, on as many threads.
            mc_over_stream = paired_ratio(times["mc"], times["stream"])
            print(f"{'':<16} {'(mc / reading the volume once)':<34} {mc_over_stream:12.2f}   (reading: {med['stream'] * 1e3:.2f} ms)")
            rows.append({"volume": name, "threads": threads, **{key: med[key] for key in times},
                         "rounds": times, "all_over_mc": all_over_mc, "mc_over_stream": mc_over_stream,
                         "triangles": mc["triangles"], "vtk_triangles": v["triangles"],
                         "surfaces": al["components"], "vtk_regions": v["regions"],
                         "track_triangles": tr["triangles"], "vtk_closest_triangles": v["one_triangles"]})
            if mc["triangles"] != v["triangles"] or al["components"] != v["regions"]:
                print(f"{'':<16} note: counts differ: isotrack {mc['triangles']} triangles / {al['components']} surfaces,"
                      f" VTK {v['triangles']} / {v['regions']}")
            if tr["triangles"] != v["one_triangles"]:
                print(f"{'':<16} note: tracked {tr['triangles']} triangles, VTK closest region {v['one_triangles']}")
        one, two = ([r["seconds"] for r in ours[threads]["mc"]] for threads in (1, 2))
        rows[-1]["two_over_one"] = paired_ratio(one, two)
        print()
    print("two threads against one (isotrack mc):")
    for r in rows:
        if "two_over_one" in r:
            print(f"  {r['volume']:<16} {r['two_over_one']:.2f}x")
    with open(os.path.join(data, "compare_vtk.json"), "w") as f:
        json.dump(rows, f, indent=1)


if __name__ == "__main__":
    main()
