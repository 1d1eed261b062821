"""Shared helpers: the isotrack CLI, procedural volumes and a PLY reader."""
import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

SOURCE_DIR = pathlib.Path(os.environ.get("ISOTRACK_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


def cli_path():
    """The isotrack executable: $ISOTRACK_CLI (set by CTest), else build/app/isotrack."""
    candidates = [os.environ.get("ISOTRACK_CLI"), SOURCE_DIR / "build" / "app" / "isotrack", shutil.which("isotrack")]
    for candidate in candidates:
        if candidate and pathlib.Path(candidate).is_file():
            return str(candidate)
    return None


@pytest.fixture(scope="session")
def cli():
    path = cli_path()
    if path is None:
        pytest.fail("the isotrack executable was not found: build it or set ISOTRACK_CLI")
    return lambda *args: subprocess.run([path, *map(str, args)], check=True, capture_output=True, text=True).stdout


def ellipsoid(shape=(20, 24, 28), radii=(0.5, 0.7, 0.9), dtype=np.float32):
    """sum((p / r)^2) over [-1, 1]^3 sampled on `shape`, indexed (z, y, x): 1 on the ellipsoid."""
    z, y, x = np.meshgrid(*(np.linspace(-1, 1, n) for n in shape), indexing="ij")
    return ((z / radii[0]) ** 2 + (y / radii[1]) ** 2 + (x / radii[2]) ** 2).astype(dtype)


def read_ply(path):
    """(positions (V, 3) in x, y, z, faces (F, 3)) from the binary PLY isotrack writes."""
    data = pathlib.Path(path).read_bytes()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    assert "format binary_little_endian 1.0" in header
    counts = {line.split()[1]: int(line.split()[2]) for line in header if line.startswith("element")}
    list_line = next(line for line in header if line.startswith("property list"))
    index_type = {"int": "<i4", "uint": "<u4"}[list_line.split()[3]]
    extra = [("component", "<i4")] if any(line.endswith(" component") for line in header) else []
    vertices = np.frombuffer(data, dtype="<f4", count=counts["vertex"] * 6, offset=end).reshape(-1, 6)
    face_type = np.dtype([("n", "u1"), ("i", index_type, 3)] + extra)
    faces = np.frombuffer(data, dtype=face_type, count=counts["face"], offset=end + vertices.nbytes)
    assert np.all(faces["n"] == 3)
    return vertices[:, :3], faces["i"].astype(np.int64)


def triangle_set(vertices, faces, decimals=5):
    """Each triangle as its three corner positions, rounded and sorted, as a set (order-free comparison)."""
    corners = np.round(np.asarray(vertices, dtype=np.float64)[np.asarray(faces, dtype=np.int64)], decimals)
    return {tuple(sorted(map(tuple, triangle))) for triangle in corners}
