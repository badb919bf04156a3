"""PTD, progressive TIN densification (Axelsson 2000).

Axelsson P. (2000) "DEM generation from laser scanner data using adaptive TIN models",
Int. Arch. Photogramm. Remote Sens. 33(B4):110-117.

1. Candidates: the lowest point of every ``candidate_cell`` (the others are judged at the end
   against the final TIN), isolated low points set aside;
2. seeds: the lowest candidate of every ``seed_cell`` (larger than the largest building) and of
   the four corner blocks;
3. iterations: a Delaunay TIN of the ground points; every candidate is located in its triangle
   in bulk (``find_simplex``); it passes when its distance to the triangle's plane is below
   ``max_distance`` and the largest angle between that plane and the lines to the triangle's
   vertices is below ``max_angle``; passing candidates join the ground (or, with
   ``one_per_triangle``, the one closest to the plane per triangle); re-triangulate, until
   nothing joins or ``max_iterations``;
4. every point within ``final_threshold`` (vertical) of the final TIN, or accepted, is ground.

Mirroring near breaklines is not implemented.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, replace

import numpy as np

from workstation.core.cloud import Cloud

from . import common

STAGE = "ground.ptd"


@dataclass(frozen=True)
class PTDParams:
    """PTD parameters. Lengths in metres, angles in degrees.

    Attributes
    ----------
    seed_cell : float
        Cell of the seed points, metres (20.0): larger than the largest building.
    candidate_cell : float
        Thinning cell of the candidates, metres (1.0).
    max_angle : float
        Iteration angle, degrees (15.0).
    max_distance : float
        Iteration distance to the triangle's plane, metres (1.5).
    one_per_triangle : bool
        Add only the passing candidate closest to the plane per triangle and iteration (False:
        every passing candidate joins; fewer iterations, about the same errors here).
    min_edge : float
        Triangles whose longest edge is shorter than this take no more points, metres (1.5).
    final_threshold : float
        Vertical distance to the final TIN below which any point is ground, metres (0.3).
    max_iterations : int
        (60).
    reclassify, last_returns_only : bool
        See :class:`workstation.ground.smrf.SMRFParams`.
    """

    seed_cell: float = 20.0
    candidate_cell: float = 1.0
    max_angle: float = 15.0
    max_distance: float = 1.5
    one_per_triangle: bool = False
    min_edge: float = 1.5
    final_threshold: float = 0.3
    max_iterations: int = 60
    reclassify: bool = False
    last_returns_only: bool = True


PRESETS: dict[str, PTDParams] = {
    "default": PTDParams(),
    "flat": PTDParams(max_angle=10.0, max_distance=1.0, seed_cell=25.0),
    "urban": PTDParams(max_angle=10.0, max_distance=1.0, seed_cell=40.0),
    "forest": PTDParams(max_angle=15.0, max_distance=1.5, seed_cell=15.0),
    "steep": PTDParams(max_angle=25.0, max_distance=2.0, seed_cell=12.0),
}


def _seeds(xyz: np.ndarray, cell: float) -> np.ndarray:
    """Indices of the lowest point per ``cell`` plus the lowest near each corner."""
    r, c, shape, _ = common.grid_index(xyz[:, :2], cell, origin=xyz[:, :2].min(axis=0))
    _, imin = common.grid_min(xyz[:, 2], r, c, shape)
    seeds = imin[imin >= 0]
    lo = xyz[:, :2].min(axis=0)
    hi = xyz[:, :2].max(axis=0)
    corners = np.array([[lo[0], lo[1]], [hi[0], lo[1]], [lo[0], hi[1]], [hi[0], hi[1]]])
    from scipy.spatial import cKDTree

    tree = cKDTree(xyz[:, :2])
    k = min(16, xyz.shape[0])
    _, j = tree.query(corners, k=k)
    j = np.atleast_2d(j)
    low = j[np.arange(4), np.argmin(xyz[j, 2], axis=1)]
    return np.unique(np.concatenate([seeds, low]))


def densify(cand: np.ndarray, p: PTDParams) -> np.ndarray:
    """Ground flags (k,) bool of candidate points (k, 3) by progressive TIN densification."""
    ground = np.zeros(cand.shape[0], dtype=bool)
    ground[_seeds(cand, p.seed_cell)] = True
    tan_a = np.tan(np.radians(p.max_angle))
    for _ in range(int(p.max_iterations)):
        gi = np.flatnonzero(ground)
        if gi.size < 3:
            break
        try:
            tri = common.delaunay(cand[gi, :2])
        except Exception:  # collinear seeds
            break
        oi = np.flatnonzero(~ground)
        if oi.size == 0:
            break
        q = cand[oi]
        with common._one_blas_thread():
            s = tri.find_simplex(q[:, :2])
        inside = s >= 0
        oi, q, s = oi[inside], q[inside], s[inside]
        if oi.size == 0:
            break
        v = gi[tri.simplices[s]]  # (k, 3) candidate indices of the vertices
        A, B, C = cand[v[:, 0]], cand[v[:, 1]], cand[v[:, 2]]
        n = np.cross(B - A, C - A)
        nz = n[:, 2]
        flat = np.abs(nz) < 1e-12
        n_norm = np.linalg.norm(n, axis=1)
        n_norm[n_norm == 0] = 1.0
        d = np.abs(np.einsum("ij,ij->i", q - A, n)) / n_norm  # perpendicular distance to the plane
        # longest horizontal edge of the triangle
        e = np.maximum.reduce([np.hypot(*(B - A)[:, :2].T), np.hypot(*(C - B)[:, :2].T), np.hypot(*(A - C)[:, :2].T)])
        # angle to each vertex: sin(alpha) = d / |P - V|; tan-test on the largest
        dist_v = np.minimum.reduce([np.linalg.norm(q - A, axis=1), np.linalg.norm(q - B, axis=1), np.linalg.norm(q - C, axis=1)])
        dist_v = np.maximum(dist_v, 1e-9)
        sin_max = np.clip(d / dist_v, 0, 1)
        tan_max = sin_max / np.sqrt(np.maximum(1 - sin_max ** 2, 1e-12))
        ok = (d < p.max_distance) & (tan_max < tan_a) & (e > p.min_edge) & ~flat
        if not ok.any():
            break
        oi, s, d = oi[ok], s[ok], d[ok]
        if p.one_per_triangle:
            order = np.lexsort((d, s))
            ss = s[order]
            first = np.ones(order.size, dtype=bool)
            first[1:] = ss[1:] != ss[:-1]
            ground[oi[order[first]]] = True
        else:
            ground[oi] = True
    return ground


def ptd_ground(xyz: np.ndarray, p: PTDParams) -> np.ndarray:
    """Ground flags (m,) bool of local metric points by PTD."""
    from .noise import isolated_low_points

    m = xyz.shape[0]
    usable = ~isolated_low_points(xyz)
    ui = np.flatnonzero(usable)
    r, c, shape, _ = common.grid_index(xyz[ui, :2], p.candidate_cell, origin=xyz[:, :2].min(axis=0))
    _, imin = common.grid_min(xyz[ui, 2], r, c, shape)
    ci = ui[imin[imin >= 0]]
    g_c = densify(xyz[ci], p)
    out = np.zeros(m, dtype=bool)
    out[ci[g_c]] = True
    gidx = ci[g_c]
    if gidx.size >= 3:
        zt = common.tin_interpolate(xyz[gidx, :2], xyz[gidx, 2], xyz[:, :2])
        out |= usable & (np.abs(xyz[:, 2] - zt) < p.final_threshold)
    return out


def ptd(cloud: Cloud, params: PTDParams | None = None, **overrides) -> Cloud:
    """Classify ground by progressive TIN densification (Axelsson 2000).

    Returns
    -------
    Cloud
        ``classification`` 2 on ground, 1 elsewhere (other classes kept unless ``reclassify``).
    """
    p = replace(params or PTDParams(), **overrides)
    t0 = time.perf_counter()
    prep = common.prepare(cloud, STAGE, p.reclassify, p.last_returns_only)
    g = ptd_ground(prep.xyz, p)
    return common.write_classes(cloud, prep, g, STAGE, p, t0, p.reclassify)
