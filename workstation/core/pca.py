"""Principal components of point neighbourhoods and of labelled point groups.

- :func:`local_pca`: the covariance of each point's k nearest neighbours (or of the points
  within a radius), its eigenvalues and its least principal axis (the normal);
- :func:`grouped_plane_fit`: the least-squares plane of every group of labelled points at once;
- :func:`sym3_eigenvalues` / :func:`sym3_eigenvector_z`: closed-form eigenvalues of symmetric
  3 × 3 matrices and the z component of their eigenvectors, for passes over millions of
  neighbourhoods where a LAPACK call per matrix costs too much.

A plane's normal is the eigenvector of the smallest eigenvalue of the points' covariance and
that eigenvalue is the variance of the points along it (Hoppe et al. 1992, "Surface
reconstruction from unorganized points"; Pauly et al. 2002 for the eigenvalue features).
Covariances are formed from coordinates centred on their mean first (two passes), so that
large eastings and northings lose no precision; the eigenproblems of all neighbourhoods or
groups are solved in one batched ``np.linalg.eigh`` call on an (m, 3, 3) array.

Eigenvalues are returned in ascending order and are those of the covariance divided by the
number of points (the mean squared deviation). With ``orient="up"`` each normal is turned so
that its z component is not negative; with ``orient=None`` its sign is LAPACK's.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import chain

import numpy as np

from .errors import InvalidInputError

#: Neighbourhoods per block of the kNN covariance: (chunk, k, 3) float64 temporaries stay at a
#: few hundred megabytes for k up to 50.
CHUNK = 200_000


@dataclass(frozen=True)
class LocalPCA:
    """Principal components of m point neighbourhoods.

    Attributes
    ----------
    normals : (m, 3) float64
        Unit eigenvector of the smallest eigenvalue (see the module docs for its sign).
    eigenvalues : (m, 3) float64
        Eigenvalues of the neighbourhood covariance, ascending (m²).
    centroids : (m, 3) float64
        Mean of each neighbourhood.
    counts : (m,) int64
        Points in each neighbourhood (k for a kNN search).
    indices : (m, k) int64 or (c,) int64
        Neighbour indices into the points: one row per query for a kNN search (nearest first),
        the neighbourhoods one after the other for a radius search (see ``indptr``).
    distances : (m, k) float64 or None
        Distances of the kNN neighbours (None for a radius search).
    indptr : (m + 1,) int64 or None
        Start of each query's neighbours in ``indices`` for a radius search (None for kNN).
    """

    normals: np.ndarray
    eigenvalues: np.ndarray
    centroids: np.ndarray
    counts: np.ndarray
    indices: np.ndarray
    distances: np.ndarray | None = None
    indptr: np.ndarray | None = None


@dataclass(frozen=True)
class GroupPlanes:
    """Least-squares planes of m point groups.

    Attributes
    ----------
    normals : (m, 3) float64
        Unit plane normals (see the module docs for their sign).
    centroids : (m, 3) float64
        Mean of each group; the plane is ``normal . (x - centroid) = 0``.
    rms : (m,) float64
        Root mean square distance of each group's points to its plane.
    counts : (m,) int64
        Points per group.
    eigenvalues : (m, 3) float64
        Eigenvalues of each group's covariance, ascending; the first is the mean squared
        distance to the plane.

    Empty groups have count 0, a zero centroid, rms 0, zero eigenvalues and an arbitrary unit normal.
    """

    normals: np.ndarray
    centroids: np.ndarray
    rms: np.ndarray
    counts: np.ndarray
    eigenvalues: np.ndarray

    @property
    def offsets(self) -> np.ndarray:
        """(m,) plane offsets d with ``normal . x + d = 0``."""
        return -np.einsum("ij,ij->i", self.normals, self.centroids)


def _points(xyz, name: str) -> np.ndarray:
    a = np.asarray(xyz, dtype=np.float64)
    if a.ndim != 2 or a.shape[1] != 3:
        raise InvalidInputError(f"{name} must be an (n, 3) array, got shape {a.shape}", field=name)
    return a


def _orient(normals: np.ndarray, orient: str | None) -> np.ndarray:
    """Normals turned to z >= 0 (``orient="up"``) or left as they are (None)."""
    if orient is None:
        return normals
    if orient != "up":
        raise InvalidInputError(f"orient must be 'up' or None, got {orient!r}", field="orient")
    return normals * np.where(normals[:, 2:3] < 0, -1.0, 1.0)


def _eigh(cov: np.ndarray, orient: str | None) -> tuple[np.ndarray, np.ndarray]:
    """Ascending eigenvalues (m, 3) and the oriented least eigenvectors (m, 3) of (m, 3, 3)."""
    if not len(cov):
        return np.zeros((0, 3)), np.zeros((0, 3))
    w, v = np.linalg.eigh(cov)
    return w, _orient(np.ascontiguousarray(v[:, :, 0]), orient)


def group_moments(xyz: np.ndarray, labels: np.ndarray, m: int):
    """Counts (m,) float, centroids (m, 3) and covariances (m, 3, 3) of the points ``xyz``
    (c, 3) grouped by ``labels`` (c,) in 0..m-1: centroids first, then the second moments of
    the centred coordinates (bincount sums), each divided by the group's count (1 when empty)."""
    return _moments(xyz, labels, m)[:3]


def _moments(xyz: np.ndarray, labels: np.ndarray, m: int):
    """:func:`group_moments` and the centred coordinates (c, 3)."""
    n = np.bincount(labels, minlength=m).astype(float)
    nn = np.where(n > 0, n, 1.0)
    c = np.column_stack([np.bincount(labels, xyz[:, i], m) / nn for i in range(3)])
    d = xyz - c[labels]
    cov = np.empty((m, 3, 3))
    for i, j in ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)):
        cov[:, i, j] = cov[:, j, i] = np.bincount(labels, d[:, i] * d[:, j], m) / nn
    return n, c, cov, d


def grouped_plane_fit(xyz: np.ndarray, labels: np.ndarray, m: int | None = None,
                      orient: str | None = "up", residuals: bool = True) -> GroupPlanes:
    """Least-squares planes of the points ``xyz`` (n, 3) grouped by ``labels`` (n,) int.

    Points with a negative label belong to no group. ``m`` is the number of groups (default
    ``labels.max() + 1``); groups without points are reported empty. One pass of bincount sums
    gives the centroids, a second the centred second moments, one batched eigh the normals.
    The RMS is that of the points' residuals to their plane (a third pass); with
    ``residuals=False`` it is the square root of the smallest eigenvalue instead, the same
    but for rounding (which reaches about 1e-8 of a group's extent for exactly planar points).

    Examples
    --------
    >>> xy = np.array([[0, 0], [1, 0], [0, 1], [1, 1.0]])
    >>> pts = np.vstack([np.column_stack([xy, np.zeros(4)]), np.column_stack([xy, 5 + xy[:, 0]])])
    >>> g = grouped_plane_fit(pts, np.repeat([0, 1], 4))
    >>> np.round(g.normals, 6).tolist(), g.counts.tolist(), np.round(g.rms, 9).tolist()
    ([[0.0, 0.0, 1.0], [-0.707107, 0.0, 0.707107]], [4, 4], [0.0, 0.0])
    """
    xyz = _points(xyz, "xyz")
    labels = np.asarray(labels)
    if labels.shape != (len(xyz),) or not np.issubdtype(labels.dtype, np.integer):
        raise InvalidInputError(f"labels must be (n,) integers for {len(xyz)} points, "
                                f"got {labels.dtype} {labels.shape}", field="labels")
    top = int(labels.max()) + 1 if labels.size else 0
    m = top if m is None else int(m)
    if top > m:
        raise InvalidInputError(f"label {top - 1} is not below the number of groups {m}", field="labels")
    on = labels >= 0
    if not on.all():
        xyz, labels = xyz[on], labels[on]
    n, c, cov, d = _moments(xyz, labels, m)
    w, normal = _eigh(cov, orient)
    if residuals:
        r = np.einsum("ij,ij->i", d, normal[labels])
        rms = np.sqrt(np.bincount(labels, r * r, m) / np.where(n > 0, n, 1.0))
    else:
        rms = np.sqrt(np.maximum(w[:, 0], 0.0))
    return GroupPlanes(normal, c, rms, n.astype(np.int64), w)


def _knn_moments(xyz: np.ndarray, idx: np.ndarray, orient: str | None, chunk: int):
    """Eigenvalues, normals and centroids of the neighbourhoods ``xyz[idx]`` (rows of idx),
    in blocks of ``chunk`` rows."""
    m, k = idx.shape
    w, normal, cen = np.empty((m, 3)), np.empty((m, 3)), np.empty((m, 3))
    for s in range(0, m, chunk):
        nb = xyz[idx[s:s + chunk]]
        mu = nb.mean(axis=1)
        c = nb - mu[:, None, :]
        cov = np.matmul(c.transpose(0, 2, 1), c) / k
        w[s:s + chunk], normal[s:s + chunk] = _eigh(cov, orient)
        cen[s:s + chunk] = mu
    return w, normal, cen


def local_pca(xyz: np.ndarray, k: int | None = None, radius: float | None = None, *, query: np.ndarray | None = None,
              search_xyz: np.ndarray | None = None, orient: str | None = "up", workers: int = 1,
              chunk: int = CHUNK) -> LocalPCA:
    """Covariance eigenvalues and normals of the neighbourhoods of points in ``xyz`` (n, 3).

    Parameters
    ----------
    xyz : (n, 3) float
        The points whose neighbourhoods are analysed.
    k, radius : int or float
        Exactly one: the k nearest points (the query point itself included when it is one of
        ``xyz``; k is capped at n), or every point within ``radius`` (same units).
    query : (m, 3) float, optional
        Points whose neighbourhoods among ``xyz`` are wanted (default: every point of ``xyz``).
    search_xyz : (n, 3) float, optional
        Coordinates in which the neighbours of every point of ``xyz`` are searched (default
        ``xyz``): an anisotropic metric, for example stretched along scan lines. The
        covariances are always those of ``xyz``. Not with ``query``.
    orient : "up" or None
        Normals turned to z >= 0, or left with LAPACK's sign.
    workers : int
        Threads of the KD-tree query (-1: all cores).
    chunk : int
        Neighbourhoods per block of the kNN covariance (bounds memory).

    Examples
    --------
    >>> g = np.stack(np.meshgrid(np.arange(5.0), np.arange(5.0)), -1).reshape(-1, 2)
    >>> r = local_pca(np.column_stack([g, 0.5 * g[:, 0]]), k=9)
    >>> np.round(r.normals[12], 6).tolist(), bool(np.all(r.eigenvalues[:, 0] < 1e-12))
    ([-0.447214, 0.0, 0.894427], True)
    """
    from scipy.spatial import cKDTree

    xyz = _points(xyz, "xyz")
    if (k is None) == (radius is None):
        raise InvalidInputError("give exactly one of k and radius", field="k")
    if query is not None and search_xyz is not None:
        raise InvalidInputError("search_xyz applies to the points' own neighbourhoods, not to query points",
                                field="search_xyz")
    space = xyz if search_xyz is None else _points(search_xyz, "search_xyz")
    if space.shape != xyz.shape:
        raise InvalidInputError(f"search_xyz has shape {space.shape}, the points {xyz.shape}", field="search_xyz")
    q = space if query is None else _points(query, "query")
    if not len(xyz):
        raise InvalidInputError("no points to search", field="xyz")
    tree = cKDTree(space)
    if k is not None:
        if int(k) < 1:
            raise InvalidInputError(f"k must be >= 1, got {k}", field="k")
        k = int(min(k, len(xyz)))
        d, idx = tree.query(q, k=k, workers=workers)
        d, idx = d.reshape(len(q), k), idx.reshape(len(q), k)
        w, normal, cen = _knn_moments(xyz, idx, orient, max(1, int(chunk)))
        return LocalPCA(normal, w, cen, np.full(len(q), k, np.int64), idx.astype(np.int64, copy=False), d)
    if not radius > 0:
        raise InvalidInputError(f"radius must be positive, got {radius}", field="radius")
    lists = tree.query_ball_point(q, float(radius), workers=workers, return_sorted=True)
    counts = np.fromiter(map(len, lists), np.int64, len(q))
    flat = np.fromiter(chain.from_iterable(lists), np.int64, int(counts.sum()))
    owner = np.repeat(np.arange(len(q)), counts)
    n, cen, cov = group_moments(xyz[flat], owner, len(q))
    w, normal = _eigh(cov, orient)
    return LocalPCA(normal, w, cen, counts, flat, None, np.concatenate([[0], np.cumsum(counts)]))


def sym3_eigenvalues(a00, a11, a22, a01, a02, a12) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Eigenvalues l1 >= l2 >= l3 of symmetric 3 × 3 matrices given by their six distinct
    entries (arrays of one shape), in closed form (O. K. Smith 1961, "Eigenvalues of a
    symmetric 3x3 matrix", Comm. ACM 4(4):168). Contiguous entry arrays are about twice as fast
    as strided views of an (m, 3, 3) array.

    Examples
    --------
    >>> [round(float(v[0]), 9) for v in sym3_eigenvalues(*np.array([[3.0], [2.0], [1.0], [0.0], [0.0], [0.0]]))]
    [3.0, 2.0, 1.0]
    """
    q = (a00 + a11 + a22) / 3
    p1 = a01 * a01 + a02 * a02 + a12 * a12
    b00, b11, b22 = a00 - q, a11 - q, a22 - q
    p2 = b00 * b00 + b11 * b11 + b22 * b22 + 2 * p1
    p = np.sqrt(np.maximum(p2 / 6, 1e-30))
    det = (b00 * (b11 * b22 - a12 * a12) - a01 * (a01 * b22 - a12 * a02) + a02 * (a01 * a12 - b11 * a02))
    r = np.clip(det / (2 * p ** 3), -1, 1)
    phi = np.arccos(r) / 3
    l1 = q + 2 * p * np.cos(phi)
    l3 = q + 2 * p * np.cos(phi + 2 * np.pi / 3)
    l2 = 3 * q - l1 - l3
    return l1, l2, l3


def sym3_eigen(cov: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`sym3_eigenvalues` of symmetric matrices (m, 3, 3): l1 >= l2 >= l3, each (m,)."""
    return sym3_eigenvalues(cov[:, 0, 0], cov[:, 1, 1], cov[:, 2, 2], cov[:, 0, 1], cov[:, 0, 2], cov[:, 1, 2])


def sym3_eigenvector_z(a00, a11, a22, a01, a02, a12, lam):
    """z component of the unit eigenvectors for eigenvalues ``lam`` of symmetric 3 × 3 matrices
    given by their six distinct entries: the longest cross product of two rows of
    (A - lam I), written out per component (the operations of ``np.cross``). The sign is
    arbitrary; callers take its magnitude."""
    a00, a11, a22 = a00 - lam, a11 - lam, a22 - lam
    a10, a20, a21 = a01, a02, a12
    c0 = (a01 * a12 - a02 * a11, a02 * a10 - a00 * a12, a00 * a11 - a01 * a10)  # row 0 x row 1
    c1 = (a01 * a22 - a02 * a21, a02 * a20 - a00 * a22, a00 * a21 - a01 * a20)  # row 0 x row 2
    c2 = (a11 * a22 - a12 * a21, a12 * a20 - a10 * a22, a10 * a21 - a11 * a20)  # row 1 x row 2
    n0 = c0[0] * c0[0] + c0[1] * c0[1] + c0[2] * c0[2]
    n1 = c1[0] * c1[0] + c1[1] * c1[1] + c1[2] * c1[2]
    n2 = c2[0] * c2[0] + c2[1] * c2[1] + c2[2] * c2[2]
    nv = np.maximum(n0, n1)
    vz = np.where(n2 > nv, c2[2], np.where(n0 >= n1, c0[2], c1[2]))
    return vz / np.sqrt(np.maximum(np.maximum(nv, n2), 1e-30))
