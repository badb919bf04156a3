r"""Correspondences between overlapping flight lines: planar patches seen by two strips.

A strip is a flight line (LAS ``point_source_id``). The overlap is cut into square plan cells
of side ``cell_m``; in every cell each strip's single returns get a least-squares plane (the
eigenvector of the smallest eigenvalue of their covariance; Pauly et al. 2002). A (cell,
strip) slot is a **patch** when

* it holds at least ``min_points`` points, spread over the cell: the middle eigenvalue is at
  least :math:`(f\,c)^2 / 12`, the variance of points uniform over a fraction ``f`` of a side
  ``c``, so the plane's tilt is determined in both directions;
* it is planar to within the measurement noise: with :math:`s^2 = \lambda_{min}\,n/(n-3)` the
  residual variance about the plane, :math:`(n-3)\,s^2/\sigma^2 \le \chi^2_{1-\alpha}(n-3)`,
  where :math:`\sigma` is the noise of a point along the normal (the range noise for a
  near-nadir beam). Unless given, :math:`\sigma` is the median of :math:`s` over the
  spread slots trimmed by the test itself (:func:`smooth_noise`), which finds the noise of
  the smooth surfaces (open ground, roads, roofs) among rough ones, at most the intraswath
  precision limit of the USGS Lidar Base Specification; edges, walls, vegetation and cars fail
  the test.

Two patches of different strips in one cell form a **correspondence** when their normals agree
within their uncertainty (:math:`\sigma_\theta^2 \approx s^2 / (n\,\lambda_{mid})` each,
the variance of a least-squares slope; :math:`\chi^2_2` test at the same level). Its
observation is the distance between the two planes along the mean normal,
:math:`d = \mathbf n^\top(\mathbf c_b - \mathbf c_a)` (Filin 2003 uses such surface-to-surface
differences; Glira et al. 2015 the point-to-plane distances of ICP), with variance
:math:`s_a^2/n_a + s_b^2/n_b`. Sloped roofs give the horizontal components of
:math:`\mathbf n` that make horizontal offsets and heading errors observable; a flat-only
overlap has none (the least-squares stage reports that, see :mod:`workstation.adjust.lsq`).

References
----------
S. Filin (2003). Recovery of systematic biases in laser altimetry data using natural surfaces.
Photogramm. Eng. Remote Sens. 69(11):1235-1242.
P. Glira, N. Pfeifer, C. Briese, C. Ressl (2015). Rigorous strip adjustment of airborne
laserscanning data based on the ICP algorithm. ISPRS Annals II-3/W5:73-80.
M. Pauly, M. Gross, L. P. Kobbelt (2002). Efficient simplification of point-sampled surfaces.
IEEE Visualization 2002:163-170.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.classes import NOISE
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.pca import grouped_plane_fit
from workstation.qc.swath import SwathParams

log = get_logger(__name__)

_SID = 1 << 16  # point source ids are u16


@dataclass(frozen=True)
class PatchParams:
    """How patches are chosen; every length in metres.

    Attributes
    ----------
    cell_m : float or None
        Side of the plan cells. None: chosen so that a cell holds on average
        ``4 * min_points`` single returns of one strip (from the median strip density), grown
        until most cells of a strip are spread over ``min_extent`` of the cell both ways.
    min_points : int
        Points of one strip in a cell for a plane. Default 10.
    noise_m : float or None
        1-sigma noise of a point along the surface normal. None: estimated (module docs).
    max_noise_m : float
        Upper bound of the estimated noise: the intraswath precision limit of the USGS Lidar
        Base Specification (QL1/QL2, the ``precision_limit_m`` of ``ws qc``'s swath check).
        Surfaces scattering more than a conforming sensor may on a smooth surface are not smooth
        (in a closed forest no slot may be). Default 0.06.
    confidence : float
        Level of the planarity and normal-agreement chi-square tests. Default 0.99.
    min_extent : float
        Fraction ``f`` of the cell side the points must span in both directions. Default 0.5.
    """

    cell_m: float | None = None
    min_points: int = 10
    noise_m: float | None = None
    max_noise_m: float = SwathParams().precision_limit_m
    confidence: float = 0.99
    min_extent: float = 0.5

    def __post_init__(self):
        if self.cell_m is not None and not (np.isfinite(self.cell_m) and self.cell_m > 0):
            raise InvalidInputError(f"cell_m must be a positive length, got {self.cell_m}", field="cell_m")
        if self.min_points < 4:
            raise InvalidInputError("min_points must be at least 4 (a plane has 3 unknowns)", field="min_points")
        for name in ("noise_m", "max_noise_m"):
            v = getattr(self, name)
            if v is not None and not (np.isfinite(v) and v > 0):
                raise InvalidInputError(f"{name} must be a positive length, got {v}", field=name)
        if not 0.5 < self.confidence < 1 or not 0 < self.min_extent <= 1:
            raise InvalidInputError("confidence must be in (0.5, 1) and min_extent in (0, 1]", field="confidence")


@dataclass(frozen=True)
class Planes:
    """Least-squares planes of point groups (slots); shapes (m,) or (m, 3).

    ``centroid`` (m), ``normal`` (unit, z >= 0), ``count``, ``s2`` (residual variance along
    the normal, m^2, n - 3 degrees of freedom), ``lam_mid`` (middle eigenvalue, m^2).
    """

    centroid: np.ndarray
    normal: np.ndarray
    count: np.ndarray
    s2: np.ndarray
    lam_mid: np.ndarray


@dataclass(frozen=True)
class Patches:
    """Correspondences between strips.

    Attributes
    ----------
    index : (k,) int64
        Indices of the points used (into the arrays given to :func:`find_patches`).
    slot : (k,) int64
        Patch of each used point (0..m-1).
    strip : (m,) int64
        Strip id (point source id) of each patch.
    pair_a, pair_b : (p,) int64
        The two patches of each correspondence (strip of a < strip of b).
    noise_m : float
        The noise used in the planarity test (given or estimated), metres.
    cell_m : float
        The cell side used, metres.
    origin : (3,) float
        Subtracted from the coordinates before fitting (numerical conditioning), metres.
    """

    index: np.ndarray
    slot: np.ndarray
    strip: np.ndarray
    pair_a: np.ndarray
    pair_b: np.ndarray
    noise_m: float
    cell_m: float
    origin: np.ndarray

    @property
    def n_slots(self) -> int:
        return int(self.strip.size)


def usable_points(attrs) -> np.ndarray:
    """Mask of single returns that are not withheld nor noise (as the swath-overlap check)."""
    n = len(next(iter(attrs.values())))
    keep = np.ones(n, bool)
    if "number_of_returns" in attrs:
        keep &= np.asarray(attrs["number_of_returns"]) <= 1
    if "withheld" in attrs:
        keep &= np.asarray(attrs["withheld"]) == 0
    if "classification" in attrs:
        keep &= ~np.isin(attrs["classification"], np.asarray(NOISE, np.uint8))
    return keep


def plane_fit(xyz: np.ndarray, slot: np.ndarray, m: int) -> Planes:
    """Planes of the points ``xyz`` (k, 3) grouped by ``slot`` (k,) into ``m`` groups (two passes:
    centroids, then centred second moments, so large coordinates lose no precision); the plane
    variance has the three degrees of freedom of the plane removed."""
    g = grouped_plane_fit(xyz, slot, m, residuals=False)
    n = g.counts.astype(float)
    s2 = g.eigenvalues[:, 0].clip(0) * n / np.maximum(n - 3, 1)
    return Planes(g.centroids, g.normals, g.counts, s2, g.eigenvalues[:, 1])


def auto_cell(xy: np.ndarray, sid: np.ndarray, min_points: int) -> float:
    """Cell side (m) holding on average ``4 * min_points`` points of one strip, from the median
    over strips of points per occupied square metre."""
    dens = []
    for s in np.unique(sid):
        q = np.floor(xy[sid == s]).astype(np.int64)
        occupied = np.unique((q[:, 0] - q[:, 0].min()) * (1 << 31) + (q[:, 1] - q[:, 1].min())).size
        dens.append(np.count_nonzero(sid == s) / max(occupied, 1))
    return float(np.sqrt(4 * min_points / np.median(dens)))


def smooth_noise(s2: np.ndarray, limit: np.ndarray, iterations: int = 200) -> float:
    r"""Noise (m) of the smooth slots among rough ones: the fixed point of
    :math:`\sigma = \mathrm{median}\{s : s^2 \le \sigma^2 \ell\}` started from the lower
    quartile of :math:`s` (so that it settles on the lowest mode when rough slots are the most),
    with :math:`\ell` the planarity limit of each slot (a median trimmed by the test itself, so
    rough slots - vegetation, edges - stop counting as the estimate falls to the smooth ones'
    mode; for Gaussian noise on planes the median of :math:`s` is :math:`\sigma` to 2 %)."""
    s = np.sqrt(s2)
    sigma = float(np.percentile(s, 25))
    for _ in range(iterations):
        inside = s2 <= sigma ** 2 * limit
        new = float(np.median(s[inside])) if inside.any() else sigma
        if abs(new - sigma) <= 1e-4 * sigma:
            break
        sigma = new
    return sigma


def _slots(xyz: np.ndarray, sid: np.ndarray, cell: float, min_points: int):
    """(order, slot per sorted point, slot keys) of the (cell, strip) groups with enough points."""
    q = np.floor(xyz[:, :2] / cell).astype(np.int64)
    q -= q.min(axis=0)
    key = (q[:, 1] * (int(q[:, 0].max()) + 1) + q[:, 0]) * _SID + sid.astype(np.int64)
    order = np.argsort(key, kind="stable")
    key = key[order]
    start = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
    count = np.diff(np.r_[start, key.size])
    big = count >= min_points
    slot_of_group = np.cumsum(big) - 1
    group = np.repeat(np.arange(start.size), count)
    keep = big[group]
    return order[keep], slot_of_group[group[keep]], key[start[big]]


def _cells(p: np.ndarray, s: np.ndarray, params: PatchParams):
    """Cell side and slots: ``params.cell_m``, or :func:`auto_cell` grown by sqrt(2) (at most six
    times) until at least half of the slots are spread over ``min_extent`` of the cell both
    ways. Scanners sample anisotropically (scan lines ~0.5 m apart along track at any pulse
    rate), so a cell sized by density alone can hold one or two scan lines of a strip."""
    cell = params.cell_m or auto_cell(p[:, :2], s, params.min_points)
    for _ in range(7):
        order, slot, key = _slots(p, s, cell, params.min_points)
        if key.size == 0:
            raise StageError("strip-adjust", f"no {cell:.2f} m cell holds {params.min_points} single returns of one "
                             "strip", "give a larger --cell")
        pl = plane_fit(p[order], slot, key.size)
        spread = pl.lam_mid >= (params.min_extent * cell) ** 2 / 12
        if params.cell_m or spread.mean() >= 0.5:
            break
        cell *= np.sqrt(2.0)
    return cell, order, slot, key, pl, spread


def _pairs(cell_key: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """All (i, j), i < j, of entries of the sorted ``cell_key`` that share a cell."""
    ia, ib = [], []
    for off in range(1, 16):  # at most 16 strips over one cell
        if off >= cell_key.size:
            break
        i = np.flatnonzero(cell_key[:-off] == cell_key[off:])
        if i.size == 0:
            break
        ia.append(i)
        ib.append(i + off)
    if not ia:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    return np.concatenate(ia), np.concatenate(ib)


def find_patches(xyz: np.ndarray, sid: np.ndarray, params: PatchParams = PatchParams(),
                 usable: np.ndarray | None = None) -> Patches:
    """Planar patches of every strip in the overlaps and their correspondences (module docs).

    Parameters
    ----------
    xyz : (n, 3) float
        Points, metres.
    sid : (n,) int
        Strip (point source id) of each point.
    params : PatchParams
    usable : (n,) bool, optional
        Points allowed (default all), e.g. :func:`usable_points`.

    Returns
    -------
    Patches
    """
    from scipy.special import chdtri  # chdtri(k, 1 - q): the q quantile of chi-square(k)

    idx = np.flatnonzero(usable) if usable is not None else np.arange(len(xyz))
    if np.unique(sid[idx]).size < 2:
        raise StageError("strip-adjust", "fewer than two strips among the usable points",
                         "give overlapping flight lines with distinct point_source_id values")
    origin = np.floor(xyz[idx].min(axis=0)) if idx.size else np.zeros(3)
    p = xyz[idx] - origin
    s = np.asarray(sid)[idx]
    cell, order, slot, key, pl, spread = _cells(p, s, params)
    dof = np.maximum(pl.count - 3, 1)
    limit = chdtri(dof, 1 - params.confidence) / dof  # s^2 / sigma^2 of a plane at the test level
    noise = params.noise_m or min(smooth_noise(pl.s2[spread], limit[spread]), params.max_noise_m)
    planar = pl.s2 <= noise ** 2 * limit
    ok = np.flatnonzero(planar & spread)
    a, b = _pairs(key[ok] // _SID)
    a, b = ok[a], ok[b]
    var_t = pl.s2 / np.maximum(pl.count * pl.lam_mid, 1e-12)  # normal direction variance (rad^2)
    ang2 = np.sum(np.cross(pl.normal[a], pl.normal[b]) ** 2, axis=1)
    agree = ang2 <= (var_t[a] + var_t[b]) * chdtri(2, 1 - params.confidence)
    a, b = a[agree], b[agree]
    used = np.unique(np.r_[a, b])
    remap = np.full(key.size, -1, np.int64)
    remap[used] = np.arange(used.size)
    keep_pt = remap[slot] >= 0
    log.info("patches: cell %.2f m, noise %.3f m, %d slots, %d planar, %d correspondences", cell, noise, key.size,
             ok.size, a.size)
    if a.size == 0:
        raise StageError("strip-adjust", f"no planar patches in the overlaps of the strips ({ok.size} smooth "
                         f"{cell:.2f} m cells, noise {noise:.3f} m)",
                         "the strips share no smooth surface (open ground, roads, roofs): adjust together with "
                         "neighbouring tiles of the same flight lines (same point_source_id), or check the overlap")
    return Patches(idx[order[keep_pt]], remap[slot[keep_pt]], (key[used] % _SID).astype(np.int64),
                   remap[a], remap[b], noise, cell, origin)
