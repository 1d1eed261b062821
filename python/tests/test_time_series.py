"""Time steps: load(path, time=) reads the step nibabel (4D NIfTI) or a .pvd names; steps() lists their times."""
import numpy as np
import pytest

import isotrack

nib = pytest.importorskip("nibabel")

SHAPE = (12, 10, 8, 4)  # x, y, z, t: nibabel's data shape


@pytest.fixture(scope="module")
def four(tmp_path_factory):
    """A 4D NIfTI whose steps differ everywhere, 0.75 time units apart from 2.0."""
    rng = np.random.default_rng(7)
    data = rng.standard_normal(SHAPE).astype(np.float32)
    image = nib.Nifti1Image(data, np.diag([1.5, 1.0, 2.0, 1.0]))
    image.header["pixdim"][4] = 0.75
    image.header["toffset"] = 2.0
    path = tmp_path_factory.mktemp("four") / "four.nii.gz"
    nib.save(image, path)
    return path, data


@pytest.mark.parametrize("time", [0, 1, 3])
def test_load_reads_the_step_nibabel_reads(four, time):
    path, data = four
    volume = isotrack.load(path, time=time)
    # isotrack's samples are indexed (z, y, x); nibabel's (x, y, z, t).
    np.testing.assert_array_equal(volume.samples, data[..., time].transpose(2, 1, 0))
    np.testing.assert_allclose(volume.spacing, (1.5, 1.0, 2.0))  # (x, y, z), as the file gives it


def test_steps_are_the_time_values(four):
    path, _ = four
    assert isotrack.steps(path) == pytest.approx([2.0, 2.75, 3.5, 4.25])


def test_default_is_the_first_step(four):
    path, data = four
    np.testing.assert_array_equal(isotrack.load(path).samples, data[..., 0].transpose(2, 1, 0))


def test_pvd_steps_are_its_datasets_in_time_order(tmp_path):
    samples = [np.full((3, 4, 5), float(t), np.float32) for t in range(3)]
    for t, s in enumerate(samples):
        nib.save(nib.Nifti1Image(s.transpose(2, 1, 0).copy(), np.eye(4)), tmp_path / f"s{t}.nii")
    (tmp_path / "series.pvd").write_text(
        '<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1"><Collection>\n'
        '<DataSet timestep="20" file="s2.nii"/><DataSet timestep="5" file="s0.nii"/>'
        '<DataSet timestep="10.5" file="s1.nii"/>\n</Collection></VTKFile>\n'
    )
    path = tmp_path / "series.pvd"
    assert isotrack.steps(path) == [5.0, 10.5, 20.0]
    for t in range(3):
        np.testing.assert_array_equal(isotrack.load(path, time=t).samples, samples[t])


def test_a_step_past_the_end_and_a_bad_time_are_refused(four):
    path, _ = four
    with pytest.raises(ValueError, match=r"no time step 4: it has 4 steps \(0\.\.3\)"):
        isotrack.load(path, time=4)
    with pytest.raises(ValueError, match="time"):
        isotrack.load(path, time=-1)
    with pytest.raises(ValueError, match="only for .vti"):
        isotrack.load(path, array="density")
