"""isotrack.marching_cubes as a drop-in for skimage.measure.marching_cubes: every keyword, every input."""
import numpy as np
import pytest

import isotrack

measure = pytest.importorskip("skimage.measure")
spatial = pytest.importorskip("scipy.spatial")

SPACING = (0.5, 1.0, 2.0)


def winding(verts, faces, normals):
    """The mean, over triangles, of the sign of its right-handed normal against its corners' normals:
    -1 when every triangle winds as scikit-image's 'descent', +1 for 'ascent'."""
    verts, normals = np.asarray(verts, np.float64), np.asarray(normals, np.float64)
    cross = np.cross(verts[faces[:, 1]] - verts[faces[:, 0]], verts[faces[:, 2]] - verts[faces[:, 0]])
    return np.mean(np.sign(np.einsum("ij,ij->i", cross, normals[faces].sum(axis=1))))


def assert_same_points(a, b, tolerance=1e-4):
    a, b = np.unique(np.asarray(a, np.float64), axis=0), np.unique(np.asarray(b, np.float64), axis=0)
    assert len(a) == len(b)
    for p, q in ((a, b), (b, a)):
        assert spatial.cKDTree(q).query(p)[0].max() < tolerance


def assert_same_as_skimage(volume, level, reference_volume=None, **keywords):
    """Same face count as scikit-image's Lorensen marching cubes with the same arguments, the same
    vertices (within 1e-4, as sets: the two may split a cell's polygon along other diagonals) and
    triangles wound the same way."""
    ours = isotrack.marching_cubes(volume, level, **keywords)
    reference = volume if reference_volume is None else reference_volume
    theirs = measure.marching_cubes(reference, level, method="lorensen", **keywords)
    assert len(ours[1]) == len(theirs[1]) > 50
    assert_same_points(ours[0], theirs[0])
    ours_winding, theirs_winding = winding(*ours[:3]), winding(*theirs[:3])
    assert abs(ours_winding) > 0.5 and np.sign(ours_winding) == np.sign(theirs_winding)
    assert ours[0].dtype == ours[2].dtype == ours[3].dtype == np.float32 and ours[3].shape == (len(ours[0]),)
    return ours


def noise(shape=(14, 15, 16), seed=0):
    return np.random.default_rng(seed).random(shape)


@pytest.mark.parametrize("step_size", [2, 3])
def test_step_size(step_size):
    assert_same_as_skimage(noise((17, 19, 20)), 0.5, spacing=SPACING, step_size=step_size)


def test_mask():
    volume = noise()
    mask = np.zeros(volume.shape, bool)
    mask[3:11, 2:, :9] = True
    mask |= np.random.default_rng(5).random(volume.shape) < 0.2
    ours = assert_same_as_skimage(volume, 0.5, mask=mask, spacing=SPACING)
    assert len(ours[1]) < len(isotrack.marching_cubes(volume, 0.5)[1])
    assert_same_as_skimage(volume, 0.5, mask=mask, step_size=2)


def test_allow_degenerate_false():
    # Samples two float32 steps above the level: their vertices round onto the sample in both
    # libraries, so triangles there collapse (a sample equal to the level would be classified
    # differently: isotrack counts it above, scikit-image below).
    rng = np.random.default_rng(1)
    volume = rng.choice([0.0, 1000.0], (12, 12, 12)).astype(np.float32)
    near = np.nextafter(np.nextafter(np.float32(500), np.float32(1e9)), np.float32(1e9))
    volume[rng.random(volume.shape) < 0.3] = near
    kept = isotrack.marching_cubes(volume, 500.0)
    ours = assert_same_as_skimage(volume, 500.0, allow_degenerate=False)
    assert len(ours[1]) < len(kept[1])  # there were degenerate triangles to remove
    corners = ours[0][ours[1]]
    assert not np.any(np.all(corners[:, 0] == corners[:, 1], axis=1) | np.all(corners[:, 1] == corners[:, 2], axis=1))


def test_gradient_direction_ascent_winds_the_other_way():
    volume = noise()
    ascent = assert_same_as_skimage(volume, 0.5, gradient_direction="ascent")
    descent = isotrack.marching_cubes(volume, 0.5)
    np.testing.assert_array_equal(ascent[1], descent[1][:, [0, 2, 1]])
    np.testing.assert_array_equal(ascent[2], descent[2])  # normals unchanged, as in scikit-image


@pytest.mark.parametrize(
    "dtype, values, level",
    [
        (np.bool_, (0, 1), 0.5),
        (np.uint8, (0, 255), 100.5),
        (np.int64, (-70000, 70000), 1000.5),
        (np.float16, (0, 1), 0.5),
        (np.float64, (0, 1), 0.5),
    ],
    ids=["bool", "uint8", "int64", "float16", "float64"],
)
def test_dtypes(dtype, values, level):
    rng = np.random.default_rng(2)
    smooth = rng.random((6, 7, 8)).repeat(2, axis=0).repeat(2, axis=1).repeat(2, axis=2)  # larger blobs
    volume = (values[0] + smooth * (values[1] - values[0])).astype(dtype) if dtype != np.bool_ else smooth > 0.5
    assert volume.dtype == dtype
    assert_same_as_skimage(volume, level, spacing=SPACING)


def test_int64_beyond_int32_is_read_exactly_as_float64():
    volume = (noise() * 2**40).astype(np.int64) + 2**45
    level = float(2**45 + 2**39) + 0.5
    ours = isotrack.marching_cubes(volume, level, threads=1)
    exact = isotrack.marching_cubes(volume.astype(np.float64), level, threads=1)
    np.testing.assert_array_equal(ours[0], exact[0])
    uint = isotrack.marching_cubes(volume.astype(np.uint64), level, threads=1)
    np.testing.assert_array_equal(uint[0], exact[0])


@pytest.mark.parametrize(
    "view",
    [
        lambda v: v[::2],
        lambda v: v[:, ::-1, 1::2],
        lambda v: np.asfortranarray(v),
        lambda v: v.astype(v.dtype.newbyteorder("S")),
    ],
    ids=["every_second_z", "reversed_and_strided", "fortran", "byte_swapped"],
)
def test_any_strides_and_byte_order(view):
    base = noise((24, 20, 22)).astype(np.float32)
    volume = view(base)
    assert_same_as_skimage(volume, 0.5, reference_volume=np.ascontiguousarray(volume, np.float32), spacing=SPACING)


def test_array_likes():
    class OnlyArray:
        """Exposes its samples through __array__ alone, as dask, xarray or zarr wrappers do."""

        def __init__(self, samples):
            self._samples = samples

        def __array__(self, dtype=None):
            return self._samples if dtype is None else self._samples.astype(dtype)

    samples = noise()
    assert_same_as_skimage(OnlyArray(samples), 0.5, reference_volume=samples, spacing=SPACING)
    assert_same_as_skimage(samples.tolist(), 0.5, reference_volume=samples)


def test_everything_at_once():
    volume = noise((20, 21, 22))
    mask = np.random.default_rng(9).random(volume.shape) < 0.7
    assert_same_as_skimage(
        volume[::-1], 0.45, reference_volume=np.ascontiguousarray(volume[::-1]), spacing=SPACING,
        gradient_direction="ascent", step_size=2, allow_degenerate=False, mask=mask,
    )


def test_level_outside_the_range_raises_as_skimage():
    volume = noise()
    for level in (-0.5, 1.5):
        with pytest.raises(ValueError, match="Surface level must be within volume data range.") as ours:
            isotrack.marching_cubes(volume, level)
        with pytest.raises(ValueError) as theirs:
            measure.marching_cubes(volume, level)
        assert str(ours.value).startswith(str(theirs.value))


def test_skimage_argument_errors():
    volume = noise()
    with pytest.raises(ValueError, match="^step_size must be at least one.$"):
        isotrack.marching_cubes(volume, 0.5, step_size=0)
    with pytest.raises(ValueError, match="^volume and mask must have the same shape."):
        isotrack.marching_cubes(volume, 0.5, mask=np.ones((3, 3, 3), bool))
    with pytest.raises(ValueError, match="gradient_direction: expected one of descent, ascent"):
        isotrack.marching_cubes(volume, 0.5, gradient_direction="up")
    with pytest.raises(ValueError, match="not with method='all'"):
        isotrack.marching_cubes(volume, 0.5, method="all", mask=np.ones(volume.shape, bool))


class Opaque:
    """An object with nothing numpy can use."""


BIG_LIST = np.zeros((120, 120, 120)).tolist()  # repr: 5.2 MB
BAD_CALLS = {
    "big list of wrong rank": lambda: isotrack.marching_cubes(BIG_LIST[0], 0.5),
    "big list, level outside": lambda: isotrack.marching_cubes(BIG_LIST, 0.5),
    "big list, unknown keyword": lambda: isotrack.marching_cubes(BIG_LIST, 0.5, stepsize=2),
    "big list, bad spacing": lambda: isotrack.marching_cubes(BIG_LIST, 0.0, spacing=BIG_LIST),
    "big list as level": lambda: isotrack.marching_cubes(np.zeros((4, 4, 4)), BIG_LIST),
    "big list as mask": lambda: isotrack.marching_cubes(np.zeros((4, 4, 4)), 0.0, mask=BIG_LIST),
    "big list as threads": lambda: isotrack.marching_cubes(np.zeros((4, 4, 4)), 0.0, threads=BIG_LIST),
    "big list as step_size": lambda: isotrack.marching_cubes(np.zeros((4, 4, 4)), 0.0, step_size=BIG_LIST),
    "long string method": lambda: isotrack.marching_cubes(np.zeros((4, 4, 4)), 0.0, method="x" * 100000),
    "long string level": lambda: isotrack.marching_cubes(np.zeros((4, 4, 4)), "9" * 100000 + "x"),
    "ragged list": lambda: isotrack.marching_cubes([[[1, 2], [3]], [[4]]], 0.5),
    "strings": lambda: isotrack.marching_cubes(np.full((4, 4, 4), "abc"), 0.5),
    "opaque object": lambda: isotrack.marching_cubes(Opaque(), 0.5),
    "huge threads": lambda: isotrack.marching_cubes(np.zeros((4, 4, 4)), 0.0, threads=10**30),
    "big list as seed": lambda: isotrack.track(np.zeros((4, 4, 4)), 0.0, seed=BIG_LIST),
    "huge seed_edge": lambda: isotrack.track(np.zeros((4, 4, 4)), 0.0, seed_edge=(0, 0, 10**20, 0)),
    "big list to track": lambda: isotrack.track(BIG_LIST, 0.5, seed=(1, 1, 1), table="none"),
    "big list to surfaces": lambda: isotrack.surfaces(BIG_LIST, float("nan")),
    "big list as path": lambda: isotrack.load(BIG_LIST),
    "big list to write_ply": lambda: isotrack.write_ply(BIG_LIST, "x.ply"),
}


@pytest.mark.parametrize("call", list(BAD_CALLS.values()), ids=list(BAD_CALLS))
def test_error_messages_are_short(call):
    with pytest.raises((TypeError, ValueError, RuntimeError, OSError)) as error:
        call()
    assert 0 < len(str(error.value)) < 300, str(error.value)[:1000]
