"""Every surface of a volume no process ever holds whole: a lazily generated N^3
float32 dask array (default 1024: 4 GiB; each 128^3 block computed by the task
that needs it, from its coordinates) through isotrack.dask.surfaces on a
LocalCluster of worker processes. Prints the surfaces, the time and each
worker's peak resident memory, and checks each surface against the same ball
extracted in this process from a box around it.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/dask_never_whole.py [N] [WORKERS]
"""
import resource
import sys
import time

import dask.array as da
import numpy as np
from dask.distributed import Client, LocalCluster

import isotrack
import isotrack.dask

N = int(sys.argv[1]) if len(sys.argv) > 1 else 1024
WORKERS = int(sys.argv[2]) if len(sys.argv) > 2 else 2
CHUNK = 128


RADIUS = N / 10
CENTRES = [((i + 0.5) * N / 3 + 0.3, (j + 0.5) * N / 2 + 0.2, (k + 0.5) * N / 2 + 0.1)
           for i in range(3) for j in range(2) for k in range(2)]  # x, y, z: twelve balls, apart


def blobs(location):
    """The twelve balls (positive inside) on the samples [lo, hi) of `location`, (z, y, x)."""
    (z0, z1), (y0, y1), (x0, x1) = location
    z, y, x = np.meshgrid(np.arange(z0, z1), np.arange(y0, y1), np.arange(x0, x1), indexing="ij", sparse=True)
    field = np.full((z1 - z0, y1 - y0, x1 - x0), -RADIUS, np.float32)
    for cx, cy, cz in CENTRES:
        field = np.maximum(field, (RADIUS - np.sqrt((x - cx) ** 2 + (y - cy) ** 2 + (z - cz) ** 2)).astype(np.float32))
    return field


def peak_rss_mib():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024


def main():
    array = da.zeros((N, N, N), chunks=CHUNK, dtype=np.float32).map_blocks(
        lambda _, block_info=None: blobs(block_info[None]["array-location"]), dtype=np.float32)
    with LocalCluster(n_workers=WORKERS, threads_per_worker=1, processes=True, memory_limit="4GiB") as cluster, \
            Client(cluster) as client:
        start = time.perf_counter()
        table = isotrack.dask.surfaces(array, 0.0, scheduler=client)
        seconds = time.perf_counter() - start
        worker_rss = client.run(peak_rss_mib)
    print(f"{N}^3 float32 ({N ** 3 * 4 / 2 ** 30:.1f} GiB, {(N // CHUNK) ** 3} blocks of {CHUNK}^3), "
          f"{WORKERS} worker processes: {len(table['triangles'])} surfaces, "
          f"{int(table['triangles'].sum())} triangles, closed {int(table['closed'].sum())}, in {seconds:.1f} s")
    for worker, rss in sorted(worker_rss.items()):
        print(f"  worker {worker}: peak RSS {rss:.0f} MiB")
    print(f"  client: peak RSS {peak_rss_mib():.0f} MiB")
    # Each ball alone, from an in-memory box around it, in this process.
    alone = []
    for cx, cy, cz in CENTRES:
        box = [(int(c - RADIUS) - 2, int(c + RADIUS) + 3) for c in (cz, cy, cx)]
        alone += [s.triangle_count for s in isotrack.surfaces(blobs(box), 0.0)]
    same = sorted(alone, reverse=True) == sorted(table["triangles"].tolist(), reverse=True)
    print(f"  each surface equals its ball extracted alone from a box: {same}")
    if not same:
        sys.exit(1)


if __name__ == "__main__":
    main()
