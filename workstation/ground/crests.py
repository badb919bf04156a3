"""Crests: terrain that a ground filter cut off as an object goes back to the ground.

A morphological ground filter (PMF, SMRF, the point classifier's provisional surface) takes
out any raised feature narrower than its window whose sides are steeper than its slope
tolerance. A dyke, a levee, a railway embankment or a narrow ridge loses its crest that way,
though sides of up to 45° are terrain. What tells such a crest from a roof or a car is its
sides: terrain is a continuous surface, never steeper than ``max_slope`` between a point and
any lower point near it (the premise of Vosselman's slope-based filter, 2000), whereas a roof
stands over the ground beyond its walls and a crown over the ground beneath it.

1. The *steep surface*: a progressive morphological filter of the lowest point per ``cell``
   whose slope tolerance is ``max_slope`` (square openings up to ``window``; Zhang et al.
   2003). It keeps all that is no steeper than terrain can be: crests, and wide roofs too.
2. Where it stands more than ``tolerance`` above the ground's own surface (the lowest ground
   point per cell, empty cells filled from the nearest), the filter cut something: each
   8-connected region of such cells is one cut feature.
3. Its *candidates* are the points off the ground within ``tolerance`` (plus one cell's
   relief) of the steep surface. A feature is a crest when at least ``min_points`` of them
   stand ``min_rise`` or more over the ground surface (a landform, not a low object that the
   ground filter rightly refused), and no candidate stands over a lower point (the lowest of a
   cell, within ``radius``) by more than ``max_slope`` times their distance plus
   ``tolerance``: one such point makes it an object (a wall, a crown), and the whole feature
   stays out. Lower points farther away are compared on the grid (the erosion of the lowest
   points with a cone, Vosselman's filter), so that a roof whose walls and nearby ground
   were not sampled is found too.
4. The candidates of the crests join the ground.

The cost is one opening sequence of the grid, two nearest fills and, for the candidates of
features that pass the height test only, one look at each cell within ``radius``.

Examples
--------
A dyke with 1:1 sides, 6 m high, whose crest and sides a filter refused, and a 6 m box (a
building) that it refused too:

>>> import numpy as np
>>> g = np.mgrid[0:80:1.0, 0:60:1.0].reshape(2, -1).T
>>> dyke = np.clip(6.0 - np.abs(g[:, 1] - 20.0) + 3.0, 0.0, 6.0)
>>> box = ((np.abs(g - [60.0, 45.0]) < 6).all(axis=1)) * 6.0
>>> xyz = np.column_stack([g, dyke + box])
>>> refused = (dyke > 0.5) | (box > 0)
>>> ground = crest_fill(xyz, ~refused)
>>> bool(ground[dyke > 0.5].all()), bool(ground[box > 0].any())
(True, False)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class CrestParams:
    """Settings of the crest fill. Lengths in metres.

    Attributes
    ----------
    max_slope : float
        Terrain is never steeper than this between neighbouring points (rise over run; 1.0 =
        45°, the riser step's bound too: :class:`workstation.ground.risers.RiserParams`).
    tolerance : float
        Vertical tolerance of the surfaces and of the slope test (0.5, the classifier's gate
        band at zero slope).
    min_rise : float
        A crest stands at least this high over the ground around it (2.0: above the cars,
        hedges and low walls the ground filter rightly refused).
    min_points : int
        ... with at least this many points (3: a surface, not a lone point).
    radius : float
        The slope test compares a point with the lowest point of each cell this near (5.0).
    window : float
        Largest opening radius of the steep surface (30.0, SMRF's window in ``auto``).
    cell : float
        Grid cell (1.0; coarsened on sparse data of a large extent:
        :func:`workstation.ground.common.auto_cell`).
    """

    max_slope: float = 1.0
    tolerance: float = 0.5
    min_rise: float = 2.0
    min_points: int = 3
    radius: float = 5.0
    window: float = 30.0
    cell: float = 1.0


@dataclass(frozen=True, eq=False)
class CrestTest:
    """What :func:`crest_test` found.

    Attributes
    ----------
    candidates : (k,) int64
        Points off the ground near the steep surface in a cut feature.
    feature : (k,) int64
        Each candidate's feature, 1..n.
    tall : (n + 1,) bool
        Features with ``min_points`` candidates ``min_rise`` or more over the ground surface
        (index 0, no feature, is False).
    slope : (k,) float64
        The steepest ``(rise - tolerance) / distance`` of each candidate of a tall feature over
        the lowest point of a cell within ``radius`` (negative where every such point is
        higher; inf straight above one; -inf where there is none but the candidate itself, and
        for the candidates of other features, which are not tested).
    beyond : (k,) bool
        Candidates of a tall feature steeper than ``max_slope`` over a lower point farther
        away (a roof whose walls and nearby ground were not sampled), found on the grid.
    max_slope : float
        The bound the slopes are held to.
    """

    candidates: np.ndarray
    feature: np.ndarray
    tall: np.ndarray
    slope: np.ndarray
    beyond: np.ndarray
    max_slope: float

    @property
    def steep(self) -> np.ndarray:
        """(k,) bool: the candidates steeper than terrain over a lower point, near or far."""
        return (self.slope > self.max_slope) | self.beyond

    @property
    def crests(self) -> np.ndarray:
        """(n + 1,) bool: the tall features none of whose candidates is steeper than terrain."""
        ok = self.tall.copy()
        ok[self.feature[self.steep]] = False
        return ok

    @property
    def joining(self) -> np.ndarray:
        """Indices of the points that join the ground: the candidates of the crests."""
        return self.candidates[self.crests[self.feature]]


def crest_fill(xyz: np.ndarray, ground: np.ndarray, p: CrestParams = CrestParams(),
               surface: np.ndarray | None = None) -> np.ndarray:
    """Ground flags (m,) bool with the crests the ground lacked added (see the module and
    :func:`crest_test`, which takes the same arguments)."""
    out = np.array(ground, dtype=bool)
    test = crest_test(xyz, out, p, surface)
    if test is not None:
        out[test.joining] = True
    return out


def crest_test(xyz: np.ndarray, ground: np.ndarray, p: CrestParams = CrestParams(),
               surface: np.ndarray | None = None) -> CrestTest | None:
    """The cut features, their candidates and the slope test (see the module); None when
    there is nothing to test (fewer than 3 ground points, no feature, no candidate).

    Parameters
    ----------
    xyz : (m, 3) float64
        Local metric coordinates.
    ground : (m,) bool
        The ground so far.
    p : CrestParams
    surface : (m,) bool, optional
        The points that can be terrain (noise left out); None: all.
    """
    from .common import auto_cell, grid_index, grid_min

    g = np.asarray(ground, dtype=bool)
    if np.count_nonzero(g) < 3:
        return None
    usable = np.ones(len(g), bool) if surface is None else np.asarray(surface, dtype=bool)
    cell = auto_cell(xyz[:, :2], p.cell)
    r, c, shape, origin = grid_index(xyz[:, :2], cell)
    flat = r * shape[1] + c
    zmin, imin = grid_min(np.where(usable, xyz[:, 2], np.inf), r, c, shape)
    alone = ~np.isfinite(zmin)  # empty, or of points that cannot be terrain only
    zmin[alone], imin[alone] = np.nan, -1
    steep = _steep_surface(zmin, cell, p)
    below = _ground_surface(xyz[:, 2], g, r, c, shape)
    if steep is None or below is None:
        return None
    cand, feature, n = _cut_features(xyz, ~g & usable, flat, origin, cell, steep, below, p)
    if len(cand) == 0:
        return None
    rise = xyz[cand, 2] - below.ravel()[flat[cand]]
    tall = np.bincount(feature[rise >= p.min_rise], minlength=n + 1) >= p.min_points
    tall[0] = False
    slope, beyond = np.full(len(cand), -np.inf), np.zeros(len(cand), bool)
    tested = np.flatnonzero(tall[feature])
    if len(tested):
        pts = cand[tested]
        slope[tested] = _steepest(xyz, pts, r[pts], c[pts], imin, cell, p)
        floor = _slope_floor(np.where(alone, np.inf, zmin), cell, p.max_slope)
        beyond[tested] = xyz[pts, 2] - p.tolerance - p.max_slope * cell * np.sqrt(2.0) > floor[r[pts], c[pts]]
    return CrestTest(cand, feature, tall, slope, beyond, p.max_slope)


def _steep_surface(zmin: np.ndarray, cell: float, p: CrestParams) -> np.ndarray | None:
    """The lowest points' grid (NaN where empty) opened progressively, cells stepping down by
    more than ``max_slope`` and empty ones filled (:func:`workstation.ground.common.fill_cut`);
    None when no cell is kept."""
    from .common import fill_cut, fill_nearest, open_square, opening_steps

    empty = np.isnan(zmin)
    if empty.all():
        return None
    z0 = fill_nearest(zmin, empty)
    (steps,) = opening_steps(z0, cell, (p.window,), open_square)
    cut = (steps > p.max_slope) | empty
    return None if cut.all() else fill_cut(z0, cut)


def _ground_surface(z: np.ndarray, ground: np.ndarray, r, c, shape) -> np.ndarray | None:
    """The lowest ground point's height per cell, empty cells filled from the nearest."""
    from .common import fill_nearest, grid_min

    zg = grid_min(z[ground], r[ground], c[ground], shape)[0]
    empty = np.isnan(zg)
    return None if empty.all() else fill_nearest(zg, empty)


def _cut_features(xyz, open_: np.ndarray, flat, origin, cell: float, steep, below, p: CrestParams):
    """The candidates (k,) (points ``open_`` to joining the ground, near the steep surface, in
    a cut feature), their feature's label (k,) (1..n) and n."""
    from scipy import ndimage

    from .common import bilinear, gradient

    labels, n = ndimage.label(steep - below > p.tolerance, structure=np.ones((3, 3), bool))
    if n == 0:
        return np.empty(0, np.int64), np.empty(0, np.int64), 0
    comp = labels.ravel()[flat]
    cand = np.flatnonzero((comp > 0) & open_)
    gy, gx = gradient(steep, cell)
    relief = np.hypot(gx, gy).ravel()[flat[cand]] * cell
    off = np.abs(xyz[cand, 2] - bilinear(steep, xyz[cand, :2] - origin, cell, (0.0, 0.0)))
    cand = cand[off <= p.tolerance + relief]
    return cand, comp[cand], n


def _slope_floor(zmin: np.ndarray, cell: float, slope: float) -> np.ndarray:
    """The height over which a point of each cell stands steeper than ``slope`` over the lowest
    point of some cell: ``min over q (z_q + slope · d)``, the grey erosion of the grid ``zmin``
    (+inf where empty) with a cone, which is what Vosselman's slope-based filter computes. Done
    as a chamfer distance transform with initial values: one raster pass down and one up, each
    row taking its neighbours in the row before, then a running minimum along it (Borgefors
    1986); exact for the 3 x 3 chamfer distance, within 8 % of the Euclidean and never shorter.
    A loop over rows, not points: O(cells)."""
    a, b = slope * cell, slope * cell * np.sqrt(2.0)
    f = np.array(zmin, dtype=np.float64)
    ramp = a * np.arange(f.shape[1])
    for rows, step in ((range(f.shape[0]), -1), (range(f.shape[0] - 1, -1, -1), 1)):
        for i in rows:
            row = f[i]
            if 0 <= i + step < f.shape[0]:  # from the row already done: straight, then diagonal
                done = f[i + step]
                row = np.minimum(row, done + a)
                row[1:] = np.minimum(row[1:], done[:-1] + b)
                row[:-1] = np.minimum(row[:-1], done[1:] + b)
            if step < 0:  # down the grid: along the row left to right
                f[i] = np.minimum.accumulate(row - ramp) + ramp
            else:  # up the grid: right to left
                f[i] = np.minimum.accumulate((row + ramp)[::-1])[::-1] - ramp
    return f


def _steepest(xyz, pts, rc, cc, imin, cell: float, p: CrestParams) -> np.ndarray:
    """(k,) the steepest ``(rise - tolerance) / distance`` of the points ``pts`` over the
    lowest point of each cell within ``radius`` (as :attr:`CrestTest.slope`); one pass per cell
    offset, each over all the points (no per-point loop, the memory of a few arrays of k)."""
    reach = int(np.ceil(p.radius / cell)) + 1
    pad = np.pad(imin, reach, constant_values=-1)
    x, y, z = xyz[pts, 0], xyz[pts, 1], xyz[pts, 2]
    out = np.full(len(pts), -np.inf)
    with np.errstate(divide="ignore", invalid="ignore"):
        for dr in range(-reach, reach + 1):
            for dc in range(-reach, reach + 1):
                if np.hypot(max(abs(dr) - 1, 0), max(abs(dc) - 1, 0)) * cell > p.radius:  # none of it is near
                    continue
                j = pad[rc + reach + dr, cc + reach + dc]
                jj = np.where(j >= 0, j, 0)
                d = np.hypot(x - xyz[jj, 0], y - xyz[jj, 1])
                excess = z - xyz[jj, 2] - p.tolerance
                slope = np.where(d > 0, excess / d, np.where(excess > 0, np.inf, -np.inf))
                np.maximum(out, np.where((j >= 0) & (d <= p.radius), slope, -np.inf), out=out)
    return out
