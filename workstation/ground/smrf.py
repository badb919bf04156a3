"""SMRF, the simple morphological filter (Pingel, Clarke & McBride 2013).

Pingel T.J., Clarke K.C., McBride W.A. (2013) "An improved simple morphological filter for the
terrain classification of airborne LIDAR data", ISPRS J. Photogramm. 77:21-30.

Steps (as in PDAL's ``filters.smrf``, vectorised on a grid):

1. minimum surface: lowest point per ``cell``; empty cells inpainted;
2. low outliers: **replaced by the low-noise step** that every ground filter runs first
   (:func:`workstation.ground.noise.low_noise`, ``noise=True``). Pingel's step, the progressive
   filter on the *negated* surface (slope 5, window 1 m) marking pits more than 5 m deep, is
   kept as ``low_outliers`` (off): it judges a cell against the 3 x 3 cells around it on the
   1 m minimum grid, and where few pulses reach the ground (a closed canopy: 0.1-0.2 ground
   points/m², so most 1 m cells hold only crown or stem echoes) every ground cell is such a
   pit; it is thrown out and the provisional DEM is inpainted from the crowns (a held-back
   conifer plot: 2,200 canopy points more than 5 m up taken for ground, DTM 5.9 m RMS from
   the vendor's). Pingel's own code notes that "in very rugged and forested terrain" its
   slope may need to be larger, or the low noise "scrubbed using other means" and the step
   disabled; the noise step is that means, and it judges a point against the lowest points
   around it, not against a dense grid;
3. objects: the progressive filter on the surface: grey openings by disks of radius
   1 … ``window``/``cell`` cells, each applied to the previous opened surface (as in Pingel's
   reference code; PDAL uses diamonds, which miss more roofs: 4.3 % against 3.7 % mean total
   error on the six ISPRS samples here); a cell whose opened height drops by more than
   ``slope · cell · radius`` is an object;
4. provisional DEM: the minimum surface without object and low-outlier cells, inpainted
   (linear interpolation over the TIN of the remaining cells);
5. classification: a point is ground when its height lies within
   ``threshold + scalar · slope`` of the provisional DEM interpolated bilinearly at the point,
   ``slope`` being the DEM's gradient magnitude there.

Optional (off by default, PDAL has no such step): ``trend_slope`` makes step 3 follow the
terrain. Pingel's ``slope`` is the steepest terrain the filter expects; on a mountainside every
convex break steeper than it is cut as an object. With ``trend_slope = k > 0`` the object test
is run a second time with a per-cell slope ``max(slope, k · trend)``, ``trend`` being the
slope magnitude |∇z| of the first pass's provisional DEM averaged over the ``window`` (a box
mean of the magnitude, so the two flanks of a ridge do not cancel), and objects are still
judged against a flat-terrain slope where the terrain is flat.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass, replace
from typing import Callable

import numpy as np

from workstation.core.cloud import Cloud

from . import common
from .options import FilterOptions

STAGE = "ground.smrf"


@dataclass(frozen=True)
class SMRFParams(FilterOptions):
    """SMRF parameters (PDAL's defaults) and the options of every filter
    (:class:`~workstation.ground.options.FilterOptions`). Lengths in metres, whatever the CRS unit.

    Attributes
    ----------
    cell : float
        Grid cell size, metres (1.0).
    slope : float
        Terrain slope, rise over run (dimensionless, 0.15).
    window : float
        Largest opening window radius, metres (18.0): larger than the largest building.
    threshold : float
        Elevation threshold, metres (0.5).
    scalar : float
        Elevation scaling factor applied to the provisional DEM's slope (1.25, metres per unit
        of slope).
    low_outliers : bool
        Pingel's grid low-outlier step (False; see the module notes: the low-noise step,
        ``noise``, replaces it).
    trend_slope : float
        Slope-adaptive object test (dimensionless factor; 0 = off, PDAL's behaviour): the
        per-cell slope is ``max(slope, trend_slope · terrain trend slope)``, see the module
        notes.
    """

    cell: float = 1.0
    slope: float = 0.15
    window: float = 18.0
    threshold: float = 0.5
    scalar: float = 1.25
    low_outliers: bool = False
    trend_slope: float = 0.0


PRESETS: dict[str, SMRFParams] = common.presets(
    SMRFParams, flat={"slope": 0.1, "window": 24.0}, urban={"slope": 0.15, "window": 30.0},
    forest={"slope": 0.3, "window": 12.0, "threshold": 0.45},
    steep={"slope": 0.6, "window": 10.0, "threshold": 0.6, "scalar": 1.5})


def progressive_filter(surface: np.ndarray, cell: float, slope, window: float) -> np.ndarray:
    """SMRF's progressive morphological object detection on a filled grid: a cell is an
    object when one opening step of radius ``r`` lowers it by more than ``slope · cell · r``.

    Parameters
    ----------
    surface : (rows, cols) float64, no NaN
    cell : float
        Cell size, metres.
    slope : float or (rows, cols) float64
        Rise over run (one value, or one per cell).
    window : float
        Largest radius, metres.

    Returns
    -------
    (rows, cols) bool
        True on object cells.
    """
    return common.opening_steps(surface, cell, (window,))[0] > slope


class SharedSurfaces:
    """What several SMRF runs on the same points share, computed once and thread-safe.

    ``auto`` runs SMRF twice (two members with the same cell and window, different tests) and
    CSF fills its empty particles from a third SMRF surface: all three start from the same grid
    of lowest points and its inpainted fill, and the disk openings of that fill do not depend
    on the slope, so one opening sequence up to the largest window gives every window's steps
    (:func:`workstation.ground.common.opening_steps`). A provisional DEM depends only on the
    cells left out of it, so one is inpainted per distinct set of them
    (:meth:`provisional`): the first DEM of the slope-adaptive test (``trend_slope``) is that
    of a run without it, and different windows or tests often flag the same cells. Each item
    is computed by the first run that needs it, the others wait for it; the results are those
    of the runs alone.

    Parameters
    ----------
    xyz : (m, 3) float64
        The local metric points every run filters (the same array object).
    params : sequence of SMRFParams
        The runs to come: their windows, per cell, are opened in one sequence.
    """

    def __init__(self, xyz: np.ndarray, params):
        self.xyz = xyz
        self._windows: dict[float, tuple] = {}
        for p in params:
            self._windows[p.cell] = tuple(sorted(set(self._windows.get(p.cell, ())) | {p.window}))
        self._lock = threading.Lock()
        self._items: dict = {}

    def serves(self, xyz: np.ndarray, p: SMRFParams) -> bool:
        """Whether a run of ``p`` on ``xyz`` can read from here (same points, a window opened
        here, no grid low-outlier step, which changes the filled surface)."""
        return xyz is self.xyz and not p.low_outliers and p.window in self._windows.get(p.cell, ())

    def get(self, key, make: Callable):
        """The item ``key``, made by ``make()`` on first use (one maker per key at a time)."""
        with self._lock:
            slot = self._items.setdefault(key, [threading.Lock(), None, False])
        with slot[0]:
            if not slot[2]:
                slot[1], slot[2] = make(), True
            return slot[1]

    def grid(self, cell: float):
        """:func:`_minimum_grid` of the points on ``cell``."""
        return self.get(("grid", cell), lambda: _minimum_grid(self.xyz, cell))

    def steps(self, cell: float, window: float) -> np.ndarray:
        """The steepest opening step up to ``window`` of the filled grid on ``cell``."""
        windows = self._windows[cell]

        def make():
            return dict(zip(windows, common.opening_steps(self.grid(cell).zfill, cell, windows)))

        return self.get(("steps", cell), make)[window]

    def provisional(self, cell: float, bad: np.ndarray) -> np.ndarray:
        """:func:`_provisional` of the grid on ``cell`` without the ``bad`` cells, made once per
        distinct set of bad cells: runs whose tests flag the same cells (a window of 18 m and
        one of 30 m over the same roofs, a slope-adaptive test that changes nothing on flat
        ground) read one inpainted surface."""
        g = self.grid(cell)
        key = ("provisional", cell, bad.shape, np.packbits(bad).tobytes())  # the cells themselves: exact
        return self.get(key, lambda: _read_only(_provisional(g.zmin, bad, g.zfill, g.off)))


def _read_only(a: np.ndarray) -> np.ndarray:
    """``a`` marked read-only: a surface shared by several runs must not be changed by one."""
    a.setflags(write=False)
    return a


@dataclass(frozen=True)
class _MinimumGrid:
    """The lowest point per cell of :func:`smrf_surface`'s grid (NaN where empty), its
    inpainted fill, the grid's origin and the (row, col) of its cell (0, 0) on the lattice."""

    zmin: np.ndarray
    zfill: np.ndarray
    origin: np.ndarray
    off: tuple


def _minimum_grid(xyz: np.ndarray, cell: float) -> _MinimumGrid:
    """SMRF's step 1 on ``cell``-metre cells (see :class:`_MinimumGrid`)."""
    # the grid starts at a multiple of the cell on prepare's 100 m lattice, with no empty margin
    r, c, shape, origin = common.grid_index(xyz[:, :2], cell, common.aligned_origin(xyz[:, :2], cell))
    off = tuple(int(v) for v in np.round(origin[::-1] / cell))  # (row, col) of cell (0, 0)
    zmin, _ = common.grid_min(xyz[:, 2], r, c, shape)
    return _MinimumGrid(zmin, common.inpaint(zmin, off), origin, off)


def _provisional(zmin: np.ndarray, bad: np.ndarray, zfill: np.ndarray, off) -> np.ndarray:
    """``zmin`` without the ``bad`` cells, inpainted (``zfill`` when every cell is bad)."""
    zp = zmin.copy()
    zp[bad] = np.nan
    if bad.all():
        return zfill.copy()
    return common.inpaint(zp, off)


def smrf_surface(xyz: np.ndarray, p: SMRFParams,
                 shared: SharedSurfaces | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Provisional DEM of SMRF on local metric points.

    ``shared`` (:class:`SharedSurfaces` of these points) serves the grid, the opening steps
    and the provisional DEMs computed once for several runs; the result is the same.

    Returns
    -------
    zpro : (rows, cols) float64
        Provisional DEM, metres.
    origin : (2,) float64
    empty_or_object : (rows, cols) bool
        Cells that were interpolated.
    """
    if shared is not None and not shared.serves(xyz, p):
        shared = None
    g = shared.grid(p.cell) if shared is not None else _minimum_grid(xyz, p.cell)
    zmin, zfill, off = g.zmin, g.zfill, g.off
    empty = np.isnan(zmin)
    low = np.zeros(zmin.shape, dtype=bool)
    if p.low_outliers:
        low = progressive_filter(-zfill, p.cell, 5.0, 1.0)
        if low.any():
            z2 = zmin.copy()
            z2[low] = np.nan
            zfill = common.inpaint(z2, off)
    # the disk openings do not depend on the slope: both tests read one sequence
    if shared is not None:
        steps = shared.steps(p.cell, p.window)
    else:
        (steps,) = common.opening_steps(zfill, p.cell, (p.window,))
    obj = steps > p.slope
    bad = empty | low | obj
    provisional = shared.provisional if shared is not None else (lambda cell, b: _provisional(zmin, b, zfill, off))
    if p.trend_slope > 0:  # the per-cell slope, from the provisional DEM of the plain test
        if bad.all():
            tol = np.full(zmin.shape, p.slope)
        else:
            tol = common.trend_tolerance(provisional(p.cell, bad), p.cell, p.slope, p.trend_slope, p.window)
        bad = empty | low | (steps > tol)
    return provisional(p.cell, bad), g.origin, bad


def smrf_ground(xyz: np.ndarray, p: SMRFParams, shared: SharedSurfaces | None = None) -> np.ndarray:
    """Ground flags (m,) bool of local metric points (m, 3) by SMRF (``shared``: see
    :func:`smrf_surface`)."""
    zpro, origin, _ = smrf_surface(xyz, p, shared)
    gy, gx = common.gradient(zpro, p.cell)
    gsurf = np.hypot(gx, gy)
    zs = common.bilinear(zpro, xyz[:, :2], p.cell, origin)
    gs = common.bilinear(gsurf, xyz[:, :2], p.cell, origin)
    return np.abs(xyz[:, 2] - zs) <= p.threshold + p.scalar * gs


def smrf(cloud: Cloud, params: SMRFParams | None = None, **overrides) -> Cloud:
    """Classify ground with SMRF (Pingel et al. 2013).

    Parameters
    ----------
    cloud : Cloud
    params : SMRFParams, optional
        Defaults: PDAL's (cell 1 m, slope 0.15, window 18 m, threshold 0.5 m, scalar 1.25).
    **overrides
        Fields of :class:`SMRFParams` to replace.

    Returns
    -------
    Cloud
        Same points and attributes; ``classification`` 2 on ground, 1 elsewhere (other classes
        kept unless ``reclassify``).

    Raises
    ------
    StageError
        No usable points, or no ground found.
    """
    p = replace(params or SMRFParams(), **overrides)
    return common.run_filter(cloud, p, STAGE, lambda prep: smrf_ground(prep.xyz, p))
