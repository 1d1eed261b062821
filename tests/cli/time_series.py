"""Time series: a .pvd collection of VTK-written .vti files, 4D NIfTI and NRRD, numbered files.

Each step is a 64^3 gyroid plus a ramp along x that grows with the step, so that
every step's surface differs. `isotrack info` must list the steps with their time
values and files; `extract --time STEP` must export byte for byte the mesh that
extracting that step's own file gives: the step's .vti for the collection, the 3D
NIfTI of that volume (written by nibabel on its own) for the 4D one and for the
series those 3D files make as a printf pattern ("three_%d.nii"), the 3D NRRD of
that step for a NRRD with a fourth (time) axis, raw and gzip. A step past
the end is one line naming the file.

Usage: /usr/bin/python3 time_series.py ISOTRACK WORK_DIR  (exit 77 without VTK)
"""
import gzip
import json
import os
import shutil
import subprocess
import sys

import nibabel
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
N = 64


def run(*args):
    done = subprocess.run([ISOTRACK, *args], capture_output=True, text=True)
    if done.returncode != 0:
        failures.append(f"isotrack {' '.join(args)}: exit {done.returncode}: {done.stderr.strip()}")
        return None
    return done.stdout


def mesh(path, *extra):
    """The PLY bytes of every surface at 0.25, or None when extract failed."""
    ply = "out_" + os.path.basename(path) + "_".join(extra) + ".ply"
    if run("extract", "--volume", path, "--iso", "0.25", "--method", "all", "--out", ply, *extra) is None:
        return None
    with open(ply, "rb") as f:
        return f.read()


run("field", "gyroid:64", "--out", "g.nrrd")
data = open("g.nrrd", "rb").read()
gyroid = np.frombuffer(data.split(b"\n\n", 1)[1], dtype="<f4").reshape(N, N, N)  # [z, y, x]
ramp = np.linspace(0.0, 1.0, N, dtype=np.float32)[None, None, :]
steps = [gyroid + np.float32(0.2 * t) * ramp for t in range(5)]

# The collection: three .vti files in steps/, listed out of time order.
times = [0.0, 0.5, 1.25]
for t in range(3):
    img = vtk.vtkImageData()
    img.SetDimensions(N, N, N)
    array = numpy_support.numpy_to_vtk(steps[t].ravel(), deep=True)
    array.SetName("g")
    img.GetPointData().AddArray(array)
    w = vtk.vtkXMLImageDataWriter()
    w.SetFileName(f"steps/step_{t}.vti")
    w.SetInputData(img)
    w.SetCompressorTypeToZLib()
    w.SetEncodeAppendedData(False)
    assert w.Write() == 1
order = [2, 0, 1]
with open("series.pvd", "w") as f:
    f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n')
    for t in order:
        f.write(f'  <DataSet timestep="{times[t]}" group="" part="0" file="steps/step_{t}.vti"/>\n')
    f.write("</Collection>\n</VTKFile>\n")

out = run("info", "--volume", "series.pvd", "--json")
if out is not None:
    info = json.loads(out)
    got = [(s["index"], s["time"], os.path.relpath(s["file"])) for s in info["steps"]]
    want = [(i, times[i], f"steps/step_{i}.vti") for i in range(3)]
    if got != want:
        failures.append(f"series.pvd: info lists {got}, expected {want}")
    print("series.pvd steps:", got)
text = run("info", "--volume", "series.pvd")
if text is not None and "3 time steps" not in text:
    failures.append("series.pvd: info's text does not say 3 time steps")

for t in range(3):
    extra = ("--time", str(t)) if t else ()
    if mesh("series.pvd", *extra) != mesh(f"steps/step_{t}.vti"):
        failures.append(f"series.pvd --time {t}: the mesh differs from steps/step_{t}.vti's")
if mesh("series.pvd", "--time", "1") == mesh("series.pvd", "--time", "2"):
    failures.append("series.pvd: steps 1 and 2 give the same mesh; the test cannot tell them apart")

# A 4D NIfTI of five steps, 2.5 time units apart, against each step written alone.
affine = np.diag([1.0, 1.0, 1.0, 1.0])
four = np.stack([s.transpose(2, 1, 0) for s in steps], axis=-1)  # [x, y, z, t]
for name in ("four.nii", "four.nii.gz"):
    image = nibabel.Nifti1Image(four, affine)
    image.header.set_xyzt_units("mm", "sec")
    image.header["pixdim"][4] = 2.5
    nibabel.save(image, name)
for t in range(5):
    nibabel.save(nibabel.Nifti1Image(np.ascontiguousarray(four[..., t]), affine), f"three_{t}.nii")
for name in ("four.nii", "four.nii.gz"):
    out = run("info", "--volume", name, "--json")
    if out is not None:
        got = [s["time"] for s in json.loads(out)["steps"]]
        if got != [0.0, 2.5, 5.0, 7.5, 10.0]:
            failures.append(f"{name}: step times {got}, expected 0, 2.5 .. 10")
    for t in (0, 2, 4):
        if mesh(name, "--time", str(t)) != mesh(f"three_{t}.nii"):
            failures.append(f"{name} --time {t}: the mesh differs from three_{t}.nii's")
    if mesh(name) != mesh("three_0.nii"):
        failures.append(f"{name}: without --time the mesh is not step 0's")

# The same steps as one NRRD with a fourth (time) axis, raw and gzip, against the
# 3D NRRD of each step; a component axis first is refused.
def nrrd_head(sizes, extra, encoding):
    return (f"NRRD0004\ntype: float\ndimension: {len(sizes)}\nsizes: {' '.join(map(str, sizes))}\n"
            f"endian: little\nencoding: {encoding}\n{extra}\n").encode()


stack = np.stack(steps).astype("<f4")  # [t, z, y, x]
four_d = "kinds: domain domain domain time\nspace directions: (1,0,0) (0,1,0) (0,0,1) none\n"
open("four.nrrd", "wb").write(nrrd_head((N, N, N, 5), four_d, "raw") + stack.tobytes())
open("four_gz.nrrd", "wb").write(nrrd_head((N, N, N, 5), four_d, "gzip") + gzip.compress(stack.tobytes(), 1))
open("vector.nrrd", "wb").write(nrrd_head((3, N, N, 5), "kinds: vector domain domain domain\n", "raw"))
for t in range(5):
    open(f"nrrd_{t}.nrrd", "wb").write(nrrd_head((N, N, N), "", "raw") + stack[t].tobytes())
for name in ("four.nrrd", "four_gz.nrrd"):
    out = run("info", "--volume", name, "--json")
    if out is not None and [s["time"] for s in json.loads(out)["steps"]] != [0.0, 1.0, 2.0, 3.0, 4.0]:
        failures.append(f"{name}: info does not list 5 steps at times 0..4")
    for t in (0, 2, 4):
        if mesh(name, "--time", str(t)) != mesh(f"nrrd_{t}.nrrd"):
            failures.append(f"{name} --time {t}: the mesh differs from nrrd_{t}.nrrd's")
done = subprocess.run([ISOTRACK, "extract", "--volume", "vector.nrrd"], capture_output=True, text=True)
if done.returncode != 1 or 'field "kinds"' not in done.stderr or done.stderr.count("\n") != 1:
    failures.append(f"vector.nrrd: exit {done.returncode}: {done.stderr.strip()}")

# The 3D files as a numbered series: a printf pattern, steps from 0, time = number.
out = run("info", "--volume", "three_%d.nii", "--json")
if out is not None:
    got = [(s["time"], s["file"]) for s in json.loads(out)["steps"]]
    if got != [(float(t), f"three_{t}.nii") for t in range(5)]:
        failures.append(f"three_%d.nii: info lists {got}")
if mesh("three_%d.nii", "--time", "3") != mesh("three_3.nii"):
    failures.append("three_%d.nii --time 3: the mesh differs from three_3.nii's")
done = subprocess.run([ISOTRACK, "extract", "--volume", "none_%04d.nii"], capture_output=True, text=True)
if done.returncode != 1 or "none_%04d.nii: no file matches the pattern" not in done.stderr:
    failures.append(f"none_%04d.nii: exit {done.returncode}: {done.stderr.strip()}")

# Steps past the end: exit 1, one line naming the file and the steps there are.
for name, steps_text in (("series.pvd", "3 steps (0..2)"), ("four.nii", "5 steps (0..4)"), ("g.nrrd", "1 step")):
    done = subprocess.run([ISOTRACK, "extract", "--volume", name, "--time", "9"], capture_output=True, text=True)
    if done.returncode != 1 or done.stderr.count("\n") != 1 or name not in done.stderr or steps_text not in done.stderr:
        failures.append(f"{name} --time 9: exit {done.returncode}: {done.stderr.strip()}")

if failures:
    print("\n".join("FAIL " + f for f in failures))
    sys.exit(1)
print("every time step reads as its own file")
