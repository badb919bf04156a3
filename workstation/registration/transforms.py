"""Rigid and similarity transforms: estimation from point pairs, composition, error measures.

The closed-form least-squares fit of a rotation, translation and optional scale between two
paired point sets is the textbook rigid-body transformation of Horn (1987, "Closed-form
solution of absolute orientation using unit quaternions", JOSA A 4(4)) in the SVD form of
Umeyama (1991, "Least-squares estimation of transformation parameters between two point
patterns", IEEE PAMI 13(4)), with the reflection guard of the latter: :func:`umeyama`, which
lives in :mod:`workstation.core.geometry` (so any layer can use it) and is re-exported here.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.core.geometry import umeyama
from workstation.core.products import RegistrationResult


def make_transform(R: np.ndarray, t: np.ndarray, scale: float = 1.0) -> np.ndarray:
    """(4, 4) matrix of ``x -> scale * R @ x + t``."""
    T = np.eye(4)
    T[:3, :3] = float(scale) * np.asarray(R, dtype=np.float64)
    T[:3, 3] = np.asarray(t, dtype=np.float64)
    return T


def split_transform(T: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """(R, t, scale) of a similarity transform ``T`` (scale from the determinant)."""
    T = np.asarray(T, dtype=np.float64)
    A = T[:3, :3]
    s = float(np.cbrt(np.linalg.det(A)))
    return A / s, T[:3, 3].copy(), s


def apply_transform(T: np.ndarray, xyz: np.ndarray) -> np.ndarray:
    """Points ``(n, 3)`` mapped by a (4, 4) transform, float64."""
    T = np.asarray(T, dtype=np.float64)
    return np.asarray(xyz, dtype=np.float64) @ T[:3, :3].T + T[:3, 3]


def invert(T: np.ndarray) -> np.ndarray:
    """Inverse of a similarity transform (exact, no general matrix inverse)."""
    R, t, s = split_transform(T)
    Ri = R.T / s
    return make_transform(R.T, -Ri @ t, 1.0 / s)


def rotation_angle_deg(R: np.ndarray) -> float:
    """Angle of a rotation matrix in degrees (0..180)."""
    c = (np.trace(np.asarray(R)[:3, :3]) - 1.0) / 2.0
    return float(np.degrees(np.arccos(np.clip(c, -1.0, 1.0))))


def transform_error(T_est: np.ndarray, T_true: np.ndarray, center=None) -> tuple[float, float]:
    """(rotation error in degrees, translation error in units) between two transforms.

    The rotation error is the angle of ``R_true^T R_est``; the translation error is
    ``|t_est - t_true|``, the usual convention of registration benchmarks (3DMatch, ETH), for
    clouds near their frame's origin. With ``center`` (3,) it is the distance between the two
    images of that point, ``|T_est(c) - T_true(c)|``: use the data's centroid for
    georeferenced coordinates, where a tiny rotation error moves ``t`` by metres.
    """
    Re, te, _ = split_transform(T_est)
    Rt, tt, _ = split_transform(T_true)
    if center is None:
        terr = float(np.linalg.norm(te - tt))
    else:
        c = np.asarray(center, dtype=np.float64).reshape(1, 3)
        terr = float(np.linalg.norm(apply_transform(T_est, c) - apply_transform(T_true, c)))
    return rotation_angle_deg(Rt.T @ Re), terr


def random_rotation(rng: np.random.Generator, max_angle_deg: float = 180.0) -> np.ndarray:
    """A rotation about a uniformly random axis by an angle uniform in [0, max_angle_deg]."""
    axis = rng.normal(size=3)
    axis /= np.linalg.norm(axis)
    ang = np.radians(rng.uniform(0.0, max_angle_deg))
    K = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + np.sin(ang) * K + (1 - np.cos(ang)) * K @ K


@dataclass(frozen=True)
class PairFit:
    """A transform fitted to point pairs with its residuals.

    Attributes
    ----------
    result : RegistrationResult
        Transform mapping the source points onto the target points.
    residuals : (n, 3) float64
        ``target - T(source)`` per pair, in target units.
    """

    result: RegistrationResult
    residuals: np.ndarray

    @property
    def residual_norms(self) -> np.ndarray:
        return np.linalg.norm(self.residuals, axis=1)


def register_point_pairs(src: np.ndarray, dst: np.ndarray, *, with_scale: bool = False,
                         weights: np.ndarray | None = None) -> PairFit:
    """Rigid (6-DoF) or similarity (7-DoF) transform from >= 3 picked point pairs or GCPs.

    Parameters
    ----------
    src : (n, 3) float
        Points picked in the source cloud (e.g. targets, GCPs in a local SfM frame).
    dst : (n, 3) float
        The same points in the target frame (survey coordinates, the reference scan).
    with_scale : bool
        Also estimate a scale (SfM without GCPs has an arbitrary one).
    weights : (n,) float, optional

    Returns
    -------
    PairFit
        ``result.inlier_rmse`` is the RMS of the 3-D residuals; ``result.meta`` holds the
        per-pair residual norms and the degrees of freedom left (3n - 6 or 3n - 7).

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> a = rng.normal(size=(5, 3))
    >>> fit = register_point_pairs(a, a + [1.0, 2.0, 3.0])
    >>> np.round(fit.result.transform[:3, 3], 6).tolist(), fit.result.inlier_rmse < 1e-9
    ([1.0, 2.0, 3.0], True)
    """
    src = np.asarray(src, dtype=np.float64)
    dst = np.asarray(dst, dtype=np.float64)
    if src.ndim == 2 and src.shape[0] >= 3:
        c = src - src.mean(axis=0)
        sv = np.linalg.svd(c, compute_uv=False)
        if sv[0] == 0 or sv[1] / sv[0] < 1e-9:
            raise InvalidInputError("the source points are (nearly) collinear",
                                    "pick at least 3 points that span a triangle")
    R, t, s = umeyama(src, dst, weights, with_scale)
    T = make_transform(R, t, s)
    res = dst - apply_transform(T, src)
    norms = np.linalg.norm(res, axis=1)
    n = src.shape[0]
    result = RegistrationResult(
        transform=T,
        scale=s,
        fitness=1.0,
        inlier_rmse=float(np.sqrt(np.mean(norms**2))),
        converged=True,
        correspondences=n,
        meta={"method": "point_pairs", "residuals": norms.tolist(), "max_residual": float(norms.max()),
              "dof_left": int(3 * n - (7 if with_scale else 6))},
    )
    return PairFit(result, res)
