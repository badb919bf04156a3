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

    A *window* (:meth:`window`) is the block of rows ``row0 … row0 + rows`` and columns
    ``col0 … col0 + cols`` of a larger grid: it keeps that grid's origin ``x0, y1`` and
    computes a point's cell exactly as the larger grid does, then shifts it by the offsets, so
    counts made on windows add up cell for cell to the counts on the whole grid.
    """

    x0: float
    y1: float
    cell: float
    rows: int
    cols: int
    units: Units
    row0: int = 0
    col0: int = 0

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
        col = np.floor((xy[:, 0] - self.x0) / self.cell).astype(np.int64) - self.col0
        row = np.floor((self.y1 - xy[:, 1]) / self.cell).astype(np.int64) - self.row0
        inside = (col >= 0) & (col < self.cols) & (row >= 0) & (row < self.rows)
        return np.clip(row, 0, self.rows - 1), np.clip(col, 0, self.cols - 1), inside

    def flat(self, xy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(flat cell index, inside) of (n, 2) plan coordinates, for ``np.bincount``."""
        row, col, inside = self.index(xy)
        return row * self.cols + col, inside

    def transform(self):
        """The rasterio ``Affine`` of the grid (north-up)."""
        from rasterio.transform import Affine

        return Affine(self.cell, 0.0, self.x0 + self.col0 * self.cell, 0.0, -self.cell, self.y1 - self.row0 * self.cell)

    def window(self, r0: int, r1: int, c0: int, c1: int) -> "QCGrid":
        """Rows ``r0:r1`` and columns ``c0:c1`` of this grid (clipped to it) as a grid of their own."""
        r0, r1 = max(int(r0), 0), min(int(r1), self.rows)
        c0, c1 = max(int(c0), 0), min(int(c1), self.cols)
        return QCGrid(self.x0, self.y1, self.cell, max(r1 - r0, 0), max(c1 - c0, 0), self.units,
                      self.row0 + r0, self.col0 + c0)

    def window_over(self, box, pad: int = 1) -> "QCGrid":
        """The window of the cells that ``box`` (xmin, ymin, xmax, ymax, CRS units) touches,
        widened by ``pad`` cells on each side."""
        c0 = int(np.floor((box[0] - self.x0) / self.cell)) - self.col0 - pad
        c1 = int(np.floor((box[2] - self.x0) / self.cell)) - self.col0 + pad + 1
        r0 = int(np.floor((self.y1 - box[3]) / self.cell)) - self.row0 - pad
        r1 = int(np.floor((self.y1 - box[1]) / self.cell)) - self.row0 + pad + 1
        return self.window(r0, r1, c0, c1)

    @property
    def block(self) -> tuple[slice, slice]:
        """Where this window lies in its whole grid: (row slice, column slice)."""
        return slice(self.row0, self.row0 + self.rows), slice(self.col0, self.col0 + self.cols)
