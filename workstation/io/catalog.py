"""The catalog of a survey's tiles, from their headers alone (as lidR's ``LAScatalog``).

Planning a run reads no point: each file's header gives its bounds, point count, point format
and CRS, and whether it is COPC (read by spatial queries) or plain LAS/LAZ (binned once into
chunks by the ``index`` stage). The catalog reports gaps (area inside the survey's extent that
no tile covers) and overlapping tiles, and refuses tiles in different CRSs, since chunks are cut
in one coordinate system.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger

log = get_logger(__name__)


@dataclass(frozen=True)
class TileInfo:
    """One input file as its header describes it.

    Attributes
    ----------
    path : Path
    bounds : tuple of float
        (xmin, ymin, zmin, xmax, ymax, zmax) in CRS units.
    point_count : int
    point_format : int
        LAS point data record format.
    crs : str or None
        WKT from the header's CRS record.
    copc : bool
        True for a COPC file (an octree-ordered LAZ 1.4 with a ``copc`` VLR).
    """

    path: Path
    bounds: tuple
    point_count: int
    point_format: int
    crs: str | None
    copc: bool

    def intersects(self, box) -> bool:
        """Whether the tile's planar bounds meet ``box`` (xmin, ymin, xmax, ymax)."""
        b = self.bounds
        return not (b[3] < box[0] or b[0] > box[2] or b[4] < box[1] or b[1] > box[3])


@dataclass(frozen=True)
class Catalog:
    """The input tiles of a project.

    Attributes
    ----------
    tiles : tuple of TileInfo
    crs : str or None
        The one CRS of the tiles (or the project's, for tiles without one).
    """

    tiles: tuple
    crs: str | None

    @property
    def point_count(self) -> int:
        return sum(t.point_count for t in self.tiles)

    @property
    def bounds(self) -> tuple:
        """Planar (xmin, ymin, xmax, ymax) of every tile."""
        b = np.array([t.bounds for t in self.tiles])
        return float(b[:, 0].min()), float(b[:, 1].min()), float(b[:, 3].max()), float(b[:, 4].max())

    def overlaps(self, tolerance: float = 1e-6) -> list[tuple[str, str, float]]:
        """Pairs of tiles whose bounds overlap by more than ``tolerance`` (CRS units²): names
        and the shared area. Adjacent tiles that only share an edge do not count."""
        b = np.array([t.bounds for t in self.tiles])
        dx = np.minimum(b[:, None, 3], b[None, :, 3]) - np.maximum(b[:, None, 0], b[None, :, 0])
        dy = np.minimum(b[:, None, 4], b[None, :, 4]) - np.maximum(b[:, None, 1], b[None, :, 1])
        area = np.where((dx > 0) & (dy > 0), dx * dy, 0.0)
        i, j = np.nonzero(np.triu(area > tolerance, 1))
        return [(self.tiles[a].path.name, self.tiles[c].path.name, float(area[a, c])) for a, c in zip(i, j)]

    def gap_area(self, cells: int = 512) -> float:
        """Area (CRS units²) inside the catalog's extent that no tile's bounds cover, on a
        ``cells``-wide raster of the extent (an estimate to a cell)."""
        x0, y0, x1, y1 = self.bounds
        w, h = max(x1 - x0, 1e-9), max(y1 - y0, 1e-9)
        step = max(w, h) / cells
        nx, ny = max(1, int(np.ceil(w / step))), max(1, int(np.ceil(h / step)))
        cx = x0 + (np.arange(nx) + 0.5) * step
        cy = y0 + (np.arange(ny) + 0.5) * step
        covered = np.zeros((ny, nx), bool)
        for t in self.tiles:
            b = t.bounds
            covered[np.ix_((cy >= b[1]) & (cy <= b[4]), (cx >= b[0]) & (cx <= b[3]))] = True
        inside = (cx[None, :] <= x1) & (cy[:, None] <= y1)
        return float(np.count_nonzero(~covered & inside) * step * step)

    def summary(self) -> dict:
        return {"files": len(self.tiles), "points": self.point_count, "bounds": list(self.bounds),
                "crs": self.crs, "copc_files": sum(t.copc for t in self.tiles),
                "gap_area": round(self.gap_area(), 1), "overlaps": [list(o) for o in self.overlaps()]}


def _is_copc(header) -> bool:
    return any(getattr(v, "user_id", "") == "copc" and getattr(v, "record_id", 0) == 1 for v in header.vlrs)


def read_tile_info(path) -> TileInfo:
    """A file's :class:`TileInfo` from its header (no point is read)."""
    from workstation.io.las import crs_string, open_las

    path = Path(path)
    with open_las(path) as reader:
        h = reader.header
        return TileInfo(path, tuple(float(v) for v in (*h.mins, *h.maxs)), int(h.point_count), int(h.point_format.id),
                        crs_string(h, path), _is_copc(h))


def _crs_name(crs: str) -> str:
    from pyproj import CRS

    try:
        c = CRS.from_user_input(crs)
        epsg = c.to_epsg()
        return f"EPSG:{epsg}" if epsg else c.name
    except Exception:
        return crs[:60]


def build_catalog(paths, crs: str | None = None, inputs_hint: str = "check [inputs] clouds") -> Catalog:
    """The catalog of ``paths`` (LAS/LAZ/COPC files) from their headers.

    Parameters
    ----------
    crs : str, optional
        The project's CRS: tiles without one take it; tiles with another are refused.
    inputs_hint : str
        What to check when there is no input or every tile is empty (says where inputs are given).

    Raises
    ------
    InvalidInputError
        An unreadable header (naming the file), tiles in more than one CRS, or no points.
    """
    from workstation.io.crs import same_crs

    tiles = [read_tile_info(p) for p in paths]
    if not tiles:
        raise InvalidInputError("there are no input tiles", inputs_hint)
    ref = crs or next((t.crs for t in tiles if t.crs), None)
    for t in tiles:
        if t.crs and ref and not same_crs(t.crs, ref):
            raise InvalidInputError(
                f"CRS {_crs_name(t.crs)} differs from the other tiles' {_crs_name(ref)}",
                "reproject the tile first (ws convert IN OUT --to-crs ...) or fix [project] crs; "
                "chunks are cut in one coordinate system", path=t.path, field="crs")
        if t.point_count and not np.all(np.isfinite(t.bounds)):
            raise InvalidInputError("header bounds are not finite numbers", "repair the header (e.g. lasinfo -repair)",
                                    path=t.path, field="bounds")
    if not any(t.point_count for t in tiles):
        raise InvalidInputError("every input tile is empty", inputs_hint)
    without = [t.path.name for t in tiles if not t.crs]
    if without and ref:
        log.info("%d tile(s) without a CRS take %s", len(without), _crs_name(ref))
    return Catalog(tuple(t for t in tiles if t.point_count), ref)
