"""Extraction over numpy arrays: axis order, measures, sample types, threads, files."""
import gc
import json
import math
import weakref

import numpy as np
import pytest

import isotrack
from conftest import ellipsoid, read_ply, triangle_set

DTYPES = [np.uint8, np.int8, np.uint16, np.int16, np.uint32, np.int32, np.float32, np.float64]


def two_balls():
    """A large and a small ball, apart, as float32 (z, y, x): inside is below 1."""
    z, y, x = np.meshgrid(*(np.linspace(0, 1, 40),) * 3, indexing="ij")
    big = ((z - 0.35) ** 2 + (y - 0.5) ** 2 + (x - 0.35) ** 2) / 0.25**2
    small = ((z - 0.8) ** 2 + (y - 0.5) ** 2 + (x - 0.8) ** 2) / 0.1**2
    return np.minimum(big, small).astype(np.float32)


def test_axis_order_spacing_and_origin_are_zyx():
    # Radii 0.5, 0.7, 0.9 along z, y, x; samples 2/19, 2/23, 2/27 apart, scaled by spacing.
    volume = ellipsoid()
    spacing, origin = (2.0, 3.0, 5.0), (10.0, 20.0, 30.0)
    surface = isotrack.track(volume, 1.0, seed_edge=(10, 12, 1, 2), spacing=spacing, origin=origin)
    lo, hi = np.array(surface.bounds)
    centre = np.array(origin) + np.array(spacing) * (np.array(volume.shape) - 1) / 2
    half_extent = np.array((0.5, 0.7, 0.9)) * np.array(spacing) * (np.array(volume.shape) - 1) / 2
    np.testing.assert_allclose((lo + hi) / 2, centre, atol=1e-4)
    np.testing.assert_allclose((hi - lo) / 2, half_extent, rtol=0.03)
    np.testing.assert_allclose(surface.vertices.min(axis=0), lo, atol=1e-4)
    np.testing.assert_allclose(surface.vertices.max(axis=0), hi, atol=1e-4)


def test_closed_ellipsoid_measures():
    n = 48
    volume = ellipsoid((n, n, n), radii=(0.8, 0.8, 0.8), dtype=np.float64)
    spacing = (2 / (n - 1),) * 3
    (surface,) = isotrack.surfaces(volume, 1.0, spacing=spacing, origin=(-1, -1, -1))
    assert surface.closed and not surface.touches_border
    assert surface.area == pytest.approx(4 * math.pi * 0.8**2, rel=0.01)
    assert surface.volume == pytest.approx(4 / 3 * math.pi * 0.8**3, rel=0.01)
    radii = np.linalg.norm(surface.vertices, axis=1)
    np.testing.assert_allclose(radii, 0.8, atol=0.01)
    # Euler characteristic of a sphere.
    edges = {tuple(sorted(e)) for f in surface.faces.tolist() for e in ((f[0], f[1]), (f[1], f[2]), (f[2], f[0]))}
    assert surface.vertex_count - len(edges) + surface.triangle_count == 2


def test_normals_point_to_lower_values_and_faces_wind_as_skimage():
    verts, faces, normals, values = isotrack.marching_cubes(ellipsoid(), 1.0)
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-5)
    centre = (np.array(ellipsoid().shape) - 1) / 2
    assert np.all(np.einsum("ij,ij->i", normals, verts - centre) < 0)  # inside is lower
    # In (z, y, x) a face's right-handed normal points away from the vertex normals (skimage's winding).
    cross = np.cross(verts[faces[:, 1]] - verts[faces[:, 0]], verts[faces[:, 2]] - verts[faces[:, 0]])
    assert np.all(np.einsum("ij,ij->i", cross, normals[faces].sum(axis=1)) < 0)
    assert values.shape == (len(verts),) and np.all(values >= 1.0)


def test_every_sample_type_gives_the_same_mesh():
    ramp = np.round(ellipsoid() * 40).clip(0, 100)
    reference = None
    for dtype in DTYPES:
        verts, faces, _, _ = isotrack.marching_cubes(ramp.astype(dtype), 40.5, threads=1)
        assert len(faces) > 500
        if reference is None:
            reference = (verts, faces)
        np.testing.assert_array_equal(verts, reference[0], err_msg=str(dtype))
        np.testing.assert_array_equal(faces, reference[1], err_msg=str(dtype))


def test_threads_give_the_same_triangles():
    volume = np.random.default_rng(7).random((30, 31, 32), dtype=np.float32)
    one = isotrack.marching_cubes(volume, 0.5, threads=1)
    two = isotrack.marching_cubes(volume, 0.5, threads=2)
    assert triangle_set(one[0], one[1]) == triangle_set(two[0], two[1])
    tracked = isotrack.track(ellipsoid(), 1.0, seed=(9.5, 11.5, 0.0), threads=2)
    assert tracked.triangle_count == isotrack.surfaces(ellipsoid(), 1.0)[0].triangle_count


def test_surfaces_partition_marching_cubes_largest_first():
    volume = two_balls()
    surfaces = isotrack.surfaces(volume, 1.0)
    assert [s.closed for s in surfaces] == [True, True]
    assert surfaces[0].triangle_count > surfaces[1].triangle_count
    verts, faces, _, _ = isotrack.marching_cubes(volume, 1.0)
    union = set().union(*(triangle_set(s.vertices, s.faces) for s in surfaces))
    assert union == triangle_set(verts, faces)
    listed = isotrack.marching_cubes(volume, 1.0, method="all")
    assert [s.triangle_count for s in listed] == [s.triangle_count for s in surfaces]


def test_track_seed_picks_the_surface_nearest_to_it():
    volume = two_balls()
    small = isotrack.track(volume, 1.0, seed=(0.8 * 39, 0.5 * 39, 0.9 * 39))
    big = isotrack.track(volume, 1.0, seed=(0.35 * 39, 0.5 * 39, 0.1 * 39))
    assert small.triangle_count < big.triangle_count
    assert small.cells_visited < volume.size / 4  # touches only the cells near it


def test_input_is_used_in_place_and_read_only_arrays_work():
    volume = ellipsoid()
    frozen = np.frombuffer(volume.tobytes(), dtype=volume.dtype).reshape(volume.shape)
    assert not frozen.flags.writeable
    a = isotrack.marching_cubes(frozen, 1.0, threads=1)
    b = isotrack.marching_cubes(volume, 1.0, threads=1)
    np.testing.assert_array_equal(a[0], b[0])


def test_surface_arrays_keep_the_surface_alive():
    surface = isotrack.track(ellipsoid(), 1.0, seed=(9.5, 11.5, 0.0))
    alive = weakref.ref(surface)
    vertices, faces, normals = surface.vertices, surface.faces, surface.normals
    expected = vertices.copy(), faces.copy(), normals.copy()
    del surface
    gc.collect()
    assert alive() is not None  # held by the arrays' base
    isotrack.marching_cubes(np.random.default_rng(1).random((40, 40, 40), dtype=np.float32), 0.5)  # reuse freed memory
    np.testing.assert_array_equal(vertices, expected[0])
    np.testing.assert_array_equal(faces, expected[1])
    np.testing.assert_array_equal(normals, expected[2])
    del vertices, faces, normals
    gc.collect()
    assert alive() is None  # and freed once they are gone


def test_marching_cubes_arrays_share_one_owner():
    verts, faces, normals, values = isotrack.marching_cubes(ellipsoid(), 1.0)
    # Views into the interleaved {position, normal} buffer, (x, y, z) read backwards: no copy.
    assert verts.strides == normals.strides == (24, -4)
    assert verts.base is normals.base is faces.base is not None
    expected = verts.copy(), faces.copy()
    del normals, values
    gc.collect()
    isotrack.marching_cubes(np.random.default_rng(2).random((40, 40, 40), dtype=np.float32), 0.5)
    np.testing.assert_array_equal(verts, expected[0])
    np.testing.assert_array_equal(faces, expected[1])


def test_level_outside_the_data_and_no_surface():
    # As scikit-image: a level outside the data is a ValueError, a level with no surface a RuntimeError.
    with pytest.raises(ValueError, match=r"^Surface level must be within volume data range\."):
        isotrack.marching_cubes(np.zeros((4, 4, 4), np.float32), 1.0)
    with pytest.raises(RuntimeError, match=r"^No surface found at the given iso value\.$"):
        isotrack.marching_cubes(np.zeros((4, 4, 4), np.float32), 0.0)
    assert isotrack.surfaces(np.zeros((4, 4, 4), np.uint8), 1) == []
    assert isotrack.marching_cubes(np.zeros((4, 4, 4), np.uint8), 0, method="all") == []


def test_level_none_is_the_command_lines_default(cli, tmp_path):
    cli("field", "blobs:32", "--out", tmp_path / "blobs.nrrd")
    report = json.loads(cli("extract", "--json", "--volume", tmp_path / "blobs.nrrd"))
    samples = isotrack.load(str(tmp_path / "blobs.nrrd")).samples
    default = isotrack.marching_cubes(samples, None, threads=1)
    chosen = isotrack.marching_cubes(samples, report["isovalue"], threads=1)
    assert len(default[1]) == report["triangles"]
    np.testing.assert_array_equal(default[0], chosen[0])
    assert isotrack.surfaces(samples)[0].triangle_count == isotrack.surfaces(samples, report["isovalue"])[0].triangle_count


def test_write_files(tmp_path):
    surface = isotrack.track(ellipsoid(), 1.0, seed=(9.5, 11.5, 0.0), spacing=(1, 2, 3), threads=1)
    isotrack.write_ply(surface, str(tmp_path / "s.ply"))
    positions, faces = read_ply(tmp_path / "s.ply")
    np.testing.assert_array_equal(positions, surface.vertices[:, ::-1])  # files are (x, y, z)
    np.testing.assert_array_equal(faces, surface.faces)
    isotrack.write_obj(surface, str(tmp_path / "s.obj"))
    obj = (tmp_path / "s.obj").read_text().splitlines()
    assert sum(line.startswith("f ") for line in obj) == surface.triangle_count
    isotrack.write_stl(surface, str(tmp_path / "s.stl"))
    assert (tmp_path / "s.stl").stat().st_size == 84 + 50 * surface.triangle_count


def test_load_keeps_samples_spacing_and_origin(cli, tmp_path):
    cli("field", "sphere:24", "--out", tmp_path / "sphere.nrrd")
    volume = isotrack.load(tmp_path / "sphere.nrrd")
    samples = volume.samples
    assert samples.shape == (24, 24, 24) and samples.flags.c_contiguous and volume.dims == (24, 24, 24)
    assert len(volume.spacing) == 3 and len(volume.origin) == 3 and volume.frame == "lps"
    info = isotrack.surfaces(samples, float(np.median(samples)), spacing=volume.spacing[::-1], origin=volume.origin[::-1])
    assert info and info[0].triangle_count > 100
    assert isotrack.surfaces(volume, float(np.median(samples)))[0].triangle_count == info[0].triangle_count


def test_load_ct_geometry_when_present():
    from conftest import SOURCE_DIR

    path = SOURCE_DIR / "assets" / "ct" / "cranium.nrrd"
    if not path.exists():
        pytest.skip("no CT sample (scripts/get_ct.sh makes it)")
    volume = isotrack.load(str(path))
    assert volume.shape == (108, 256, 256) and volume.dtype == np.int16
    assert volume.spacing == pytest.approx((0.957, 0.957, 1.5), abs=1e-3)
