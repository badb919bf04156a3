"""Point geometry helpers: degeneracy checks, the local origin, the similarity fit.

- :func:`affine_dimension` / :func:`require_spread`: checks before a C++ library call;
- :func:`default_origin`: the origin subtracted before coordinates go to a float32 library;
- :func:`umeyama`: the least-squares rigid or similarity transform between paired points.

Numpy only, so every layer (io, interop, registration, photogrammetry) can use them.

Some C++ libraries (Open3D, PoissonRecon, OpenCV) crash the process on degenerate input
(Open3D's Poisson on one repeated point is a segmentation fault) or return an absurd result
(a DLT camera from coplanar points). The checks measure the *affine dimension* of a point set - 0 all the same point,
1 collinear, 2 coplanar, 3 a volume - from the singular values of the centred points, and
raise :class:`InvalidInputError` before the call.
"""

from __future__ import annotations

import numpy as np

from .errors import InvalidInputError

#: Singular values below this share of the largest count as zero: above the resolution of
#: singular values taken from the scatter matrix (about sqrt(float64 eps) = 1.5e-8 of the
#: largest), below any real spread (0.1 mm over 100 m is 1e-6).
RTOL = 1e-7

_SHAPES = {0: "all the same point", 1: "collinear", 2: "coplanar", 3: "spread in 3D"}


def affine_dimension(points: np.ndarray, rtol: float = RTOL) -> int:
    """Dimension (0-3) of the smallest affine subspace holding ``points`` (n, d).

    Singular values of the centred points (square roots of the d × d scatter matrix's
    eigenvalues, O(n d²)) under ``rtol`` times the largest one count as zero.

    Examples
    --------
    >>> affine_dimension(np.ones((5, 3)))
    0
    >>> t = np.linspace(0, 1, 5)
    >>> affine_dimension(np.column_stack([t, 2 * t, 1 + t]))
    1
    >>> affine_dimension(np.column_stack([t, t ** 2, np.zeros(5)]))
    2
    """
    p = np.asarray(points, dtype=np.float64)
    if len(p) < 2 or not np.ptp(p, axis=0).any():  # one point repeated (its mean may round off it)
        return 0
    c = p - p.mean(axis=0)
    scale = np.abs(c).max()
    if not scale > 0:
        return 0
    c /= scale
    s = np.sqrt(np.clip(np.linalg.eigvalsh(c.T @ c), 0.0, None))
    return int(np.count_nonzero(s > rtol * s.max()))


def require_spread(points: np.ndarray, dimension: int, *, what: str, min_points: int | None = None,
                   field: str | None = None, path=None, rtol: float = RTOL) -> None:
    """Raise :class:`InvalidInputError` unless ``points`` number at least ``min_points`` (default
    ``dimension + 1``) and span ``dimension`` dimensions (2: not collinear, 3: not coplanar).

    Parameters
    ----------
    points : (n, d) float
    dimension : int
        The affine dimension ``what`` needs.
    what : str
        The step, in words ("screened Poisson meshing").
    """
    need = dimension + 1 if min_points is None else min_points
    n = len(points)
    if n < need:
        raise InvalidInputError(f"{what} needs at least {need} points, got {n}", "check the input", path=path, field=field)
    d = affine_dimension(points, rtol)
    if d < dimension:
        raise InvalidInputError(
            f"{what} needs points spread in {dimension}D, but the {n} points are {_SHAPES[d]}",
            "check the input (a wrong column, a failed conversion or one repeated point)", path=path, field=field)


def default_origin(xyz: np.ndarray) -> np.ndarray:
    """Reproducible local origin of (n, 3) coordinates: the bounding-box centre rounded to
    whole units, (3,) float64 (zeros when there are no points).

    Subtracted before coordinates go to a library that works in float32 or loses precision
    on large values (Open3D tensors, MeshLab, VTK): UTM eastings of 500 000 m keep
    millimetres once local. Rounding keeps the origin easy to read back in logs.

    Examples
    --------
    >>> default_origin(np.array([[500000.2, 10.0, 1.0], [500003.9, 12.0, 2.0]])).tolist()
    [500002.0, 11.0, 2.0]
    >>> default_origin(np.zeros((0, 3))).tolist()
    [0.0, 0.0, 0.0]
    """
    xyz = np.asarray(xyz, dtype=np.float64)
    if xyz.size == 0:
        return np.zeros(3)
    return np.round(0.5 * (xyz.min(axis=0) + xyz.max(axis=0)))


def umeyama(src: np.ndarray, dst: np.ndarray, weights: np.ndarray | None = None, with_scale: bool = False):
    """Least-squares ``dst ~ s R src + t`` from paired points (Umeyama 1991).

    The SVD form of Umeyama (1991, "Least-squares estimation of transformation parameters
    between two point patterns", IEEE PAMI 13(4)) of Horn's (1987) absolute orientation, with
    its reflection guard: ``R`` is always a proper rotation (det +1).

    Parameters
    ----------
    src, dst : (n, 3) float
        Paired points, n >= 3, not all collinear.
    weights : (n,) float, optional
        Non-negative pair weights.
    with_scale : bool
        Estimate the similarity scale ``s`` (7 DoF) instead of fixing it to 1 (6 DoF).

    Returns
    -------
    R : (3, 3) float64
    t : (3,) float64
    s : float

    Raises
    ------
    InvalidInputError
        Shapes differ or are not (n, 3), fewer than 3 pairs, or all weights zero.

    Examples
    --------
    >>> src = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
    >>> R, t, s = umeyama(src, 2.0 * src + [1.0, 2.0, 3.0], with_scale=True)
    >>> np.allclose(R, np.eye(3)), np.round(t, 9).tolist(), round(s, 9)
    (True, [1.0, 2.0, 3.0], 2.0)
    """
    src = np.asarray(src, dtype=np.float64)
    dst = np.asarray(dst, dtype=np.float64)
    if src.shape != dst.shape or src.ndim != 2 or src.shape[1] != 3:
        raise InvalidInputError(f"paired points must both be (n, 3), got {src.shape} and {dst.shape}")
    if src.shape[0] < 3:
        raise InvalidInputError(f"{src.shape[0]} point pairs given", "at least 3 non-collinear pairs are needed")
    w = np.ones(src.shape[0]) if weights is None else np.asarray(weights, dtype=np.float64)
    ws = w.sum()
    if ws <= 0:
        raise InvalidInputError("all pair weights are zero")
    w = w / ws
    mu_s = w @ src
    mu_d = w @ dst
    xs = src - mu_s
    xd = dst - mu_d
    C = (xd * w[:, None]).T @ xs
    U, S, Vt = np.linalg.svd(C)
    D = np.eye(3)
    if np.linalg.det(U) * np.linalg.det(Vt) < 0:
        D[2, 2] = -1.0
    R = U @ D @ Vt
    var_s = float(w @ np.einsum("ij,ij->i", xs, xs))
    s = float(np.trace(np.diag(S) @ D) / var_s) if with_scale and var_s > 0 else 1.0
    t = mu_d - s * R @ mu_s
    return R, t, s
