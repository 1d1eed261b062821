"""A sparse float32 raw volume: N^3 samples of 0 (holes in the file, no disk used)
with a few small balls written into it (1 inside, falling to 0 over one sample at
the radius). Prints one line per ball: centre x,y,z and radius, in samples.

Usage: /usr/bin/python3 bench/make_sparse_volume.py OUT.raw N [BALLS]
"""
import os
import sys

import numpy as np

path, n = sys.argv[1], int(sys.argv[2])
count = int(sys.argv[3]) if len(sys.argv) > 3 else 5
with open(path, "wb") as f:
    f.truncate(n * n * n * 4)  # a hole: reads as zeros, occupies nothing
volume = np.memmap(path, dtype="<f4", mode="r+", shape=(n, n, n))  # (z, y, x)
rng = np.random.default_rng(7)
for b in range(count):
    radius = 6 + 4 * b
    centre = rng.integers(radius + 2, n - radius - 2, size=3)
    lo, hi = centre - radius - 2, centre + radius + 3
    z, y, x = np.meshgrid(*(np.arange(l, h) for l, h in zip(lo[::-1], hi[::-1])), indexing="ij")
    distance = np.sqrt((x - centre[0]) ** 2 + (y - centre[1]) ** 2 + (z - centre[2]) ** 2)
    volume[lo[2]:hi[2], lo[1]:hi[1], lo[0]:hi[0]] = np.clip(radius + 0.5 - distance, 0, 1).astype("<f4")
    print(f"{centre[0]},{centre[1]},{centre[2]} {radius}")
volume.flush()
del volume
os.sync()
