"""Volumes carry their geometry: affines against nibabel, meshes against `isotrack extract --frame`."""
import json

import numpy as np
import pytest

import isotrack
from conftest import read_ply

nib = pytest.importorskip("nibabel")

LPS_FROM_RAS = np.diag([-1.0, -1.0, 1.0, 1.0])


def rotation(axis, degrees):
    """Rodrigues: the rotation by `degrees` about `axis`."""
    k = np.asarray(axis, np.float64) / np.linalg.norm(axis)
    cross = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    t = np.radians(degrees)
    return np.eye(3) + np.sin(t) * cross + (1 - np.cos(t)) * cross @ cross


def affine(linear, translation):
    out = np.eye(4)
    out[:3, :3], out[:3, 3] = linear, translation
    return out


# nibabel (RAS) affines: an axis-aligned RAS sform (the usual NIfTI), a flipped
# one (x runs to the right: a mirror in LPS), an oblique one, and one whose LPS
# direction is the identity with unit spacing.
AFFINES = {
    "axis_aligned": affine(np.diag([0.8, 1.2, 2.0]), [-10.0, 20.0, 5.0]),
    "flipped": affine(np.diag([-0.8, 1.2, 2.0]), [10.0, -20.0, 30.0]),
    "oblique": affine(rotation([1, 2, 3], 30) @ np.diag([0.8, 1.2, 2.0]), [3.0, -4.0, 5.0]),
    "lps_unit": affine(np.diag([-1.0, -1.0, 1.0]), [7.0, 8.0, -9.0]),
}
FRAMES = ["lps", "ras", "voxel"]
DIMS = (20, 17, 14)  # nx, ny, nz: nibabel's data shape
CENTRE = np.array([8.5, 9.0, 6.0])  # index (i, j, k) of the blob's centre, off the grid's middle
LEVEL = 1.0


def expected_affine(name, frame):
    """The index-to-frame affine, from nibabel's alone."""
    ras = AFFINES[name]
    return {"lps": LPS_FROM_RAS @ ras, "ras": ras, "voxel": np.eye(4)}[frame]


@pytest.fixture(scope="module")
def niftis(tmp_path_factory):
    """One NIfTI per affine: an ellipsoid blob (below LEVEL inside), float32, sform and qform set."""
    folder = tmp_path_factory.mktemp("nifti")
    i, j, k = np.meshgrid(*(np.arange(n, dtype=np.float64) for n in DIMS), indexing="ij")
    data = (((i - CENTRE[0]) / 6.0) ** 2 + ((j - CENTRE[1]) / 5.0) ** 2 + ((k - CENTRE[2]) / 4.0) ** 2).astype(
        np.float32
    )
    paths = {}
    for name, matrix in AFFINES.items():
        image = nib.Nifti1Image(data, matrix)
        image.set_sform(matrix, code=1)
        image.set_qform(matrix, code=1)
        paths[name] = folder / f"{name}.nii"
        nib.save(image, str(paths[name]))
    return paths


@pytest.mark.parametrize("frame", FRAMES)
@pytest.mark.parametrize("name", list(AFFINES))
def test_affine_matches_nibabel(niftis, name, frame):
    volume = isotrack.load(niftis[name], frame=frame)
    np.testing.assert_allclose(volume.affine, expected_affine(name, frame), atol=1e-6)
    np.testing.assert_allclose(volume.origin, volume.affine[:3, 3], atol=0)
    assert volume.frame == frame and volume.dims == DIMS and volume.shape == DIMS[::-1]
    np.testing.assert_allclose(volume.spacing, np.linalg.norm(AFFINES[name][:3, :3], axis=0), rtol=1e-6)
    if frame != "voxel":
        np.testing.assert_allclose(volume.direction @ np.diag(volume.spacing), volume.affine[:3, :3], atol=1e-6)
        np.testing.assert_allclose(volume.direction.T @ volume.direction, np.eye(3), atol=1e-6)


def test_samples_are_nibabels_without_a_copy(niftis):
    volume = isotrack.load(niftis["oblique"])
    reference = np.asarray(nib.load(str(niftis["oblique"])).dataobj)
    assert volume.dtype == reference.dtype == np.float32
    np.testing.assert_array_equal(volume.samples, reference.T)  # (z, y, x) is nibabel's (i, j, k) reversed
    assert volume.samples.base is not None and not volume.samples.flags.owndata
    assert volume.in_frame("ras").samples is volume.samples


@pytest.mark.parametrize("frame", FRAMES)
@pytest.mark.parametrize("name", list(AFFINES))
def test_marching_cubes_gives_the_command_lines_vertices(cli, niftis, tmp_path, name, frame):
    ply = tmp_path / "cli.ply"
    cli("extract", "--volume", niftis[name], "--iso", LEVEL, "--frame", frame, "--threads", 1, "--out", ply)
    cli_positions, cli_faces = read_ply(ply)
    volume = isotrack.load(niftis[name], frame=frame)
    verts, faces, normals, values = isotrack.marching_cubes(volume, LEVEL, threads=1)
    assert len(faces) > 500
    np.testing.assert_allclose(verts, cli_positions, atol=1e-4)  # both world (x, y, z)
    np.testing.assert_array_equal(faces, cli_faces)


@pytest.mark.parametrize("frame", FRAMES)
@pytest.mark.parametrize("name", list(AFFINES))
def test_vertices_are_nibabels_affine_applied_to_the_index(niftis, name, frame):
    volume = isotrack.load(niftis[name], frame=frame)
    world, faces, normals, _ = isotrack.marching_cubes(volume, LEVEL, threads=1)
    grid, grid_faces, _, _ = isotrack.marching_cubes(volume.samples, LEVEL, threads=1)  # raw: (z, y, x) indices
    np.testing.assert_array_equal(np.sort(faces, axis=1), np.sort(grid_faces, axis=1))
    index = np.c_[grid[:, ::-1].astype(np.float64), np.ones(len(grid))]
    np.testing.assert_allclose(world, (index @ expected_affine(name, frame).T)[:, :3], atol=1e-4)
    # Normals: unit, towards lower values (the blob's inside); faces wind counter-clockwise
    # seen from where the normals point, as in files, mirrored or not.
    centre = (expected_affine(name, frame) @ np.r_[CENTRE, 1.0])[:3]
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-5)
    assert np.all(np.einsum("ij,ij->i", normals, world - centre) < 0)
    cross = np.cross(world[faces[:, 1]] - world[faces[:, 0]], world[faces[:, 2]] - world[faces[:, 0]])
    assert np.all(np.einsum("ij,ij->i", cross, normals[faces].sum(axis=1)) > 0)


@pytest.mark.parametrize("frame", FRAMES)
def test_track_seeds_and_surfaces_in_the_frame(cli, niftis, frame):
    name = "oblique"
    volume = isotrack.load(niftis[name], frame=frame)
    (every,) = isotrack.surfaces(volume, LEVEL)
    report = json.loads(cli("extract", "--json", "--volume", niftis[name], "--iso", LEVEL, "--frame", frame,
                            "--method", "all"))
    lo, hi = report["surfaces"][0]["bounds"]
    np.testing.assert_allclose(every.bounds, (lo, hi), atol=1e-4)  # world (x, y, z)
    np.testing.assert_allclose(every.bounds[0], every.vertices.min(axis=0), atol=1e-5)
    seed = tuple(float(c) for c in every.vertices[7])  # a world point (x, y, z) in the frame
    tracked = isotrack.track(volume, LEVEL, seed=seed)
    track_report = json.loads(cli("extract", "--json", "--volume", niftis[name], "--iso", LEVEL, "--frame", frame,
                                  "--method", "track", "--seed", ",".join(map(repr, seed))))
    assert tracked.triangle_count == every.triangle_count == track_report["triangles"]
    assert tracked.area == pytest.approx(track_report["surfaces"][0]["area"], rel=1e-6)
    # seed_edge is in array indices (z, y, x, axis), whatever the frame: the edge along x through the blob.
    k, j = int(CENTRE[2]), int(CENTRE[1])
    crossing = int(np.argmax(volume.samples[k, j, int(CENTRE[0]):] >= LEVEL)) + int(CENTRE[0]) - 1
    by_edge = isotrack.track(volume, LEVEL, seed_edge=(k, j, crossing, 2))
    assert (by_edge.triangle_count, by_edge.area) == (tracked.triangle_count, tracked.area)


def test_volume_options(niftis):
    volume = isotrack.load(niftis["oblique"])
    with pytest.raises(ValueError, match="a Volume carries its own"):
        isotrack.marching_cubes(volume, LEVEL, spacing=(1, 1, 1))
    with pytest.raises(ValueError, match="frame: expected one of lps, ras, voxel"):
        isotrack.load(niftis["oblique"], frame="world")
    coarse = isotrack.marching_cubes(volume, LEVEL, step_size=2)[0]
    raw = isotrack.marching_cubes(volume.samples[::2, ::2, ::2], LEVEL)[0][:, ::-1].astype(np.float64) * 2
    np.testing.assert_allclose(coarse, (np.c_[raw, np.ones(len(raw))] @ volume.affine.T)[:, :3], atol=1e-4)
    assert "oblique.nii" in repr(volume) and "frame lps" in repr(volume)


def test_oblique_dicom_affine_matches_pydicom(cli, tmp_path):
    """An oblique DICOM series, written with pydicom: the LPS affine from its own attributes."""
    pydicom = pytest.importorskip("pydicom")
    import sys

    from conftest import SOURCE_DIR

    sys.path.insert(0, str(SOURCE_DIR / "scripts"))
    try:
        import ct_to_dicom
    finally:
        sys.path.pop(0)
    turn = rotation([2, -1, 1], 25)
    row, column, normal = turn[:, 0], turn[:, 1], turn[:, 2]
    spacing, origin = (0.75, 0.875, 1.25), np.array([-30.5, 12.25, 40.0])  # exact in binary: short DS values
    k, j, i = np.meshgrid(*(np.arange(n) for n in (10, 12, 14)), indexing="ij")
    samples = (100 * (((i - 6.5) / 5) ** 2 + ((j - 5.5) / 4) ** 2 + ((k - 4.5) / 3) ** 2)).astype(np.int16)
    study = pydicom.uid.generate_uid()
    for index, ds in enumerate(ct_to_dicom.series(samples, [repr(s) for s in spacing], study, 1, "oblique")):
        ds.ImageOrientationPatient = [f"{v:.8f}" for v in np.r_[row, column]]
        ds.ImagePositionPatient = [f"{v:.6f}" for v in origin + index * spacing[2] * normal]
        pydicom.dcmwrite(str(tmp_path / f"slice_{index:03d}.dcm"), ds, write_like_original=False)
    # The affine from the files' own attributes, as DICOM defines it (LPS).
    first, second = (pydicom.dcmread(str(tmp_path / f"slice_{n:03d}.dcm")) for n in (0, 1))
    cosines = np.array(first.ImageOrientationPatient, np.float64)
    expected = np.eye(4)
    expected[:3, 0] = cosines[:3] * float(first.PixelSpacing[1])
    expected[:3, 1] = cosines[3:] * float(first.PixelSpacing[0])
    expected[:3, 2] = np.array(second.ImagePositionPatient, np.float64) - np.array(first.ImagePositionPatient, np.float64)
    expected[:3, 3] = np.array(first.ImagePositionPatient, np.float64)
    volume = isotrack.load(tmp_path)
    np.testing.assert_allclose(volume.affine, expected, atol=1e-5)
    np.testing.assert_array_equal(volume.samples, samples)
    np.testing.assert_allclose(isotrack.load(tmp_path, frame="ras").affine, np.diag([-1, -1, 1, 1]) @ expected, atol=1e-5)
    cli("extract", "--volume", tmp_path, "--iso", 100.5, "--threads", 1, "--out", tmp_path / "cli.ply")
    verts, faces, _, _ = isotrack.marching_cubes(volume, 100.5, threads=1)
    positions, cli_faces = read_ply(tmp_path / "cli.ply")
    np.testing.assert_allclose(verts, positions, atol=1e-4)
    np.testing.assert_array_equal(faces, cli_faces)
