"""Checks of point geometry before it goes to a C++ library (Open3D, PoissonRecon, OpenCV).

Some libraries crash the process on degenerate input (Open3D's Poisson on one repeated point
is a segmentation fault) or return an absurd result (a DLT camera from coplanar points). The
functions here measure the *affine dimension* of a point set - 0 all the same point,
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
