"""Typed product records: rasters, meshes, cameras, reconstructions, registration results, QC.

Numpy only. Stages return these, never bare tuples or sentinel matrices. Each checks its own
shapes on construction so a malformed product fails where it is made.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping

import numpy as np

from .errors import InvalidInputError


@dataclass(frozen=True)
class Raster:
    """A georeferenced grid.

    Attributes
    ----------
    array : (rows, cols) or (bands, rows, cols) array
        Cell values; row 0 is the northern edge.
    transform : tuple of 6 float
        Affine (a, b, c, d, e, f) in rasterio/GDAL order: x = a*col + b*row + c,
        y = d*col + e*row + f, for the upper-left corner of a cell.
    crs : str or None
    nodata : float or None
    meta : mapping
        Free-form description (kind, resolution reason, vertical accuracy...).
    """

    array: np.ndarray
    transform: tuple
    crs: str | None = None
    nodata: float | None = None
    meta: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self):
        a = np.asarray(self.array)
        if a.ndim not in (2, 3):
            raise InvalidInputError(f"raster array must be 2-D or 3-D, got {a.shape}", field="array")
        if len(tuple(self.transform)) != 6:
            raise InvalidInputError("transform needs 6 coefficients", field="transform")
        object.__setattr__(self, "transform", tuple(float(t) for t in self.transform))

    @property
    def shape(self) -> tuple[int, int]:
        return self.array.shape[-2:]

    @property
    def resolution(self) -> tuple[float, float]:
        """Cell size (x, y) in CRS units, both positive."""
        return abs(self.transform[0]), abs(self.transform[4])

    def cell_centers(self) -> tuple[np.ndarray, np.ndarray]:
        """X and Y of every cell centre as two (rows, cols) arrays."""
        rows, cols = self.shape
        a, b, c, d, e, f = self.transform
        cc, rr = np.meshgrid(np.arange(cols) + 0.5, np.arange(rows) + 0.5)
        return a * cc + b * rr + c, d * cc + e * rr + f


@dataclass(frozen=True)
class Mesh:
    """A triangle mesh.

    Attributes
    ----------
    vertices : (n, 3) float64
    faces : (m, 3) int64, indices into vertices
    vertex_attrs : mapping of str to (n, ...) arrays (``rgb`` u8 or u16, ``normal`` f4, ...)
    face_attrs : mapping of str to (m, ...) arrays (``classification``, ``material``, ``object_id``)
    crs : str or None
    """

    vertices: np.ndarray
    faces: np.ndarray
    vertex_attrs: Mapping[str, np.ndarray] = field(default_factory=dict)
    face_attrs: Mapping[str, np.ndarray] = field(default_factory=dict)
    crs: str | None = None
    meta: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self):
        v = np.asarray(self.vertices, dtype=np.float64)
        f = np.asarray(self.faces, dtype=np.int64)
        if v.ndim != 2 or v.shape[1] != 3:
            raise InvalidInputError(f"vertices must be (n, 3), got {v.shape}", field="vertices")
        if f.ndim != 2 or f.shape[1] != 3:
            raise InvalidInputError(f"faces must be (m, 3) triangles, got {f.shape}", field="faces")
        if f.size and (f.min() < 0 or f.max() >= v.shape[0]):
            raise InvalidInputError("face index out of range", field="faces")
        for k, a in self.vertex_attrs.items():
            if len(a) != v.shape[0]:
                raise InvalidInputError(f"{len(a)} values for {v.shape[0]} vertices", field=k)
        for k, a in self.face_attrs.items():
            if len(a) != f.shape[0]:
                raise InvalidInputError(f"{len(a)} values for {f.shape[0]} faces", field=k)
        object.__setattr__(self, "vertices", v)
        object.__setattr__(self, "faces", f)

    @property
    def n_vertices(self) -> int:
        return self.vertices.shape[0]

    @property
    def n_faces(self) -> int:
        return self.faces.shape[0]

    def face_areas(self) -> np.ndarray:
        t = self.vertices[self.faces]
        return 0.5 * np.linalg.norm(np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0]), axis=1)


@dataclass(frozen=True)
class Camera:
    """A pinhole camera with OpenCV distortion.

    Attributes
    ----------
    width, height : int
        Image size in pixels.
    fx, fy, cx, cy : float
        Focal lengths and principal point in pixels (pixel centres at integer coordinates,
        OpenCV convention).
    skew : float
    dist : (5,) float
        OpenCV order k1, k2, p1, p2, k3.
    model : str
        Name of the model ("OPENCV", "PINHOLE", ...).
    """

    width: int
    height: int
    fx: float
    fy: float
    cx: float
    cy: float
    skew: float = 0.0
    dist: tuple = (0.0, 0.0, 0.0, 0.0, 0.0)
    model: str = "OPENCV"

    @property
    def K(self) -> np.ndarray:
        return np.array([[self.fx, self.skew, self.cx], [0.0, self.fy, self.cy], [0.0, 0.0, 1.0]])


@dataclass(frozen=True)
class Pose:
    """World-to-camera pose: x_cam = R @ X_world + t.

    Attributes
    ----------
    R : (3, 3) float, rotation world -> camera
    t : (3,) float
    """

    R: np.ndarray
    t: np.ndarray

    @property
    def center(self) -> np.ndarray:
        """Camera centre in the world frame, -R^T t."""
        return -np.asarray(self.R).T @ np.asarray(self.t)

    @property
    def matrix(self) -> np.ndarray:
        m = np.eye(4)
        m[:3, :3] = self.R
        m[:3, 3] = self.t
        return m


@dataclass(frozen=True)
class Image:
    """One oriented image: its file, the index of its camera and its pose."""

    name: str
    camera_id: int
    pose: Pose
    path: str | None = None


@dataclass(frozen=True)
class Tracks:
    """Image observations of the sparse points of a reconstruction, one row per observation.

    Attributes
    ----------
    point : (m,) int64
        Row of the observed point in ``Reconstruction.points``.
    image : (m,) int64
        Id of the observing image (a key of ``Reconstruction.images``).
    uv : (m, 2) float64
        Measured pixel, OpenCV convention (origin at the centre of the top-left pixel).
    """

    point: np.ndarray
    image: np.ndarray
    uv: np.ndarray

    def __post_init__(self):
        p = np.asarray(self.point, dtype=np.int64).reshape(-1)
        i = np.asarray(self.image, dtype=np.int64).reshape(-1)
        uv = np.asarray(self.uv, dtype=np.float64)
        if uv.shape != (p.shape[0], 2) or i.shape != p.shape:
            raise InvalidInputError(f"tracks need (m,) point, (m,) image and (m, 2) uv, got {p.shape}, {i.shape}, {uv.shape}")
        for name, a in (("point", p), ("image", i), ("uv", uv)):
            a.setflags(write=False)
            object.__setattr__(self, name, a)

    def __len__(self) -> int:
        return int(self.point.shape[0])


@dataclass(frozen=True)
class Reconstruction:
    """Cameras, oriented images and (optionally) sparse points with colours.

    Attributes
    ----------
    cameras : mapping of int to Camera
    images : mapping of int to Image
    points : (n, 3) float64 or None
    colors : (n, 3) uint8 or None
    crs : str or None
        Set once the reconstruction is georeferenced.
    meta : mapping
    tracks : Tracks or None
        Image observations of ``points`` (needed by a bundle adjustment); None when not loaded.
    """

    cameras: Mapping[int, Camera]
    images: Mapping[int, Image]
    points: np.ndarray | None = None
    colors: np.ndarray | None = None
    crs: str | None = None
    meta: Mapping[str, Any] = field(default_factory=dict)
    tracks: Tracks | None = None


@dataclass(frozen=True)
class RegistrationResult:
    """The outcome of registering SOURCE to TARGET.

    Attributes
    ----------
    transform : (4, 4) float
        Maps source points into the target frame (scale included for 7-DoF results).
    scale : float
        Similarity scale (1.0 for rigid).
    fitness : float
        Share of source points with a correspondence within the distance threshold.
    inlier_rmse : float
        RMS distance of the inlier correspondences, in target units.
    converged : bool
    correspondences : int
    information : (6, 6) float or None
    meta : mapping
    """

    transform: np.ndarray
    scale: float = 1.0
    fitness: float = 0.0
    inlier_rmse: float = float("nan")
    converged: bool = False
    correspondences: int = 0
    information: np.ndarray | None = None
    meta: Mapping[str, Any] = field(default_factory=dict)

    def __post_init__(self):
        T = np.asarray(self.transform, dtype=np.float64)
        if T.shape != (4, 4):
            raise InvalidInputError(f"transform must be 4x4, got {T.shape}", field="transform")
        object.__setattr__(self, "transform", T)

    def to_dict(self) -> dict:
        return {
            "transform": self.transform.tolist(),
            "scale": float(self.scale),
            "fitness": float(self.fitness),
            "inlier_rmse": float(self.inlier_rmse),
            "converged": bool(self.converged),
            "correspondences": int(self.correspondences),
            **({"information": np.asarray(self.information).tolist()} if self.information is not None else {}),
            **{k: v for k, v in self.meta.items() if isinstance(v, (int, float, str, bool, list, dict))},
        }


@dataclass(frozen=True)
class QCReport:
    """Quality-control figures: named metrics, tables and notes."""

    metrics: Mapping[str, Any] = field(default_factory=dict)
    tables: Mapping[str, list] = field(default_factory=dict)
    notes: tuple = ()
