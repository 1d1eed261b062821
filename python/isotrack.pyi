"""Isosurfaces of 3D numpy arrays: isotrack's marching cubes and surface tracking.

Arrays are indexed (z, y, x); coordinates are (z, y, x) tuples. See help(isotrack).
"""
from typing import List, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

Volume = npt.NDArray[
    Union[np.uint8, np.int8, np.uint16, np.int16, np.uint32, np.int32, np.float32, np.float64]
]
Triple = Tuple[float, float, float]
Table = Literal["consistent", "classic", "trilinear"]

class Surface:
    """One isosurface: an indexed triangle mesh (numpy views, no copy) and its measures."""

    @property
    def vertices(self) -> npt.NDArray[np.float32]:
        """(V, 3) vertex positions in (z, y, x), world units."""
    @property
    def normals(self) -> npt.NDArray[np.float32]:
        """(V, 3) unit normals in (z, y, x), pointing towards lower values."""
    @property
    def faces(self) -> npt.NDArray[np.uint32]:
        """(F, 3) vertex indices, one row per triangle."""
    @property
    def triangle_count(self) -> int: ...
    @property
    def vertex_count(self) -> int: ...
    @property
    def area(self) -> float: ...
    @property
    def volume(self) -> Optional[float]:
        """Enclosed volume of a closed surface, else None."""
    @property
    def closed(self) -> bool: ...
    @property
    def touches_border(self) -> bool: ...
    @property
    def bounds(self) -> Tuple[Triple, Triple]:
        """((zmin, ymin, xmin), (zmax, ymax, xmax)) in world units."""
    @property
    def cells_visited(self) -> int: ...
    @property
    def nbytes(self) -> int: ...
    @property
    def seconds(self) -> float: ...
    def __len__(self) -> int: ...

MeshTuple = Tuple[
    npt.NDArray[np.float32], npt.NDArray[np.uint32], npt.NDArray[np.float32], npt.NDArray[np.float32]
]

@overload
def marching_cubes(
    volume: Volume,
    level: Optional[float] = None,
    *,
    spacing: Sequence[float] = (1.0, 1.0, 1.0),
    method: Literal["mc", "lewiner", "lorensen"] = "mc",
    table: Table = "consistent",
    threads: int = 0,
    origin: Sequence[float] = (0.0, 0.0, 0.0),
) -> MeshTuple: ...
@overload
def marching_cubes(
    volume: Volume,
    level: Optional[float] = None,
    *,
    spacing: Sequence[float] = (1.0, 1.0, 1.0),
    method: Literal["all"],
    table: Table = "consistent",
    threads: int = 0,
    origin: Sequence[float] = (0.0, 0.0, 0.0),
) -> List[Surface]: ...
def track(
    volume: Volume,
    level: float,
    *,
    seed: Optional[Sequence[float]] = None,
    seed_edge: Optional[Sequence[int]] = None,
    spacing: Sequence[float] = (1.0, 1.0, 1.0),
    table: Table = "consistent",
    threads: int = 0,
    origin: Sequence[float] = (0.0, 0.0, 0.0),
) -> Surface: ...
def surfaces(
    volume: Volume,
    level: float,
    *,
    spacing: Sequence[float] = (1.0, 1.0, 1.0),
    table: Table = "consistent",
    threads: int = 0,
    origin: Sequence[float] = (0.0, 0.0, 0.0),
) -> List[Surface]: ...
def load(path: str) -> Tuple[np.ndarray, Triple, Triple]: ...
def write_ply(surface: Surface, path: str) -> None: ...
def write_obj(surface: Surface, path: str) -> None: ...
def write_stl(surface: Surface, path: str) -> None: ...
