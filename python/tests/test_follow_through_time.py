"""Time series followed step by step: load_steps and follow_through_time.

A 4D NIfTI (nibabel) of Gaussian blobs (sigma 4 voxels, level 0.5): A moves
steadily along x, 4 voxels a step; C and D move towards each other and meet at
step 4. follow_through_time must give the records of `isotrack extract
--all-times` (its track.json), each step's surfaces those of that step alone,
A one id throughout, and D ended merged into C.
"""
import json

import numpy as np
import pytest

import isotrack

nib = pytest.importorskip("nibabel")

NX, NY, NZ, STEPS, SIGMA, LEVEL = 64, 64, 32, 6, 4.0, 0.5
A_ROW, CD_ROW, Z = 16.0, 46.0, 15.5


def centres(t):
    return {"A": (10.0 + 4.0 * t, A_ROW), "C": (16.0 + 3.0 * t, CD_ROW), "D": (48.0 - 3.0 * t, CD_ROW)}


def blobs(t):
    """Step t, indexed (x, y, z) as nibabel has it."""
    x, y, z = np.meshgrid(np.arange(NX), np.arange(NY), np.arange(NZ), indexing="ij")
    peaks = {"A": 1.0, "C": 1.0, "D": 0.8}
    return sum(
        peaks[name] * np.exp(-((x - cx) ** 2 + (y - cy) ** 2 + (z - Z) ** 2) / (2 * SIGMA**2))
        for name, (cx, cy) in centres(t).items()
    ).astype(np.float32)


@pytest.fixture(scope="module")
def series(tmp_path_factory):
    path = tmp_path_factory.mktemp("blobs") / "blobs.nii.gz"
    image = nib.Nifti1Image(np.stack([blobs(t) for t in range(STEPS)], axis=-1), np.eye(4))
    image.header["pixdim"][4] = 0.5
    nib.save(image, path)
    return path


def centre(record):
    lo, hi = record["bounds"]
    return [(a + b) / 2 for a, b in zip(lo, hi)]


def id_at(step, x, y):
    found = [s["id"] for s in step["surfaces"] if s["bounds"] and np.allclose(centre(s)[:2], (x, y), atol=1.0)]
    assert len(found) == 1, (x, y, step)
    return found[0]


def test_load_steps_reads_each_step_in_turn(series):
    times = []
    for t, (time, volume) in enumerate(isotrack.load_steps(series)):
        times.append(time)
        np.testing.assert_array_equal(volume.samples, isotrack.load(series, time=t).samples)
        assert volume.frame == "lps"
    assert times == isotrack.steps(series) == pytest.approx([0.5 * t for t in range(STEPS)])


def test_each_step_is_that_step_alone(series):
    followed = isotrack.follow_through_time(series, LEVEL, surfaces=True)
    assert followed["isovalue"] == LEVEL and len(followed["steps"]) == STEPS
    for t, step in enumerate(followed["steps"]):
        alone = isotrack.surfaces(isotrack.load(series, time=t), LEVEL)
        shown = [s for s in step["surfaces"] if s["presence"] == "shown"]
        assert sorted(s["triangles"] for s in shown) == sorted(s.triangle_count for s in alone)
        for s in shown:
            assert s["surface"].triangle_count == s["triangles"]
            assert s["surface"].area == pytest.approx(s["area"])
            np.testing.assert_allclose(s["surface"].bounds, s["bounds"])


def test_a_moving_blob_keeps_its_id_and_a_merge_is_reported(series):
    steps = isotrack.follow_through_time(series, LEVEL, frame="voxel")["steps"]
    first = {name: id_at(steps[0], *c) for name, c in centres(0).items()}
    for t, step in enumerate(steps):
        assert id_at(step, *centres(t)["A"]) == first["A"]
        by_id = {s["id"]: s for s in step["surfaces"]}
        if t:
            assert by_id[first["A"]]["continues"] == first["A"] and not by_id[first["A"]]["split"]
            assert by_id[first["C"]]["continues"] == first["C"]
        if t < 4:
            assert by_id[first["D"]]["presence"] == "shown"
        elif t == 4:
            d = by_id[first["D"]]
            assert (d["presence"], d["merged_into"], d["ended"]) == ("merged", first["C"], True)
        else:
            assert first["D"] not in by_id


def test_a_seed_follows_its_blob(series):
    steps = isotrack.follow_through_time(series, LEVEL, method="track", seed=(10.0, A_ROW, Z), frame="voxel")["steps"]
    for t, step in enumerate(steps):
        (tracked,) = step["surfaces"]
        assert (tracked["id"], tracked["presence"]) == (0, "shown")
        assert centre(tracked)[:2] == pytest.approx(centres(t)["A"], abs=1.0)


def test_the_records_are_track_json(series, cli, tmp_path):
    cli("extract", "--volume", series, "--iso", LEVEL, "--method", "tree", "--all-times", "--out-dir", tmp_path)
    track = json.loads((tmp_path / "track.json").read_text())
    followed = isotrack.follow_through_time(series, LEVEL, method="tree")
    assert followed["isovalue"] == track["isovalue"]
    for ours, theirs in zip(followed["steps"], track["steps"], strict=True):
        assert (ours["step"], ours["time"]) == (theirs["step"], theirs["time"])
        for a, b in zip(ours["surfaces"], theirs["surfaces"], strict=True):
            b = {key: value for key, value in b.items() if key != "file"}
            a = dict(a, bounds=None if a["bounds"] is None else [list(corner) for corner in a["bounds"]])
            assert a == pytest.approx(b)


def test_misuse_is_refused(series, tmp_path):
    with pytest.raises(ValueError, match="seed"):
        isotrack.follow_through_time(series, LEVEL, method="track")
    with pytest.raises(ValueError, match="seed"):
        isotrack.follow_through_time(series, LEVEL, seed=(1, 2, 3))
    with pytest.raises(ValueError, match="method"):
        isotrack.follow_through_time(series, LEVEL, method="mc")
    with pytest.raises(ValueError, match="finite"):
        isotrack.follow_through_time(series, float("nan"))
    # A numbered series whose second step has other dims: refused when reached, naming its file.
    for t, shape in enumerate([(8, 8, 8), (8, 8, 9)]):
        nib.save(nib.Nifti1Image(np.zeros(shape, np.float32), np.eye(4)), tmp_path / f"odd_{t}.nii")
    steps = isotrack.load_steps(tmp_path / "odd_%d.nii")
    next(steps)
    with pytest.raises(ValueError, match=r"odd_1\.nii.*dims 8x8x9, the first step's 8x8x8"):
        next(steps)
