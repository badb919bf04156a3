"""Upright models: the gravity direction and main façade of an SfM reconstruction.

An SfM model comes out in an arbitrary frame (COLMAP fixes it to the first image pair). This
module finds the vertical and the main façade from the model alone and returns the rotation
that makes z point up and the façade face -y, as COLMAP's ``model_orientation_aligner`` does
(Schönberger, *Robust Methods for Accurate and Efficient 3D Modeling from Unstructured
Imagery*, PhD thesis, ETH Zürich 2018; COLMAP ``EstimateGravityVectorFromImageOrientation``):

1. **Image orientation.** People hold cameras upright: the image's -y axis (up in the photo)
   is close to the world's up, whatever the camera looks at. Each image's down axis (the
   second row of its world-to-camera rotation) votes; the vote with the most others within a
   cosine distance of ``max_axis_distance`` (COLMAP's 0.05) wins and its inliers are averaged
   (a consensus mean, robust to portrait and tilted shots).
2. **Horizon refinement.** The mean up vector leans by the common pitch of the photos (a
   camera looking up at a façade leans its up axis backwards). The image rows (the camera x
   axes) of upright photos are horizontal whatever the pitch, so the vertical is refined as
   the direction most orthogonal to the x axes, in the least-squares sense, with the mean up
   vector as a prior: minimise ``Σ (x_i·g)² / σ_roll² + |g - (g·g₀) g₀|² / σ_pitch²``
   (an eigenvector problem), iteratively reweighted (Cauchy) so that tilted photos do not
   pull it. Portrait photos take their y axis as the horizontal one.
3. **Nadir blocks.** When every optical axis lies within ``NADIR_BLOCK_SPREAD_DEG`` of one
   direction (an aerial block), the photos are not upright: the vertical is the mean viewing
   direction reversed.
4. **Main façade.** In the levelled frame, the sparse points' normals (principal axes of
   their ``k`` nearest neighbours) that are near horizontal vote for the azimuth of the
   dominant vertical plane (an axial histogram, 2° bins, peak refined by the axial mean of
   its ±10° neighbourhood). Its outward side is the one the cameras stand on (or, with cameras
   all around, the side with more points). Without points, the façade faces the cameras' mean
   horizontal viewing direction.

The result is a rotation about the centroid of the camera centres (no scale change, the
model's units are kept): ``X' = R (X - c) + c``, as a
:class:`~workstation.photogrammetry.georef.Similarity` with ``scale = 1``.

Examples
--------
>>> from workstation.photogrammetry.rigs import look_at
>>> from workstation.core.products import Camera, Image, Reconstruction
>>> cam = Camera(640, 480, 500.0, 500.0, 319.5, 239.5)
>>> centres = [[20 * np.cos(a), 20 * np.sin(a), 2.0] for a in np.linspace(0, 2 * np.pi, 12, endpoint=False)]
>>> imgs = {k + 1: Image(f"{k}.jpg", 1, look_at(np.array(c), np.array([0, 0, 5.0]))) for k, c in enumerate(centres)}
>>> o = estimate_orientation(Reconstruction({1: cam}, imgs))
>>> np.round(o.up, 6).tolist() == [0, 0, 1], round(o.tilt_deg, 6)
(True, 0.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger
from workstation.core.pca import local_pca
from workstation.core.products import Image, Reconstruction

from .georef import Similarity

log = get_logger(__name__)

NADIR_BLOCK_SPREAD_DEG = 10.0  # as photogrammetry.sfm: optical axes all within this of their mean
FACADE_FACING = ("-y", "+y")


@dataclass(frozen=True)
class OrientParams:
    """Settings of :func:`estimate_orientation`.

    Attributes
    ----------
    max_axis_distance : float
        Cosine distance (1 - cos angle, unitless) under which two images' down axes agree in
        the consensus vote (COLMAP's default 0.05, about 18°).
    roll_sigma_deg : float
        Expected roll of hand-held or tripod photos, degrees: the weight of the horizontal
        image rows in the refinement.
    pitch_sigma_deg : float
        Expected common pitch of the photos, degrees: the weight of the mean up vector (the
        prior) in the refinement.
    iterations : int
        Reweighting iterations of the refinement.
    assume : {"auto", "upright", "nadir"}
        ``upright``: photos held upright (façades, objects); ``nadir``: an aerial block
        looking down; ``auto``: nadir when every optical axis lies within
        ``NADIR_BLOCK_SPREAD_DEG`` of their mean, else upright.
    facade : {"auto", "points", "cameras", "none"}
        How the main façade is found: from the points' normals (``auto`` falls back to the
        cameras when there are too few vertical-plane points), from the cameras' mean
        viewing direction, or not at all (the rotation then only levels the model).
    facing : {"-y", "+y"}
        Direction the façade's outward normal points to after the rotation.
    normal_neighbors : int
        Neighbours (count) of the PCA normal of a sparse point.
    vertical_plane_deg : float
        Normals within this angle of the horizontal (degrees) count as vertical-plane points.
    min_facade_points : int
        Fewest vertical-plane points (count) for a façade from the points.
    max_points : int
        Points used for the façade (a seeded random subset above it, count).
    """

    max_axis_distance: float = 0.05
    roll_sigma_deg: float = 2.0
    pitch_sigma_deg: float = 15.0
    iterations: int = 5
    assume: str = "auto"
    facade: str = "auto"
    facing: str = "-y"
    normal_neighbors: int = 12
    vertical_plane_deg: float = 20.0
    min_facade_points: int = 30
    max_points: int = 100_000

    def __post_init__(self):
        if self.assume not in ("auto", "upright", "nadir"):
            raise InvalidInputError(f"assume must be auto, upright or nadir, got {self.assume!r}", field="assume")
        if self.facade not in ("auto", "points", "cameras", "none"):
            raise InvalidInputError(f"facade must be auto, points, cameras or none, got {self.facade!r}",
                                    field="facade")
        if self.facing not in FACADE_FACING:
            raise InvalidInputError(f"facing must be -y or +y, got {self.facing!r}", field="facing")
        if not 0 < self.max_axis_distance < 1 or self.roll_sigma_deg <= 0 or self.pitch_sigma_deg <= 0:
            raise InvalidInputError("max_axis_distance must be in (0, 1) and the sigmas positive")
        if self.normal_neighbors < 3:
            raise InvalidInputError("normal_neighbors must be >= 3", field="normal_neighbors")


@dataclass(frozen=True)
class Orientation:
    """The upright frame of a reconstruction.

    Attributes
    ----------
    similarity : Similarity
        ``X_upright = R (X - c) + c`` as ``scale = 1, R, t = c - R c`` (model units kept).
    up : (3,) float
        Unit up vector in the input frame.
    facade_normal : (3,) float or None
        Unit outward normal of the main façade in the input frame (horizontal), or None.
    tilt_deg : float
        Angle between the input frame's z axis and ``up``, degrees.
    method : str
        ``image-orientation`` (upright photos) or ``nadir`` (aerial block).
    facade_source : str
        ``points``, ``cameras`` or ``none``.
    inliers : int
        Images that agreed on the vertical (consensus inliers).
    """

    similarity: Similarity
    up: np.ndarray
    facade_normal: np.ndarray | None
    tilt_deg: float
    method: str
    facade_source: str
    inliers: int

    @property
    def R(self) -> np.ndarray:
        return np.asarray(self.similarity.R)

    def to_meta(self) -> dict[str, Any]:
        """Scalar entries for ``Reconstruction.meta`` and cameras.json."""
        return {"upright": True, "upright_method": self.method, "upright_tilt_deg": round(float(self.tilt_deg), 4),
                "upright_facade": self.facade_source, "upright_inliers": int(self.inliers),
                "upright_R": " ".join(f"{v:.12g}" for v in self.R.ravel()),
                "upright_t": " ".join(f"{v:.12g}" for v in np.asarray(self.similarity.t))}


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _rotations(rec: Reconstruction) -> np.ndarray:
    if not rec.images:
        raise InvalidInputError("the reconstruction has no oriented images", "run ws sfm first")
    return np.stack([np.asarray(im.pose.R, dtype=float) for im in rec.images.values()])


def consensus_axis(axes: np.ndarray, max_axis_distance: float = 0.05) -> tuple[np.ndarray, np.ndarray]:
    """The consensus mean of unit vectors (COLMAP's ``FindBestConsensusAxis``).

    Each vector is a candidate; the one with the most vectors within ``max_axis_distance``
    (1 - cos) wins and its inliers are averaged.

    Returns
    -------
    axis : (3,) float, unit
    inliers : (n,) bool
    """
    a = _unit(np.asarray(axes, dtype=float))
    cand = a if a.shape[0] <= 2000 else a[np.random.default_rng(0).choice(a.shape[0], 2000, replace=False)]
    close = (1.0 - cand @ a.T) < max_axis_distance  # (candidates, n), memory bounded by 2000 n
    best = int(np.argmax(close.sum(axis=1)))
    inl = close[best]
    return _unit(a[inl].mean(axis=0)), inl


def _refine_up(x_axes: np.ndarray, y_axes: np.ndarray, g0: np.ndarray, params: OrientParams) -> np.ndarray:
    """Refine the up vector with the horizontal image rows (see the module docstring, step 2)."""
    sr2 = math.radians(params.roll_sigma_deg) ** 2
    lam = 1.0 / math.radians(params.pitch_sigma_deg) ** 2
    g = g0
    for _ in range(max(1, params.iterations)):
        portrait = np.abs(x_axes @ g) > np.abs(y_axes @ g)
        h = np.where(portrait[:, None], y_axes, x_axes)  # each image's horizontal axis
        r2 = (h @ g) ** 2
        w = 1.0 / (1.0 + r2 / sr2)  # Cauchy weights: tilted photos count less
        M = (h * (w / sr2)[:, None]).T @ h + lam * (np.eye(3) - np.outer(g0, g0))
        vals, vecs = np.linalg.eigh(M)
        g_new = vecs[:, 0] * np.sign(vecs[:, 0] @ g0)
        if np.arccos(np.clip(g_new @ g, -1, 1)) < 1e-10:
            return g_new
        g = g_new
    return g


def estimate_up(rec: Reconstruction, params: OrientParams = OrientParams()) -> tuple[np.ndarray, str, int]:
    """The unit up vector of a reconstruction's frame (steps 1-3 of the module docstring).

    Returns
    -------
    up : (3,) float
    method : str
        ``image-orientation`` or ``nadir``.
    inliers : int
        Images in the consensus.
    """
    Rs = _rotations(rec)
    views = Rs[:, 2, :]  # optical axes in the world
    spread = _viewing_spread_deg(views)
    nadir = params.assume == "nadir" or (
        params.assume == "auto" and len(views) >= 2 and spread < NADIR_BLOCK_SPREAD_DEG)
    if nadir:
        axis, inl = consensus_axis(views, params.max_axis_distance)
        return -axis, "nadir", int(inl.sum())
    down, inl = consensus_axis(Rs[:, 1, :], params.max_axis_distance)
    g0 = -down
    up = _refine_up(Rs[inl, 0, :], Rs[inl, 1, :], g0, params) if inl.sum() >= 2 else g0
    return up, "image-orientation", int(inl.sum())


def _viewing_spread_deg(views: np.ndarray) -> float:
    """Largest angle between an optical axis and their mean direction, degrees."""
    m = views.mean(axis=0)
    if np.linalg.norm(m) < 1e-9:
        return 180.0
    return float(np.degrees(np.arccos(np.clip(views @ _unit(m), -1, 1))).max())


def level_rotation(up: np.ndarray) -> np.ndarray:
    """The smallest rotation (3, 3) taking the unit vector ``up`` to +z (Rodrigues)."""
    u = _unit(np.asarray(up, dtype=float))
    z = np.array([0.0, 0.0, 1.0])
    v, c = np.cross(u, z), float(u @ z)
    if np.linalg.norm(v) < 1e-15:
        return np.eye(3) if c > 0 else np.diag([1.0, -1.0, -1.0])
    K = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + K + K @ K / (1.0 + c)


def point_normals(points: np.ndarray, k: int = 12) -> np.ndarray:
    """Unit (unsigned) normals of points: the least principal axis of each point's k nearest
    neighbours (Hoppe et al. 1992, "Surface reconstruction from unorganized points")."""
    return local_pca(points, k=k, orient=None).normals


def _dominant_azimuth(normals_h: np.ndarray) -> float:
    """Azimuth (radians, mod π) of the most common horizontal normal direction (axial data)."""
    theta = np.mod(np.arctan2(normals_h[:, 1], normals_h[:, 0]), np.pi)
    nb = 90  # 2° bins
    hist = np.bincount(np.minimum((theta / np.pi * nb).astype(int), nb - 1), minlength=nb).astype(float)
    smooth = sum(np.roll(hist, s) for s in (-2, -1, 0, 1, 2))  # circular (axial) window of ±4°
    peak = (np.argmax(smooth) + 0.5) * np.pi / nb
    d = np.angle(np.exp(2j * (theta - peak))) / 2  # axial difference in (-π/2, π/2]
    near = np.abs(d) < math.radians(10)
    return float(peak + np.angle(np.exp(2j * d[near]).mean()) / 2)


def _facade_from_points(P: np.ndarray, centres: np.ndarray, params: OrientParams) -> np.ndarray | None:
    """Outward horizontal normal (levelled frame) of the dominant vertical plane, or None."""
    if P.shape[0] > params.max_points:
        P = P[np.random.default_rng(0).choice(P.shape[0], params.max_points, replace=False)]
    if P.shape[0] < max(params.min_facade_points, params.normal_neighbors):
        return None
    nrm = point_normals(P, params.normal_neighbors)
    vert = np.abs(nrm[:, 2]) < math.sin(math.radians(params.vertical_plane_deg))
    if vert.sum() < params.min_facade_points:
        return None
    az = _dominant_azimuth(nrm[vert])
    n = np.array([math.cos(az), math.sin(az), 0.0])
    on_plane = vert & (np.abs(nrm[:, :2] @ n[:2]) > math.cos(math.radians(10)))
    p_mean = P[on_plane].mean(axis=0)
    cam_side = np.sign((centres[:, :2] - p_mean[:2]) @ n[:2])
    if abs(cam_side.mean()) > 0.5:  # most cameras stand on one side of the façade
        return n * np.sign(cam_side.mean())
    pts_side = np.sign((P[on_plane, :2] - P[:, :2].mean(axis=0)) @ n[:2])
    return n * (1.0 if pts_side.sum() >= 0 else -1.0)


def _facade_from_cameras(views_levelled: np.ndarray) -> np.ndarray | None:
    """Façade normal facing the cameras' mean horizontal viewing direction, or None when the
    cameras look all around (their mean horizontal direction is shorter than 0.5)."""
    h = views_levelled[:, :2]
    h = h[np.linalg.norm(h, axis=1) > 1e-9]
    if h.shape[0] == 0:
        return None
    m = _unit(h).mean(axis=0)
    if np.linalg.norm(m) < 0.5:
        return None
    m = m / np.linalg.norm(m)
    return np.array([-m[0], -m[1], 0.0])


def estimate_orientation(rec: Reconstruction, params: OrientParams = OrientParams(),
                         points: np.ndarray | None = None) -> Orientation:
    """The rotation that makes a reconstruction upright with its main façade facing ``params.facing``.

    Parameters
    ----------
    rec : Reconstruction
        Oriented images (and, optionally, its sparse ``points``).
    params : OrientParams
    points : (n, 3) float, optional
        Points for the façade (default: ``rec.points``; a dense cloud works too).

    Returns
    -------
    Orientation
    """
    up, method, inliers = estimate_up(rec, params)
    L = level_rotation(up)
    Rs = _rotations(rec)
    centres = np.stack([im.pose.center for im in rec.images.values()])
    c = centres.mean(axis=0)
    P = rec.points if points is None else points
    normal_l, source = None, "none"
    if params.facade in ("auto", "points") and P is not None and len(P) and method != "nadir":
        normal_l = _facade_from_points((np.asarray(P, float) - c) @ L.T, (centres - c) @ L.T, params)
        source = "points" if normal_l is not None else source
    if normal_l is None and params.facade in ("auto", "cameras") and method != "nadir":
        normal_l = _facade_from_cameras(Rs[:, 2, :] @ L.T)
        source = "cameras" if normal_l is not None else source
    if normal_l is None:
        R = L
    else:  # rotate about z so that the façade normal becomes ∓y
        target = np.array([0.0, -1.0 if params.facing == "-y" else 1.0, 0.0])
        a = math.atan2(target[1], target[0]) - math.atan2(normal_l[1], normal_l[0])
        Rz = np.array([[math.cos(a), -math.sin(a), 0.0], [math.sin(a), math.cos(a), 0.0], [0.0, 0.0, 1.0]])
        R = Rz @ L
    tilt = math.degrees(math.acos(float(np.clip(up[2], -1, 1))))
    log.info("upright: %s, up tilted %.2f deg from z, %d/%d images agree, facade from %s",
             method, tilt, inliers, len(rec.images), source)
    normal = None if normal_l is None else L.T @ normal_l
    return Orientation(Similarity(1.0, R, c - R @ c), up, normal, tilt, method, source, inliers)


def orient_reconstruction(rec: Reconstruction, orientation: Orientation) -> Reconstruction:
    """A new reconstruction in the upright frame (poses, points; tracks and colours carried
    over; ``meta`` gains the :meth:`Orientation.to_meta` entries)."""
    sim = orientation.similarity
    images = {k: Image(im.name, im.camera_id, sim.apply_pose(im.pose), im.path) for k, im in rec.images.items()}
    pts = None if rec.points is None else sim.apply(rec.points)
    meta = {**dict(rec.meta), **orientation.to_meta()}
    return Reconstruction(dict(rec.cameras), images, pts, rec.colors, rec.crs, meta, rec.tracks)


def orient_cloud(cloud: Cloud, orientation: Orientation) -> Cloud:
    """A new cloud in the upright frame: points moved, ``normal`` vectors rotated."""
    sim = orientation.similarity
    out = cloud.with_xyz(sim.apply(cloud.xyz))
    if "normal" in cloud.attrs:
        out = out.with_attrs(normal=(np.asarray(cloud.attrs["normal"], float) @ orientation.R.T).astype(np.float32))
    return out.with_history("upright", {"method": orientation.method, "tilt_deg": float(orientation.tilt_deg)})


def upright(rec: Reconstruction, params: OrientParams = OrientParams()) -> tuple[Reconstruction, Orientation]:
    """:func:`estimate_orientation` then :func:`orient_reconstruction`."""
    o = estimate_orientation(rec, params)
    return orient_reconstruction(rec, o), o


__all__ = [
    "NADIR_BLOCK_SPREAD_DEG",
    "OrientParams",
    "Orientation",
    "consensus_axis",
    "estimate_orientation",
    "estimate_up",
    "level_rotation",
    "orient_cloud",
    "orient_reconstruction",
    "point_normals",
    "upright",
]
