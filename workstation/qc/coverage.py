"""Point density, coverage and data voids of a delivery (USGS Lidar Base Specification 2024).

Two accumulators, one per pass of ``ws qc`` (:mod:`workstation.qc.context`):

* :class:`DensityPass` (pass 1) measures the **aggregate nominal pulse density** ANPD
  (points/m²) and spacing ANPS = 1/sqrt(ANPD) (m) as the USGS Lidar Base Specification (LBS)
  asks: from the first returns of *single swaths*, so that the double coverage of overlaps does
  not inflate it. Each swath (``point_source_id``) of each file is measured on its own and the
  figures are aggregated by area: ANPD = Σ first returns / Σ swath areas. A swath's area in a
  file is the convex hull of its first returns grown by half a point spacing (each point
  stands for a cell one spacing wide, so the hull through the outermost points misses a band
  of half a spacing: Steiner's formula A + P·d/2 + π(d/2)², solved with d = sqrt(A / n)). A
  straight swath cut by a rectangular tile is convex, so the figure is exact there; large
  areas without returns inside a swath (water) lower it.
* :class:`CoveragePass` (pass 2) counts first returns on a grid of 2×ANPS cells and reports
  the **spatial distribution** (LBS: at least 90 % of the 2×ANPS cells hold a first return;
  ASPRS Positional Accuracy Standards 2014 and the usual course notes ask 95 %) and the
  **data voids**: empty areas of (4×ANPS)² or more inside the flown area, except water, where
  no return is expected.

Selected points: withheld points (LAS 1.4 R15 withheld flag) and noise (classes 7 and 18) are
never counted; a first return is ``return_number <= 1`` (0 is what some writers store when
they record no return numbers; :mod:`workstation.qc.validate` reports it). Lengths and areas
in results are metres whatever the CRS unit; coordinates (centroids, bounding boxes, the
GeoJSON) stay in the CRS.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.classes import NOISE, ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.units import Units

from .context import Finding, QCGrid
from .density import hull_area, hull_candidates, hull_points

CHECK = "coverage"


# ---------------------------------------------------------------------------- point selection
def usable(chunk: Cloud) -> np.ndarray:
    """(n,) bool: points that count for density and coverage (not withheld, not noise)."""
    keep = np.ones(chunk.n, dtype=bool)
    withheld = chunk.attrs.get("withheld")
    if withheld is not None:
        keep &= np.asarray(withheld) == 0
    cls = chunk.attrs.get("classification")
    if cls is not None:
        keep &= ~np.isin(cls, np.array([int(c) for c in NOISE], dtype=np.asarray(cls).dtype))
    return keep


def first_returns(chunk: Cloud) -> np.ndarray:
    """(n,) bool: usable first returns (every usable point when return numbers are absent)."""
    keep = usable(chunk)
    rn = chunk.attrs.get("return_number")
    return keep if rn is None else keep & (np.asarray(rn) <= 1)


def coverage_grid(bounds, anps_m: float, units: Units) -> QCGrid:
    """The grid of 2×ANPS cells over ``bounds`` (xmin, ymin, xmax, ymax in CRS units) on which
    the LBS assesses the spatial distribution; ``anps_m`` in metres."""
    _check_anps(anps_m)
    return QCGrid.over(bounds, 2.0 * units.h_from_m(anps_m), units)


def _check_anps(anps_m: float) -> None:
    if not (isinstance(anps_m, (int, float, np.floating)) and math.isfinite(anps_m) and anps_m > 0):
        raise InvalidInputError(f"the aggregate nominal point spacing is {anps_m!r}",
                                "ANPS must be a positive number of metres (pass 1 found no first returns?)",
                                field="anps_m")


# ---------------------------------------------------------------------------- pass 1: density
@dataclass
class _Piece:
    """One swath within one file: its first-return count and convex-hull vertices (CRS units)."""

    n: int
    hull: np.ndarray


def _grown_hull_area(hull: np.ndarray, n: int) -> float:
    """Area (CRS units²) of the hull of ``n`` points grown by half their spacing d = sqrt(A/n):
    A = A_h + P·d/2 + π·d²/4, solved by fixed-point iteration (0 for a degenerate hull)."""
    a_h = hull_area(hull)
    if n < 3 or a_h <= 0:
        return 0.0
    perimeter = float(np.sum(np.hypot(*(np.roll(hull, -1, axis=0) - hull).T)))
    area = a_h
    for _ in range(20):
        d = math.sqrt(area / n)
        new = a_h + perimeter * d / 2 + math.pi * d * d / 4
        if abs(new - area) <= 1e-12 * new:
            break
        area = new
    return new


class DensityPass:
    """Pass 1: ANPD and ANPS from single-swath first returns (USGS LBS 2024, "Nominal Pulse
    Spacing"; ASPRS Positional Accuracy Standards 2014 §C.3 for the NPS/density duality).

    Parameters
    ----------
    units : Units
        Units of the delivery's CRS (areas are reported in m²).

    Examples
    --------
    >>> g = np.stack(np.meshgrid(np.arange(0, 20, 0.5), np.arange(0, 20, 0.5)), -1).reshape(-1, 2)
    >>> c = Cloud(np.c_[g + 0.25, np.zeros(len(g))], {"return_number": np.ones(len(g)),
    ...                                               "point_source_id": np.full(len(g), 7)})
    >>> p = DensityPass(Units()); p.add(c, "a.laz")
    >>> r = p.result(); round(r["anpd"], 2), round(r["anps"], 2), [s["id"] for s in r["swaths"]]
    (4.0, 0.5, [7])
    """

    def __init__(self, units: Units):
        self.units = units
        self._pieces: dict[tuple[str, int], _Piece] = {}
        self._psid_seen: dict[str, bool] = {}
        self._no_returns: set[str] = set()

    def add(self, chunk: Cloud, source: str) -> None:
        """Add a chunk (CRS units) read from the file ``source``."""
        source = str(source)
        if "return_number" not in chunk.attrs:
            self._no_returns.add(source)
        first = first_returns(chunk)
        psid = chunk.attrs.get("point_source_id")
        ids = np.zeros(int(first.sum()), np.int64) if psid is None else np.asarray(psid)[first].astype(np.int64)
        if ids.size:
            self._psid_seen[source] = self._psid_seen.get(source, False) or bool(ids.any())
        xy = chunk.xyz[first, :2]
        order = np.argsort(ids, kind="stable")
        ids, xy = ids[order], xy[order]
        starts = np.flatnonzero(np.r_[True, ids[1:] != ids[:-1]]) if len(ids) else np.empty(0, np.int64)
        for s, e in zip(starts, np.r_[starts[1:], len(ids)]):  # one swath at a time
            key = (source, int(ids[s]))
            piece = self._pieces.get(key) or _Piece(0, np.empty((0, 2)))
            hull = hull_points(np.vstack([piece.hull, hull_candidates(xy[s:e])]))
            self._pieces[key] = _Piece(piece.n + int(e - s), hull)

    def state(self) -> dict:
        """The pieces (swath within file: first returns and hull) as arrays, in the order they
        were met, and the files without swath ids or return numbers (:meth:`from_states`)."""
        keys = list(self._pieces)
        hulls = [self._pieces[k].hull for k in keys]
        return {"piece_source": np.array([k[0] for k in keys], dtype=str),
                "piece_sid": np.array([k[1] for k in keys], np.int64),
                "piece_n": np.array([self._pieces[k].n for k in keys], np.int64),
                "piece_len": np.array([len(h) for h in hulls], np.int64),
                "piece_hull": np.concatenate(hulls) if hulls else np.empty((0, 2)),
                "psid_source": np.array(list(self._psid_seen), dtype=str),
                "psid_seen": np.array(list(self._psid_seen.values()), bool),
                "no_returns": np.array(sorted(self._no_returns), dtype=str)}

    @classmethod
    def from_states(cls, units: Units, states: list[dict]) -> "DensityPass":
        """The pass over several files from the :meth:`state` of each (files distinct)."""
        p = cls(units)
        for st in states:
            hulls = np.split(np.asarray(st["piece_hull"]).reshape(-1, 2), np.cumsum(st["piece_len"])[:-1])
            for src, sid, n, h in zip(st["piece_source"], st["piece_sid"], st["piece_n"], hulls):
                p._pieces[(str(src), int(sid))] = _Piece(int(n), h)
            p._psid_seen.update({str(k): bool(v) for k, v in zip(st["psid_source"], st["psid_seen"])})
            p._no_returns.update(str(k) for k in st["no_returns"])
        return p

    def _swaths(self) -> dict[int, dict]:
        out: dict[int, dict] = {}
        for (_, sid), piece in sorted(self._pieces.items(), key=lambda kv: kv[0][1]):
            area = self.units.area_to_m2(_grown_hull_area(piece.hull, piece.n))
            s = out.setdefault(sid, {"id": sid, "first_returns": 0, "area_m2": 0.0, "files": 0, "ignored": 0})
            if area > 0:
                s["first_returns"] += piece.n
                s["area_m2"] += area
                s["files"] += 1
            else:  # fewer than 3 points or all on a line: no area to divide by
                s["ignored"] += piece.n
        for s in out.values():
            s["anpd"] = s["first_returns"] / s["area_m2"] if s["area_m2"] > 0 else float("nan")
        return out

    def result(self) -> dict:
        """``anpd`` (first returns/m²), ``anps`` (m), ``first_returns``, ``area_m2`` (Σ swath
        areas, m²), ``ignored_first_returns`` (in swath pieces with no area), ``swaths``
        ([{id, first_returns, area_m2, anpd, files}] per point_source_id), ``method``.
        ANPD and ANPS are NaN without first returns."""
        swaths = list(self._swaths().values())
        n = sum(s["first_returns"] for s in swaths)
        area = sum(s["area_m2"] for s in swaths)
        anpd = n / area if area > 0 else float("nan")
        return {
            "anpd": float(anpd),
            "anps": float(1 / math.sqrt(anpd)) if anpd > 0 else float("nan"),
            "first_returns": int(n),
            "area_m2": float(area),
            "ignored_first_returns": int(sum(s["ignored"] for s in swaths)),
            "swaths": [{k: s[k] for k in ("id", "first_returns", "area_m2", "anpd", "files")} for s in swaths],
            "method": "USGS LBS single-swath first returns (not withheld, not noise); per point_source_id and file, "
                      "area = convex hull of the first returns grown by half the point spacing; "
                      "ANPD = sum of first returns / sum of areas; ANPS = 1/sqrt(ANPD)",
        }

    def findings(self) -> list[Finding]:
        """Warnings on what makes the figures doubtful: files without swath ids (overlaps counted
        twice), files without return numbers, geographic coordinates; an error without first returns."""
        out = []
        for src in sorted(s for s, seen in self._psid_seen.items() if not seen):
            out.append(Finding(CHECK, "warning", src, "point_source_id", "one swath id per flight line", "all 0",
                               "no point_source_id: the file is measured as one swath, so overlaps may inflate the "
                               "density"))
        for src in sorted(self._no_returns):
            out.append(Finding(CHECK, "warning", src, "return_number", "return numbers", "absent",
                               "no return numbers: every point is counted as a first return"))
        if self.units.geographic:
            out.append(Finding(CHECK, "warning", None, "crs", "projected coordinates", "geographic",
                               "areas in degrees are converted with metres per degree of latitude: densities are "
                               "approximate"))
        if not (self.result()["first_returns"] > 0):
            out.append(Finding(CHECK, "error", None, "first_returns", "first returns over an area", "none",
                               "no usable first returns: density, spacing and coverage cannot be measured"))
        return out


# ---------------------------------------------------------------------------- pass 2: coverage
@dataclass(frozen=True)
class CoverageParams:
    """Thresholds of the coverage and void checks (USGS LBS 2024, "Data Voids" and "Spatial
    Distribution and Regularity").

    Attributes
    ----------
    required_coverage : float
        Fraction (0-1) of the assessed 2×ANPS cells that must hold a first return (LBS: 0.90;
        ASPRS 2014 and the course notes: 0.95).
    void_side_anps : float
        A void is an empty area of at least (void_side_anps × ANPS)² m² (LBS: 4).
    water_buffer_cells : int
        Empty cells within this many cells (8-neighbourhood steps) of a cell holding a water
        (class 9) point are water, not voids.
    water_border_fraction : float
        An empty area whose boundary (cell sides inside the footprint) faces water cells for at
        least this fraction (0-1) is water, not a void (no returns from open water is expected;
        shores are often only partly classified as water, so a quarter is enough).
    max_listed : int
        Voids listed in the result and given a finding, largest first; the rest are counted.
    """

    required_coverage: float = 0.90
    void_side_anps: float = 4.0
    water_buffer_cells: int = 1
    water_border_fraction: float = 0.25
    max_listed: int = 1000

    def __post_init__(self):
        for name in ("required_coverage", "water_border_fraction"):
            if not 0.0 <= getattr(self, name) <= 1.0:
                raise InvalidInputError(f"is {getattr(self, name)!r}", "give a fraction between 0 and 1", field=name)
        if not self.void_side_anps > 0:
            raise InvalidInputError(f"is {self.void_side_anps!r}", "give a positive multiple of ANPS",
                                    field="void_side_anps")
        for name in ("water_buffer_cells", "max_listed"):
            if getattr(self, name) < 0:
                raise InvalidInputError(f"is {getattr(self, name)!r}", "give a count of 0 or more", field=name)


def _accumulate(flat_grid: np.ndarray, idx: np.ndarray) -> None:
    """``flat_grid[idx] += 1`` for repeated indices, in memory bounded by the chunk: a
    ``bincount`` over the chunk's index window when it is compact, else sort and count."""
    if idx.size == 0:
        return
    lo, hi = int(idx.min()), int(idx.max())
    if hi - lo + 1 <= 8 * idx.size:
        flat_grid[lo:hi + 1] += np.bincount(idx - lo, minlength=hi - lo + 1).astype(flat_grid.dtype)
        return
    s = np.sort(idx)
    starts = np.flatnonzero(np.r_[True, s[1:] != s[:-1]])
    flat_grid[s[starts]] += np.diff(np.r_[starts, s.size]).astype(flat_grid.dtype)


class CoveragePass:
    """Pass 2: first returns per 2×ANPS cell, coverage and data voids (USGS LBS 2024).

    The footprint (the flown area) is the union of each file's convex hull of usable points
    and the cells holding first returns, with every empty area they enclose: tile corners
    outside the flown area lie outside it, a gap between two swaths inside a tile lies inside.
    Coverage is the fraction of footprint cells holding a first return, water cells excluded.
    A void is a 4-connected empty area (``scipy.ndimage.label``) whose size, estimated as its
    empty cells plus a quarter cell along its boundary, is at least (4×ANPS)²: the points
    bordering a hole lie up to one spacing (half a cell) out, so a hole of side s leaves on
    average s/cell − ½ empty cells across, and a rectangular hole at a random offset gets its
    area to within a quarter cell on average (one cell row at worst). Empty areas near water
    points, or whose boundary faces water for a set share (a quarter by default), are water,
    not voids: a dropout on land has no water on its boundary, while open water often has
    only part of its shore classified as water.

    Parameters
    ----------
    grid : QCGrid
        Cells of 2×ANPS (CRS units) over the delivery (see :func:`coverage_grid`).
    anps_m : float
        Aggregate nominal point spacing in metres (from :class:`DensityPass`).
    params : CoverageParams
    """

    def __init__(self, grid: QCGrid, anps_m: float, params: CoverageParams = CoverageParams()):
        _check_anps(anps_m)
        self.grid, self.anps_m, self.params = grid, float(anps_m), params
        self._counts = np.zeros(grid.shape, np.int32)
        self._water = np.zeros(grid.shape, bool)
        self._hulls: dict[str, np.ndarray] = {}
        self._outside = 0
        self._cache = None

    def add(self, chunk: Cloud, source: str) -> None:
        """Add a chunk (CRS units) read from the file ``source``."""
        keep = usable(chunk)
        if not keep.any():
            return
        self._cache = None
        xy = chunk.xyz[keep, :2]
        source = str(source)
        old = self._hulls.get(source, np.empty((0, 2)))
        self._hulls[source] = hull_points(np.vstack([old, hull_candidates(xy)]))
        flat, inside = self.grid.flat(xy)
        first = first_returns(chunk)[keep]
        self._outside += int(np.count_nonzero(~inside))
        _accumulate(self._counts.reshape(-1), flat[first & inside])
        cls = chunk.attrs.get("classification")
        if cls is not None:
            self._water.reshape(-1)[flat[(np.asarray(cls)[keep] == ASPRSClass.WATER) & inside]] = True

    def state(self) -> dict:
        """Counts and water cells of this (window) grid, the files' hulls, points outside."""
        return {"counts": self._counts, "water": self._water, "window": np.array(
                    [self.grid.row0, self.grid.col0, self.grid.rows, self.grid.cols], np.int64),
                "hull_source": np.array(list(self._hulls), dtype=str),
                "hull_len": np.array([len(h) for h in self._hulls.values()], np.int64),
                "hull_xy": np.concatenate(list(self._hulls.values())) if self._hulls else np.empty((0, 2)),
                "outside": np.array([self._outside], np.int64)}

    @classmethod
    def from_states(cls, grid: QCGrid, anps_m: float, params: CoverageParams, states: list[dict]) -> "CoveragePass":
        """The pass over the whole ``grid`` from the :meth:`state` of passes over windows of it
        (files distinct): counts added cell by cell, water cells and hulls joined."""
        cov = cls(grid, anps_m, params)
        for st in states:
            r0, c0, rows, cols = (int(v) for v in st["window"])
            block = (slice(r0, r0 + rows), slice(c0, c0 + cols))
            cov._counts[block] += np.asarray(st["counts"]).reshape(rows, cols)
            cov._water[block] |= np.asarray(st["water"]).reshape(rows, cols)
            hulls = np.split(np.asarray(st["hull_xy"]).reshape(-1, 2), np.cumsum(st["hull_len"])[:-1])
            cov._hulls.update({str(k): h for k, h in zip(st["hull_source"], hulls)})
            cov._outside += int(np.asarray(st["outside"]).sum())
        return cov

    # -- analysis -------------------------------------------------------------------------
    def _footprint(self, filled: np.ndarray) -> np.ndarray:
        """Union of the files' hulls (cells whose centre lies inside) and the filled cells,
        with the empty areas they enclose."""
        from rasterio.features import rasterize
        from scipy import ndimage

        polys = [({"type": "Polygon", "coordinates": [np.vstack([h, h[:1]]).tolist()]}, 1)
                 for h in self._hulls.values() if len(h) >= 3 and hull_area(h) > 0]
        hulls = rasterize(polys, out_shape=self.grid.shape, transform=self.grid.transform(), fill=0,
                          dtype="uint8").astype(bool) if polys else np.zeros(self.grid.shape, bool)
        return ndimage.binary_fill_holes(hulls | filled)

    def _analyse(self) -> dict:
        if self._cache is None:
            self._cache = _analyse(self._counts > 0, self._footprint(self._counts > 0), self._water,
                                   self.grid, self.anps_m, self.params)
        return self._cache

    def result(self) -> dict:
        """``cell_m`` (m), ``anps_m`` (m), ``coverage`` (0-1, NaN without assessed cells),
        ``required_coverage``, ``cells`` (assessed: footprint less water), ``filled``,
        ``footprint_cells``, ``water_cells`` (empty cells taken as water), ``footprint_area_m2``,
        ``voids`` (count), ``void_area_m2``, ``min_void_area_m2`` ((4×ANPS)²), ``void_list``
        ([{id, area_m2, cells, centroid [x, y], bbox [xmin, ymin, xmax, ymax], edge,
        water_border}]: CRS coordinates, ``edge`` when it touches the footprint's edge,
        ``water_border`` the share 0-1 of its boundary facing water; largest first, at most
        ``max_listed``), ``voids_unlisted``,
        ``points_outside_grid``."""
        a = self._analyse()
        voids = a["voids"]
        assessed = int(a["footprint"].sum() - a["water"].sum())
        filled = int(a["filled"].sum())
        cell_m2 = self.grid.cell_m**2
        keep = self.params.max_listed
        return {
            "cell_m": float(self.grid.cell_m),
            "anps_m": self.anps_m,
            "coverage": filled / assessed if assessed > 0 else float("nan"),
            "required_coverage": self.params.required_coverage,
            "cells": assessed,
            "filled": filled,
            "footprint_cells": int(a["footprint"].sum()),
            "water_cells": int(a["water"].sum()),
            "footprint_area_m2": float(a["footprint"].sum() * cell_m2),
            "voids": len(voids),
            "void_area_m2": float(sum(v["area_m2"] for v in voids)),
            "min_void_area_m2": a["min_area_m2"],
            "void_list": voids[:keep],
            "voids_unlisted": max(len(voids) - keep, 0),
            "points_outside_grid": self._outside,
        }

    def findings(self) -> list[Finding]:
        """An error when coverage is under the requirement and one per listed void (the LBS
        rejects voids), a summary of unlisted voids, a warning for points outside the grid."""
        r, p, u = self.result(), self.params, self.grid.units
        out = []
        if r["coverage"] < p.required_coverage:
            out.append(Finding(CHECK, "error", None, "coverage",
                               f">= {p.required_coverage:.0%} of 2xANPS cells ({u.describe_h(r['cell_m'])}) hold a "
                               f"first return", f"{r['coverage']:.1%}",
                               f"{r['cells'] - r['filled']} of {r['cells']} cells inside the flown area are empty"))
        for v in r["void_list"]:
            where = "at the edge of the flown area" if v["edge"] else "inside the flown area"
            out.append(Finding(CHECK, "error", None, "void", f"no void >= {r['min_void_area_m2']:.3g} m² ((4xANPS)²)",
                               f"{v['area_m2']:.1f} m²",
                               f"void {v['id']} of {v['area_m2']:.1f} m² {where}, centred at "
                               f"({v['centroid'][0]:.2f}, {v['centroid'][1]:.2f})"))
        if r["voids_unlisted"]:
            out.append(Finding(CHECK, "error", None, "void", "no voids", f"{r['voids_unlisted']} more",
                               f"{r['voids_unlisted']} smaller voids are not listed"))
        if r["points_outside_grid"]:
            out.append(Finding(CHECK, "warning", None, "bounds", "points inside the delivery bounds",
                               f"{r['points_outside_grid']} outside", "points outside the QC grid were not counted"))
        return out

    def write(self, out_dir, crs) -> dict[str, Path]:
        """``density.tif`` (first returns/m² per cell, float32, nodata -9999 outside the
        footprint), ``voids.tif`` (uint8: 1 void, 0 other cells of the footprint, 255 outside)
        and ``voids.geojson`` (one polygon per void, coordinates in ``crs``); atomic, replacing
        existing files. Returns {"density", "voids", "voids_geojson"}: paths."""
        from workstation.core.products import Raster
        from workstation.io.geotiff import write_raster

        out_dir = Path(out_dir)
        a = self._analyse()
        t = self.grid.transform()
        transform = (t.a, t.b, t.c, t.d, t.e, t.f)
        dens = np.where(a["footprint"], self._counts / np.float32(self.grid.cell_m**2), np.nan).astype(np.float32)
        vmask = np.where(a["footprint"], (a["labels"] > 0).astype(np.uint8), np.uint8(255))
        meta = {"kind": "qc", "cell_m": self.grid.cell_m, "anps_m": self.anps_m}
        paths = {
            "density": write_raster(Raster(dens, transform, crs, -9999.0, {**meta, "units": "first returns/m²"}),
                                    out_dir / "density.tif", overwrite=True),
            "voids": write_raster(Raster(vmask, transform, crs, 255, {**meta, "values": "1 void, 0 not, 255 outside"}),
                                  out_dir / "voids.tif", overwrite=True),
        }
        paths["voids_geojson"] = _write_voids_geojson(a, t, crs, out_dir / "voids.geojson")
        return paths


# ---------------------------------------------------------------------------- analysis helpers
def _edge_counts(labels: np.ndarray, n: int, flags: dict[str, tuple[np.ndarray, bool]]) -> dict[str, np.ndarray]:
    """Per label 1..n: cell sides facing a cell of another label (``"all"``) and, of those, the
    sides facing a cell where each flag grid is True (``flags``: name -> (grid, value beyond it))."""
    lab = np.pad(labels, 1)
    padded = {k: np.pad(g, 1, constant_values=v) for k, (g, v) in flags.items()}
    out = {k: np.zeros(n + 1) for k in ("all", *flags)}
    core = lab[1:-1, 1:-1]
    rows, cols = labels.shape
    for dr, dc in ((-1, 0), (1, 0), (0, -1), (0, 1)):
        nb = lab[1 + dr:1 + dr + rows, 1 + dc:1 + dc + cols]
        face = (core > 0) & (nb != core)
        ids = core[face]
        out["all"] += np.bincount(ids, minlength=n + 1)
        for k, g in padded.items():
            out[k] += np.bincount(ids, weights=g[1 + dr:1 + dr + rows, 1 + dc:1 + dc + cols][face], minlength=n + 1)
    return {k: v[1:] for k, v in out.items()}


def _water_cells(water: np.ndarray, empty: np.ndarray, buffer: int) -> np.ndarray:
    """Empty cells within ``buffer`` cells of a cell holding a water point."""
    from scipy import ndimage

    if buffer > 0 and water.any():
        water = ndimage.binary_dilation(water, np.ones((3, 3), bool), iterations=buffer)
    return water & empty


def _analyse(filled, footprint, water, grid: QCGrid, anps_m: float, p: CoverageParams) -> dict:
    """Empty areas of the footprint: which are water, which are voids (see :class:`CoveragePass`)."""
    from scipy import ndimage

    empty = footprint & ~filled
    wet = _water_cells(water, empty, p.water_buffer_cells)
    labels, n = ndimage.label(empty & ~wet)
    e = _edge_counts(labels, n, {"wet": (wet | water, False), "out": (~footprint, True)})
    inner = e["all"] - e["out"]
    is_water = (e["wet"] >= p.water_border_fraction * inner) & (inner > 0) & (e["wet"] > 0)
    cells = np.bincount(labels.ravel(), minlength=n + 1)[1:]
    size = (cells + e["all"] / 4) * grid.cell_m**2  # empty cells and a quarter cell along their boundary
    min_area = (p.void_side_anps * anps_m) ** 2
    is_void = (size >= min_area) & ~is_water
    wet |= np.r_[False, is_water][labels]
    keep = np.r_[0, np.where(is_void, np.arange(1, n + 1), 0)]
    labels = keep[labels]
    wet_share = np.divide(e["wet"], inner, out=np.zeros(n), where=inner > 0)
    voids = _void_records(labels, np.flatnonzero(is_void) + 1, size, cells, e["out"] > 0, wet_share, grid)
    relabel = np.zeros(n + 1, np.int32)
    relabel[[v.pop("_label") for v in voids]] = np.arange(1, len(voids) + 1)
    return {"filled": filled, "footprint": footprint, "water": wet, "labels": relabel[labels], "voids": voids,
            "min_area_m2": float(min_area)}


def _void_records(labels, ids, size, cells, edge, wet_share, grid: QCGrid) -> list[dict]:
    """One dict per void label in ``ids`` (CRS coordinates), largest first, numbered 1..n."""
    from scipy import ndimage

    if len(ids) == 0:
        return []
    rr, cc = np.nonzero(labels)
    lab = labels[rr, cc]
    n_max = int(labels.max()) + 1
    cnt = np.bincount(lab, minlength=n_max)
    cx = grid.x0 + (np.bincount(lab, cc + 0.5, n_max) / np.maximum(cnt, 1)) * grid.cell
    cy = grid.y1 - (np.bincount(lab, rr + 0.5, n_max) / np.maximum(cnt, 1)) * grid.cell
    slices = ndimage.find_objects(labels)
    order = ids[np.argsort(-size[ids - 1], kind="stable")]
    out = []
    for k, i in enumerate(order, 1):  # one record per void
        rs, cs = slices[i - 1]
        out.append({"id": k, "area_m2": float(size[i - 1]), "cells": int(cells[i - 1]),
                    "centroid": [float(cx[i]), float(cy[i])],
                    "bbox": [grid.x0 + cs.start * grid.cell, grid.y1 - rs.stop * grid.cell,
                             grid.x0 + cs.stop * grid.cell, grid.y1 - rs.start * grid.cell],
                    "edge": bool(edge[i - 1]), "water_border": float(wet_share[i - 1]), "_label": int(i)})
    return out


def _geojson_crs(crs) -> dict | None:
    """The (pre-RFC 7946) ``crs`` member naming the EPSG code, which GDAL and QGIS read."""
    if not crs:
        return None
    from workstation.io.crs import crs_info

    try:
        epsg = crs_info(str(crs)).epsg
    except InvalidInputError:
        return None
    return {"type": "name", "properties": {"name": f"urn:ogc:def:crs:EPSG::{epsg}"}} if epsg else None


def _write_voids_geojson(a: dict, transform, crs, path: Path) -> Path:
    """One Feature per void (polygon of its cells, with holes), properties as in ``void_list``."""
    from rasterio.features import shapes

    from workstation.io.atomic import atomic_path

    labels = a["labels"]
    rings: dict[int, list] = {}
    if labels.any():
        for geom, value in shapes(labels, mask=labels > 0, connectivity=4, transform=transform):
            rings.setdefault(int(value), []).append(geom["coordinates"])
    feats = []
    for v in a["voids"]:
        polys = rings.get(v["id"], [])
        geom = {"type": "Polygon", "coordinates": polys[0]} if len(polys) == 1 else \
            {"type": "MultiPolygon", "coordinates": polys}
        feats.append({"type": "Feature", "properties": dict(v), "geometry": geom})
    doc = {"type": "FeatureCollection", "features": feats}
    member = _geojson_crs(crs)
    if member:
        doc["crs"] = member
    with atomic_path(path, overwrite=True) as tmp:
        tmp.write_text(json.dumps(doc))
    return path
