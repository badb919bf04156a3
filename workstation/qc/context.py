"""What every quality-control check shares: the delivery's grid and units, and a finding.

``ws qc`` streams a delivery (one or many LAS/LAZ/COPC files) twice, chunk by chunk
(:mod:`workstation.qc.run`):

* **pass 1** feeds each chunk to the checks that need nothing measured beforehand
  (format validation, first-return density per swath, the class histogram and a ground grid);
* **pass 2** feeds each chunk to the checks whose cell size comes from pass 1's aggregate
  nominal point spacing (ANPS): 2×ANPS coverage and voids, swath separation (DZ), points
  above or below the ground surface, and the ground points near checkpoints.

Each check is a small accumulator: ``add(chunk, source)`` with a :class:`~workstation.core.cloud.Cloud`
chunk in CRS units and the file it came from, then ``result()`` -> a JSON-ready dict with every
length in metres (``QCGrid.units`` converts), plus ``findings()`` -> a list of :class:`Finding`.
Memory is bounded by the grids, never by the point count.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from workstation.core.units import Units


@dataclass(frozen=True)
class Finding:
    """One thing a check found wrong or worth knowing, as ``lasvalidate`` reports it.

    Attributes
    ----------
    check : str
        The check that found it ("format", "coverage", "swath", "accuracy", "classes").
    severity : str
        "error" (the delivery breaks the format or a hard rule), "warning" (suspicious) or "info".
    file : str or None
        The file it concerns (None for a finding about the whole delivery).
    field : str
        The header field, dimension or quantity ("point_count", "classification", "void").
    expected, found : str
        What the standard or the header says, and what the data holds.
    message : str
        One sentence for people.
    """

    check: str
    severity: str
    file: str | None
    field: str
    expected: str
    found: str
    message: str

    def to_dict(self) -> dict:
        return asdict(self)


@dataclass(frozen=True)
class QCGrid:
    """A regular plan grid over the whole delivery, in CRS units.

    Cells are ``cell`` CRS units square; cell (row, col) covers
    ``x0 + col·cell <= x < x0 + (col + 1)·cell`` and ``y1 - (row + 1)·cell < y <= y1 - row·cell``
    (row 0 at the top, as a GeoTIFF). ``units`` converts lengths and areas to metres.
    """

    x0: float
    y1: float
    cell: float
    rows: int
    cols: int
    units: Units

    @classmethod
    def over(cls, bounds, cell: float, units: Units) -> "QCGrid":
        """The grid of ``cell`` units covering ``bounds`` = (xmin, ymin, xmax, ymax), its origin
        on a multiple of ``cell`` so that grids of different files line up."""
        xmin, ymin, xmax, ymax = (float(b) for b in bounds)
        x0 = np.floor(xmin / cell) * cell
        y1 = (np.floor(ymax / cell) + 1) * cell
        cols = max(int(np.floor((xmax - x0) / cell)) + 1, 1)
        rows = max(int(np.floor((y1 - ymin) / cell)) + 1, 1)
        return cls(float(x0), float(y1), float(cell), rows, cols, units)

    @property
    def shape(self) -> tuple[int, int]:
        return self.rows, self.cols

    @property
    def cell_m(self) -> float:
        """The cell side in metres."""
        return self.cell * self.units.h

    def index(self, xy: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(row, col, inside) of (n, 2) plan coordinates; row/col are clipped into the grid and
        ``inside`` says which points really fall in it."""
        col = np.floor((xy[:, 0] - self.x0) / self.cell).astype(np.int64)
        row = np.floor((self.y1 - xy[:, 1]) / self.cell).astype(np.int64)
        inside = (col >= 0) & (col < self.cols) & (row >= 0) & (row < self.rows)
        return np.clip(row, 0, self.rows - 1), np.clip(col, 0, self.cols - 1), inside

    def flat(self, xy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(flat cell index, inside) of (n, 2) plan coordinates, for ``np.bincount``."""
        row, col, inside = self.index(xy)
        return row * self.cols + col, inside

    def transform(self):
        """The rasterio ``Affine`` of the grid (north-up)."""
        from rasterio.transform import Affine

        return Affine(self.cell, 0.0, self.x0, 0.0, -self.cell, self.y1)
