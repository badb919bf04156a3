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
        self._keys = np.empty(0, dtype=np.int64)
        self._hull = np.empty((0, 2))
        self._too_fine = False

    def add(self, xy: np.ndarray) -> None:
        """Add (m, 2) plan coordinates."""
        if len(xy) == 0:
            return
        x, y = xy[:, 0], xy[:, 1]  # column by column: numpy reduces (n, 2) along axis 0 much slower
        if self.origin is None:
            self.origin = np.floor(np.array([x.min(), y.min()]) / self.cell) * self.cell - 2**20 * self.cell
        span = float(np.max(np.array([x.max(), y.max()]) - self.origin)) / self.cell
        self._too_fine |= not span < _MAX_INDEX  # the packed 64-bit cell keys would wrap around
        self._hull = hull_points(np.vstack([self._hull, hull_candidates(xy)]))
        if self._too_fine and not self.strict:
            self.n += len(xy)
            return
        if self._too_fine:
            from workstation.core.errors import InvalidInputError

            raise InvalidInputError(
                f"a density cell of {self.cell:g} CRS units makes {span:.3g} cells across the data "
                f"(at most {_MAX_INDEX:.3g})", f"use a larger --density-cell, e.g. {self.cell * span / 2**30:.2g}",
                field="--density-cell")
        ij = np.floor((xy - self.origin) / self.cell).astype(np.int64)
        keys = sorted_unique((ij[:, 0] << 32) + ij[:, 1])
        # two sorted runs: the stable sort (timsort) merges them in linear time
        self._keys = sorted_unique(np.concatenate([self._keys, keys]), kind="stable")
        self.n += len(xy)

    def result(self) -> dict:
        """{points, occupied_cells, cell_size, occupied_area_m2, footprint_area_m2,
        density_occupied, density_footprint, nps} with densities in points/m² and NPS in
        CRS units."""
        m2 = self.metres_per_unit**2
        occ_area = float("nan") if self._too_fine else self._keys.size * self.cell**2 * m2
        fp_area = hull_area(self._hull) * m2
        d_occ = self.n / occ_area if occ_area > 0 else float("nan")
        d_fp = self.n / fp_area if fp_area > 0 else float("nan")
        nps_m = float(np.sqrt(1.0 / d_occ)) if d_occ > 0 else float("nan")
        return {
            "points": int(self.n),
            "cell_size": float(self.cell),
            "occupied_cells": int(self._keys.size),
            "occupied_area_m2": float(occ_area),
            "footprint_area_m2": float(fp_area),
            "density_occupied": float(d_occ),
            "density_footprint": float(d_fp),
            "nps_m": nps_m,
            "nps": nps_m / self.metres_per_unit if np.isfinite(nps_m) else float("nan"),
        }


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
    x, y = np.ascontiguousarray(xy[:, 0]), np.ascontiguousarray(xy[:, 1])
    s, d = x + y, x - y
    # left, lower-left, bottom, lower-right, right, upper-right, top, upper-left: counter-clockwise
    order = [x.argmin(), s.argmin(), y.argmin(), d.argmax(), x.argmax(), s.argmax(), y.argmax(), d.argmin()]
    poly = xy[order]  # (repeated points make edges of length 0, skipped)
    inside = np.ones(len(xy), dtype=bool)
    for a, b in zip(poly, np.roll(poly, -1, axis=0)):
        edge = b - a
        if not edge.any():
            continue
        inside &= edge[0] * (y - a[1]) - edge[1] * (x - a[0]) > 0
    return xy[~inside]


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
