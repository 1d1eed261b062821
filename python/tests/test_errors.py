"""Bad input raises ValueError, file trouble OSError, with messages that name the problem."""
import numpy as np
import pytest

import isotrack
from conftest import ellipsoid


@pytest.mark.parametrize("dtype", [np.complex64, np.str_, object, "datetime64[s]"])
def test_unsupported_dtype(dtype):
    with pytest.raises(ValueError, match="unsupported dtype"):
        isotrack.marching_cubes(np.zeros((4, 4, 4), dtype), 0.5)


def test_int64_beyond_float64_precision():
    volume = np.zeros((4, 4, 4), np.int64)
    volume[1, 1, 1] = 2**53 + 1
    with pytest.raises(ValueError, match=r"no exact float64 \(beyond 2\*\*53\)"):
        isotrack.marching_cubes(volume, 0.5)
    volume[1, 1, 1] = 2**53  # exact in float64
    assert len(isotrack.marching_cubes(volume, 0.5)[1]) > 0


def test_not_three_dimensional():
    with pytest.raises(ValueError, match=r"3D array.*\(4, 4\)"):
        isotrack.marching_cubes(np.zeros((4, 4), np.float32), 0.5)


def test_foreign_byte_order_is_read_as_its_values():
    volume = ellipsoid()
    swapped = volume.astype(volume.dtype.newbyteorder("S"))
    np.testing.assert_array_equal(isotrack.marching_cubes(swapped, 1.0)[1], isotrack.marching_cubes(volume, 1.0)[1])


@pytest.mark.parametrize("level", [float("nan"), float("inf")])
def test_level_not_finite(level):
    for call in (
        lambda: isotrack.marching_cubes(ellipsoid(), level),
        lambda: isotrack.surfaces(ellipsoid(), level),
        lambda: isotrack.track(ellipsoid(), level, seed=(0, 0, 0)),
    ):
        with pytest.raises(ValueError, match="level: must be a finite number"):
            call()


@pytest.mark.parametrize("spacing", [(1, 0, 1), (1, -1, 1), (1, float("nan"), 1)])
def test_bad_spacing(spacing):
    with pytest.raises(ValueError, match="spacing"):
        isotrack.marching_cubes(ellipsoid(), 1.0, spacing=spacing)


def test_bad_options():
    with pytest.raises(ValueError, match="method: expected one of mc, lewiner, lorensen, all"):
        isotrack.marching_cubes(ellipsoid(), 1.0, method="flying")
    with pytest.raises(ValueError, match="table: expected one of consistent, classic, trilinear"):
        isotrack.surfaces(ellipsoid(), 1.0, table="mine")
    with pytest.raises(ValueError, match="threads"):
        isotrack.surfaces(ellipsoid(), 1.0, threads=-1)


def test_wrong_seed():
    volume = ellipsoid()
    with pytest.raises(ValueError, match="exactly one of seed"):
        isotrack.track(volume, 1.0)
    with pytest.raises(ValueError, match="exactly one of seed"):
        isotrack.track(volume, 1.0, seed=(0, 0, 0), seed_edge=(0, 0, 0, 0))
    with pytest.raises(ValueError, match="not crossed"):
        isotrack.track(volume, 1.0, seed_edge=(0, 0, 0, 2))  # a corner, outside the ellipsoid
    with pytest.raises(ValueError, match="outside"):
        isotrack.track(volume, 1.0, seed_edge=(0, 0, 500, 2))
    with pytest.raises(ValueError, match="axis"):
        isotrack.track(volume, 1.0, seed_edge=(10, 12, 1, 3))
    with pytest.raises(ValueError):
        isotrack.track(np.zeros((4, 4, 4), np.float32), 1.0, seed=(1, 1, 1))  # nothing crossed


def test_file_errors(tmp_path):
    with pytest.raises(OSError, match="missing.nrrd"):
        isotrack.load(str(tmp_path / "missing.nrrd"))
    (tmp_path / "samples.raw").write_bytes(b"\0" * 64)
    with pytest.raises(OSError, match="samples.raw"):
        isotrack.load(str(tmp_path / "samples.raw"))
    surface = isotrack.surfaces(ellipsoid(), 1.0)[0]
    with pytest.raises(OSError):
        isotrack.write_ply(surface, str(tmp_path / "no" / "such" / "dir.ply"))
