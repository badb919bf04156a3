"""Thinning: one point per voxel, or Poisson-disk sampling (no two kept points closer than a radius).

Both keep real points with all their attributes (never averaged ones), in input order, and
are deterministic.

- :func:`voxel_thin` groups points by integer voxel keys ``floor((xyz - min) / size)`` (the
  grid starts at the cloud's minimum corner, as PDAL's voxel filters do) and keeps per voxel
  the first point in input order (PDAL ``filters.voxeldownsize`` mode ``first``), the point
  nearest the voxel's centroid (``filters.voxelcentroidnearestneighbor``), the one nearest
  its centre (``filters.voxelcenternearestneighbor``), or the lowest / highest.
- :func:`poisson_thin` is PDAL's ``filters.sample``: points are taken in input order and a
  point is kept when no already kept point lies within ``radius`` (3D). It runs over blocks
  of consecutive points: the block's points near points kept by earlier blocks are dropped
  with a KD-tree query, then the block's own conflicts (pairs closer than the radius, from
  ``cKDTree.query_pairs``) are resolved in order. The result is exactly the sequential
  greedy one, with memory bounded by a block's pairs.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError

KEEP = ("first", "centroid", "center", "lowest", "highest")


@dataclass(frozen=True)
class VoxelParams:
    """Parameters of :func:`voxel_thin`.

    Attributes
    ----------
    size : float
        Voxel edge in CRS units (metres for a metric CRS), > 0.
    keep : str
        Which point of a voxel stays: "first" (input order), "centroid" (nearest the mean of
        the voxel's points), "center" (nearest the voxel's centre), "lowest", "highest" (z).
    """

    size: float
    keep: str = "first"

    def __post_init__(self):
        if not (np.isfinite(self.size) and self.size > 0):
            raise InvalidInputError(f"voxel size must be a positive number, got {self.size}", field="voxel")
        if self.keep not in KEEP:
            raise InvalidInputError(f"unknown keep rule '{self.keep}'", f"one of {', '.join(KEEP)}", field="keep")


@dataclass(frozen=True)
class PoissonParams:
    """Parameters of :func:`poisson_thin`.

    Attributes
    ----------
    radius : float
        Smallest 3D distance between kept points, CRS units, > 0.
    block : int, optional
        Consecutive points resolved together (memory: the pairs within a block); default: all
        points at once when their conflict pairs fit ``max_pairs``, else blocks that do.
    max_pairs : int
        Conflict pairs held at once (16 bytes each).
    """

    radius: float
    block: int | None = None
    max_pairs: int = 40_000_000

    def __post_init__(self):
        if not (np.isfinite(self.radius) and self.radius > 0):
            raise InvalidInputError(f"radius must be a positive number, got {self.radius}", field="poisson")


def voxel_keys(xyz: np.ndarray, size: float, origin: np.ndarray | None = None) -> np.ndarray:
    """(n,) int64 voxel number of each point (voxels of edge ``size`` from ``origin``, default
    the minimum corner), unique per voxel: the three integer indices packed into one."""
    origin = xyz.min(axis=0) if origin is None else origin
    ijk = np.floor((xyz - origin) / size).astype(np.int64)
    dims = ijk.max(axis=0) + 1
    if float(np.prod(dims.astype(np.float64))) >= 2.0**62:
        raise InvalidInputError(f"{size} is too small a voxel for this extent ({dims.tolist()} voxels a side)",
                                "use a larger --voxel", field="voxel")
    return (ijk[:, 0] * dims[1] + ijk[:, 1]) * dims[2] + ijk[:, 2]


def _first_per_group(keys: np.ndarray, order_key: np.ndarray | None = None) -> np.ndarray:
    """Index of the point with the smallest ``order_key`` (then input order) in each key group."""
    if order_key is None:
        return np.unique(keys, return_index=True)[1]  # first occurrences
    order = np.lexsort((order_key, keys))  # stable: ties stay in input order
    k = keys[order]
    starts = np.flatnonzero(np.r_[True, k[1:] != k[:-1]])
    return order[starts]


def voxel_thin(cloud: Cloud, params: VoxelParams) -> Cloud:
    """One point per occupied voxel (see :class:`VoxelParams`), in input order.

    Examples
    --------
    >>> c = Cloud(np.array([[0.1, 0, 0.5], [0.2, 0, 0.1], [1.5, 0, 0]]))
    >>> voxel_thin(c, VoxelParams(1.0)).xyz[:, 0].tolist(), voxel_thin(c, VoxelParams(1.0, "lowest")).xyz[:, 0].tolist()
    ([0.1, 1.5], [0.2, 1.5])
    """
    if cloud.n == 0:
        raise StageError("thin", "the cloud is empty")
    xyz = cloud.xyz
    origin = xyz.min(axis=0)
    keys = voxel_keys(xyz, params.size, origin)
    if params.keep == "first":
        idx = _first_per_group(keys)
    elif params.keep in ("lowest", "highest"):
        idx = _first_per_group(keys, xyz[:, 2] if params.keep == "lowest" else -xyz[:, 2])
    elif params.keep == "center":
        ijk = np.floor((xyz - origin) / params.size)
        idx = _first_per_group(keys, np.linalg.norm(xyz - (origin + (ijk + 0.5) * params.size), axis=1))
    else:  # centroid
        _, inverse, counts = np.unique(keys, return_inverse=True, return_counts=True)
        local = xyz - origin  # sums of small numbers: no precision lost to large coordinates
        centroid = np.column_stack([np.bincount(inverse, local[:, i]) for i in range(3)]) / counts[:, None] + origin
        idx = _first_per_group(keys, np.linalg.norm(xyz - centroid[inverse], axis=1))
    return cloud[np.sort(idx)].with_history("thin", {"voxel": params.size, "keep": params.keep})


def _greedy_in_order(n: int, pairs: np.ndarray) -> np.ndarray:
    """Kept flags of the sequential rule "keep i unless an earlier kept point conflicts" for
    conflict ``pairs`` (m, 2) with i < j, decided in vectorised rounds: a point whose earlier
    neighbours are all removed is kept, a point with a kept earlier neighbour is removed. Each
    round decides at least the first undecided point, and the pairs of decided points drop
    out, so the rounds are as many as the longest chain of conflicts (a few on real data)."""
    state = np.zeros(n, dtype=np.int8)  # 0 undecided, 1 kept, -1 removed
    first, later = pairs[:, 0], pairs[:, 1]
    while True:
        blocked = np.zeros(n, dtype=bool)
        blocked[later[state[first] != -1]] = True  # an earlier neighbour is kept or undecided
        state[(state == 0) & ~blocked] = 1
        state[later[state[first] == 1]] = -1
        live = state[later] == 0
        if not live.any():
            break
        first, later = first[live], later[live]
    state[state == 0] = 1
    return state == 1


def _block_size(tree, xyz: np.ndarray, r: float, max_pairs: int) -> int:
    """Points per block so that a block's conflict pairs stay under ``max_pairs``, from the
    mean neighbour count of a regular sample of about 20,000 points."""
    sample = xyz[:: max(1, len(xyz) // 20_000)]
    per_point = max((tree.query_ball_point(sample, r, return_length=True).mean() - 1) / 2, 1e-9)
    return int(max(10_000, min(len(xyz), max_pairs / per_point)))


def poisson_mask(xyz: np.ndarray, params: PoissonParams) -> np.ndarray:
    """(n,) bool of the points :func:`poisson_thin` keeps."""
    from scipy.spatial import cKDTree

    n, r = len(xyz), float(params.radius)
    tree = cKDTree(xyz)
    block = params.block or _block_size(tree, xyz, r, params.max_pairs)
    if block >= n:  # one block: the pairs of the whole cloud, from the tree already built
        pairs = tree.query_pairs(r * (1 - 1e-12), output_type="ndarray")
        pairs.sort(axis=1)
        return _greedy_in_order(n, pairs)
    keep = np.zeros(n, dtype=bool)
    kept_tree = None
    for a in range(0, n, block):
        b = min(n, a + block)
        cand = np.arange(a, b)
        if kept_tree is not None:  # drop the block's points near points kept before
            d, _ = kept_tree.query(xyz[cand], k=1, distance_upper_bound=r, workers=-1)
            cand = cand[~(d < r)]
        if cand.size:
            pairs = cKDTree(xyz[cand]).query_pairs(r * (1 - 1e-12), output_type="ndarray")
            pairs.sort(axis=1)
            keep[cand[_greedy_in_order(cand.size, pairs)]] = True
        if b < n:
            kept_tree = cKDTree(xyz[keep])
    return keep


def poisson_thin(cloud: Cloud, params: PoissonParams) -> Cloud:
    """Poisson-disk sample (PDAL ``filters.sample``): no two kept points closer than ``radius``,
    every dropped point within ``radius`` of a kept one; points taken in input order.

    Examples
    --------
    >>> c = Cloud(np.array([[0.0, 0, 0], [0.5, 0, 0], [1.0, 0, 0], [1.2, 0, 0]]))
    >>> poisson_thin(c, PoissonParams(0.8)).xyz[:, 0].tolist()
    [0.0, 1.0]
    """
    if cloud.n == 0:
        raise StageError("thin", "the cloud is empty")
    return cloud[poisson_mask(cloud.xyz, params)].with_history("thin", {"poisson": params.radius})
