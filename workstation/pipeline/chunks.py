"""Processing chunks: square cells over the catalog, aligned to multiples of their size.

A chunk is processed with the points of its neighbours within ``buffer`` and writes only its
own (core) points, so every point is written exactly once and filters see the terrain beyond
a chunk's edge. Chunks are named by their lower-left corner in CRS units (``482250_5452000``,
as lastile names tiles), and aligned to multiples of the size, so two runs of the same survey
cut it the same way.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True, order=True)
class Chunk:
    """One square chunk.

    Attributes
    ----------
    ix, iy : int
        Column and row: the chunk covers [ix·size, (ix+1)·size) × [iy·size, (iy+1)·size).
    size, buffer : float
        Side and buffer in CRS units.
    """

    ix: int
    iy: int
    size: float
    buffer: float

    @property
    def name(self) -> str:
        return f"{self.ix * self.size:.0f}_{self.iy * self.size:.0f}"

    @property
    def bounds(self) -> tuple:
        """Core (xmin, ymin, xmax, ymax): points with xmin ≤ x < xmax, ymin ≤ y < ymax."""
        return (self.ix * self.size, self.iy * self.size, (self.ix + 1) * self.size, (self.iy + 1) * self.size)

    @property
    def buffered(self) -> tuple:
        x0, y0, x1, y1 = self.bounds
        b = self.buffer
        return (x0 - b, y0 - b, x1 + b, y1 + b)

    def neighbours(self) -> list["Chunk"]:
        """This chunk and the eight around it (those a buffer up to the size can reach)."""
        return [Chunk(self.ix + a, self.iy + b, self.size, self.buffer) for a in (-1, 0, 1) for b in (-1, 0, 1)]

    def core_mask(self, xy: np.ndarray) -> np.ndarray:
        """Which of the points ``xy`` (m, 2) are this chunk's own."""
        return (np.floor(xy[:, 0] / self.size) == self.ix) & (np.floor(xy[:, 1] / self.size) == self.iy)


@dataclass(frozen=True)
class ChunkGrid:
    """The chunks of a catalog: size and buffer in CRS units, and the chunks that meet a tile.

    Attributes
    ----------
    size, buffer : float
        In CRS units (the project's metres converted).
    chunks : tuple of Chunk
        Every chunk whose core meets the bounds of at least one tile, sorted.
    """

    size: float
    buffer: float
    chunks: tuple

    def chunk_ids(self, xy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(ix, iy) of the chunk that owns each point."""
        return np.floor(xy[:, 0] / self.size).astype(np.int64), np.floor(xy[:, 1] / self.size).astype(np.int64)

    def by_index(self) -> dict:
        return {(c.ix, c.iy): c for c in self.chunks}


def chunk_grid(catalog, size_m: float, buffer_m: float) -> ChunkGrid:
    """Chunks of ``size_m`` metres with ``buffer_m`` metres of buffer over ``catalog``'s tiles
    (lengths converted to the catalog CRS's unit)."""
    from workstation.ground.common import crs_unit_factors

    per_unit = crs_unit_factors(catalog.crs)[0]
    size, buffer = size_m / per_unit, buffer_m / per_unit
    found: set[tuple[int, int]] = set()
    for t in catalog.tiles:
        x0, y0, _, x1, y1, _ = t.bounds
        for ix in range(math.floor(x0 / size), math.floor(x1 / size) + 1):
            for iy in range(math.floor(y0 / size), math.floor(y1 / size) + 1):
                found.add((ix, iy))
    return ChunkGrid(size, buffer, tuple(Chunk(ix, iy, size, buffer) for ix, iy in sorted(found)))
