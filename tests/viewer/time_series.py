"""The viewer on a time series: the .pvd of 6 steps of moving, merging blobs
that tests/cli/all_times.py makes (the same samples, written by VTK itself).

Session tests/viewer/time_series.isotrack: blob A tracked from its centre at
step 0 and selected, then `play` to the last step and `time 3`. Checked from the
--json summary: at least 5 steps are shown during play (every step after the
first), at every step shown the selection is A's id with A's colour, tracked,
its box centred where A is at that step, and its triangles those of the surface
at A in `isotrack extract --method all` of that step's file alone; `time 3`
shows step 3 again with the triangles it had during play. A second session
opened with `--time 2 --array density` shows step 2's surfaces (those of
extracting steps/blobs_2.vti alone), and so do numbered files
(`steps/blobs_%d.vti --time 5`) and a 4D NIfTI of the steps (`--time 4`);
`--array` naming no array is an error, and so are `time 6` and playing onto a step whose grid differs (one line
each).
Prints the median frame time while playing.

Usage: /usr/bin/python3 time_series.py ISOTRACK WORK_DIR  (exit 77 without VTK or nibabel)
"""
import json
import os
import shutil
import subprocess
import sys

import numpy as np

try:
    import nibabel
    import vtk
    from vtk.util import numpy_support
except ImportError:
    print("python3-vtk9 or python3-nibabel is missing: skipped")
    sys.exit(77)

ISOTRACK, WORK = sys.argv[1], sys.argv[2]
HERE = os.path.dirname(os.path.abspath(__file__))
shutil.rmtree(WORK, ignore_errors=True)
os.makedirs(os.path.join(WORK, "steps"))
os.chdir(WORK)
failures = []
# As tests/cli/all_times.py: A moves along x alone; C and D meet at step 4.
NX, NY, NZ, SIGMA, ISO, STEPS = 64, 64, 32, 4.0, 0.5, 6
A_ROW, CD_ROW, Z = 16.0, 46.0, 15.5


def a_x(t):
    return 10.0 + 4.0 * t


def blobs(t):
    """Step t's samples, indexed [z, y, x]."""
    z, y, x = np.meshgrid(np.arange(NZ), np.arange(NY), np.arange(NX), indexing="ij")

    def blob(cx, cy, peak):
        return peak * np.exp(-((x - cx) ** 2 + (y - cy) ** 2 + (z - Z) ** 2) / (2 * SIGMA**2))

    c_x, d_x = 16.0 + 3.0 * t, 48.0 - 3.0 * t
    return (blob(a_x(t), A_ROW, 1.0) + blob(c_x, CD_ROW, 1.0) + blob(d_x, CD_ROW, 0.8)).astype(np.float32)


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
    assert w.Write() == 1
with open("blobs.pvd", "w") as f:
    f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n')
    for t in range(STEPS):
        f.write(f'  <DataSet timestep="{times[t]}" group="" part="0" file="steps/blobs_{t}.vti"/>\n')
    f.write("</Collection>\n</VTKFile>\n")


def viewer(*args):
    done = subprocess.run([ISOTRACK, "--size", "960x600", "--json", *map(str, args)], capture_output=True, text=True)
    return done.returncode, done.stdout, done.stderr


def alone(t):
    """Step t's file extracted alone: each surface's triangles and box centre."""
    done = subprocess.run([ISOTRACK, "extract", "--volume", f"steps/blobs_{t}.vti", "--iso", str(ISO), "--method",
                           "all", "--frame", "voxel", "--json"],
                          capture_output=True, text=True, check=True)
    return json.loads(done.stdout)["surfaces"]


def centre(surface):
    lo, hi = surface["bounds"]
    return [(a + b) / 2 for a, b in zip(lo, hi)]


rc, out, err = viewer("--volume", "blobs.pvd", "--iso", ISO, "--method", "all", "--script",
                      os.path.join(HERE, "time_series.isotrack"))
if rc != 0:
    print(err)
    sys.exit(f"the session failed: exit {rc}")
summary = json.loads(out)
time = summary["time"]
print(f"steps {time['steps']}, shown during play {time['steps_shown_during_play']}, "
      f"{time['play_frames']} frames while playing, median {time['play_median_frame_ms']:.2f} ms; "
      f"whole session median {summary['median_frame_ms']:.2f} ms over {summary['frames']} frames")
if time["steps"] != STEPS:
    failures.append(f"steps {time['steps']}, expected {STEPS}")
if time["steps_shown_during_play"] < STEPS - 1:
    failures.append(f"{time['steps_shown_during_play']} steps shown during play, expected at least {STEPS - 1}")
if (time["step_shown"], time["time_shown"]) != (3, times[3]):
    failures.append(f"after `time 3`: step {time['step_shown']} at {time['time_shown']} shown")
shown = time["shown"]
played = sorted({s["step"] for s in shown if s["during_play"]})
if played != list(range(1, STEPS)):
    failures.append(f"steps shown during play: {played}, expected 1..{STEPS - 1}")
first = shown[0]
for s in shown:
    where = f"step {s['step']}"
    if s["time"] != times[s["step"]]:
        failures.append(f"{where}: time {s['time']}, expected {times[s['step']]}")
    if s["selected"] is None or s["selected"] != first["selected"]:
        failures.append(f"{where}: selected {s['selected']}, expected {first['selected']} throughout")
        continue
    if s["colour"] != first["colour"] or not s["tracked"] or not s["present"]:
        failures.append(f"{where}: colour {s['colour']} (first {first['colour']}), tracked {s['tracked']}, "
                        f"present {s['present']}")
    cx, cy = s["centre"][0], s["centre"][1]
    if abs(cx - a_x(s["step"])) > 1.0 or abs(cy - A_ROW) > 1.0:
        failures.append(f"{where}: the selected surface is centred at {s['centre']}, A is at "
                        f"({a_x(s['step'])}, {A_ROW})")
    at_a = [x for x in alone(s["step"]) if abs(centre(x)[0] - a_x(s["step"])) < 1 and abs(centre(x)[1] - A_ROW) < 1]
    if len(at_a) != 1 or at_a[0]["triangles"] != s["triangles"]:
        failures.append(f"{where}: {s['triangles']} triangles, extracting the step alone gives "
                        f"{[x['triangles'] for x in at_a]} at A")
step3 = [s["triangles"] for s in shown if s["step"] == 3]
if len(set(step3)) != 1:
    failures.append(f"step 3 shown with {step3} triangles: during play and after `time 3` differ")

# --time and --array: the session opens at step 2 of the density array.
rc, out, err = viewer("--volume", "blobs.pvd", "--time", 2, "--array", "density", "--iso", ISO, "--script",
                      os.path.join(HERE, "time_start.isotrack"))
if rc != 0:
    failures.append(f"--time 2 --array density: exit {rc}: {err.strip()}")
else:
    summary = json.loads(out)
    got = sorted(s["triangles"] for s in summary["surfaces"])
    expected = sorted(s["triangles"] for s in alone(2))
    if summary["time"]["step_shown"] != 2 or got != expected:
        failures.append(f"--time 2: step {summary['time']['step_shown']}, triangles {got}, alone {expected}")
# The other kinds of series: numbered files, and a 4D NIfTI of the same steps.
nibabel.save(nibabel.Nifti1Image(np.stack([blobs(t).transpose(2, 1, 0) for t in range(STEPS)], axis=3), np.eye(4)),
             "blobs_4d.nii")
for volume, step in (("steps/blobs_%d.vti", 5), ("blobs_4d.nii", 4)):
    rc, out, err = viewer("--volume", volume, "--time", step, "--iso", ISO, "--script",
                          os.path.join(HERE, "time_start.isotrack"))
    if rc != 0:
        failures.append(f"{volume} --time {step}: exit {rc}: {err.strip()}")
        continue
    summary = json.loads(out)
    got = sorted(s["triangles"] for s in summary["surfaces"])
    expected = sorted(s["triangles"] for s in alone(step))
    if (summary["time"]["steps"], summary["time"]["step_shown"]) != (STEPS, step) or got != expected:
        failures.append(f"{volume} --time {step}: {summary['time']['steps']} steps, step "
                        f"{summary['time']['step_shown']} shown, triangles {got}, alone {expected}")
rc, out, err = viewer("--volume", "blobs.pvd", "--array", "nothing", "--iso", ISO, "--script",
                      os.path.join(HERE, "time_start.isotrack"))
if rc == 0 or "nothing" not in err or len(err.strip().splitlines()) != 1:
    failures.append(f"--array nothing: exit {rc}, stderr {err.strip()!r}; expected one line naming the array")

with open("past_the_end.isotrack", "w") as f:
    f.write("wait\ntime 6\n")
rc, out, err = viewer("--volume", "blobs.pvd", "--iso", ISO, "--script", "past_the_end.isotrack")
if rc != 1 or err.strip() != "isotrack: past_the_end.isotrack:2: time 6: blobs.pvd has 6 steps (0..5)":
    failures.append(f"time 6: exit {rc}, stderr {err.strip()!r}")

# A step on another grid: an error naming it, and playback stops there.
img = vtk.vtkImageData()
img.SetDimensions(32, 32, 16)
img.GetPointData().SetScalars(numpy_support.numpy_to_vtk(blobs(0)[::2, ::2, ::2].ravel().copy(), deep=True))
w = vtk.vtkXMLImageDataWriter()
w.SetFileName("steps/small.vti")
w.SetInputData(img)
assert w.Write() == 1
with open("mixed.pvd", "w") as f:
    f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n'
            '  <DataSet timestep="0" file="steps/blobs_0.vti"/>\n  <DataSet timestep="1" file="steps/small.vti"/>\n'
            '</Collection>\n</VTKFile>\n')
with open("mixed.isotrack", "w") as f:
    f.write("wait\nplay\n")
rc, out, err = viewer("--volume", "mixed.pvd", "--iso", ISO, "--script", "mixed.isotrack")
if rc != 1 or len(err.strip().splitlines()) != 1 or "small.vti" not in err:
    failures.append(f"a step on another grid: exit {rc}, stderr {err.strip()!r}")
print(f"a step on another grid: {err.strip()}")

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
