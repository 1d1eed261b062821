"""Capping, smoothing and decimation through track and surfaces, and the quality properties."""
import numpy as np
import pytest

import isotrack


def ball(shape=(26, 26, 26), centre=(11.7, 12.4, 4.3), radius=8.0):
    """A ball (above level 0) cut by the volume's x = 0 face; arrays are (z, y, x)."""
    z, y, x = np.indices(shape, dtype=np.float64)
    return (radius - np.sqrt((z - centre[0]) ** 2 + (y - centre[1]) ** 2 + (x - centre[2]) ** 2)).astype(np.float32)


def test_cap_closes_a_cut_ball_as_a_padded_copy_would():
    volume = ball()
    open_surface = isotrack.surfaces(volume, 0.0)[0]
    assert not open_surface.closed and open_surface.boundary_edges > 0
    capped = isotrack.surfaces(volume, 0.0, cap=True)[0]
    padded = np.pad(volume, 1, constant_values=volume.min())
    reference = isotrack.surfaces(padded, 0.0)[0]
    assert capped.closed and capped.boundary_edges == 0
    assert capped.triangle_count == reference.triangle_count
    assert capped.volume == pytest.approx(reference.volume, rel=1e-6)
    # The capped mesh sits where the padded copy's does, one spacing back
    # (to float rounding: the two add their origins differently).
    reference = isotrack.surfaces(padded, 0.0, origin=(-1.0, -1.0, -1.0))[0]
    np.testing.assert_allclose(np.sort(capped.vertices, axis=0), np.sort(reference.vertices, axis=0), atol=1e-5)
    tracked = isotrack.track(volume, 0.0, seed=(11.7, 12.4, 12.3), cap=True)
    assert tracked.closed and tracked.triangle_count == capped.triangle_count


def test_smoothing_keeps_the_volume_and_decimation_the_closure():
    volume = ball(centre=(12.3, 12.6, 12.2))
    raw = isotrack.surfaces(volume, 0.0)[0]
    smooth = isotrack.surfaces(volume, 0.0, smooth=20)[0]
    assert smooth.closed and smooth.volume == pytest.approx(raw.volume, rel=0.01)
    assert np.allclose(np.linalg.norm(smooth.normals, axis=1), 1.0, atol=1e-5)
    decimated = isotrack.track(volume, 0.0, seed=(12.3, 12.6, 20.2), decimate=0.1)
    assert decimated.closed
    assert decimated.triangle_count <= 0.11 * raw.triangle_count
    assert decimated.volume == pytest.approx(raw.volume, rel=0.08)  # 10% of a small ball: chords cut in
    bounded = isotrack.surfaces(volume, 0.0, decimate_error=0.05)[0]
    assert raw.triangle_count / 10 < bounded.triangle_count < raw.triangle_count


def test_quality_properties_and_refusals():
    surface = isotrack.surfaces(ball(centre=(12.3, 12.6, 12.2)), 0.0)[0]
    assert surface.degenerate_triangles == 0
    assert surface.non_manifold_edges == 0
    below1, below10, below20 = surface.min_angle_fractions
    assert 0.0 <= below1 <= below10 <= below20 <= 1.0
    with pytest.raises(ValueError, match="pass band"):
        isotrack.surfaces(ball(), 0.0, smooth=5, passband=3.0)
    with pytest.raises(ValueError, match="ratio"):
        isotrack.surfaces(ball(), 0.0, decimate=1.5)


def test_snap_table_on_integer_samples():
    """An integer ball at an integer isovalue: the consistent table's zero-area
    triangles and slivers, none with table="snap", the same surfaces, fewer triangles."""
    z, y, x = np.indices((24, 24, 24), dtype=np.float64)
    volume = np.rint(40.0 - 4.0 * np.sqrt((z - 11.3) ** 2 + (y - 12.1) ** 2 + (x - 11.8) ** 2)).astype(np.int16)
    consistent = isotrack.surfaces(volume, 0.0)
    snapped = isotrack.surfaces(volume, 0.0, table="snap")
    assert consistent[0].degenerate_triangles > 0
    assert len(snapped) == len(consistent) == 1
    s = snapped[0]
    assert s.closed and s.degenerate_triangles == 0 and s.non_manifold_edges == 0
    assert s.triangle_count < consistent[0].triangle_count
    assert s.min_angle_fractions[1] < consistent[0].min_angle_fractions[1]
    assert s.volume == pytest.approx(consistent[0].volume, rel=0.02)
    tracked = isotrack.track(volume, 0.0, seed=(11.8, 12.1, 16.3), table="snap")
    assert tracked.triangle_count == s.triangle_count
    # No two vertices at one place: a sample at the isovalue is one vertex.
    assert len(np.unique(s.vertices, axis=0)) == len(s.vertices)
