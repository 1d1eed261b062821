"""isotrack.dask against the in-memory functions: zarr volumes in 64^3 chunks, on Dask clusters.

The references are isotrack.surfaces, isotrack.track and isotrack.marching_cubes
on the whole array in memory: chunk by chunk, joined by their shared crossed
edges, the surfaces must be the same ones.
"""
import os
import pathlib
import subprocess
import sys
from collections.abc import MutableMapping

import numpy as np
import pytest

from conftest import SOURCE_DIR, read_ply

da = pytest.importorskip("dask.array")
zarr = pytest.importorskip("zarr")
distributed = pytest.importorskip("distributed")
pytest.importorskip("scipy")

import isotrack  # noqa: E402
import isotrack.dask as idask  # noqa: E402
from isotrack import _isotrack  # noqa: E402

CT = SOURCE_DIR / "assets" / "ct" / "cranium.nrrd"
CHUNKS = (64, 64, 64)


@pytest.fixture(scope="module")
def client():
    """Two in-process workers, one thread each: Dask's distributed scheduler without process start-up."""
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=":0")
    with distributed.Client(cluster) as c:
        yield c
    cluster.close()


@pytest.fixture(scope="module")
def volumes(tmp_path_factory, cli):
    """name -> (in-memory samples, level, zarr path): the fields by the CLI, written in 64^3 chunks."""
    folder = tmp_path_factory.mktemp("zarr")
    made = {}
    for spec in ("noise:128", "gyroid:128", "gyroid:256"):
        nrrd = folder / (spec.replace(":", "_") + ".nrrd")
        cli("field", spec, "--out", nrrd)
        made[spec] = np.array(isotrack.load(str(nrrd)).samples)
    made["gyroid file"] = str(folder / "gyroid_128.nrrd")
    if CT.is_file():
        made["ct"] = np.array(isotrack.load(str(CT)).samples)
    out = {"gyroid file": made.pop("gyroid file")}
    for name, samples in made.items():
        path = folder / (name.replace(":", "_") + ".zarr")
        zarr.save_array(str(path), samples, chunks=CHUNKS)
        level = 400.0 if name == "ct" else _isotrack.level(samples, None, False)
        out[name] = (samples, level, str(path))
    return out


def assert_same_surfaces(table, reference):
    assert len(table["id"]) == len(reference)
    ref_triangles = np.array([s.triangle_count for s in reference])
    np.testing.assert_array_equal(table["triangles"], ref_triangles)
    # Sorted alike, ties by the first grid edge: row by row the same surfaces.
    np.testing.assert_allclose(table["area"], [s.area for s in reference], rtol=1e-6, atol=1e-9)
    np.testing.assert_array_equal(table["closed"], [s.closed for s in reference])
    np.testing.assert_array_equal(table["vertices"], [s.vertex_count for s in reference])
    np.testing.assert_allclose(table["bounds"], [s.bounds for s in reference], atol=1e-4)
    np.testing.assert_array_equal(table["touches_border"], [s.touches_border for s in reference])


def same_triangles(va, fa, vb, fb, decimals=5):
    """Whether two meshes hold the same triangles (corner positions rounded), in any order (numpy, for big meshes)."""
    pa, pb = (np.round(np.asarray(v, dtype=np.float64), decimals) for v in (va, vb))
    _, rank = np.unique(np.concatenate([pa, pb]), axis=0, return_inverse=True)
    rank = rank.ravel()

    def rows(ranks, faces):
        t = np.sort(ranks[np.asarray(faces, dtype=np.int64)], axis=1)
        return t[np.lexsort(t.T[::-1])]

    a, b = rows(rank[: len(pa)], fa), rows(rank[len(pa) :], fb)
    return a.shape == b.shape and bool(np.array_equal(a, b))


def enclosed_volume(surface):
    """A closed surface's enclosed volume from its mesh, in float64 about its first vertex."""
    v = np.asarray(surface.vertices, dtype=np.float64)
    v = v - v[0]
    f = np.asarray(surface.faces, dtype=np.int64)
    return abs(np.einsum("ij,ij->i", v[f[:, 0]], np.cross(v[f[:, 1]], v[f[:, 2]])).sum() / 6.0)


@pytest.mark.parametrize("name", ["noise:128", "gyroid:128", "gyroid:256", "ct"])
def test_surfaces_equal_in_memory(name, volumes, client):
    if name not in volumes:
        pytest.skip(f"{CT} missing: run scripts/get_ct.sh")
    samples, level, path = volumes[name]
    array = da.from_zarr(path)
    assert array.chunks[0][0] == 64
    table = idask.surfaces(array, level)
    reference = isotrack.surfaces(samples, level, threads=1)
    assert len(reference) > 0
    assert_same_surfaces(table, reference)
    closed = np.flatnonzero(table["closed"])[:50]
    expected = [enclosed_volume(reference[k]) for k in closed]
    np.testing.assert_allclose(table["volume"][closed], expected, rtol=1e-6, atol=1e-9)
    assert np.all(np.isnan(table["volume"][~table["closed"]]))
    verts, faces, normals, values = idask.marching_cubes(array, level)
    mc_verts, mc_faces, _, _ = isotrack.marching_cubes(samples, level)
    assert len(faces) == table["triangles"].sum() == len(mc_faces)
    assert len(verts) == len(mc_verts) == table["vertices"].sum()
    if name == "gyroid:128":
        assert same_triangles(verts, faces, mc_verts, mc_faces)
        np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-5)
        assert values.min() >= level


def test_spacing_origin_and_ply_folders(volumes, client, tmp_path):
    samples, level, path = volumes["gyroid:128"]
    spacing, origin = (0.5, 1.25, 2.0), (10.0, -3.0, 7.5)
    array = da.from_zarr(path)
    table = idask.surfaces(array, level, spacing=spacing, origin=origin, out=tmp_path)
    reference = isotrack.surfaces(samples, level, spacing=spacing, origin=origin, threads=1)
    assert_same_surfaces(table, reference)
    for k, surface in enumerate(reference):
        positions, faces = read_ply(tmp_path / f"surface_{k:04d}.ply")
        assert len(faces) == surface.triangle_count and len(positions) == surface.vertex_count
        assert same_triangles(positions[:, ::-1], faces, surface.vertices, surface.faces, 3)


class CountingStore(MutableMapping):
    """A zarr store that remembers which chunk keys were read."""

    def __init__(self, inner):
        self.inner, self.chunks_read = inner, set()

    def __getitem__(self, key):
        if not key.split("/")[-1].startswith("."):
            self.chunks_read.add(key)
        return self.inner[key]

    def __setitem__(self, key, value):
        self.inner[key] = value

    def __delitem__(self, key):
        del self.inner[key]

    def __iter__(self):
        return iter(self.inner)

    def __len__(self):
        return len(self.inner)


@pytest.mark.filterwarnings("ignore:Running on a single-machine scheduler")
def test_track_reads_only_the_chunks_it_crosses(tmp_path):
    # A ball of radius 12 across the face between two chunks of a 512^3 volume
    # (8^3 = 512 chunks; only the two chunks it lies in are ever written).
    store = zarr.DirectoryStore(str(tmp_path / "sparse.zarr"))
    z = zarr.open_array(store, mode="w", shape=(512, 512, 512), chunks=CHUNKS, dtype="f4", fill_value=10.0)
    box = (slice(80, 120), slice(80, 120), slice(108, 148))
    zz, yy, xx = np.mgrid[box]
    z[box] = np.sqrt((zz - 100.2) ** 2 + (yy - 99.7) ** 2 + (xx - 128.4) ** 2).astype(np.float32) - 12.0
    counting = CountingStore(zarr.DirectoryStore(str(tmp_path / "sparse.zarr")))
    array = da.from_zarr(zarr.open_array(counting, mode="r"))
    surface = idask.track(array, 0.0, seed=(100.0, 100.0, 116.5), scheduler="threads")
    assert len(counting.chunks_read) <= 0.05 * 512
    assert sorted(surface.chunks) == [(1, 1, 1), (1, 1, 2)] and surface.waves == 2
    # The reference: in-memory track on a box of samples holding the ball, placed where it lies.
    lo = (64, 64, 64)
    samples = np.asarray(z[64:129, 64:129, 64:193])
    reference = isotrack.track(samples, 0.0, seed=(100.0, 100.0, 116.5), origin=lo, threads=1)
    assert reference.closed and surface.closed
    assert surface.triangle_count == reference.triangle_count and surface.vertex_count == reference.vertex_count
    assert same_triangles(surface.vertices, surface.faces, reference.vertices, reference.faces)
    assert surface.area == pytest.approx(reference.area, rel=1e-6)
    assert surface.volume == pytest.approx(enclosed_volume(reference), rel=1e-6)


def test_track_equals_in_memory_track(volumes, client):
    samples, level, path = volumes["gyroid:128"]
    array = da.from_zarr(path)
    for seed in [(64.0, 64.0, 64.0), (3.2, 100.0, 17.0)]:
        surface = idask.track(array, level, seed=seed)
        reference = isotrack.track(samples, level, seed=seed, threads=1)
        assert surface.triangle_count == reference.triangle_count
        assert surface.vertex_count == reference.vertex_count
        assert same_triangles(surface.vertices, surface.faces, reference.vertices, reference.faces)
        assert surface.area == pytest.approx(reference.area, rel=1e-6)
        assert surface.closed == reference.closed and len(surface.chunks) == 8
    # A seed edge, taken from the reference's own vertices (z, y, x, axis).
    edge = tuple(int(v) for v in isotrack.surfaces(samples, level, threads=1)[-1].vertex_edges[0])
    by_edge = idask.track(array, level, seed_edge=edge)
    assert by_edge.triangle_count == isotrack.track(samples, level, seed_edge=edge, threads=1).triangle_count


PROCESS_SCRIPT = """
import sys, numpy as np, dask.array as da, distributed, isotrack, isotrack.dask as idask
path, nrrd, level = sys.argv[1], sys.argv[2], float(sys.argv[3])
if __name__ == "__main__":
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster, \\
            distributed.Client(cluster) as client:
        table = idask.surfaces(da.from_zarr(path), level)
        from_file = idask.surfaces(idask.from_file(nrrd, chunks=64), level)
        assert np.array_equal(table["triangles"], from_file["triangles"])
        assert np.array_equal(table["area"], from_file["area"])
        pids = set(client.run(lambda: __import__("os").getpid()).values())
        print(len(pids), " ".join(map(str, table["triangles"])), " ".join(map(repr, table["area"])), sep=" | ")
"""


def test_worker_processes(volumes, tmp_path):
    """Real worker processes (spawned, so the script has its __main__ guard), from zarr and from a NRRD file."""
    samples, level, path = volumes["gyroid:128"]
    script = tmp_path / "on_processes.py"
    script.write_text(PROCESS_SCRIPT)
    run = subprocess.run([sys.executable, str(script), path, volumes["gyroid file"], repr(level)], capture_output=True, text=True, timeout=120,
                         env=dict(os.environ))
    assert run.returncode == 0, run.stderr[-2000:]
    workers, triangles, areas = run.stdout.strip().splitlines()[-1].split(" | ")
    reference = isotrack.surfaces(samples, level, threads=1)
    assert int(workers) == 2
    assert [int(t) for t in triangles.split()] == [s.triangle_count for s in reference]
    np.testing.assert_allclose([float(a) for a in areas.split()], [s.area for s in reference], rtol=1e-6)


def test_import_without_dask():
    code = (
        "import sys; sys.modules['dask'] = None\n"
        "import isotrack, numpy as np\n"
        "assert len(isotrack.surfaces(np.random.rand(8, 8, 8), 0.5)) >= 1\n"
        "try:\n    import isotrack.dask\nexcept ImportError:\n    print('refused')\n"
    )
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=dict(os.environ))
    assert run.returncode == 0, run.stderr
    assert run.stdout.strip() == "refused"


def test_bad_arguments(volumes):
    array = da.zeros((8, 8, 8), chunks=4)
    with pytest.raises(ValueError, match="level"):
        idask.surfaces(array, None)
    with pytest.raises(ValueError, match="exactly one"):
        idask.track(array, 0.5)
    with pytest.raises(ValueError, match="not crossed|no grid edge"):
        idask.track(array, 0.5, seed=(1.0, 1.0, 1.0))
    with pytest.raises(ValueError, match=r"seed_edge \(1, 2, 3, 0\) is not crossed"):
        idask.track(array, 0.5, seed_edge=(1, 2, 3, 0))
    with pytest.raises(ValueError, match="outside"):
        idask.track(array, 0.5, seed_edge=(7, 2, 3, 0))
    with pytest.raises(ValueError, match="3D"):
        idask.surfaces(da.zeros((8, 8), chunks=4), 0.5)
    assert len(idask.surfaces(array, 0.5)["id"]) == 0


@pytest.mark.parametrize(
    "shape, chunks",
    [((65, 65, 65), 64), ((40, 33, 50), ((10, 1, 29), (32, 1), (1, 24, 25))), ((30, 30, 30), 7)],
    ids=["last-chunk-one-sample", "chunks-of-one-sample", "many-small-chunks"],
)
@pytest.mark.filterwarnings("ignore:Running on a single-machine scheduler")
def test_irregular_chunks(shape, chunks):
    """Chunks of one sample (in the middle: one layer of cells; at the end: no cells) and many small ones."""
    from scipy.ndimage import gaussian_filter

    samples = gaussian_filter(np.random.default_rng(1).random(shape), 2).astype(np.float32)
    level = float(np.median(samples))
    array = da.from_array(samples, chunks=chunks)
    assert_same_surfaces(idask.surfaces(array, level, scheduler="sync"), isotrack.surfaces(samples, level, threads=1))
    surface = idask.track(array, level, seed=(5.3, 6.1, 7.7), scheduler="sync")
    reference = isotrack.track(samples, level, seed=(5.3, 6.1, 7.7), threads=1)
    assert same_triangles(surface.vertices, surface.faces, reference.vertices, reference.faces)
    assert surface.vertex_count == reference.vertex_count


def test_module_command_line(volumes, tmp_path):
    """python3 -m isotrack.dask: every surface into a folder of PLY files, and one tracked surface."""
    samples, level, path = volumes["gyroid:128"]
    reference = isotrack.surfaces(samples, level, threads=1)
    command = [sys.executable, "-m", "isotrack.dask", "--volume", path, f"--iso={level!r}"]  # = for a negative level
    run = subprocess.run(command + ["--out", str(tmp_path / "all")], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert run.stdout.startswith(f"{len(reference)} surfaces, {sum(s.triangle_count for s in reference)} triangles")
    for k, surface in enumerate(reference):
        assert len(read_ply(tmp_path / "all" / f"surface_{k:04d}.ply")[1]) == surface.triangle_count
    seed = ["--method", "track", "--seed", "64,64,64", "--out", str(tmp_path / "one.ply")]
    run = subprocess.run(command + seed, capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    tracked = isotrack.track(samples, level, seed=(64, 64, 64), threads=1)
    positions, faces = read_ply(tmp_path / "one.ply")
    assert same_triangles(positions[:, ::-1], faces, tracked.vertices, tracked.faces)


def test_extract_scheduler_hands_over_to_dask(volumes, tmp_path):
    """isotrack extract --scheduler (or a .zarr volume) runs the module: the same surfaces."""
    from conftest import cli_path

    samples, level, _ = volumes["gyroid:128"]
    reference = isotrack.surfaces(samples, level, threads=1)
    zarr = pytest.importorskip("zarr")
    store = tmp_path / "gyroid.zarr"
    zarr.save_array(str(store), samples, chunks=(64, 64, 64))
    command = [cli_path(), "extract", "--volume", str(store), f"--iso={level!r}", "--method", "all"]
    expected = f"{len(reference)} surfaces, {sum(s.triangle_count for s in reference)} triangles"
    for extra in ([], ["--scheduler", "local:2"]):
        run = subprocess.run(command + extra, capture_output=True, text=True)
        assert run.returncode == 0, run.stderr
        assert run.stdout.startswith(expected)
    # What Dask does not do is refused at once, in one line.
    run = subprocess.run(command + ["--json"], capture_output=True, text=True)
    assert run.returncode == 1
    assert run.stderr.strip().splitlines() == ["isotrack: --scheduler (Dask): --json is not supported there (docs/distributed.md)"]
