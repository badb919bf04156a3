"""Classification checks of a lidar delivery for ``ws qc``.

What is checked, and after which rule:

* **Class histogram** over all 256 codes, with the withheld, synthetic, key-point and overlap
  flags (LAS 1.4 R15, Table 17). Codes 8 and 12 (reserved since LAS 1.4; model key-point and
  overlap before) and 23-63 (reserved) are listed in the result; the finding is
  :mod:`workstation.qc.validate`'s, which knows the file's LAS version.
* **Noise share**: the shares of low (7) and high (18) noise. USGS Lidar Base Specification
  2024 (LBS, §"Point classification") asks for noise to be classified (7, 18) or withheld; a
  large flagged share points at fog, rain, or a noise filter that removes real returns.
* **Unflagged noise**: a ground surface is built in pass 1 from the ground class (2) - the
  centroid of the ground points of each grid cell, triangulated and interpolated linearly at
  every cell centre (:func:`workstation.raster.grid.tin_surface`, the DTM method of
  :mod:`workstation.raster.dem`; cells without ground inside the hull of the ground cells are
  filled by the same TIN, NaN outside; rim cells that no triangle reaches keep their
  centroid's height). Pass 2 samples the surface bilinearly under every
  point not flagged as noise nor withheld (the value of its own cell in the outer half cell,
  where a neighbour has no surface) and counts, per class, the points more than
  ``below_m`` under it and more than ``above_m`` over it: noise the classification missed.
  Water (9) and topo-bathymetric returns (40-45, ASPRS LAS Domain Profile for topo-bathy
  lidar, 2013) and every point of a water cell lie legitimately under a TIN spanned across
  the banks and are not tested for "below".
* **Ground under every building**: building cells (6) are closed by one cell, their holes
  filled, and labelled into footprints (8-connected, ``scipy.ndimage.label``). A footprint
  passes when ground cells exist in a ring around it - the DTM under a building is a TIN
  spanned from that ring, which needs at least three vertices - and when its roof stands above
  that surface (median over its cells of the highest building return minus the surface).
* **Bridge decks not in ground** (USGS LBS 2024: the bare-earth surface excludes bridge decks,
  which are class 17): ground points in the interior cells of the bridge deck (deck cells
  eroded by one cell, so that abutments where deck and ground meet do not count) whose height
  reaches the lowest deck return of the cell less ``deck_tolerance_m``.

Every length in a result is in metres and every area in m², whatever the CRS unit
(``QCGrid.units``); plan coordinates (centroids) stay in CRS units. Memory is bounded by the
grid (about :data:`BYTES_PER_CELL` bytes a cell), never by the point count.

Examples
--------
>>> from workstation.core.cloud import Cloud
>>> from workstation.core.units import METRES
>>> xy = np.stack(np.meshgrid(np.arange(0.25, 20, 0.5), np.arange(0.25, 20, 0.5)), -1).reshape(-1, 2)
>>> cls = np.full(len(xy), 2, np.uint8); cls[:10] = 1
>>> z = np.where(cls == 2, 100.0, 80.0)          # ten unclassified points 20 m under the ground
>>> chunk = Cloud(np.column_stack([xy, z]), {"classification": cls})
>>> grid = QCGrid.over((0, 0, 20, 20), 1.0, METRES)
>>> p1 = ClassPass1(grid); p1.add(chunk, "a.las")
>>> p2 = p1.second_pass(); p2.add(chunk, "a.las")
>>> r = class_checks(p1, p2)
>>> r["histogram"], r["below_surface"]
({'1': 10, '2': 1590}, 10)
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass

import numpy as np

from workstation.core.budget import check_grid
from workstation.core.classes import NOISE, ASPRSClass, class_name
from workstation.core.errors import InvalidInputError
from workstation.core.products import Raster

from .context import Finding, QCGrid

#: Bytes per grid cell of both passes together (accumulators, surface, labels, temporaries).
BYTES_PER_CELL = 96
#: Flags counted next to the histogram (LAS 1.4 R15 point record flags).
FLAGS = ("withheld", "synthetic", "key_point", "overlap")
#: Codes 40-45 of the ASPRS LAS Domain Profile for topo-bathy lidar (2013): bathymetric point,
#: water surface, derived water surface, submerged object, IHO S-57 object, no bottom found.
TOPO_BATHY = (40, 41, 42, 43, 44, 45)
#: Classes whose objects may rise higher than any tree (buildings, wires, towers, overhead
#: structures): counted per class above the surface, but not as unflagged high noise.
TALL_STRUCTURES = (ASPRSClass.BUILDING, ASPRSClass.WIRE_GUARD, ASPRSClass.WIRE_CONDUCTOR,
                   ASPRSClass.TRANSMISSION_TOWER, ASPRSClass.WIRE_CONNECTOR, ASPRSClass.OVERHEAD_STRUCTURE)
#: Codes LAS 1.4 R15 reserves (8 and 12 had meanings before LAS 1.4).
RESERVED = (8, 12, *range(23, 64))
_NOT_CLASSIFIED = (ASPRSClass.CREATED_NEVER_CLASSIFIED, ASPRSClass.UNCLASSIFIED)
_S3 = np.ones((3, 3), bool)
#: The per-file counts of pass 2.
_FILE_COUNTS = ("below_surface", "above_surface", "deck_in_ground")


@dataclass(frozen=True)
class ClassParams:
    """Parameters of the classification checks; every length in metres, whatever the CRS unit.

    Attributes
    ----------
    cell_m : float
        Side of the ground-surface grid cell, m (default 1 m: the USGS LBS DEM cell of QL2 data,
        whose aggregate nominal pulse spacing is ≤ 0.71 m, so most cells hold a ground return).
        Used by :func:`class_grid`; a grid passed in directly keeps its own cell.
    below_m : float
        A non-noise point more than this under the ground surface is unflagged low noise, m
        (default 1 m ≈ 3 × the USGS QL2 vegetated vertical accuracy of 0.30 m at the 95th
        percentile, rounded up: a real return lies that far under the terrain with negligible
        probability, while ditches and gridding error stay above it).
    above_m : float
        A point more than this over the ground surface is unflagged high noise, m (default
        120 m, above the tallest known tree, the 116 m Hyperion redwood; classes in
        :data:`TALL_STRUCTURES` are exempt).
    noise_share_warn : float
        Share (0-1) of points flagged 7 or 18 above which a warning is given (default 0.01: no
        standard sets it; 1 % is far beyond what a clear-weather acquisition produces).
    max_unflagged_share : float
        Share (0-1) of points beyond ``below_m``/``above_m`` tolerated (default 0: the LBS asks
        every noise point to be classified or withheld).
    building_min_area_m2 : float
        Smaller building blobs are fragments, not footprints, m² (default 4 m², a 2 m × 2 m shed).
    ring_m : float
        Width of the ring around a footprint searched for ground cells, m (default 3 m: past
        eaves and the occluded strip along walls, short of the next street's ground).
    ring_min_ground_cells : int
        Ground cells the ring needs (default 3, the vertices of one TIN triangle).
    building_min_height_m : float
        A roof must stand this high above the surface (median over the footprint), m (default
        2 m, the ground offset under which LAStools ``lasclassify`` considers no building).
    deck_tolerance_m : float
        Ground points higher than the lowest deck return of their cell less this are deck
        points in the ground class, m (default 0.5 m: over 3 × the QL1/QL2 RMSEz of 0.10 m,
        far under any clearance beneath a bridge).
    max_listed : int
        Failing buildings listed in full; the rest are counted.
    """

    cell_m: float = 1.0
    below_m: float = 1.0
    above_m: float = 120.0
    noise_share_warn: float = 0.01
    max_unflagged_share: float = 0.0
    building_min_area_m2: float = 4.0
    ring_m: float = 3.0
    ring_min_ground_cells: int = 3
    building_min_height_m: float = 2.0
    deck_tolerance_m: float = 0.5
    max_listed: int = 1000

    def __post_init__(self):
        for name in ("cell_m", "below_m", "above_m", "ring_m"):
            v = getattr(self, name)
            if not (math.isfinite(v) and v > 0):
                raise InvalidInputError(f"must be a positive length in metres, got {v!r}", field=name)
        for name in ("noise_share_warn", "max_unflagged_share"):
            v = getattr(self, name)
            if not 0 <= v <= 1:
                raise InvalidInputError(f"must be a share between 0 and 1, got {v!r}", field=name)
        for name in ("building_min_area_m2", "building_min_height_m", "deck_tolerance_m",
                     "ring_min_ground_cells", "max_listed"):
            v = getattr(self, name)
            if not (math.isfinite(v) and v >= 0):
                raise InvalidInputError(f"must be zero or positive, got {v!r}", field=name)


#: Cells per side of the blocks the ground surface is triangulated in, and of the margin of
#: neighbouring cells each block is triangulated with (:func:`blocked_tin`).
SURFACE_BLOCK, SURFACE_MARGIN = 512, 128


def blocked_tin(du, dv, z, valid, block: int = SURFACE_BLOCK, margin: int = SURFACE_MARGIN) -> np.ndarray:
    """:func:`workstation.raster.grid.tin_surface` computed block by block, each block with
    ``margin`` cells of its neighbours, so that its memory (a Delaunay of the void rims, some
    hundred bytes a cell) is bounded by the block, not by the survey. Equal to the whole-grid
    surface wherever the triangles filling a void lie within the margin; a void wider than the
    margin is filled from the rim points the block sees (it is only a reference height for the
    class checks)."""
    from workstation.raster.grid import tin_surface

    R, C = z.shape
    if R <= block + 2 * margin and C <= block + 2 * margin:
        return tin_surface(du, dv, z, valid)
    out = np.full((R, C), np.nan)
    for r0 in range(0, R, block):
        for c0 in range(0, C, block):
            ra, rb, ca, cb = max(r0 - margin, 0), min(r0 + block + margin, R), max(c0 - margin, 0), min(c0 + block + margin, C)
            win = (slice(ra, rb), slice(ca, cb))
            if not valid[win].any():
                continue
            part = tin_surface(du[win], dv[win], z[win], valid[win])
            out[r0:r0 + block, c0:c0 + block] = part[r0 - ra:r0 - ra + block, c0 - ca:c0 - ca + block]
    return out


def class_grid(bounds, units, params: ClassParams = ClassParams()) -> QCGrid:
    """The :class:`QCGrid` of ``params.cell_m`` metres (in CRS units) over ``bounds``
    (xmin, ymin, xmax, ymax) in CRS units; refuses a grid that would not fit in memory."""
    cell = units.h_from_m(params.cell_m)
    xmin, ymin, xmax, ymax = (float(b) for b in bounds)
    check_grid((ymax - ymin) / cell + 2, (xmax - xmin) / cell + 2, what="classification check grid",
               option="--surface-cell", cell=params.cell_m, bytes_per_cell=BYTES_PER_CELL)
    return QCGrid.over(bounds, cell, units)


def _attr(chunk, name: str) -> np.ndarray:
    """A per-point attribute, zeros when the chunk lacks it."""
    a = chunk.get(name)
    return np.zeros(chunk.n, np.uint8) if a is None else np.asarray(a)


def _codes(counts: np.ndarray) -> dict[str, int]:
    """{"code": count} of the non-zero entries of a 256-bin histogram."""
    return {str(c): int(counts[c]) for c in np.flatnonzero(counts)}


class ClassPass1:
    """Pass 1: class histogram, ground centroids, building, bridge-deck and water cells.

    Feed every chunk to :meth:`add`, then :meth:`second_pass` gives the :class:`ClassPass2`
    to feed the same chunks; :func:`class_checks` merges both.

    Parameters
    ----------
    grid : QCGrid
        The grid of the ground surface (see :func:`class_grid`).
    params : ClassParams
    """

    def __init__(self, grid: QCGrid, params: ClassParams = ClassParams()):
        check_grid(grid.rows, grid.cols, what="classification check grid", option="cell_m",
                   cell=grid.cell_m, bytes_per_cell=BYTES_PER_CELL)
        n = grid.rows * grid.cols
        self.grid, self.params = grid, params
        self.hist = np.zeros(256, np.int64)
        self.flags = dict.fromkeys(FLAGS, 0)
        self.files: dict[str, int] = {}
        self._g_n = np.zeros(n, np.int32)
        self._g_su, self._g_sv = np.zeros(n, np.float32), np.zeros(n, np.float32)
        self._g_sz = np.zeros(n)
        self._b_max = np.full(n, -np.inf, np.float32)
        self._d_min = np.full(n, np.inf, np.float32)
        self._water = np.zeros(n, bool)
        self._surface: np.ndarray | None = None

    @property
    def points(self) -> int:
        return int(self.hist.sum())

    def add(self, chunk, source: str) -> None:
        """Add a :class:`~workstation.core.cloud.Cloud` chunk (CRS units) read from ``source``."""
        if chunk.n == 0:
            return
        cls = _attr(chunk, "classification").astype(np.uint8, copy=False)
        self.hist += np.bincount(cls, minlength=256)
        for f in FLAGS:
            self.flags[f] += int(np.count_nonzero(_attr(chunk, f)))
        self.files[source] = self.files.get(source, 0) + chunk.n
        idx, inside = self.grid.flat(chunk.xyz[:, :2])
        keep = inside & (_attr(chunk, "withheld") == 0)
        self._add_ground(chunk.xyz, idx, keep & (cls == ASPRSClass.GROUND))
        z = chunk.xyz[:, 2]
        b = keep & (cls == ASPRSClass.BUILDING)
        np.maximum.at(self._b_max, idx[b], z[b].astype(np.float32))
        d = keep & (cls == ASPRSClass.BRIDGE_DECK)
        np.minimum.at(self._d_min, idx[d], z[d].astype(np.float32))
        self._water[idx[keep & (cls == ASPRSClass.WATER)]] = True
        self._surface = None

    def _add_ground(self, xyz: np.ndarray, idx: np.ndarray, m: np.ndarray) -> None:
        """Sums of the ground points' offsets from their cell centres (cells) and heights."""
        if not m.any():
            return
        g, i = self.grid, idx[m]
        u = (xyz[m, 0] - g.x0) / g.cell - 0.5 - (i % g.cols + g.col0)
        v = (g.y1 - xyz[m, 1]) / g.cell - 0.5 - (i // g.cols + g.row0)
        np.add.at(self._g_n, i, 1)
        np.add.at(self._g_su, i, u.astype(np.float32))
        np.add.at(self._g_sv, i, v.astype(np.float32))
        np.add.at(self._g_sz, i, xyz[m, 2])

    _GRIDS = ("_g_n", "_g_su", "_g_sv", "_g_sz", "_b_max", "_d_min", "_water")

    def state(self) -> dict:
        """The histogram, flags, per-file counts and this (window) grid's cell accumulators."""
        g = self.grid
        return {"hist": self.hist, "flags": np.array([self.flags[f] for f in FLAGS], np.int64),
                "file_names": np.array(list(self.files), dtype=str),
                "file_points": np.array(list(self.files.values()), np.int64),
                "window": np.array([g.row0, g.col0, g.rows, g.cols], np.int64),
                **{k[1:]: getattr(self, k) for k in self._GRIDS}}

    @classmethod
    def from_states(cls, grid: QCGrid, params: ClassParams, states: list[dict]) -> "ClassPass1":
        """Pass 1 over the whole ``grid`` from the :meth:`state` of passes over windows of it
        (files distinct): sums added, highest and lowest kept, water cells joined."""
        p = cls(grid, params)
        ops = {"_g_n": np.add, "_g_su": np.add, "_g_sv": np.add, "_g_sz": np.add, "_b_max": np.maximum,
               "_d_min": np.minimum, "_water": np.logical_or}
        for st in states:
            r0, c0, rows, cols = (int(v) for v in st["window"])
            p.hist += np.asarray(st["hist"], np.int64)
            for f, v in zip(FLAGS, st["flags"]):
                p.flags[f] += int(v)
            p.files.update({str(k): int(v) for k, v in zip(st["file_names"], st["file_points"])})
            for k, op in ops.items():
                whole = getattr(p, k).reshape(grid.shape)[r0:r0 + rows, c0:c0 + cols]
                op(whole, np.asarray(st[k[1:]]).reshape(rows, cols), out=whole)
        return p

    @property
    def ground_cells(self) -> np.ndarray:
        """(rows, cols) bool: cells holding a ground point."""
        return (self._g_n > 0).reshape(self.grid.shape)

    def surface(self) -> np.ndarray:
        """(rows, cols) float64 ground surface at the cell centres, CRS vertical units: a linear
        TIN of the ground centroid of each cell (the centroid's height in the cells of the
        hull's rim that no triangle reaches), NaN outside the hull of the ground cells."""
        if self._surface is None:
            shape, valid = self.grid.shape, self._g_n > 0
            c = np.maximum(self._g_n, 1)
            du, dv = (self._g_su / c).reshape(shape), (self._g_sv / c).reshape(shape)
            z = np.where(valid, self._g_sz / c, np.nan).reshape(shape)
            tin = blocked_tin(du.astype(np.float64), dv.astype(np.float64), z, valid.reshape(shape))
            self._surface = np.where(np.isnan(tin), z, tin)  # the hull's rim: the cell's centroid
        return self._surface

    def deck_floor(self) -> np.ndarray:
        """(rows, cols) float64: the lowest bridge-deck return of each interior deck cell (deck
        cells closed by one cell, then eroded by one), NaN elsewhere; CRS vertical units."""
        from scipy.ndimage import binary_closing, binary_erosion

        occ = np.isfinite(self._d_min).reshape(self.grid.shape)
        interior = binary_erosion(binary_closing(occ, _S3), _S3, border_value=1) & occ
        return np.where(interior, self._d_min.reshape(self.grid.shape), np.nan)

    def water_mask(self) -> np.ndarray:
        """(rows, cols) bool: cells holding a water return, grown by one cell."""
        from scipy.ndimage import binary_dilation

        return binary_dilation(self._water.reshape(self.grid.shape), _S3)

    def second_pass(self) -> "ClassPass2":
        """The :class:`ClassPass2` on this pass's surface, bridge decks and water cells."""
        return ClassPass2(self.grid, self.surface(), self.params, deck_floor=self.deck_floor(),
                          water=self.water_mask())

    def buildings(self) -> dict:
        """Building footprints and the ones without ground around or under them.

        Returns
        -------
        dict
            ``count`` (footprints of at least ``building_min_area_m2``), ``fragments``
            (smaller blobs), ``without_ground`` (failing footprints), ``list`` (the failing
            ones, at most ``max_listed``: ``id``, ``centroid`` [x, y] in CRS units,
            ``area_m2``, ``ring_ground_cells``, ``height_m`` (median roof height over the
            surface, m; None where the surface does not reach), ``reasons``), ``listed``.
        """
        from scipy.ndimage import binary_closing, binary_fill_holes, find_objects, label

        g, p = self.grid, self.params
        occ = np.isfinite(self._b_max).reshape(g.shape)
        labels, n = label(binary_fill_holes(binary_closing(occ, _S3) | occ), structure=_S3)
        area = np.bincount(labels.ravel(), minlength=n + 1)[1:] * g.units.area_to_m2(g.cell**2)
        height = g.units.v_to_m(np.where(occ, self._b_max.reshape(g.shape), np.nan) - self.surface())
        big = np.flatnonzero(area >= p.building_min_area_m2) + 1
        k = max(int(math.ceil(g.units.h_from_m(p.ring_m) / g.cell - 1e-9)), 1)
        oi, oj = np.mgrid[-k : k + 1, -k : k + 1]
        disk = np.hypot(oi, oj) <= k
        failing, objects, ground = [], find_objects(labels), self.ground_cells
        for lab in big:
            entry = self._judge(labels, lab, objects[lab - 1], disk, height, ground)
            entry["area_m2"] = float(area[lab - 1])
            if entry["reasons"]:
                failing.append(entry)
        return {"count": int(len(big)), "fragments": int(n - len(big)), "without_ground": len(failing),
                "list": failing[: p.max_listed], "listed": min(len(failing), p.max_listed)}

    def _judge(self, labels, lab: int, sl, disk, height, ground) -> dict:
        """One footprint: ground cells in its ring (``disk`` around it), median roof height, centroid."""
        from scipy.ndimage import binary_dilation

        g, p, k = self.grid, self.params, disk.shape[0] // 2
        r0, r1 = max(sl[0].start - k, 0), min(sl[0].stop + k, g.rows)
        c0, c1 = max(sl[1].start - k, 0), min(sl[1].stop + k, g.cols)
        foot = labels[r0:r1, c0:c1] == lab
        ring = binary_dilation(foot, disk) & ~foot
        ring_ground = int(np.count_nonzero(ring & ground[r0:r1, c0:c1]))
        h = height[r0:r1, c0:c1][foot]
        h = h[np.isfinite(h)]
        med = float(np.median(h)) if len(h) else None
        rows, cols = np.nonzero(foot)
        cx = g.x0 + (c0 + cols.mean() + 0.5) * g.cell
        cy = g.y1 - (r0 + rows.mean() + 0.5) * g.cell
        reasons = []
        if ring_ground < p.ring_min_ground_cells:
            reasons.append("no ground around")
        if med is not None and med < p.building_min_height_m:
            reasons.append("not above the ground surface")
        return {"id": int(lab), "centroid": [float(cx), float(cy)], "ring_ground_cells": ring_ground,
                "height_m": med, "reasons": reasons}


class ClassPass2:
    """Pass 2: points beyond the ground surface, and ground points at bridge-deck level.

    Parameters
    ----------
    grid : QCGrid
        The grid of pass 1.
    surface : (rows, cols) float
        The ground surface at the cell centres, CRS vertical units, NaN where unknown
        (:meth:`ClassPass1.surface`).
    params : ClassParams
    deck_floor : (rows, cols) float, optional
        Lowest deck return of interior bridge-deck cells, NaN elsewhere (:meth:`ClassPass1.deck_floor`).
    water : (rows, cols) bool, optional
        Cells whose points are not tested for "below" (:meth:`ClassPass1.water_mask`).
    any_surface : bool, optional
        Whether the surface of the whole delivery holds a value anywhere, when ``grid`` is a
        window of it (default: whether ``surface`` does). Without any, no point is tested.
    """

    def __init__(self, grid: QCGrid, surface: np.ndarray, params: ClassParams = ClassParams(), *,
                 deck_floor: np.ndarray | None = None, water: np.ndarray | None = None,
                 any_surface: bool | None = None):
        for name, a in (("surface", surface), ("deck_floor", deck_floor), ("water", water)):
            if a is not None and np.shape(a) != grid.shape:
                raise InvalidInputError(f"has shape {np.shape(a)}, the grid {grid.shape}", field=name)
        self.grid, self.params = grid, params
        x0, y1 = grid.x0 + grid.col0 * grid.cell, grid.y1 - grid.row0 * grid.cell  # a window's own corner
        self._dem = Raster(np.asarray(surface, np.float64), (grid.cell, 0.0, x0, 0.0, -grid.cell, y1))
        self._flat = self._dem.array.ravel()
        self._any = bool(np.isfinite(self._flat).any()) if any_surface is None else bool(any_surface)
        self._deck = None if deck_floor is None else np.asarray(deck_floor, np.float64).ravel()
        self._water = None if water is None else np.asarray(water, bool).ravel()
        self.below = np.zeros(256, np.int64)
        self.above = np.zeros(256, np.int64)
        self.tested = 0
        self.deck_in_ground = 0
        self.files: dict[str, dict] = {}

    def add(self, chunk, source: str) -> None:
        """Add a :class:`~workstation.core.cloud.Cloud` chunk (CRS units) read from ``source``."""
        f = self.files.setdefault(source, {"below_surface": 0, "above_surface": 0, "deck_in_ground": 0})
        if chunk.n == 0 or not self._any:
            return
        from workstation.raster.dem import sample_bilinear

        u, p = self.grid.units, self.params
        cls = _attr(chunk, "classification").astype(np.uint8, copy=False)
        usable = _attr(chunk, "withheld") == 0
        test = usable & ~np.isin(cls, NOISE)
        xyz, c = chunk.xyz[test], cls[test]
        idx, inside = self.grid.flat(xyz[:, :2])
        ground = sample_bilinear(self._dem, xyz[:, 0], xyz[:, 1])
        edge = np.isnan(ground) & inside  # next to a cell without surface: the cell's own value
        ground[edge] = self._flat[idx[edge]]
        dz = u.v_to_m(xyz[:, 2] - ground)
        ok = np.isfinite(dz)
        self.tested += int(ok.sum())
        exempt = np.isin(c, (ASPRSClass.WATER, *TOPO_BATHY))
        if self._water is not None:
            exempt |= self._water[idx] & inside
        below = np.bincount(c[ok & ~exempt & (dz < -p.below_m)], minlength=256)
        above = np.bincount(c[ok & (dz > p.above_m)], minlength=256)
        self.below += below
        self.above += above
        f["below_surface"] += int(below.sum())
        f["above_surface"] += int(_high_noise(above))
        hits = self._deck_hits(chunk.xyz[usable & (cls == ASPRSClass.GROUND)])
        self.deck_in_ground += hits
        f["deck_in_ground"] += hits

    def state(self) -> dict:
        """The counts of this pass, to add to those of the passes over the other files."""
        names = list(self.files)
        return {"below": self.below, "above": self.above, "tested": np.array([self.tested], np.int64),
                "deck_in_ground": np.array([self.deck_in_ground], np.int64), "file_names": np.array(names, dtype=str),
                "file_counts": np.array([[self.files[n][k] for k in _FILE_COUNTS] for n in names],
                                        np.int64).reshape(-1, 3)}

    def _deck_hits(self, ground: np.ndarray) -> int:
        """Ground points in interior deck cells at the deck's level."""
        if self._deck is None or len(ground) == 0:
            return 0
        idx, inside = self.grid.flat(ground[:, :2])
        floor = np.where(inside, self._deck[idx], np.nan)
        tol = self.grid.units.v_from_m(self.params.deck_tolerance_m)
        with np.errstate(invalid="ignore"):
            return int(np.count_nonzero(ground[:, 2] >= floor - tol))

    def result(self) -> dict:
        """Pass-2 counts: ``below_surface``, ``above_surface`` (tall-structure classes left out),
        ``below_by_class``, ``above_by_class``, ``tested`` (points with a surface under them),
        ``deck_in_ground``, ``files``."""
        return pass2_result(self.below, self.above, self.tested, self.deck_in_ground, self.files)


def pass2_result(below: np.ndarray, above: np.ndarray, tested: int, deck_in_ground: int, files: dict) -> dict:
    """The :meth:`ClassPass2.result` of counts (``below``/``above``: 256 per-class counts),
    whether they come from one pass or are the sums of several passes over parts of a delivery."""
    return {"below_surface": int(below.sum()), "above_surface": int(_high_noise(above)),
            "below_by_class": _codes(below), "above_by_class": _codes(above),
            "tested": int(tested), "deck_in_ground": int(deck_in_ground),
            "files": {k: dict(v) for k, v in files.items()}}


def pass2_merged(states: list[dict]) -> dict:
    """:func:`pass2_result` of the :meth:`ClassPass2.state` of passes over distinct files."""
    below, above = np.zeros(256, np.int64), np.zeros(256, np.int64)
    tested = deck = 0
    files: dict = {}
    for st in states:
        below += st["below"]
        above += st["above"]
        tested += int(np.asarray(st["tested"]).sum())
        deck += int(np.asarray(st["deck_in_ground"]).sum())
        for name, c in zip(st["file_names"], np.asarray(st["file_counts"]).reshape(-1, 3)):
            files[str(name)] = dict(zip(_FILE_COUNTS, (int(v) for v in c)))
    return pass2_result(below, above, tested, deck, files)


def _high_noise(above: np.ndarray) -> int:
    """Points above the surface, tall-structure classes left out."""
    keep = np.ones(256, bool)
    keep[list(TALL_STRUCTURES)] = False
    return int(above[keep].sum())


def class_checks(p1: ClassPass1, p2: ClassPass2 | None = None) -> dict:
    """The merged result of both passes (``p2`` None: pass 1 only), JSON-ready, lengths in m.

    Returns
    -------
    dict
        ``points``, ``classified`` (any code other than 0 and 1), ``histogram`` {"code": n} and
        ``names`` {"code": name} of the codes present, ``flags`` {flag: n}, ``noise_share``
        {"low", "high", "withheld"} (0-1), ``reserved_codes``, ``cell_m``, ``below_m``,
        ``above_m``, ``below_surface`` / ``above_surface`` (None without a ground class or a
        pass 2), ``below_by_class`` / ``above_by_class``, ``tested``, ``buildings`` (see
        :meth:`ClassPass1.buildings`), ``bridge`` {"deck_points", "deck_in_ground"}, ``files``
        {source: counts}, ``params`` and ``criteria`` [{"name", "value", "threshold", "pass"}]
        (empty for an unclassified delivery: nothing to judge).
    """
    return class_result(pass1_result(p1), None if p2 is None else p2.result(), p1.params)


def pass1_result(p1: ClassPass1) -> dict:
    """The part of :func:`class_checks` that pass 1 alone decides (histogram, buildings), JSON-ready."""
    p, hist = p1.params, p1.hist
    res = _histogram(p1)
    res.update({"cell_m": p1.grid.cell_m, "below_m": p.below_m, "above_m": p.above_m,
                "below_surface": None, "above_surface": None, "below_by_class": {}, "above_by_class": {},
                "tested": 0, "buildings": p1.buildings(),
                "bridge": {"deck_points": int(hist[ASPRSClass.BRIDGE_DECK]), "deck_in_ground": None},
                "files": {s: {"points": k} for s, k in p1.files.items()}, "params": asdict(p)})
    return res


def class_result(res1: dict, r2: dict | None, p: ClassParams) -> dict:
    """:func:`class_checks` from the pass-1 part ``res1`` (:func:`pass1_result`) and the pass-2
    counts ``r2`` (:func:`pass2_result`; None: pass 1 only)."""
    import copy

    res = copy.deepcopy(res1)
    if r2 is not None:
        res["bridge"]["deck_in_ground"] = r2["deck_in_ground"]
        for s, counts in r2["files"].items():
            res["files"].setdefault(s, {"points": 0}).update(counts)
        if res["histogram"].get(str(int(ASPRSClass.GROUND))):
            keys = ("below_surface", "above_surface", "below_by_class", "above_by_class", "tested")
            res.update({k: r2[k] for k in keys})
    res["criteria"] = _criteria(res, p) if res["classified"] else []
    return res


def _histogram(p1: ClassPass1) -> dict:
    """The histogram part of the result: codes present, names, flags, noise shares."""
    n, hist = p1.points, p1.hist
    codes = _codes(hist)
    classified = bool(np.delete(hist, list(_NOT_CLASSIFIED)).any())
    return {"points": n, "classified": classified, "histogram": codes,
            "names": {c: class_name(int(c)) for c in codes}, "flags": dict(p1.flags),
            "noise_share": {"low": _share(hist[ASPRSClass.LOW_POINT], n),
                            "high": _share(hist[ASPRSClass.HIGH_NOISE], n),
                            "withheld": _share(p1.flags["withheld"], n)},
            "reserved_codes": [c for c in RESERVED if hist[c]]}


def _share(k, n: int) -> float:
    return float(k) / n if n else 0.0


def _criterion(name: str, value, threshold, ok: bool) -> dict:
    return {"name": name, "value": value, "threshold": threshold, "pass": bool(ok)}


def _criteria(res: dict, p: ClassParams) -> list[dict]:
    """Pass/fail lines of a classified delivery (a building or bridge line only where there are some)."""
    n, ground = res["points"], int(res["histogram"].get(str(int(ASPRSClass.GROUND)), 0))
    out = [_criterion("ground class present", ground, 1, ground >= 1)]
    b = res["buildings"]
    if b["count"]:
        out.append(_criterion("ground under every building", b["without_ground"], 0, b["without_ground"] == 0))
    if res["below_surface"] is not None:
        for key, name in (("below_surface", "unflagged low noise share"), ("above_surface", "unflagged high noise share")):
            v = _share(res[key], n)
            out.append(_criterion(name, v, p.max_unflagged_share, v <= p.max_unflagged_share))
    flagged = res["noise_share"]["low"] + res["noise_share"]["high"]
    out.append(_criterion("flagged noise share", flagged, p.noise_share_warn, flagged <= p.noise_share_warn))
    deck = res["bridge"]
    if deck["deck_points"] and deck["deck_in_ground"] is not None:
        out.append(_criterion("bridge decks not in ground", deck["deck_in_ground"], 0, deck["deck_in_ground"] == 0))
    return out


def class_findings(res: dict) -> list[Finding]:
    """Findings (check "classes") from a :func:`class_checks` result."""
    if not res["classified"]:
        return [Finding("classes", "info", None, "classification", "ASPRS classes other than 0/1",
                        "only codes " + ", ".join(res["histogram"]) if res["histogram"] else "no points",
                        "the delivery is not classified: the classification checks were not run")]
    out = []  # reserved codes: a finding of qc.validate, which knows the file's LAS version
    for c in res["criteria"]:
        if not c["pass"] and not c["name"].startswith("unflagged"):  # those: per file, below
            out.append(_criterion_finding(res, c))
    return out + _file_findings(res)


def _file_findings(res: dict) -> list[Finding]:
    """One finding per file and direction holding unflagged noise."""
    out = []
    for src, f in res["files"].items():
        for key, word, m in (("below_surface", "below", res["below_m"]), ("above_surface", "above", res["above_m"])):
            if f.get(key):
                out.append(Finding("classes", "warning", src, "classification",
                                   f"no unflagged point {m:g} m {word} the ground", str(f[key]),
                                   f"{f[key]} points not flagged as noise lie more than {m:g} m {word} the ground surface"))
    return out


def _criterion_finding(res: dict, c: dict) -> Finding:
    """The delivery-wide finding of a failing criterion."""
    name, value = c["name"], c["value"]
    if name == "ground under every building":
        b = res["buildings"]
        where = "; ".join(f"({e['centroid'][0]:.1f}, {e['centroid'][1]:.1f}): {', '.join(e['reasons'])}" for e in b["list"][:5])
        expected = "ground around and under every building"
        msg = f"{value} of {b['count']} buildings lack ground around or under them, e.g. {where}"
    elif name == "bridge decks not in ground":
        expected = "no ground point at bridge-deck level (USGS LBS 2024)"
        msg = f"{value} ground points lie at bridge-deck level inside bridge-deck cells (class 17)"
    elif name == "ground class present":
        expected = "ground points (class 2)"
        msg = "the delivery is classified but holds no ground (class 2): no ground surface, surface checks skipped"
    else:
        expected = f"{name} <= {c['threshold']:g}"
        msg = f"{name} is {value:.4g}, more than {c['threshold']:g}"
    return Finding("classes", "warning", None, "classification", expected,
                   f"{value:.4g}" if isinstance(value, float) else str(value), msg)
