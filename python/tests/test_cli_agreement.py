"""The module gives the same triangles and measures as the isotrack command line."""
import json

import numpy as np
import pytest

import isotrack
from conftest import read_ply


@pytest.fixture(scope="module")
def blobs(cli, tmp_path_factory):
    path = tmp_path_factory.mktemp("blobs") / "blobs.nrrd"
    cli("field", "blobs:32", "--out", path)
    return path


def extract_json(cli, *args):
    return json.loads(cli("extract", "--json", *args))


def raw(path):
    """A file's samples as a raw array, with spacing and origin in (z, y, x) (blobs lie axis-aligned)."""
    volume = isotrack.load(str(path))
    assert np.array_equal(volume.direction, np.eye(3))
    return volume.samples, volume.spacing[::-1], volume.origin[::-1]


def test_marching_cubes_matches_cli_vertex_for_vertex(cli, blobs, tmp_path):
    report = extract_json(cli, "--volume", blobs, "--iso", "0.5", "--threads", "1", "--out", tmp_path / "cli.ply")
    samples, spacing, origin = raw(blobs)
    verts, faces, normals, values = isotrack.marching_cubes(samples, 0.5, spacing=spacing, origin=origin, threads=1)
    assert report["triangles"] > 1000
    assert (len(faces), len(verts)) == (report["triangles"], report["vertices"])
    cli_positions, cli_faces = read_ply(tmp_path / "cli.ply")
    # One thread: the same vertices in the same order; the module's are (z, y, x).
    np.testing.assert_array_equal(verts[:, ::-1], cli_positions)
    np.testing.assert_array_equal(faces, cli_faces)


def test_surfaces_match_cli_method_all(cli, blobs):
    report = extract_json(cli, "--volume", blobs, "--iso", "0.5", "--method", "all")
    samples, spacing, origin = raw(blobs)
    surfaces = isotrack.surfaces(samples, 0.5, spacing=spacing, origin=origin)
    assert len(surfaces) == report["components"] > 1
    for surface, expected in zip(surfaces, report["surfaces"]):
        assert surface.triangle_count == expected["triangles"]
        assert surface.vertex_count == expected["vertices"]
        assert surface.closed == expected["closed"]
        assert surface.area == pytest.approx(expected["area"], rel=1e-9)
        lo, hi = expected["bounds"]
        assert surface.bounds[0] == pytest.approx(lo[::-1]) and surface.bounds[1] == pytest.approx(hi[::-1])
        if expected["enclosed_volume"] is None:
            assert surface.volume is None
        else:
            assert surface.volume == pytest.approx(expected["enclosed_volume"], rel=1e-9)


def test_track_matches_cli_method_track(cli, blobs):
    samples, spacing, origin = raw(blobs)
    largest = isotrack.surfaces(samples, 0.5, spacing=spacing, origin=origin)[0]
    seed_zyx = largest.vertices[0]
    x, y, z = (float(c) for c in seed_zyx[::-1])
    report = extract_json(cli, "--volume", blobs, "--iso", "0.5", "--method", "track", "--seed", f"{x!r},{y!r},{z!r}")
    surface = isotrack.track(samples, 0.5, seed=tuple(float(c) for c in seed_zyx), spacing=spacing, origin=origin)
    expected = report["surfaces"][0]
    assert surface.triangle_count == expected["triangles"] == largest.triangle_count
    assert surface.cells_visited == expected["cells_visited"]
    assert surface.area == pytest.approx(expected["area"], rel=1e-6)


def test_default_level_is_the_command_lines_on_the_ct(cli):
    """level=None takes the isovalue info suggests and extract opens at without --iso."""
    from conftest import SOURCE_DIR

    ct = SOURCE_DIR / "assets" / "ct" / "cranium.nrrd"
    if not ct.is_file():
        pytest.skip("the CT sample is missing (scripts/get_ct.sh makes it)")
    info = json.loads(cli("info", "--volume", ct, "--json"))
    report = extract_json(cli, "--volume", ct, "--method", "all")
    assert report["isovalue"] == info["suggested_isovalue"]
    volume = isotrack.load(str(ct))
    surfaces = isotrack.surfaces(volume)
    assert [s.triangle_count for s in surfaces] == [s["triangles"] for s in report["surfaces"]]
    # The middle of the range (scikit-image's default) gives another surface.
    middle = float(volume.samples.min() + volume.samples.max()) / 2
    assert sum(s.triangle_count for s in isotrack.surfaces(volume, middle)) != report["triangles"]
