"""Noise before ground filtering: statistical and radius outliers, isolated low points.

A single point a few metres under the terrain pulls a cloth, a minimum surface or a TIN seed
down with it; ground filters therefore run on clouds whose noise is classified first.
Points below their neighbourhood go to class 7 (:attr:`ASPRSClass.LOW_POINT`), isolated points
above it to class 18 (:attr:`ASPRSClass.HIGH_NOISE`). Ground filters skip both classes.

* statistical outliers: mean distance to the ``k`` nearest neighbours above the mean plus
  ``std_ratio`` standard deviations (Rusu et al. 2008, PCL's StatisticalOutlierRemoval);
* radius outliers: fewer than ``min_neighbors`` other points within ``radius``;
* isolated low points: a point more than ``depth`` below the second-lowest of its ``k``
  horizontal neighbours (so pairs of low points are caught too).

:func:`low_noise` is the **low-noise step every ground filter runs first** (``noise=True`` in
each method's parameters, ``ws ground --no-noise-step`` to skip it): PDAL and LAStools
workflows drop low noise before SMRF or lasground (``filters.elm`` / ``filters.outlier``, then
``filters.smrf``), because one point metres under the terrain becomes a cell minimum, a TIN
seed or a cloth anchor and is taken for ground with everything around it. Its points get
class 7 (:attr:`ASPRSClass.LOW_POINT`).
"""

from __future__ import annotations

import time
from dataclasses import asdict, dataclass, replace

import numpy as np

from workstation.core.classes import ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.cpu import in_blocks
from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger

from . import common

log = get_logger(__name__)
STAGE = "ground.noise"


@dataclass(frozen=True)
class NoiseParams:
    """Noise detection parameters. Lengths in metres, whatever the CRS unit.

    Attributes
    ----------
    statistical : bool
        Run the statistical test (True).
    k : int
        Neighbours for the statistical and low-point tests (8).
    std_ratio : float
        Standard deviations above the mean neighbour distance (3.0).
    radius : float
        Radius of the radius test, metres (0; 0 disables it).
    min_neighbors : int
        Fewest neighbours within ``radius`` for a point to be kept (2).
    low_depth : float
        Depth below the neighbours' second-lowest point that makes a point an isolated low
        point, metres (1.5; 0 disables the test).
    low_k : int
        Horizontal neighbours of the low-point test (10).
    """

    statistical: bool = True
    k: int = 8
    std_ratio: float = 3.0
    radius: float = 0.0
    min_neighbors: int = 2
    low_depth: float = 1.5
    low_k: int = 10


#: Points per block of the neighbour queries: each block's neighbour lists are reused from
#: the heap (:func:`workstation.core.cpu.in_blocks`).
_BLOCK = 32768


def isolated_low_points(xyz: np.ndarray, depth: float = 1.5, k: int = 10) -> np.ndarray:
    """(m,) bool: points more than ``depth`` below the 2nd-lowest of their ``k`` xy-neighbours.

    Parameters
    ----------
    xyz : (m, 3) float64, metres (local coordinates recommended).
    """
    from scipy.spatial import cKDTree

    m = xyz.shape[0]
    if m < 3 or depth <= 0:
        return np.zeros(m, dtype=bool)
    kk = min(k + 1, m)
    tree = cKDTree(xyz[:, :2])
    out = np.empty(m, bool)

    def block(s):  # a block of points at a time: no neighbour list of the whole cloud
        q = xyz[s:s + _BLOCK]
        _, j = tree.query(q[:, :2], k=kk, workers=1)
        nz = xyz[j[:, 1:], 2]
        if nz.shape[1] > 1:
            ref = np.partition(nz, 1, axis=1)[:, 1]  # 2nd-lowest neighbour, O(k) per point
        else:
            ref = nz[:, 0]
        out[s:s + _BLOCK] = q[:, 2] < ref - depth

    in_blocks(block, m, _BLOCK)
    return out


def statistical_outliers(xyz: np.ndarray, k: int = 8, std_ratio: float = 3.0) -> np.ndarray:
    """(m,) bool: mean distance to the ``k`` nearest 3D neighbours > mean + std_ratio·std."""
    from scipy.spatial import cKDTree

    m = xyz.shape[0]
    if m <= k:
        return np.zeros(m, dtype=bool)
    tree = cKDTree(xyz)
    md = np.empty(m)

    def block(s):
        d, _ = tree.query(xyz[s:s + _BLOCK], k=k + 1)
        md[s:s + _BLOCK] = d[:, 1:].mean(axis=1)

    in_blocks(block, m, _BLOCK)
    return md > md.mean() + std_ratio * md.std()


def radius_outliers(xyz: np.ndarray, radius: float, min_neighbors: int = 2) -> np.ndarray:
    """(m,) bool: fewer than ``min_neighbors`` other points within ``radius`` (3D)."""
    from scipy.spatial import cKDTree

    if radius <= 0:
        return np.zeros(xyz.shape[0], dtype=bool)
    counts = cKDTree(xyz).query_ball_point(xyz, r=radius, return_length=True) - 1
    return counts < min_neighbors


def noise_mask(xyz: np.ndarray, p: NoiseParams) -> tuple[np.ndarray, np.ndarray]:
    """Low and high noise flags (m,) bool of local metric points."""
    from scipy.spatial import cKDTree

    low = isolated_low_points(xyz, p.low_depth, p.low_k)
    out = np.zeros(xyz.shape[0], dtype=bool)
    if p.statistical:
        out |= statistical_outliers(xyz, p.k, p.std_ratio)
    if p.radius > 0:
        out |= radius_outliers(xyz, p.radius, p.min_neighbors)
    high = np.zeros_like(out)
    if out.any():
        # outliers below their neighbourhood are low noise, above it high noise
        kk = min(p.k + 1, xyz.shape[0])
        _, j = cKDTree(xyz[:, :2]).query(xyz[out, :2], k=kk)
        med = np.median(xyz[j[:, 1:], 2], axis=1)
        below = xyz[out, 2] < med
        idx = np.flatnonzero(out)
        low[idx[below]] = True
        high[idx[~below]] = True
    return low, high & ~low


def classify_noise(cloud: Cloud, params: NoiseParams | None = None, **overrides) -> Cloud:
    """Classify noise: class 7 (low point) and 18 (high noise); other classes untouched.

    Points already in a class other than 0/1 keep it.
    """
    p = replace(params or NoiseParams(), **overrides)
    t0 = time.perf_counter()
    prep = common.prepare(cloud, STAGE, reclassify=False, min_points=1)
    low, high = noise_mask(prep.xyz, p)
    old = cloud.attrs.get("classification")
    cls = np.ones(cloud.n, dtype=np.uint8) if old is None else np.array(old, dtype=np.uint8)
    free = np.isin(cls, (int(ASPRSClass.CREATED_NEVER_CLASSIFIED), int(ASPRSClass.UNCLASSIFIED), int(ASPRSClass.GROUND)))
    li = prep.index[low]
    hi = prep.index[high]
    cls[li[free[li]]] = int(ASPRSClass.LOW_POINT)
    cls[hi[free[hi]]] = int(ASPRSClass.HIGH_NOISE)
    log.info("%s: %d low and %d high noise points", STAGE, int(low.sum()), int(high.sum()))
    return cloud.with_attrs(classification=cls).with_history(STAGE, asdict(p), time.perf_counter() - t0)


# -- the low-noise step of every ground filter -----------------------------------------------
@dataclass(frozen=True)
class LowNoiseParams:
    """The low-noise step run before every ground filter (:func:`low_noise`). Lengths in
    metres, whatever the CRS unit.

    Attributes
    ----------
    depth : float
        How far below its surroundings a point must lie to be low noise, metres (1.0, the
        threshold of PDAL's ``filters.elm``).
    cell : float
        Cell of the lower envelope, metres (2.0): the two lowest points of each cell are what a
        point is judged against, so canopy, roofs and walls above the ground never are.
    k : int
        Envelope points around each point (64): enough that a neighbourhood holds several
        ground points even where few pulses reach the ground (0.1-0.2 ground points/m² under a
        closed canopy: a radius of about 7 m).
    radius : float
        Farthest envelope point considered, metres (10.0).
    max_slope : float
        Steepest local terrain slope the test corrects for, rise over run (1.0).
    iterations : int
        Passes (4): after a point is taken out, the next-lowest point of its cell is judged (a
        low point under a low point, as ELM does).
    """

    depth: float = 1.0
    cell: float = 2.0
    k: int = 64
    radius: float = 10.0
    max_slope: float = 1.0
    iterations: int = 4


_SUPPORT = 2  # envelope points at a point's level needed to keep it: pairs of low points go too


def _envelope(z: np.ndarray, flat: np.ndarray, size: int, out: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Indices of the lowest and of the second-lowest point of each cell (``out`` excluded)."""
    first = _cell_argmin(np.where(out, np.inf, z), flat, size)
    taken = out.copy()
    taken[first] = True
    second = _cell_argmin(np.where(taken, np.inf, z), flat, size)
    return first, second


def _cell_argmin(z: np.ndarray, flat: np.ndarray, size: int) -> np.ndarray:
    """Index of the lowest finite ``z`` of each occupied cell (flat cell index per point)."""
    zmin = np.full(size, np.inf)
    np.fmin.at(zmin, flat, z)
    hit = np.flatnonzero(np.isfinite(z) & (z == zmin[flat]))
    imin = np.full(size, np.iinfo(np.int64).max, dtype=np.int64)
    np.minimum.at(imin, flat[hit], hit)
    return imin[imin != np.iinfo(np.int64).max]


def _local_planes(dxy: np.ndarray, nz: np.ndarray, valid: np.ndarray, depth: float,
                  max_slope: float) -> tuple[np.ndarray, np.ndarray]:
    """Per point, a robust plane through the lowest neighbour of each 45-degree octant.

    Every plane no steeper than ``max_slope`` through three of the (up to eight) octant minima
    is tried, the one with the most minima within ``depth`` of it wins (the lower at the point on a tie: the ground is the
    lower envelope), and the plane is refitted by least squares to those minima. Octants with
    no ground (only crowns or a roof in them) and other low points among the minima are
    outvoted, as in RANSAC (Fischler & Bolles 1981) with every sample tried.

    Returns
    -------
    coef : (m, 3) float64
        Height at the point and gradient (dz/dx, dz/dy) of the plane.
    ok : (m,) bool
        At least four octants held a neighbour and three minima agree.
    """
    from itertools import combinations

    m = nz.shape[0]
    octant = (np.floor((np.arctan2(dxy[..., 1], dxy[..., 0]) + np.pi) / (np.pi / 4)).astype(np.int8)) % 8
    zv = np.where(valid, nz, np.inf)
    lo = np.full((m, 8, 3), np.nan)  # x, y, z of each octant's minimum
    rows = np.arange(m)
    for o in range(8):
        zo = np.where(octant == o, zv, np.inf)
        a = np.argmin(zo, axis=1)
        hit = np.isfinite(zo[rows, a])
        lo[hit, o, :2] = dxy[rows[hit], a[hit]]
        lo[hit, o, 2] = zo[rows[hit], a[hit]]
    # octant-major copies (8, m): every product below runs on contiguous rows
    lx, ly, lz = (np.ascontiguousarray(lo[..., c].T) for c in range(3))
    have = np.isfinite(lz)
    best = np.full(m, -np.inf)
    inl = np.zeros((8, m), dtype=bool)
    for i, j, k in combinations(range(8), 3):
        u = (lx[j] - lx[i], ly[j] - ly[i], lz[j] - lz[i])
        v = (lx[k] - lx[i], ly[k] - ly[i], lz[k] - lz[i])
        n0, n1, n2 = u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]  # plane normal
        # a plane steeper than max_slope would join ground on one side to crowns on the other
        good = have[i] & have[j] & have[k] & (np.abs(n2) * max_slope >= np.hypot(n0, n1))
        good &= np.abs(n2) > 1e-9
        if not good.any():
            continue
        nzc = np.where(good, n2, 1.0)
        # z of the plane at each octant minimum and at the point (0, 0)
        zp = lz[i] + (n0 * lx[i] + n1 * ly[i]) / nzc
        zat = zp - (n0 * lx + n1 * ly) / nzc
        ins = have & (np.abs(lz - zat) <= depth)
        score = np.where(good, ins.sum(axis=0) * 1e6 - zp, -np.inf)
        win = score > best
        best[win] = score[win]
        inl[:, win] = ins[:, win]
    have, inl = np.ascontiguousarray(have.T), np.ascontiguousarray(inl.T)
    w = inl.astype(np.float64)
    ok = (have.sum(axis=1) >= 4) & (w.sum(axis=1) >= 3)
    A = np.concatenate([np.ones((m, 8, 1)), np.nan_to_num(lo[..., :2])], axis=-1)
    ata = np.einsum("nki,nk,nkj->nij", A, w, A) + 1e-9 * np.eye(3)
    atb = np.einsum("nki,nk,nk->ni", A, w, np.nan_to_num(lo[..., 2]))
    coef = np.linalg.solve(ata, atb[..., None])[..., 0]
    return coef, ok


def low_noise(xyz: np.ndarray, p: LowNoiseParams | None = None) -> np.ndarray:
    """(m,) bool: isolated low points, which no ground filter should see.

    An Extended Local Minimum test (Chen et al. 2012, "Upward-fusion urban DTM generating
    method using airborne Lidar data", ISPRS J. Photogramm. 72:121-130; PDAL's
    ``filters.elm``: a cell's lowest point more than 1 m below the next lowest is noise, and
    the next one is judged in turn), made independent of the grid, of the slope and of the
    density:

    1. the *lower envelope*: the lowest and second-lowest point of every ``cell`` (objects above
       the ground never take part, so sparse ground under a closed canopy is judged against
       other ground, not against the crowns: the failure of SMRF's grid low-outlier test and
       of a k-nearest-neighbour test over all points);
    2. for each cell minimum, its ``k`` nearest envelope points within ``radius``: a robust
       plane through the lowest of them in each of eight directions (:func:`_local_planes`)
       gives the local terrain height and slope;
    3. the minimum is low noise when it lies more than ``depth`` under that plane **and** fewer
       than two of the envelope points lie within ``depth`` of its height, corrected for the
       plane's slope (capped at ``max_slope``; as they are within one cell): a true ground
       point at the foot of a slope or in a ditch has neighbours at its level, a multipath
       return does not;
    4. repeated on the next-lowest point of each cell that lost a point (``iterations``).

    Limit: a lone ground return with no other ground within about ``radius`` and objects all
    around it (between wagons, under a station roof: 60 of ISPRS samp42's ground points) is
    geometrically such a low point and is taken too.

    Parameters
    ----------
    xyz : (m, 3) float64
        Local metric points (metres; :func:`workstation.ground.common.prepare`).
    p : LowNoiseParams, optional

    Returns
    -------
    (m,) bool
        True on low noise.

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> xy = rng.uniform(0, 40, (4000, 2))
    >>> xyz = np.column_stack([xy, 0.2 * xy[:, 0]])
    >>> xyz[7, 2] -= 20.0
    >>> np.flatnonzero(low_noise(xyz)).tolist()
    [7]
    """
    p = p or LowNoiseParams()
    m = xyz.shape[0]
    noise = np.zeros(m, dtype=bool)
    if m < 3 or p.depth <= 0:
        return noise
    grid = _noise_grid(xyz, p)
    if grid is None:
        return noise
    flat, size, cell = grid
    z = xyz[:, 2]
    judge_cells = None  # first pass: every cell
    for _ in range(max(1, int(p.iterations))):
        first, second = _envelope(z, flat, size, noise)
        env = np.concatenate([first, second])
        cand = first if judge_cells is None else first[np.isin(flat[first], judge_cells)]
        if cand.size == 0 or env.size <= _SUPPORT:
            break
        new = cand[_low_minima(xyz, cand, env, p, cell)]
        if new.size == 0:
            break
        noise[new] = True
        judge_cells = np.unique(flat[new])
    return noise


def _noise_grid(xyz: np.ndarray, p: LowNoiseParams):
    """The internal grid of :func:`low_noise` as ``(flat cell index per point, cell count, cell
    size in metres)``: ``p.cell``, coarsened on a cloud spread far wider than its points; None
    (step skipped) when even that grid does not fit, leaving the refusal, naming its option, to
    the ground filter's own check."""
    cell = common.auto_cell(xyz[:, :2], p.cell)
    try:
        r, c, shape, _ = common.grid_index(xyz[:, :2], cell, common.aligned_origin(xyz[:, :2], cell))
    except InvalidInputError:
        log.warning("%s: the points are spread too wide for the low-noise step's grid; step skipped", STAGE)
        return None
    return r * shape[1] + c, shape[0] * shape[1], cell


def _low_minima(xyz: np.ndarray, cand: np.ndarray, env: np.ndarray, p: LowNoiseParams, cell: float) -> np.ndarray:
    """Steps 2-3 of :func:`low_noise` for the cell minima ``cand`` against the envelope points
    ``env``: (len(cand),) bool, True where the minimum lies more than ``p.depth`` under its local
    plane (or, without a plane, under the second-lowest neighbour, as ELM) and fewer than
    ``_SUPPORT`` envelope points lie at its level, among at least ``_SUPPORT`` neighbours."""
    from scipy.spatial import cKDTree

    z = xyz[:, 2]
    kk = min(int(p.k) + 1, env.size)
    d, j = cKDTree(xyz[env, :2]).query(xyz[cand, :2], k=kk, distance_upper_bound=p.radius, workers=-1)
    valid = np.isfinite(d)
    nb = env[np.where(valid, j, 0)]
    valid &= nb != cand[:, None]
    dxy = xyz[nb, :2] - xyz[cand, None, :2]
    nz = np.where(valid, z[nb], np.inf)
    coef, ok = _local_planes(dxy, nz, valid, p.depth, p.max_slope)
    support = _level_support(dxy, nz, valid, coef, ok, z[cand, None], p, cell)
    # without a plane (an edge, a corner): under the second-lowest envelope point, as ELM
    second_low = np.partition(nz, 1, axis=1)[:, 1] if nz.shape[1] > 1 else nz[:, 0]
    below = np.where(ok, z[cand] < coef[:, 0] - p.depth, z[cand] < second_low - p.depth)
    return below & (support < _SUPPORT) & (valid.sum(axis=1) >= _SUPPORT)


def _level_support(dxy, nz, valid, coef, ok, zc, p: LowNoiseParams, cell: float) -> np.ndarray:
    """(n,) int: the neighbours within ``p.depth`` of each candidate's height ``zc`` once the
    local plane's slope (capped at ``p.max_slope``, 0 without a plane) is taken out; neighbours
    within one ``cell`` may also match without the slope, where a wrong slope counts most."""
    g = coef[:, 1:]
    s = np.hypot(g[:, 0], g[:, 1])
    g *= np.minimum(1.0, p.max_slope / np.maximum(s, 1e-12))[:, None]
    g[~ok] = 0.0
    level = np.abs(nz - np.einsum("nkd,nd->nk", dxy, g) - zc)
    # as they are too within a cell of the point, where a wrong plane slope counts most
    close = np.einsum("nkd,nkd->nk", dxy, dxy) <= cell * cell
    level = np.where(close, np.minimum(level, np.abs(nz - zc)), level)
    return ((level <= p.depth) & valid).sum(axis=1)
