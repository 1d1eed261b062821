"""isotrack on chunked volumes with Dask: every surface, one tracked surface, or one mesh.

Each chunk of a dask array (zyx) is one task. It reads its own samples plus one
more on each high side (the cells [lo, hi) need the samples [lo, hi]) from the
array's source, runs core's extraction on that block, and returns its surface
pieces as compact figures: triangles, area, signed volume, bounds and the
global ids of the crossed edges on its faces shared with other chunks (see
isotrack/_chunks.py). The client joins pieces sharing an edge into surfaces
(connected components), so nothing but those figures, and meshes only when
asked for, comes back from the workers. The volume itself is never sent: a
task's graph reads its block from the source (a zarr store, a file, or whatever
the dask array wraps).

Tasks run on whatever Dask runs them with: the default threaded scheduler, or
the distributed Client made last (a LocalCluster or Client("tcp://...")).
The consistent table only: it is the one whose cells' triangles join across
chunk faces with no holes, so that joined pieces are exactly the in-memory
surfaces. See docs/distributed.md. From a shell: python3 -m isotrack.dask --help.
"""

import os

import numpy as np
import dask
import dask.array as da

from . import _chunks
from . import _inputs

__all__ = ["surfaces", "track", "marching_cubes", "from_file", "TrackedSurface"]


class _FileSamples:
    """A volume file's samples for da.from_array, pickled as its path: each worker opens
    (maps) the file itself and reads only the slices its tasks ask for."""

    def __init__(self, path):
        from . import open as open_volume

        self.path = os.fspath(path)
        samples = open_volume(self.path, frame="voxel").samples
        self.shape, self.dtype, self.ndim = samples.shape, samples.dtype, 3
        self._samples = samples

    def __getstate__(self):
        return {"path": self.path, "shape": self.shape, "dtype": self.dtype, "ndim": 3}

    def __setstate__(self, state):
        self.__dict__.update(state, _samples=None)

    def __getitem__(self, key):
        if self._samples is None:
            from . import open as open_volume

            self._samples = open_volume(self.path, frame="voxel").samples
        return np.array(self._samples[key])


def from_file(path, chunks=64):
    """A dask array (z, y, x) over a volume file isotrack reads (isotrack.open), in `chunks`.

    Its graph holds the file's path, not its samples: each worker maps the file
    itself (so the file must be reachable there at the same path) and reads the
    slices of its tasks. The samples are the raw array's: pass spacing (and
    origin) yourself, e.g. spacing=isotrack.open(path).spacing[::-1].
    """
    return da.from_array(_FileSamples(path), chunks=chunks, name=f"isotrack-file-{os.path.abspath(path)}")


def _grid(array, spacing, origin):
    if not isinstance(array, da.Array):
        array = da.asarray(array)
    if array.ndim != 3:
        raise ValueError(f"array: expected a 3D (z, y, x) dask array, got {array.ndim} dimensions")
    if min(array.shape) < 2:
        raise ValueError(f"array: every axis needs at least 2 samples, got shape {array.shape}")
    spacing = _inputs.triple(spacing, "spacing", "(z, y, x)", True)
    origin = _inputs.triple(origin, "origin", "(z, y, x)")
    return array, _chunks.Grid(array.shape, array.chunks, spacing, origin)


def _level(level):
    if level is None:
        raise ValueError("level: isotrack.dask needs a level (the suggested one would read the whole volume first)")
    return _inputs.level_of(level)


def _pieces(array, grid, level, meshes, scheduler):
    """Every chunk's surface pieces, one task per chunk, gathered as compact figures."""
    task = dask.delayed(_chunks.surface_pieces, pure=True)
    tasks = [task(array[grid.slices(c)], c, grid, level, meshes) for c in grid.chunk_indices()]
    return _chunks.merged(list(dask.compute(*tasks, scheduler=scheduler)))


def _components(pieces):
    """Surface label per piece: pieces sharing a crossed edge are one surface."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    count = len(pieces["triangles"])
    order = np.argsort(pieces["shared"], kind="stable")
    ids, owner = pieces["shared"][order], pieces["shared_piece"][order]
    same = ids[1:] == ids[:-1]
    graph = coo_matrix((np.ones(int(same.sum())), (owner[:-1][same], owner[1:][same])), shape=(count, count))
    return connected_components(graph, directed=False)[1].astype(np.int64)


def _table(pieces, labels):
    """The surfaces' figures, largest first (ties: the first grid edge in memory order), as extract --method all.

    Also returns each label's rank in that order."""
    count = int(labels.max()) + 1 if len(labels) else 0

    def total(key, dtype=np.float64):
        return np.bincount(labels, pieces[key], minlength=count).astype(dtype)

    triangles = total("triangles", np.int64)
    # A vertex on a face shared by k pieces was counted k times.
    owner = labels[pieces["shared_piece"]]
    _, first, repeats = np.unique(pieces["shared"], return_index=True, return_counts=True)
    vertices = total("vertices", np.int64) - np.bincount(owner[first], repeats - 1, minlength=count).astype(np.int64)
    border = total("touches_border") > 0
    closed = ~border & (triangles > 0)
    volume = np.where(closed, np.abs(total("signed_volume")), np.nan)
    bounds = np.empty((count, 2, 3))
    first_edge = np.full(count, np.iinfo(np.int64).max, dtype=np.int64)
    np.minimum.at(first_edge, labels, pieces["first_edge"].astype(np.int64))
    for a in range(3):
        bounds[:, 0, a], bounds[:, 1, a] = np.inf, -np.inf
        np.minimum.at(bounds[:, 0, a], labels, pieces["bounds"][:, 0, a])
        np.maximum.at(bounds[:, 1, a], labels, pieces["bounds"][:, 1, a])
    order = np.lexsort((first_edge, -triangles))
    table = {
        "id": np.arange(count, dtype=np.int64),
        "triangles": triangles[order],
        "vertices": vertices[order],
        "area": total("area")[order],
        "volume": volume[order],
        "bounds": bounds[order],
        "closed": closed[order],
        "touches_border": border[order],
        "pieces": np.bincount(labels, minlength=count)[order],
    }
    rank = np.empty(count, dtype=np.int64)
    rank[order] = np.arange(count)
    return table, rank


def _stitch(mesh, faces=None):
    """One mesh from gathered pieces (all of them, or the given faces): one vertex per crossed edge.

    Returns (vertices, faces, normals, values)."""
    vertices, normals, ids, values, all_faces, _ = mesh
    faces = all_faces if faces is None else faces
    used, inverse = np.unique(faces, return_inverse=True)
    _, first, renumber = np.unique(ids[used], return_index=True, return_inverse=True)
    keep = used[first]
    stitched = renumber[inverse].reshape(-1, 3).astype(np.uint32)
    return vertices[keep], stitched, normals[keep], values[keep]


def write_ply(path, vertices, faces, normals):
    """A binary PLY as isotrack's writers make it: (x, y, z) positions and normals, uint indices."""
    header = (
        "ply\nformat binary_little_endian 1.0\ncomment isotrack.dask\n"
        f"element vertex {len(vertices)}\nproperty float x\nproperty float y\nproperty float z\n"
        "property float nx\nproperty float ny\nproperty float nz\n"
        f"element face {len(faces)}\nproperty list uchar uint vertex_indices\nend_header\n"
    )
    rows = np.empty((len(vertices), 6), dtype="<f4")
    rows[:, :3], rows[:, 3:] = np.asarray(vertices)[:, ::-1], np.asarray(normals)[:, ::-1]
    face_rows = np.empty(len(faces), dtype=[("n", "u1"), ("i", "<u4", 3)])
    face_rows["n"], face_rows["i"] = 3, faces
    with open(path, "wb") as f:
        f.write(header.encode())
        f.write(rows.tobytes())
        f.write(face_rows.tobytes())


def surfaces(array, level, spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0), out=None, scheduler=None):
    """Every connected surface of a chunked volume, one Dask task per chunk.

    Args:
        array: a 3D dask array indexed (z, y, x) (from zarr, numpy, or
            isotrack.open(...).samples through da.from_array); its chunks are
            the tasks. Anything else is wrapped by da.asarray.
        level: the isovalue (required: the suggested one would read every sample first).
        spacing, origin: (z, y, x), as for isotrack.surfaces.
        out: a folder: each surface is written there as surface_0000.ply (largest
            first), its pieces' meshes gathered to the client and stitched with
            one vertex per crossed edge.
        scheduler: passed to dask.compute (None: the current one, a Client's if made).

    Returns:
        A dict of numpy arrays, one row per surface, largest first: id, triangles,
        vertices, area, volume (enclosed, NaN when not closed), bounds (N, 2, 3:
        lowest and highest corner, (z, y, x)), closed, touches_border, pieces.
        The same surfaces, counts, areas and closed flags as isotrack.surfaces.
    """
    array, grid = _grid(array, spacing, origin)
    level = _level(level)
    pieces = _pieces(array, grid, level, out is not None, scheduler)
    labels = _components(pieces)
    table, rank = _table(pieces, labels)
    if out is not None:
        os.makedirs(out, exist_ok=True)
        vertices, normals, ids, values, faces, face_piece = pieces["mesh"]
        surface_of_face = rank[labels[face_piece]]
        order = np.argsort(surface_of_face, kind="stable")
        bounds = np.searchsorted(surface_of_face[order], np.arange(len(rank) + 1))
        for k in range(len(rank)):
            v, f, n, _ = _stitch(pieces["mesh"], faces[order[bounds[k] : bounds[k + 1]]])
            write_ply(os.path.join(out, f"surface_{k:04d}.ply"), v, f, n)
    return table


def marching_cubes(array, level, spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0), scheduler=None):
    """The whole mesh of a chunked volume, gathered to the client, scikit-image style.

    Returns (verts, faces, normals, values) as isotrack.marching_cubes does
    ((z, y, x) float32 positions, uint32 faces, unit normals, per-vertex the
    larger sample of its edge): the same triangles, one vertex per crossed
    edge, in another order. For meshes that fit in the client's memory.
    """
    array, grid = _grid(array, spacing, origin)
    pieces = _pieces(array, grid, _level(level), True, scheduler)
    if len(pieces["mesh"][4]) == 0:
        raise RuntimeError("No surface found at the given iso value.")
    return _stitch(pieces["mesh"])


class TrackedSurface:
    """One surface tracked across chunks: its stitched mesh, figures, and the chunks it read."""

    def __init__(self, pieces, chunks, waves):
        vertices, faces, normals, values = _stitch(pieces["mesh"])
        table, _ = _table(pieces, np.zeros(len(pieces["triangles"]), dtype=np.int64))
        self.vertices, self.faces, self.normals, self.values = vertices, faces, normals, values
        self.triangle_count = int(table["triangles"][0])
        self.vertex_count = len(vertices)
        self.area = float(table["area"][0])
        self.closed = bool(table["closed"][0])
        self.volume = float(table["volume"][0]) if self.closed else None
        self.touches_border = bool(table["touches_border"][0])
        self.bounds = tuple(tuple(corner) for corner in table["bounds"][0])
        self.chunks = sorted(chunks)  # the chunks whose blocks were read, (i, j, k)
        self.waves = waves  # rounds of tasks, one per step the surface took into new chunks

    def __repr__(self):
        return (
            f"<isotrack.dask.TrackedSurface: {self.triangle_count} triangles, area {self.area}, "
            f"{'closed' if self.closed else 'open'}, {len(self.chunks)} chunks in {self.waves} waves>"
        )


def _seed_id(array, grid, level, seed, seed_edge, scheduler):
    """The global id of the seed edge; a point's nearest crossed edge from the chunks around it only."""
    if seed_edge is not None:
        edge = [_inputs.integer(v, "seed_edge", 0) for v in seed_edge]
        if len(edge) != 4 or edge[3] > 2:
            raise ValueError("seed_edge: expected (z, y, x, axis), axis 0 (z), 1 (y) or 2 (x)")
        ends = np.array(edge[:3]) + (np.arange(3) == edge[3])
        if np.any(ends >= grid.shape):
            raise ValueError(f"seed_edge {tuple(edge)} lies outside the volume of shape {grid.shape}")
        ends = array[tuple(slice(v, e + 1) for v, e in zip(edge[:3], ends))].compute(scheduler=scheduler).ravel()
        if (ends[0] >= level) == (ends[-1] >= level):  # isotrack counts a sample equal to the level as above it
            raise ValueError(f"seed_edge {tuple(edge)} is not crossed at level {level}")
        return int(_chunks.encode(*(np.array([v]) for v in edge), grid.shape)[0])
    point = np.asarray(_inputs.triple(seed, "seed", "(z, y, x)"), dtype=np.float64)
    index = np.clip(np.round((point - grid.origin) / grid.spacing), 0, np.array(grid.shape) - 1)
    home = [int(np.searchsorted(s, i, side="right") - 1) for s, i in zip(grid.starts, index)]
    reach = 0
    while True:
        # The chunks within `reach` of the point's: their samples, as one block.
        low = [max(h - reach, 0) for h in home]
        high = [min(h + reach, len(s) - 1) for h, s in zip(home, grid.starts)]
        lo = np.array([s[a] for s, a in zip(grid.starts, low)], dtype=np.int64)
        hi = np.array([min(s[b] + z[b] + 1, n) for s, z, b, n in zip(grid.starts, grid.sizes, high, grid.shape)])
        block = array[tuple(slice(int(a), int(b)) for a, b in zip(lo, hi))]
        try:
            found, distance = dask.compute(
                dask.delayed(_chunks.nearest_edge)(block, lo, grid, level, tuple(point)), scheduler=scheduler
            )[0]
        except ValueError:
            found, distance = None, np.inf
        # An edge outside the block lies at least as far as the nearest of its faces inside the volume.
        inner = [(point - (grid.origin + lo * grid.spacing))[a] for a in range(3) if lo[a] > 0]
        inner += [((grid.origin + (hi - 1) * grid.spacing) - point)[a] for a in range(3) if hi[a] < grid.shape[a]]
        if not inner or distance <= max(min(inner), 0.0):
            if found is None:
                raise ValueError(f"level {level}: no grid edge of the volume is crossed")
            return found
        reach += 1


def track(array, level, seed=None, *, seed_edge=None, spacing=(1.0, 1.0, 1.0), origin=(0.0, 0.0, 0.0), scheduler=None):
    """The one surface through a seed, grown chunk by chunk: only the chunks it crosses are read.

    Each wave is one task per chunk the surface has newly reached: it reads
    that chunk's block, tracks from the edges it was entered by (core's
    trackSurface, once per entry not already reached from another), and
    returns its pieces and the crossed edges on its shared faces. Those edges
    name the neighbouring chunks of the next wave; tracking stops when no new
    chunk is reached. The same triangles as isotrack.track.

    Args:
        array, level, spacing, origin: as for surfaces.
        seed: a point (z, y, x): the crossed edge nearest to it (searched in
            its chunk, and in wider rings of chunks only while one could hold a
            nearer edge).
        seed_edge: or a crossed grid edge (z, y, x, axis) in array indices.

    Returns:
        A TrackedSurface: vertices, faces, normals, values, triangle_count,
        vertex_count, area, volume, closed, touches_border, bounds, chunks, waves.
    """
    if (seed is None) == (seed_edge is None):
        raise ValueError("track: give exactly one of seed (a point) or seed_edge=(z, y, x, axis)")
    array, grid = _grid(array, spacing, origin)
    level = _level(level)
    start = _seed_id(array, grid, level, seed, seed_edge, scheduler)
    first_chunk = grid.chunks_of_edges(np.array([start]))[0][1]
    pending, covered, found, waves = {first_chunk: {start}}, {}, [], 0
    task = dask.delayed(_chunks.tracked_pieces, pure=True)
    while pending:
        waves += 1
        chunks = sorted(pending)
        tasks = [task(array[grid.slices(c)], c, grid, level, sorted(pending[c]), True) for c in chunks]
        results = dask.compute(*tasks, scheduler=scheduler)
        for chunk, pieces in zip(chunks, results):
            covered.setdefault(chunk, set()).update(pieces["shared"].tolist())
        found += results
        ids = np.unique(np.concatenate([r["shared"] for r in results]).astype(np.int64))
        pending = {}
        for e, chunk in grid.chunks_of_edges(ids):
            edge = int(ids[e])
            if edge not in covered.get(chunk, ()):
                pending.setdefault(chunk, set()).add(edge)
    pieces = _chunks.merged(found)
    return TrackedSurface(pieces, covered.keys(), waves)


def _main(argv=None):
    """python3 -m isotrack.dask: surfaces or one tracked surface of a zarr folder or volume file."""
    import argparse
    import contextlib

    parser = argparse.ArgumentParser(prog="python3 -m isotrack.dask", description=_main.__doc__)
    parser.add_argument("--volume", required=True, help="a zarr array folder (*.zarr) or a file isotrack.open reads")
    parser.add_argument("--iso", type=float, required=True, help="the isovalue")
    parser.add_argument("--method", choices=("all", "track", "mc"), default="all")
    parser.add_argument("--seed", help="track: Z,Y,X in the array's coordinates (index * spacing)")
    parser.add_argument("--spacing", help="Z,Y,X (default: a file's own spacing, 1,1,1 for zarr)")
    parser.add_argument("--chunks", type=int, default=64, help="chunk size for a volume file (zarr keeps its own)")
    parser.add_argument("--scheduler", help="tcp://HOST:PORT of a Dask scheduler, or local:N for N worker processes")
    parser.add_argument("--out", help="all: a folder of PLY files; track, mc: one PLY file")
    args = parser.parse_args(argv)
    triple = lambda text: tuple(float(v) for v in text.split(","))  # noqa: E731
    if args.volume.rstrip("/").endswith(".zarr"):
        array, spacing = da.from_zarr(args.volume), (1.0, 1.0, 1.0)
    else:
        from . import open as open_volume

        array, spacing = from_file(args.volume, args.chunks), open_volume(args.volume).spacing[::-1]
    spacing = triple(args.spacing) if args.spacing else spacing
    with contextlib.ExitStack() as stack:
        if args.scheduler:
            import distributed

            if args.scheduler.startswith("local:"):
                workers = int(args.scheduler[len("local:") :])
                cluster = stack.enter_context(distributed.LocalCluster(n_workers=workers, threads_per_worker=1))
                stack.enter_context(distributed.Client(cluster))
            else:
                stack.enter_context(distributed.Client(args.scheduler))
        if args.method == "all":
            table = surfaces(array, args.iso, spacing=spacing, out=args.out)
            print(f"{len(table['id'])} surfaces, {int(table['triangles'].sum())} triangles")
            for k in range(min(len(table["id"]), 10)):
                closed = "closed" if table["closed"][k] else "open"
                print(f"  {k}: {table['triangles'][k]} triangles, area {table['area'][k]:.6g}, {closed}")
            return 0
        if args.method == "track":
            if not args.seed:
                parser.error("--method track needs --seed Z,Y,X")
            found = track(array, args.iso, seed=triple(args.seed), spacing=spacing)
            print(f"{found.triangle_count} triangles, area {found.area:.6g}, {'closed' if found.closed else 'open'}, "
                  f"{len(found.chunks)} of {array.npartitions} chunks read in {found.waves} waves")
            mesh = (found.vertices, found.faces, found.normals)
        else:
            vertices, faces, normals, _ = marching_cubes(array, args.iso, spacing=spacing)
            print(f"{len(faces)} triangles")
            mesh = (vertices, faces, normals)
        if args.out:
            write_ply(args.out, *mesh)
    return 0


if __name__ == "__main__":
    raise SystemExit(_main())
