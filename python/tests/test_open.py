"""isotrack.open: samples left in their file (a read-only map), the same surfaces as
samples in memory, and a file truncated under an extraction an OSError naming it."""
import os

import numpy as np
import pytest

import isotrack
from conftest import ellipsoid


def detached_nrrd(tmp_path, samples, name="vol"):
    """samples (z, y, x) float32 as NAME.raw behind a detached header NAME.nhdr."""
    raw = tmp_path / f"{name}.raw"
    samples.astype("<f4").tofile(raw)
    header = tmp_path / f"{name}.nhdr"
    nz, ny, nx = samples.shape
    header.write_text(f"NRRD0004\ntype: float\ndimension: 3\nsizes: {nx} {ny} {nz}\nendian: little\n"
                      f"encoding: raw\ndata file: {name}.raw\n")
    return header, raw


def test_open_maps_the_file_and_gives_the_surfaces_of_memory(tmp_path):
    samples = ellipsoid((40, 48, 56))
    header, raw = detached_nrrd(tmp_path, samples)
    volume = isotrack.open(header)
    assert not volume.samples.flags.writeable
    assert not volume.samples.flags.owndata
    # The map reads the file: a change on disk shows through, which a copy would not.
    np.testing.assert_array_equal(volume.samples, samples)
    in_memory = isotrack.surfaces(np.ascontiguousarray(samples), 1.0)
    mapped = isotrack.surfaces(volume, 1.0)
    assert [s.triangle_count for s in mapped] == [s.triangle_count for s in in_memory]
    verts, faces, _, _ = isotrack.marching_cubes(volume, 1.0)
    assert len(faces) == sum(s.triangle_count for s in in_memory)
    seed = tuple(float(v) for v in verts[0])
    assert isotrack.track(volume, 1.0, seed=seed).triangle_count == in_memory[0].triangle_count


def test_a_file_truncated_under_an_extraction_raises_oserror(tmp_path):
    samples = ellipsoid((64, 64, 64))
    header, raw = detached_nrrd(tmp_path, samples, "cut")
    volume = isotrack.open(header)
    os.truncate(raw, 4096)
    with pytest.raises(OSError, match="cut.raw.*truncated or removed while it was read") as error:
        isotrack.surfaces(volume, 1.0)
    assert len(str(error.value)) < 300
