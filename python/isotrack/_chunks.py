"""What a Dask task does with one chunk of a volume: the worker half of isotrack.dask.

Nothing here imports Dask: a worker needs numpy and isotrack only. A chunk owns
the cells [lo, hi) of the volume along each axis; it reads the samples [lo, hi]
(its own and one more on the high side, where the next chunk starts), so its
cells are exactly its own and the chunks' cells together are the volume's. With
the consistent table a cell's triangles depend only on its eight samples, so the
chunks' triangles are the whole volume's.

A crossed grid edge is named globally by core (isotrack/chunks.h: its memory
order, ((z * ny + y) * nx + x) * 3 + axis with axis 0 along x, the order core
breaks ties between equal-sized surfaces by), which also says which edges lie on
faces a chunk shares. An edge on a face two chunks share is the same edge, and
the same vertex, for both: pieces that share one are one surface.
"""

import numpy as np

from . import _inputs
from . import _isotrack
from ._isotrack import Geometry as _Geometry

_IDENTITY = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))
_EMPTY = np.zeros(0, dtype=np.int64)


class Grid:
    """A chunked volume's layout: its shape, chunk starts and geometry, all (z, y, x)."""

    def __init__(self, shape, chunks, spacing, origin):
        self.shape = tuple(int(n) for n in shape)
        self.starts = tuple(np.concatenate([[0], np.cumsum(c)[:-1]]).astype(np.int64) for c in chunks)
        self.sizes = tuple(np.asarray(c, dtype=np.int64) for c in chunks)
        self.spacing = np.asarray(spacing, dtype=np.float64)
        self.origin = np.asarray(origin, dtype=np.float64)

    def chunk_indices(self):
        """Every chunk (i, j, k) that owns at least one cell."""
        ranges = [[i for i in range(len(s)) if s[i] < n - 1] for s, n in zip(self.starts, self.shape)]
        return [(i, j, k) for i in ranges[0] for j in ranges[1] for k in ranges[2]]

    def samples_of(self, chunk):
        """(lo, hi): the samples [lo, hi) the chunk reads, its own and one more on the high side."""
        lo = np.array([s[c] for s, c in zip(self.starts, chunk)], dtype=np.int64)
        size = np.array([s[c] for s, c in zip(self.sizes, chunk)], dtype=np.int64)
        return lo, np.minimum(lo + size + 1, self.shape)

    def slices(self, chunk):
        lo, hi = self.samples_of(chunk)
        return tuple(slice(int(a), int(b)) for a, b in zip(lo, hi))

    def chunks_of_edges(self, ids):
        """For each global edge id, the chunks whose samples hold the whole edge: (edge index, chunk) pairs."""
        z, y, x, axis = decode(ids, self.shape)
        coordinates, found = (z, y, x), []
        per_axis = []
        for a in range(3):
            c = coordinates[a]
            along = axis == a  # the edge runs from c to c + 1 along this axis: only the chunk owning cell c
            starts, last = self.starts[a], len(self.starts[a]) - 1
            owner = np.clip(np.searchsorted(starts, c, side="right") - 1, 0, last)
            below = np.where(~along & (owner > 0) & (starts[np.minimum(owner, last)] == c), owner - 1, -1)
            per_axis.append((owner, below))
        owns_cells = [s < n - 1 for s, n in zip(self.starts, self.shape)]
        for e in range(len(ids)):
            options = [[c for c in (o[e], b[e]) if c >= 0 and owns[c]] for (o, b), owns in zip(per_axis, owns_cells)]
            found += [(e, (i, j, k)) for i in options[0] for j in options[1] for k in options[2]]
        return found


def encode(z, y, x, axis_zyx, shape):
    """Core's global edge ids (isotrack/chunks.h) of global (z, y, x) and an axis in (z, y, x) order."""
    edges = np.stack([np.asarray(v, dtype=np.int64) for v in (z, y, x, axis_zyx)], axis=1)
    return _isotrack.edge_ids(edges.reshape(-1, 4), tuple(int(n) for n in shape))


def decode(ids, shape):
    """(z, y, x, axis in (z, y, x) order) of core's global edge ids."""
    edges = _isotrack.edges_of_ids(np.asarray(ids, dtype=np.int64).ravel(), tuple(int(n) for n in shape))
    return edges[:, 0], edges[:, 1], edges[:, 2], edges[:, 3]


def _geometry(grid, lo):
    origin = grid.origin + lo * grid.spacing
    return _Geometry(tuple(grid.spacing[::-1]), tuple(origin[::-1]), _IDENTITY, "")


def pieces_of(found, block, grid, lo, hi, meshes):
    """The compact figures of one chunk's surface pieces, as arrays with one row per piece.

    triangles, vertices, area, signed_volume (about the volume's origin: additive
    over pieces), bounds (P, 2, 3), first_edge (the piece's first grid edge in
    memory order), touches_border, and the crossed edges on faces shared with
    other chunks as shared (global ids) with shared_piece (their piece's row).
    With `meshes`, "mesh": (vertices, normals, edge ids, values, faces,
    face_piece), faces indexing the chunk's vertices.
    """
    shape = tuple(int(b - a) for a, b in zip(lo, hi))
    vertices, normals, local, faces, sizes, triangles, area, bounds, signed, ids, shared, border = (
        _isotrack.concatenated(list(found), tuple(grid.origin), tuple(int(v) for v in lo), shape, grid.shape)
    )
    count = len(sizes)
    label = np.repeat(np.arange(count), sizes)
    offsets = np.concatenate([[0], np.cumsum(sizes)[:-1]]).astype(np.int64)
    faces = faces.astype(np.int64)
    face_piece = np.repeat(np.arange(count), triangles)
    result = {
        "triangles": triangles,
        "vertices": sizes,
        "area": area,
        "signed_volume": signed,
        "bounds": bounds,
        "first_edge": np.minimum.reduceat(ids, offsets) if count else _EMPTY,
        "touches_border": np.bincount(label, border, minlength=count) > 0,
        "shared": ids[shared],
        "shared_piece": label[shared],
    }
    if meshes:
        result["mesh"] = (vertices, normals, ids, _edge_values(block, local), faces, face_piece)
    return result


def _edge_values(block, local):
    """Per vertex, the larger of the samples at its edge's two ends (scikit-image's `values` slot)."""
    z, y, x, axis = (local[:, a] for a in range(4))
    first = block[z, y, x]
    second = block[z + (axis == 0), y + (axis == 1), x + (axis == 2)]
    return np.maximum(first, second).astype(np.float32)


def _readable(block):
    return _inputs.samples_of(np.asarray(block))


def surface_pieces(block, chunk, grid, level, meshes):
    """Every connected piece of the surfaces within one chunk's cells."""
    lo, hi = grid.samples_of(chunk)
    samples = _readable(block)
    found = []
    if min(samples.shape) >= 2:
        found = _isotrack.marching_cubes(samples, level, _geometry(grid, lo), "consistent", 1, None, True, False, True)
    return pieces_of(found, samples, grid, lo, hi, meshes)


def tracked_pieces(block, chunk, grid, level, entries, meshes):
    """The pieces within one chunk reached from its entry edges (global ids), each tracked once."""
    lo, hi = grid.samples_of(chunk)
    samples = _readable(block)
    geometry = _geometry(grid, lo)
    entries = np.asarray(sorted(entries), dtype=np.int64)
    z, y, x, axis = decode(entries, grid.shape)
    reached = np.zeros(len(entries), dtype=bool)
    found = []
    for k, edge in enumerate(zip(z - lo[0], y - lo[1], x - lo[2], axis)):
        if reached[k]:
            continue  # on a piece already tracked from an earlier entry
        surface = _isotrack.track(samples, level, geometry, "consistent", 1, None, tuple(int(v) for v in edge), False)
        e = surface.vertex_edges.astype(np.int64)
        reached |= np.isin(entries, encode(e[:, 0] + lo[0], e[:, 1] + lo[1], e[:, 2] + lo[2], e[:, 3], grid.shape))
        found.append(surface)
    return pieces_of(found, samples, grid, lo, hi, meshes)


def nearest_edge(block, lo, grid, level, point):
    """The crossed edge of a block nearest a (z, y, x) point: its global id and world distance."""
    samples = _readable(block)
    z, y, x, axis = _isotrack.nearest_edge(samples, level, _geometry(grid, lo), tuple(point))
    middle = grid.origin + (np.array([z, y, x], dtype=np.float64) + lo + 0.5 * (np.arange(3) == axis)) * grid.spacing
    ids = encode(np.array([z + lo[0]]), np.array([y + lo[1]]), np.array([x + lo[2]]), np.array([axis]), grid.shape)
    return int(ids[0]), float(np.linalg.norm(middle - np.asarray(point, dtype=np.float64)))


def merged(results):
    """The pieces of many chunks (pieces_of's dicts) as one, piece rows renumbered."""
    keys = ("triangles", "vertices", "area", "signed_volume", "bounds", "first_edge", "touches_border", "shared")
    out = {k: np.concatenate([r[k] for r in results]) if results else np.zeros(0) for k in keys}
    counts = [len(r["triangles"]) for r in results]
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]]).astype(np.int64) if results else []
    out["shared_piece"] = np.concatenate([r["shared_piece"] + s for r, s in zip(results, starts)] + [_EMPTY])
    out["shared"] = out["shared"].astype(np.int64)
    out["bounds"] = out["bounds"].reshape(-1, 2, 3)
    if results and "mesh" in results[0]:
        firsts = np.concatenate([[0], np.cumsum([len(r["mesh"][0]) for r in results])[:-1]]).astype(np.int64)
        mesh = [np.concatenate([r["mesh"][k] for r in results]) for k in range(4)]
        faces = np.concatenate([r["mesh"][4] + f for r, f in zip(results, firsts)])
        face_piece = np.concatenate([r["mesh"][5] + s for r, s in zip(results, starts)])
        out["mesh"] = (*mesh, faces, face_piece)
    return out
