"""Isosurfaces of 3D volumes: isotrack's marching cubes and surface tracking.

Two kinds of input, two kinds of coordinates:

- A raw array (numpy, or anything np.asarray takes) indexed (z, y, x), x
  varying fastest, as numpy and scikit-image have it. Coordinates (spacing,
  origin, seeds, vertices, normals, bounds) are (z, y, x) too; a sample's
  position is origin + index * spacing, as scikit-image's marching_cubes gives.
- A Volume, from isotrack.load: samples with the file's geometry (spacing,
  origin, direction). Vertices, normals, seeds and bounds are world (x, y, z)
  in the Volume's frame ("lps", the default, "ras" or "voxel"), exactly as
  `isotrack extract --frame` writes them: what volume.affine gives for an index
  (i, j, k) = (x, y, z) = samples[k, j, i].

Functions: marching_cubes (a drop-in for skimage.measure.marching_cubes),
track (the one surface through a seed), surfaces (every connected surface),
load (NRRD, NIfTI, MetaImage, VTK, DICOM; time steps of .pvd and 4D NIfTI, listed by
steps, read in turn by load_steps), follow_through_time (every surface of
every step with an id that lasts, as `isotrack extract --all-times` writes its
track.json) and write_ply, write_obj, write_stl.
Bad input raises ValueError (TypeError for an argument of the wrong kind);
unreadable files and write failures raise OSError.
"""
import math
import os

import numpy as np

from . import _inputs
from ._isotrack import Geometry as _Geometry
from ._isotrack import Surface
from ._isotrack import __version__
from . import _isotrack

Surface.__module__ = "isotrack"

__all__ = ["Volume", "Surface", "marching_cubes", "track", "surfaces", "load", "open", "steps", "load_steps", "follow_through_time", "write_ply", "write_obj", "write_stl"]

_FRAMES = _isotrack.FRAMES  # core's names (isotrack/orientation.h, tables.h, extract.h)
_TABLES = _isotrack.TABLES
# marching_cubes gives one mesh ("mc", also under scikit-image's names) or every surface ("all").
_MC, _ALL = (name for name in _isotrack.METHODS if name in ("mc", "all"))
_METHODS = (_MC, "lewiner", "lorensen", _ALL)
_GRADIENTS = ("descent", "ascent")
_IDENTITY = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))


class Volume:
    """Samples and where they lie, as isotrack.load reads them.

    samples: the samples as a numpy array indexed (z, y, x), in the file's own
        sample type, a view of the memory isotrack read them into (no copy; its
        base keeps that memory alive).
    frame: "lps", "ras" or "voxel": the coordinates of affine, origin and
        direction here, and of the vertices, normals, seeds and bounds of
        every extraction from this Volume.
    affine: 4x4 float64 taking a sample's index (i, j, k, 1), i along x (the
        last array axis), to world (x, y, z, 1) in the frame. For "lps" (DICOM,
        ITK) it is nibabel's img.affine with x and y negated; for "ras" nibabel's
        img.affine itself; for "voxel" the identity.
    spacing: (x, y, z) distances between samples along i, j, k, in world units.
    origin: (x, y, z) world position of samples[0, 0, 0] in the frame.
    direction: 3x3 float64, its columns the unit world vectors of i, j, k in the
        frame (the identity for "voxel").
    dims: (nx, ny, nz); shape: samples.shape, (nz, ny, nx); dtype; path.
    """

    __slots__ = ("samples", "frame", "affine", "spacing", "origin", "direction", "path", "_lps")

    def __init__(self, samples, lps, frame, path):
        """Made by isotrack.load and Volume.in_frame; `lps` is (spacing, origin, direction
        columns) in isotrack's LPS world."""
        self.samples = samples
        self.frame = _inputs.choice(frame, "frame", _FRAMES)
        self.path = path
        self._lps = lps
        spacing, _, _ = lps
        affine = np.array(_isotrack.frame_affine(*lps, self.frame), dtype=np.float64)
        self.affine = affine
        self.spacing = tuple(spacing)
        self.origin = tuple(float(v) for v in affine[:3, 3])
        self.direction = np.eye(3) if self.frame == "voxel" else affine[:3, :3] / np.array(spacing)
        for array in (self.affine, self.direction):
            array.flags.writeable = False

    @property
    def dims(self):
        """(nx, ny, nz): samples along x, y and z."""
        return tuple(reversed(self.samples.shape))

    @property
    def shape(self):
        return self.samples.shape

    @property
    def dtype(self):
        return self.samples.dtype

    def in_frame(self, frame):
        """The same samples (not copied) in another frame: "lps", "ras" or "voxel"."""
        return Volume(self.samples, self._lps, frame, self.path)

    def _geometry(self, step=1):
        spacing, origin, direction = self._lps
        return _Geometry(tuple(s * step for s in spacing), origin, direction, self.frame)

    def __repr__(self):
        return (
            f"<isotrack.Volume {self.path!r}: dims {self.dims}, {self.dtype}, spacing "
            f"{tuple(round(s, 6) for s in self.spacing)}, frame {self.frame}>"
        )


def _samples_and_geometry(volume, spacing, origin, step=1):
    """The samples and geometry of a Volume or a raw array (spacing and origin in (z, y, x))."""
    if isinstance(volume, Volume):
        if spacing is not None or origin is not None:
            raise ValueError(
                "spacing, origin: a Volume carries its own; give volume.samples to place a raw array yourself"
            )
        return _inputs.samples_of(volume.samples), volume._geometry(step)
    samples = _inputs.samples_of(volume)
    spacing = _inputs.triple((1.0, 1.0, 1.0) if spacing is None else spacing, "spacing", "(z, y, x)", True)
    origin = _inputs.triple((0.0, 0.0, 0.0) if origin is None else origin, "origin", "(z, y, x)")
    return samples, _Geometry(tuple(s * step for s in spacing[::-1]), origin[::-1], _IDENTITY, "")


def marching_cubes(
    volume,
    level=None,
    *,
    spacing=None,
    gradient_direction="descent",
    step_size=1,
    allow_degenerate=True,
    method="mc",
    mask=None,
    table="consistent",
    threads=0,
    origin=None,
):
    """Marching cubes over every cell of a volume; a drop-in for skimage.measure.marching_cubes.

    Args:
        volume: a Volume (isotrack.load), or a 3D array indexed (z, y, x) of any
            real or bool dtype, any strides, or anything np.asarray takes. Arrays
            of uint8, int8, uint16, int16, uint32, int32, float32 or float64 that
            are C-contiguous are used in place; others are converted (bool to
            uint8, float16 to float32, int64 and uint64 to int32/uint32 or
            exactly to float64, ValueError beyond 2**53) or copied (only the
            elements a strided view such as vol[::2] shows).
        level: the isovalue. None takes isotrack's suggested isovalue (the
            valley above the histogram's tallest peak, else Otsu's threshold;
            the one the command line and viewer open on; scikit-image takes the
            middle of the range). A
            level outside the finite samples' range raises ValueError, as
            scikit-image does.
        spacing: (z, y, x) distances between samples of a raw array (default
            (1, 1, 1)); not with a Volume, which has its own.
        gradient_direction: "descent" (the object is brighter than its
            surroundings; the default) or "ascent": winds every triangle the
            other way, as scikit-image does. Normals are not changed.
        step_size: march cells step_size samples wide: the samples at
            0, step_size, 2 * step_size, ... along each axis, as scikit-image.
        allow_degenerate: False removes triangles with two corners at one
            position and merges those corners, as scikit-image does.
        method: "mc" for one mesh ("lewiner" and "lorensen" are accepted as its
            names, so code written for scikit-image runs unchanged), or "all"
            for a list of Surface objects, one per connected surface, largest
            first (with mask or allow_degenerate=False: ValueError).
        mask: an array of the volume's shape; a cell is marched only where the
            mask is true at its corner of highest indices, as in scikit-image.
        table: "consistent" (isotrack's, no holes between cells), "classic",
            "trilinear" (the trilinear interpolant's topology, MC33) or "snap"
            (the 3-state table: samples near the level snapped onto it).
        threads: threads to use; 0 uses every core. With more than one, the
            vertices and triangles come in another order; they are the same.
        origin: the (z, y, x) position of sample [0, 0, 0] of a raw array.

    Returns:
        For "mc", (verts, faces, normals, values) like scikit-image's: verts
        (V, 3) float32, (z, y, x) for a raw array (origin + index * spacing),
        world (x, y, z) in the frame for a Volume (volume.affine applied to the
        index, as `isotrack extract --frame` writes them); faces (F, 3) uint32;
        normals (V, 3) float32 unit vectors in the verts' axes, pointing
        towards lower values; values (V,) float32, the larger of the two
        samples at the ends of each vertex's grid edge. All four are views of
        the mesh isotrack built, not copies. For "all", a list of Surface.

    Raises:
        ValueError: bad volume, level outside the data range or not finite,
            unknown method, table or gradient_direction, a mask of another shape.
        RuntimeError: no surface at the level ("No surface found at the given
            iso value.", as scikit-image).

    Example:
        >>> import numpy as np, isotrack
        >>> z, y, x = np.mgrid[-1:1:32j, -1:1:32j, -1:1:32j]
        >>> verts, faces, normals, values = isotrack.marching_cubes(x*x + y*y + z*z, 0.5)
    """
    method = _inputs.choice(method, "method", _METHODS)
    ascent = _inputs.choice(gradient_direction, "gradient_direction", _GRADIENTS) == "ascent"
    step = _inputs.step_of(step_size)
    allow_degenerate = bool(allow_degenerate)
    if method == _ALL and (mask is not None or not allow_degenerate):
        raise ValueError("mask and allow_degenerate=False apply to one mesh: not with method='all'")
    table, threads = _inputs.choice(table, "table", _TABLES), _inputs.integer(threads, "threads", 0)
    samples, geometry = _samples_and_geometry(volume, spacing, origin, step)
    iso = _isotrack.level(samples, _inputs.level_of(level), True)
    cells = None if mask is None else _inputs.cell_mask(mask, samples.shape, step)
    if step > 1:
        samples = np.ascontiguousarray(samples[::step, ::step, ::step])
    result = _isotrack.marching_cubes(
        samples, iso, geometry, table, threads, cells, allow_degenerate, ascent, method == _ALL
    )
    if method != _ALL and len(result[1]) == 0:
        raise RuntimeError("No surface found at the given iso value.")
    return result


_PROCESSING_DOC = """
        cap: close the surfaces the volume's border cuts, as if the volume
            were padded with one layer of samples below level (its smallest
            sample): what `isotrack extract --cap` does.
        smooth: windowed-sinc smoothing iterations (0: none), without
            shrinkage; border vertices stay, and no vertex moves farther
            than half the smallest spacing. Normals are then the
            area-weighted face normals.
        passband: the smoothing filter's pass band in (0, 2); smaller smooths more.
        decimate: keep this fraction (0, 1] of the triangles (meshoptimizer),
            within decimate_error of the original.
        decimate_error: the decimation's bound in world units (default: 0.98
            of the smallest spacing); alone, decimate as far as it allows."""


def _processing(cap, smooth, passband, decimate, decimate_error):
    smooth = _inputs.integer(smooth, "smooth", 0)
    passband, decimate = float(passband), float(decimate)
    error = None if decimate_error is None else float(decimate_error)
    return dict(cap=bool(cap), smooth=smooth, passband=passband, decimate=decimate, decimate_error=error)


def track(
    volume,
    level=None,
    *,
    seed=None,
    seed_edge=None,
    spacing=None,
    table="consistent",
    threads=0,
    origin=None,
    cap=False,
    smooth=0,
    passband=0.1,
    decimate=1.0,
    decimate_error=None,
):
    """The one connected surface through a seed, touching only the cells it crosses.

    Args:
        volume: a Volume or a raw array, as for marching_cubes.
        level: the isovalue (finite); None takes isotrack's suggested isovalue.
        seed: a point, in the coordinates vertices come in: (z, y, x) for a raw
            array (origin + index * spacing), world (x, y, z) in the frame for
            a Volume. Tracking starts at the crossed grid edge whose midpoint
            is nearest to it.
        seed_edge: or a grid edge (z, y, x, axis) crossed by the surface, in
            array indices for either kind of volume: the edge from
            samples[z, y, x] one step along axis (0: z, 1: y, 2: x).
        spacing, origin: of a raw array, in (z, y, x), as for marching_cubes.
        table: "consistent", "classic", "trilinear" or "snap", as for marching_cubes.
        threads: threads to use (at most 64); 0 uses every core.
        cap, smooth, passband, decimate, decimate_error: mesh processing,
            applied in that order (see surfaces).

    Returns:
        A Surface.

    Raises:
        ValueError: neither or both of seed and seed_edge; a seed edge outside
            the volume or not crossed at level; no crossed edge at all; bad volume.

    Example:
        >>> ct = isotrack.load("assets/ct/cranium.nrrd")
        >>> skull = isotrack.track(ct, 400, seed=(122, 122, 160))   # world (x, y, z), LPS
        >>> skull.triangle_count, skull.area, skull.closed
    """
    if (seed is None) == (seed_edge is None):
        raise ValueError("track: give exactly one of seed (a point) or seed_edge=(z, y, x, axis)")
    table, threads = _inputs.choice(table, "table", _TABLES), _inputs.integer(threads, "threads", 0)
    samples, geometry = _samples_and_geometry(volume, spacing, origin)
    order = "(x, y, z)" if isinstance(volume, Volume) else "(z, y, x)"
    point = None if seed is None else _inputs.triple(seed, "seed", order)
    edge = None
    if seed_edge is not None:
        try:
            edge = tuple(_inputs.integer(v, "seed_edge", -(2**31)) for v in seed_edge)
        except TypeError:
            raise TypeError(f"seed_edge: expected four integers (z, y, x, axis), got {_inputs.shown(seed_edge)}") from None
        if len(edge) != 4:
            raise ValueError(f"seed_edge: expected four integers (z, y, x, axis), got {len(edge)}")
    iso = _isotrack.level(samples, _inputs.level_of(level), False)
    processing = _processing(cap, smooth, passband, decimate, decimate_error)
    return _isotrack.track(samples, iso, geometry, table, threads, point, edge, False, **processing)


def surfaces(
    volume,
    level=None,
    *,
    spacing=None,
    table="consistent",
    threads=0,
    origin=None,
    cap=False,
    smooth=0,
    passband=0.1,
    decimate=1.0,
    decimate_error=None,
):
    """Every connected surface of a volume, largest (most triangles) first.

    Together they hold exactly the triangles of marching_cubes with the same
    table. Arguments as for marching_cubes (level None: isotrack's suggested
    isovalue); returns a list of Surface, empty when nothing crosses the level.
    Each surface is processed, in this order, as these keywords say:
    """
    table, threads = _inputs.choice(table, "table", _TABLES), _inputs.integer(threads, "threads", 0)
    samples, geometry = _samples_and_geometry(volume, spacing, origin)
    iso = _isotrack.level(samples, _inputs.level_of(level), False)
    processing = _processing(cap, smooth, passband, decimate, decimate_error)
    return _isotrack.marching_cubes(samples, iso, geometry, table, threads, None, True, False, True, **processing)


surfaces.__doc__ += _PROCESSING_DOC


def load(path, frame="lps", *, time=0, array=None):
    """Reads a volume with isotrack's loaders, with its geometry.

    Formats by extension: .nrrd .nhdr, .nii .nii.gz, .mhd .mha, .vtk, .vti, a
    .pvd collection, and DICOM (a folder, a DICOMDIR or a multi-frame file), as
    the command line reads them.
    Uncompressed samples in the machine's byte order (raw NRRD, .nii, MetaImage
    with a raw data file) are mapped, not read: see open().

    Args:
        path: the file or folder.
        frame: "lps" (DICOM and ITK's world, isotrack's default), "ras"
            (nibabel's and NIfTI's), or "voxel" (sample indices): the
            coordinates of the Volume's affine and of every mesh made from it.
        time: a time series (.pvd collection, 4D NIfTI): the step to read, by
            its index in steps(path); 0, the first, by default.
        array: a .vti file: the PointData array to read, by name (default: the
            first with one component).

    Returns:
        A Volume: samples (no copy), spacing, origin, direction, affine, frame.

    Raises:
        OSError: the file cannot be read or is malformed (the message names the
            file, the field and the value).
    """
    frame = _inputs.choice(frame, "frame", _FRAMES)
    try:
        name = os.fspath(path)
    except TypeError:
        raise TypeError(f"path: expected a path, got {_inputs.shown(path)}") from None
    if not isinstance(name, str):
        name = os.fsdecode(name)
    time = _inputs.integer(time, "time", 0, 2**63 - 1)
    if array is not None and not isinstance(array, str):
        raise TypeError(f"array: expected a name, got {_inputs.shown(array)}")
    samples, spacing, origin, direction = _isotrack.load(name, time, array or "")
    return Volume(samples, (spacing, origin, direction), frame, name)


def steps(path):
    """The time values of a time series' steps, step 0 first.

    A .pvd collection has one step per DataSet, in the order of their timestep
    values; a 4D NIfTI one per 3D volume, at toffset + t * pixdim[4] (t when
    pixdim[4] is 0); a 4D NRRD one per index t of its last (time) axis, at t;
    numbered files, given as a printf pattern such as "step_%04d.nrrd", one per
    number from 0 (or 1), at that number; any other volume file one step at
    time 0. load(path, time=i) reads step i.

    Raises:
        OSError: the file cannot be read or is malformed.
    """
    return [time for time, _ in _isotrack.steps(os.fspath(path))]


def _path_of(path):
    try:
        name = os.fspath(path)
    except TypeError:
        raise TypeError(f"path: expected a path, got {_inputs.shown(path)}") from None
    return name if isinstance(name, str) else os.fsdecode(name)


def _array_of(array):
    if array is not None and not isinstance(array, str):
        raise TypeError(f"array: expected a name, got {_inputs.shown(array)}")
    return array or ""


def load_steps(path, frame="lps", *, array=None):
    """Every step of a time series in turn, as (time, Volume), step 0 first.

    One step is held at a time and the next is read on a background thread
    while the caller works on this one, so a loop over a long series reads it
    once and waits little. Every step must share the first step's grid (dims,
    spacing, origin, direction): a step that does not raises ValueError naming
    its file and the field, when the loop reaches it. Arguments as for load();
    steps(path) lists the time values without reading any samples.

    Example:
        >>> for time, volume in isotrack.load_steps("blobs.pvd"):
        ...     print(time, len(isotrack.surfaces(volume, 0.5)))
    """
    frame = _inputs.choice(frame, "frame", _FRAMES)
    name = _path_of(path)
    reader = _isotrack.StepReader(name, _array_of(array))
    for step in range(len(reader)):
        samples, spacing, origin, direction = reader.load(step)
        yield reader.time(step), Volume(samples, (spacing, origin, direction), frame, name)


def follow_through_time(
    path,
    level=None,
    *,
    method="all",
    seed=None,
    frame="lps",
    array=None,
    table="consistent",
    threads=0,
    min_persistence=0.0,
    min_size=0,
    surfaces=False,
):
    """Every surface of every step of a time series, each with an id that lasts.

    The records `isotrack extract --all-times` writes to track.json, from the
    same core code: who continues whom is decided as between isovalues in the
    viewer (footprints shared from step to step; a tracked seed followed to
    where its feature moved). A surface that continues one of the previous
    step keeps its id; the further parts of a split and surfaces born in a step
    get new ids; a surface that ends is listed once more, in the step where it
    ended, with presence "merged" and merged_into set, or "gone".

    Args:
        path: a time series (.pvd, 4D NIfTI or NRRD, numbered files) or a volume (one step).
        level: the isovalue of every step; None takes the first step's suggested one.
        method: "all" or "tree" (every surface) or "track" (the one through seed).
        seed: method "track": a world point (x, y, z) in the frame, on the first step.
        frame: "lps", "ras" or "voxel": of seed and of the surfaces' vertices.
        array: a .vti's PointData array, as for load().
        table, threads: as for surfaces(); min_persistence, min_size: method
            "tree", each step's contour tree simplified as extract's options do.
        surfaces: also give each shown surface's Surface (key "surface").

    Returns:
        {"source", "method", "table", "isovalue", "frame", "steps"}: steps a
        list of {"step", "time", "seconds", "surfaces"}, each surface a dict
        with "id", "continues", "split", "presence" ("shown", "merged", "gone"),
        "merged_into", "ended", "triangles", "area", "volume" (enclosed; None
        when open) and "closed".

    Raises:
        ValueError: a bad argument, or a step on another grid than the first.
        OSError: a step cannot be read.
    """
    name = _path_of(path)
    method = _inputs.choice(method, "method", ("all", "tree", "track"))
    table, frame = _inputs.choice(table, "table", _TABLES), _inputs.choice(frame, "frame", _FRAMES)
    threads, min_size = _inputs.integer(threads, "threads", 0), _inputs.integer(min_size, "min_size", 0, 2**63 - 1)
    if (seed is None) == (method == "track"):
        raise ValueError("follow_through_time: method \"track\" needs a seed, and only it takes one")
    point = None if seed is None else _inputs.triple(seed, "seed", "(x, y, z)")
    iso = _inputs.level_of(level)
    if iso is not None and not math.isfinite(iso):
        raise ValueError(f"level: must be a finite number, got {iso}")
    followed = _isotrack.follow_through_time(
        name, _array_of(array), iso, method, table, threads, point, frame, float(min_persistence), min_size, bool(surfaces)
    )
    return dict(source=name, method=method, table=table, isovalue=followed["isovalue"], frame=frame, steps=followed["steps"])


def open(path, frame="lps", *, time=0, array=None):  # isotrack.open; this module never calls the builtin
    """A volume whose samples stay in their file: nothing is read until used.

    The samples of uncompressed files in the machine's byte order (raw NRRD,
    attached or detached .nhdr, .nii, MetaImage with a raw data file) are a
    read-only array over a memory map of the file, so a volume bigger than
    memory opens at once, and track() reads only the pages its surface crosses.
    Compressed or byte-swapped files are decoded into memory, and refused when
    they would not fit. A file truncated or removed while in use makes the next
    extraction raise OSError naming it. Otherwise the same as load().
    """
    return load(path, frame, time=time, array=array)


def _writer(write, what):
    def write_surface(surface, path):
        if not isinstance(surface, Surface):
            raise TypeError(f"surface: expected an isotrack.Surface, got {_inputs.shown(surface)}")
        try:
            name = os.fsdecode(os.fspath(path))
        except TypeError:
            raise TypeError(f"path: expected a path, got {_inputs.shown(path)}") from None
        write(surface, name)

    write_surface.__doc__ = (
        f"Writes a Surface as {what}. Files are (x, y, z): a raw array's surface in grid coordinates "
        "(its vertices read backwards), a Volume's in world coordinates in its frame (its vertices as they are)."
    )
    return write_surface


write_ply = _writer(_isotrack.write_ply, "binary little-endian PLY")
write_obj = _writer(_isotrack.write_obj, "Wavefront OBJ")
write_stl = _writer(_isotrack.write_stl, "binary STL")
write_ply.__name__, write_obj.__name__, write_stl.__name__ = "write_ply", "write_obj", "write_stl"
