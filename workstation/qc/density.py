"""Point density and nominal point spacing (ASPRS Positional Accuracy Standards 2014, §C.3).

Density is given two ways: over occupied cells of a grid (default 1 m; voids and the area
outside the data do not count, as the ASPRS aggregate nominal point density ANPD over the
non-voided area) and over the footprint (the 2-D convex hull). The nominal point spacing is
NPS = sqrt(1 / ANPD).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


#: Cells a side the packed keys ``(i << 32) + j`` hold without wrapping (i, j < 2^31).
_MAX_INDEX = 2.0**31


@dataclass
class DensityAccumulator:
    """Accumulates occupied cells and hull points over chunks of a large file.

    Parameters
    ----------
    cell : float
        Grid cell size in CRS units (1 m expressed in those units by the caller).
    metres_per_unit : float
        To express areas in m².
    strict : bool
        A cell too small for the data's extent (more than 2^31 cells across) is an
        :class:`InvalidInputError` naming ``--density-cell`` (True: the user chose the cell),
        or leaves the occupied-cell figures NaN (False: a default cell on data that spans
        more than it can index).
    """

    cell: float
    metres_per_unit: float = 1.0
    origin: np.ndarray | None = None
    n: int = 0
    strict: bool = True

    def __post_init__(self):
        self._runs: list[np.ndarray] = []  # sorted unique cell keys, runs of decreasing size
        self._hull = np.empty((0, 2))
        self._too_fine = False

    def add(self, xy: np.ndarray) -> None:
        """Add (m, 2) plan coordinates."""
        if len(xy) == 0:
            return
        x, y = xy[:, 0], xy[:, 1]  # column by column: numpy reduces (n, 2) along axis 0 much slower
        cells = self.start((x.min(), y.min()), (x.max(), y.max()))
        keys = sorted_unique(self.cell_keys(x, y)) if cells else None
        self.merge(len(xy), hull_candidates(xy), keys)

    def start(self, lo, hi) -> bool:
        """Prepare to add points whose plan extent is ``lo`` (xmin, ymin) to ``hi`` (xmax,
        ymax): the first call sets the grid origin. False when the points are to be counted
        without cell keys (cell too fine, not strict); a cell too fine when strict raises."""
        if self.origin is None:
            self.origin = np.floor(np.asarray(lo, dtype=np.float64) / self.cell) * self.cell - 2**20 * self.cell
        span = float(np.max(np.asarray(hi, dtype=np.float64) - self.origin)) / self.cell
        self._too_fine |= not span < _MAX_INDEX  # the packed 64-bit cell keys would wrap around
        if self._too_fine and self.strict:
            from workstation.core.errors import InvalidInputError

            raise InvalidInputError(
                f"a density cell of {self.cell:g} CRS units makes {span:.3g} cells across the data "
                f"(at most {_MAX_INDEX:.3g})", f"use a larger --density-cell, e.g. {self.cell * span / 2**30:.2g}",
                field="--density-cell")
        return not self._too_fine

    def cell_keys(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """The packed cell key ``(i << 32) + j`` of each point (after :meth:`start`)."""
        t = np.subtract(x, self.origin[0])
        i = np.floor(np.divide(t, self.cell, out=t), out=t).astype(np.int64)
        np.subtract(y, self.origin[1], out=t)
        j = np.floor(np.divide(t, self.cell, out=t), out=t).astype(np.int64)
        i <<= 32
        i += j
        return i

    def merge(self, n: int, hull_cands: np.ndarray, keys: np.ndarray | None) -> None:
        """Fold in ``n`` points started with :meth:`start`: ``hull_cands`` (k, 2) a superset of
        their hull vertices, ``keys`` their sorted unique cell keys (None when :meth:`start`
        said False)."""
        self._hull = hull_points(np.vstack([self._hull, hull_cands]))
        if keys is not None and not self._too_fine:
            self._runs.append(keys)
            # merge the last run into the one before while that one is less than twice its size:
            # each key takes part in O(log chunks) merges, not one per chunk, and the runs stay
            # fewer than log2 of the cell count
            while len(self._runs) > 1 and len(self._runs[-2]) < 2 * len(self._runs[-1]):
                last = self._runs.pop()
                self._runs[-1] = _merge_runs(self._runs[-1], last)
        self.n += n

    def occupied_cells(self) -> int:
        """The number of distinct occupied cells so far."""
        while len(self._runs) > 1:
            last = self._runs.pop()
            self._runs[-1] = _merge_runs(self._runs[-1], last)
        return len(self._runs[0]) if self._runs else 0

    def result(self) -> dict:
        """{points, occupied_cells, cell_size, occupied_area_m2, footprint_area_m2,
        density_occupied, density_footprint, nps} with densities in points/m² and NPS in
        CRS units."""
        m2 = self.metres_per_unit**2
        cells = self.occupied_cells()
        occ_area = float("nan") if self._too_fine else cells * self.cell**2 * m2
        fp_area = hull_area(self._hull) * m2
        d_occ = self.n / occ_area if occ_area > 0 else float("nan")
        d_fp = self.n / fp_area if fp_area > 0 else float("nan")
        nps_m = float(np.sqrt(1.0 / d_occ)) if d_occ > 0 else float("nan")
        return {
            "points": int(self.n),
            "cell_size": float(self.cell),
            "occupied_cells": int(cells),
            "occupied_area_m2": float(occ_area),
            "footprint_area_m2": float(fp_area),
            "density_occupied": float(d_occ),
            "density_footprint": float(d_fp),
            "nps_m": nps_m,
            "nps": nps_m / self.metres_per_unit if np.isfinite(nps_m) else float("nan"),
        }


def _merge_runs(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The sorted unique union of two sorted unique key arrays (the stable sort, timsort,
    merges two sorted runs in linear time)."""
    return sorted_unique(np.concatenate([a, b]), kind="stable")


def sorted_unique(a: np.ndarray, kind: str = "quicksort") -> np.ndarray:
    """``np.unique(a)`` by one sort and a comparison with the neighbour (numpy 2's hash-based
    ``unique`` of int64 is some 50x slower on millions of keys)."""
    s = np.sort(a, kind=kind)
    return s[np.r_[True, s[1:] != s[:-1]]] if len(s) else s


def hull_candidates(xy: np.ndarray) -> np.ndarray:
    """The points that may be vertices of the convex hull of ``xy`` (Akl-Toussaint): those not
    strictly inside the octagon of the extreme points along x, y, x+y and x-y. Exact; removes
    nearly every point of a survey, so Qhull sees thousands of points instead of millions."""
    if len(xy) < 64:
        return xy
    return xy[outside_octagon(np.ascontiguousarray(xy[:, 0]), np.ascontiguousarray(xy[:, 1]))]


def outside_octagon(x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Which points (x, y) are not strictly inside the octagon of their extreme points along
    x, y, x+y and x-y (see :func:`hull_candidates`)."""
    s, d = x + y, x - y
    # left, lower-left, bottom, lower-right, right, upper-right, top, upper-left: counter-clockwise
    order = [x.argmin(), s.argmin(), y.argmin(), d.argmax(), x.argmax(), s.argmax(), y.argmax(), d.argmin()]
    px, py = x[order], y[order]  # (repeated points make edges of length 0, skipped)
    inside = np.ones(len(x), dtype=bool)
    t, u = np.empty_like(x), np.empty_like(x)  # reused: fresh temporaries per edge cost more than the arithmetic
    for k in range(8):
        ex, ey = px[(k + 1) % 8] - px[k], py[(k + 1) % 8] - py[k]
        if not (ex or ey):
            continue
        np.subtract(y, py[k], out=t)  # ex * (y - py) - ey * (x - px) > 0: left of the edge
        t *= ex
        np.subtract(x, px[k], out=u)
        u *= ey
        t -= u
        inside &= t > 0
    return ~inside


def hull_points(xy: np.ndarray) -> np.ndarray:
    """The vertices of the 2-D convex hull of (n, 2) ``xy`` (Qhull; the extreme points of a
    degenerate set)."""
    if len(xy) < 3:
        return xy
    from scipy.spatial import ConvexHull, QhullError

    try:
        h = ConvexHull(xy)
    except (QhullError, ValueError):
        return xy[[xy[:, 0].argmin(), xy[:, 0].argmax(), xy[:, 1].argmin(), xy[:, 1].argmax()]]
    return xy[h.vertices]


def hull_area(hull: np.ndarray) -> float:
    """Area of the polygon ``hull`` (vertices in order; the shoelace formula)."""
    if len(hull) < 3:
        return 0.0
    x, y = hull[:, 0], hull[:, 1]
    return float(0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1))))


def density(xy: np.ndarray, cell: float = 1.0, metres_per_unit: float = 1.0) -> dict:
    """Density figures for plan coordinates (n, 2) in one call (see :class:`DensityAccumulator`).

    Examples
    --------
    >>> g = np.stack(np.meshgrid(np.arange(0, 10, 0.5), np.arange(0, 10, 0.5)), -1).reshape(-1, 2)
    >>> r = density(g + 0.25)
    >>> r["density_occupied"], r["nps"]
    (4.0, 0.5)
    """
    acc = DensityAccumulator(cell, metres_per_unit)
    acc.add(np.asarray(xy, dtype=np.float64)[:, :2])
    return acc.result()
