#!/usr/bin/env python3
"""isotrack.dask against in-memory isotrack.surfaces, on zarr volumes in 64^3 chunks.

For each volume: per-surface equality with the in-memory surfaces (counts,
triangles, areas within 1e-6 relative, closed flags), wall-clock seconds on Dask's
default threaded scheduler and on a LocalCluster of 1 and of 2 worker processes (one thread each; cluster start-up
not counted; best of --repeat), the bytes the workers sent each other (their
transfer logs) and the bytes of the tasks' results sent to the client. Then
track on one small ball in a sparse 512^3 volume: the chunks it read.

    PYTHONPATH=build/python ISOTRACK_CLI=build/app/isotrack /usr/bin/python3 bench/dask_surfaces.py
    (--repeat 3 --size 256 --ct assets/ct/cranium.nrrd)
"""
import argparse
import os
import pickle
import subprocess
import tempfile
import time
from collections.abc import MutableMapping

import numpy as np
import dask
import dask.array as da
import distributed
import zarr

import isotrack
import isotrack.dask as idask
from isotrack import _chunks, _isotrack


def field(spec, folder):
    path = os.path.join(folder, spec.replace(":", "_") + ".nrrd")
    cli = os.environ.get("ISOTRACK_CLI", "build/app/isotrack")
    subprocess.run([cli, "field", spec, "--out", path], check=True, capture_output=True)
    return np.array(isotrack.load(path).samples)


def result_bytes(array, level):
    """Bytes of the per-chunk results (pickled), as they travel to the client."""
    grid = _chunks.Grid(array.shape, array.chunks, (1, 1, 1), (0, 0, 0))
    task = dask.delayed(_chunks.surface_pieces)
    results = dask.compute(*[task(array[grid.slices(c)], c, grid, level, False) for c in grid.chunk_indices()])
    return sum(len(pickle.dumps(r, protocol=5)) for r in results), len(results)


def transferred(client):
    logs = client.run(lambda dask_worker: sum(t["total"] for t in dask_worker.transfer_incoming_log))
    client.run(lambda dask_worker: dask_worker.transfer_incoming_log.clear())
    return sum(logs.values())


def best(repeat, call):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        out = call()
        times.append(time.perf_counter() - start)
    return min(times), out


def check(table, reference):
    same = (
        len(table["id"]) == len(reference)
        and np.array_equal(table["triangles"], [s.triangle_count for s in reference])
        and np.allclose(table["area"], [s.area for s in reference], rtol=1e-6, atol=1e-9)
        and np.array_equal(table["closed"], [s.closed for s in reference])
    )
    return "yes" if same else "NO"


class CountingStore(MutableMapping):
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


def sparse_track(folder):
    path = os.path.join(folder, "sparse.zarr")
    z = zarr.open_array(path, mode="w", shape=(512,) * 3, chunks=(64,) * 3, dtype="f4", fill_value=10.0)
    box = (slice(80, 120), slice(80, 120), slice(108, 148))
    zz, yy, xx = np.mgrid[box]
    z[box] = np.sqrt((zz - 100.2) ** 2 + (yy - 99.7) ** 2 + (xx - 128.4) ** 2).astype(np.float32) - 12.0
    counting = CountingStore(zarr.DirectoryStore(path))
    array = da.from_zarr(zarr.open_array(counting, mode="r"))
    start = time.perf_counter()
    surface = idask.track(array, 0.0, seed=(100.0, 100.0, 116.5), scheduler="threads")
    seconds = time.perf_counter() - start
    return surface, len(counting.chunks_read), seconds


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--ct", default="assets/ct/cranium.nrrd")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        volumes = {f"gyroid:{args.size}": field(f"gyroid:{args.size}", folder)}
        volumes[f"noise:{args.size // 2}"] = field(f"noise:{args.size // 2}", folder)
        if os.path.isfile(args.ct):
            volumes["CT"] = np.array(isotrack.load(args.ct).samples)
        rows = {}
        for name, samples in volumes.items():
            level = 400.0 if name == "CT" else float(_isotrack.level(samples, None, False))
            path = os.path.join(folder, name.replace(":", "_") + ".zarr")
            zarr.save_array(path, samples, chunks=(64, 64, 64))
            memory, reference = best(args.repeat, lambda: isotrack.surfaces(samples, level, threads=1))
            row = {"volume": f"{name} {'x'.join(map(str, samples.shape[::-1]))} {samples.dtype}", "level": f"{level:g}"}
            row["surfaces"], row["in-memory s"] = len(reference), memory
            row["threads s"] = best(args.repeat, lambda: idask.surfaces(da.from_zarr(path), level, scheduler="threads"))[0]
            row["results MB"], row["tasks"] = result_bytes(da.from_zarr(path), level)
            row["results MB"] /= 1e6
            rows[name] = (row, samples, level, path, reference)
        for workers in (1, 2):
            with distributed.LocalCluster(
                n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=":0"
            ) as cluster, distributed.Client(cluster) as client:
                for row, samples, level, path, reference in rows.values():
                    array = da.from_zarr(path)
                    transferred(client)
                    seconds, table = best(args.repeat, lambda: idask.surfaces(array, level))
                    row[f"{workers} workers s"] = seconds
                    row[f"worker-to-worker MB ({workers})"] = transferred(client) / args.repeat / 1e6
                    row["equal"] = check(table, reference) if row.get("equal", "yes") == "yes" else "NO"
        rows = [r[0] for r in rows.values()]
        surface, read, seconds = sparse_track(folder)
    keys = ["volume", "level", "surfaces", "equal", "in-memory s", "threads s", "1 workers s", "2 workers s",
            "worker-to-worker MB (2)", "results MB", "tasks"]
    print("| " + " | ".join(keys) + " |")
    print("|" + "---|" * len(keys))
    for row in rows:
        print("| " + " | ".join(f"{row[k]:.3f}" if isinstance(row[k], float) else str(row[k]) for k in keys) + " |")
    print(
        f"\ntrack, one ball in a sparse 512^3 float32 zarr (64^3 chunks, 512 of them): {surface.triangle_count} "
        f"triangles, {len(surface.chunks)} chunk tasks in {surface.waves} waves, {read} of 512 chunks read "
        f"({100 * read / 512:.1f} %), {seconds:.3f} s"
    )


if __name__ == "__main__":
    main()
