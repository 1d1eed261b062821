"""Isosurfaces of 3D volumes: isotrack's marching cubes and surface tracking.

Raw arrays are indexed (z, y, x) and their coordinates are (z, y, x); a Volume
(isotrack.load) gives world (x, y, z) in its frame. See help(isotrack).
"""
import os
from typing import Any, Dict, Iterator, List, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

Triple = Tuple[float, float, float]
Frame = Literal["lps", "ras", "voxel"]
Table = Literal["consistent", "classic", "trilinear", "snap"]
GradientDirection = Literal["descent", "ascent"]
# Any real or bool dtype, any strides, or anything np.asarray takes.
ArrayInput = Union[npt.ArrayLike, Any]

class Volume:
    """Samples and where they lie, as isotrack.load reads them."""

    samples: npt.NDArray[Any]
    """(nz, ny, nx), indexed (z, y, x), the file's sample type; a view (no copy)."""
    frame: Frame
    affine: npt.NDArray[np.float64]
    """4x4: index (i, j, k, 1), i along x, to world (x, y, z, 1) in the frame."""
    spacing: Triple
    """(x, y, z) distances between samples, world units."""
    origin: Triple
    """(x, y, z) world position of samples[0, 0, 0] in the frame."""
    direction: npt.NDArray[np.float64]
    """3x3, columns the unit world vectors of i, j, k in the frame."""
    path: str
    @property
    def dims(self) -> Tuple[int, int, int]:
        """(nx, ny, nz)."""
    @property
    def shape(self) -> Tuple[int, int, int]: ...
    @property
    def dtype(self) -> np.dtype[Any]: ...
    def in_frame(self, frame: Frame) -> "Volume": ...

VolumeInput = Union[Volume, ArrayInput]

class Surface:
    """One isosurface: an indexed triangle mesh (numpy views, no copy) and its measures.

    Coordinates are (z, y, x) for a raw array's surface, world (x, y, z) in the frame for a Volume's.
    """

    @property
    def vertices(self) -> npt.NDArray[np.float32]:
        """(V, 3) vertex positions."""
    @property
    def normals(self) -> npt.NDArray[np.float32]:
        """(V, 3) unit normals, pointing towards lower values."""
    @property
    def vertex_edges(self) -> npt.NDArray[np.int32]:
        """(V, 4) per vertex its grid edge (z, y, x, axis), axis 0 along z, as seed_edge takes it (a copy)."""
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
        """(lowest, highest) corner, in the vertices' coordinates."""
    @property
    def cells_visited(self) -> int: ...
    @property
    def nbytes(self) -> int: ...
    @property
    def seconds(self) -> float: ...
    @property
    def degenerate_triangles(self) -> int: ...
    @property
    def boundary_edges(self) -> int: ...
    @property
    def non_manifold_edges(self) -> int: ...
    @property
    def min_angle_fractions(self) -> Tuple[float, float, float]: ...
    def __len__(self) -> int: ...

MeshTuple = Tuple[
    npt.NDArray[np.float32], npt.NDArray[np.uint32], npt.NDArray[np.float32], npt.NDArray[np.float32]
]

@overload
def marching_cubes(
    volume: VolumeInput,
    level: Optional[float] = None,
    *,
    spacing: Optional[Sequence[float]] = None,
    gradient_direction: GradientDirection = "descent",
    step_size: int = 1,
    allow_degenerate: bool = True,
    method: Literal["mc", "lewiner", "lorensen"] = "mc",
    mask: Optional[npt.ArrayLike] = None,
    table: Table = "consistent",
    threads: int = 0,
    origin: Optional[Sequence[float]] = None,
) -> MeshTuple: ...
@overload
def marching_cubes(
    volume: VolumeInput,
    level: Optional[float] = None,
    *,
    spacing: Optional[Sequence[float]] = None,
    gradient_direction: GradientDirection = "descent",
    step_size: int = 1,
    allow_degenerate: Literal[True] = True,
    method: Literal["all"],
    mask: None = None,
    table: Table = "consistent",
    threads: int = 0,
    origin: Optional[Sequence[float]] = None,
    cap: bool = False,
    smooth: int = 0,
    passband: float = 0.1,
    decimate: float = 1.0,
    decimate_error: Optional[float] = None,
) -> List[Surface]: ...
def track(
    volume: VolumeInput,
    level: Optional[float] = None,
    *,
    seed: Optional[Sequence[float]] = None,
    seed_edge: Optional[Sequence[int]] = None,
    spacing: Optional[Sequence[float]] = None,
    table: Table = "consistent",
    threads: int = 0,
    origin: Optional[Sequence[float]] = None,
    cap: bool = False,
    smooth: int = 0,
    passband: float = 0.1,
    decimate: float = 1.0,
    decimate_error: Optional[float] = None,
) -> Surface: ...
def surfaces(
    volume: VolumeInput,
    level: Optional[float] = None,
    *,
    spacing: Optional[Sequence[float]] = None,
    table: Table = "consistent",
    threads: int = 0,
    origin: Optional[Sequence[float]] = None,
    cap: bool = False,
    smooth: int = 0,
    passband: float = 0.1,
    decimate: float = 1.0,
    decimate_error: Optional[float] = None,
) -> List[Surface]: ...
def load(
    path: Union[str, os.PathLike[str]], frame: Frame = "lps", *, time: int = 0, array: Optional[str] = None
) -> Volume: ...
def steps(path: Union[str, os.PathLike[str]]) -> List[float]: ...
def load_steps(
    path: Union[str, os.PathLike[str]], frame: Frame = "lps", *, array: Optional[str] = None
) -> Iterator[Tuple[float, Volume]]:
    """Every step in turn as (time, Volume), the next read in the background."""
def follow_through_time(
    path: Union[str, os.PathLike[str]],
    level: Optional[float] = None,
    *,
    method: Literal["all", "tree", "track"] = "all",
    seed: Optional[Sequence[float]] = None,
    frame: Frame = "lps",
    array: Optional[str] = None,
    table: Table = "consistent",
    threads: int = 0,
    min_persistence: float = 0.0,
    min_size: int = 0,
    surfaces: bool = False,
) -> Dict[str, Any]:
    """Every surface of every step with an id that lasts: the records of extract --all-times' track.json."""
def open(
    path: Union[str, os.PathLike[str]], frame: Frame = "lps", *, time: int = 0, array: Optional[str] = None
) -> Volume:
    """load(), with uncompressed samples left in their file (a read-only memory map)."""
def write_ply(surface: Surface, path: Union[str, os.PathLike[str]]) -> None: ...
def write_obj(surface: Surface, path: Union[str, os.PathLike[str]]) -> None: ...
def write_stl(surface: Surface, path: Union[str, os.PathLike[str]]) -> None: ...
