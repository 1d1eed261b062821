"""extract --all-times on a .pvd of 6 steps of moving, merging blobs written by VTK itself.

Gaussian blobs (sigma 4 voxels, isovalue 0.5) in a 64x64x32 grid, each step a
.vti written by vtkXMLImageDataWriter (zlib, appended raw), listed in a .pvd:
  - A (peak 1.0) moves steadily along x, 4 voxels a step, alone;
  - C (peak 1.0) and D (peak 0.8) move towards each other, 3 voxels a step each,
    and meet at step 4 (at step 3 they are 14 voxels apart and still two).
Checked against extracting each step's own file alone (`extract --method all`,
`tree`, and `track --seed` at A's centre): the per-step triangle counts of
track.json and of the mesh files; A keeps one id through all steps (its box
centred on where it is), the seed follows A, C keeps its id and D ends merged
into C. Misuse (no --out-dir, --time, --method mc) is refused in one line, and a
single volume is one step.

Usage: /usr/bin/python3 all_times.py ISOTRACK WORK_DIR  (exit 77 without VTK)
"""
import json
import os
import shutil
import subprocess
import sys
import time

import numpy as np

try:
    import vtk
    from vtk.util import numpy_support
except ImportError:
    print("python3-vtk9 is missing: skipped")
    sys.exit(77)

ISOTRACK, WORK = sys.argv[1], sys.argv[2]
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(os.path.join(WORK, "steps"))
os.chdir(WORK)
failures = []
NX, NY, NZ, SIGMA, ISO, STEPS = 64, 64, 32, 4.0, 0.5, 6
A_ROW, CD_ROW, Z = 16.0, 46.0, 15.5


def a_x(t):
    return 10.0 + 4.0 * t


def c_x(t):
    return 16.0 + 3.0 * t


def d_x(t):
    return 48.0 - 3.0 * t


def blobs(t):
    """Step t's samples, indexed [z, y, x]."""
    z, y, x = np.meshgrid(np.arange(NZ), np.arange(NY), np.arange(NX), indexing="ij")

    def blob(cx, cy, peak):
        return peak * np.exp(-((x - cx) ** 2 + (y - cy) ** 2 + (z - Z) ** 2) / (2 * SIGMA**2))

    return (blob(a_x(t), A_ROW, 1.0) + blob(c_x(t), CD_ROW, 1.0) + blob(d_x(t), CD_ROW, 0.8)).astype(np.float32)


times = [0.25 * t for t in range(STEPS)]
for t in range(STEPS):
    img = vtk.vtkImageData()
    img.SetDimensions(NX, NY, NZ)
    array = numpy_support.numpy_to_vtk(blobs(t).ravel(), deep=True)
    array.SetName("density")
    img.GetPointData().SetScalars(array)
    w = vtk.vtkXMLImageDataWriter()
    w.SetFileName(f"steps/blobs_{t}.vti")
    w.SetInputData(img)
    w.SetCompressorTypeToZLib()
    w.SetEncodeAppendedData(False)
    assert w.Write() == 1
with open("blobs.pvd", "w") as f:
    f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n')
    for t in range(STEPS):
        f.write(f'  <DataSet timestep="{times[t]}" group="" part="0" file="steps/blobs_{t}.vti"/>\n')
    f.write("</Collection>\n</VTKFile>\n")


def run(*args):
    done = subprocess.run([ISOTRACK, *map(str, args)], capture_output=True, text=True)
    if done.returncode != 0:
        failures.append(f"isotrack {' '.join(map(str, args))}: exit {done.returncode}: {done.stderr.strip()}")
        return None
    return done.stdout


def alone(t, method, *extra):
    """The triangle counts of step t's own file, sorted."""
    out = run("extract", "--volume", f"steps/blobs_{t}.vti", "--iso", ISO, "--method", method, "--json", *extra)
    if out is None:
        return None
    return sorted(s["triangles"] for s in json.loads(out)["surfaces"])


def ply_faces(path):
    with open(path, "rb") as f:
        header = f.read(4096).split(b"end_header")[0].decode()
    return next(int(line.split()[2]) for line in header.splitlines() if line.startswith("element face"))


def all_times(out_dir, method, *extra):
    start = time.perf_counter()
    if run("extract", "--volume", "blobs.pvd", "--iso", ISO, "--all-times", "--out-dir", out_dir, "--method", method,
           "--frame", "voxel", *extra) is None:
        return None
    print(f"{method}: {STEPS} steps in {time.perf_counter() - start:.3f} s (whole command)")
    with open(os.path.join(out_dir, "track.json")) as f:
        return json.load(f)


def centre(record):
    lo, hi = record["bounds"]
    return [(a + b) / 2 for a, b in zip(lo, hi)]


def near(record, x, y):
    c = centre(record)
    return abs(c[0] - x) < 1.0 and abs(c[1] - y) < 1.0


for method in ("all", "tree"):
    track = all_times(f"out_{method}", method)
    if track is None:
        continue
    steps = track["steps"]
    if [s["step"] for s in steps] != list(range(STEPS)) or [s["time"] for s in steps] != times:
        failures.append(f"{method}: steps {[(s['step'], s['time']) for s in steps]}, expected times {times}")
        continue
    a_id = next((s["id"] for s in steps[0]["surfaces"] if near(s, a_x(0), A_ROW)), None)
    c_id = next((s["id"] for s in steps[0]["surfaces"] if near(s, c_x(0), CD_ROW)), None)
    d_id = next((s["id"] for s in steps[0]["surfaces"] if near(s, d_x(0), CD_ROW)), None)
    if None in (a_id, c_id, d_id):
        failures.append(f"{method}: step 0 does not show blobs A, C and D where they are")
        continue
    for t, step in enumerate(steps):
        shown = [s for s in step["surfaces"] if s["presence"] == "shown"]
        if sorted(s["triangles"] for s in shown) != alone(t, method):
            failures.append(f"{method} step {t}: triangles {sorted(s['triangles'] for s in shown)}, "
                            f"alone {alone(t, method)}")
        for s in shown:
            path = os.path.join(f"out_{method}", s["file"])
            if s["file"] != f"step_{t:04d}/surface_{s['id']:04d}.ply" or ply_faces(path) != s["triangles"]:
                failures.append(f"{method} step {t}: surface {s['id']}: file {s['file']} does not hold its triangles")
            if not s["area"] > 0 or s["volume"] is None or not s["volume"] > 0:
                failures.append(f"{method} step {t}: surface {s['id']}: area {s['area']}, volume {s['volume']}")
        a = next((s for s in shown if s["id"] == a_id), None)
        if a is None or not near(a, a_x(t), A_ROW) or (t > 0 and (a["continues"] != a_id or a["split"])):
            failures.append(f"{method} step {t}: blob A does not keep id {a_id}: {a}")
        c = next((s for s in shown if s["id"] == c_id), None)
        if c is None or (t > 0 and c["continues"] != c_id):
            failures.append(f"{method} step {t}: blob C does not keep id {c_id}")
        d = next((s for s in step["surfaces"] if s["id"] == d_id), None)
        if t < 4:
            if d is None or d["presence"] != "shown" or not near(d, d_x(t), CD_ROW):
                failures.append(f"{method} step {t}: blob D is not shown where it is: {d}")
        elif t == 4:
            if d is None or d["presence"] != "merged" or d["merged_into"] != c_id or not d["ended"]:
                failures.append(f"{method} step 4: blob D is not reported merged into C ({c_id}): {d}")
            if len(shown) != 2:
                failures.append(f"{method} step 4: {len(shown)} surfaces shown, expected A and C+D")
        elif d is not None:
            failures.append(f"{method} step {t}: blob D, ended at step 4, is listed again: {d}")
    print(f"{method}: A keeps id {a_id}; D ({d_id}) merges into C ({c_id}) at step 4;",
          "ms a step:", [round(s["seconds"] * 1e3, 1) for s in steps])

# The seed at A's centre: the tracked surface is A at every step, as tracking each step's file from A's centre.
track = all_times("out_track", "track", "--seed", f"{a_x(0)},{A_ROW},{Z}")
if track is not None:
    for t, step in enumerate(track["steps"]):
        s = step["surfaces"]
        want = alone(t, "track", "--seed", f"{a_x(t)},{A_ROW},{Z}", "--frame", "voxel")
        if len(s) != 1 or s[0]["id"] != 0 or s[0]["presence"] != "shown" or [s[0]["triangles"]] != want:
            failures.append(f"track step {t}: {s}, expected surface 0 with {want} triangles")
        elif not near(s[0], a_x(t), A_ROW):
            failures.append(f"track step {t}: the tracked surface is not blob A: centre {centre(s[0])}")

# A single volume is one step; misuse is one line.
one = run("extract", "--volume", "steps/blobs_2.vti", "--iso", ISO, "--method", "all", "--all-times", "--out-dir",
          "out_one", "--out-format", "stl", "--json")
if one is not None:
    report = json.loads(one)
    with open("out_one/track.json") as f:
        steps = json.load(f)["steps"]
    if report["steps"] != 1 or len(steps) != 1 or not os.path.isfile("out_one/step_0000/surface_0000.stl"):
        failures.append(f"a single volume: {report}")
for extra, words in (([], "--out-dir"), (["--out-dir", "x", "--time", "1"], "--time"),
                     (["--out-dir", "x", "--method", "mc"], "not mc"),
                     (["--out-dir", "x", "--out", "a.ply"], "not with --out")):
    args = ["extract", "--volume", "blobs.pvd", "--iso", str(ISO), "--all-times", *extra]
    if "--method" not in extra:
        args += ["--method", "all"]
    done = subprocess.run([ISOTRACK, *args], capture_output=True, text=True)
    if done.returncode == 0 or done.stderr.count("\n") != 1 or words not in done.stderr:
        failures.append(f"{' '.join(args)}: exit {done.returncode}: {done.stderr.strip()}")

if failures:
    print("\n".join("FAIL " + f for f in failures))
    sys.exit(1)
print("every step as its own file; A keeps its id, D merges into C")
