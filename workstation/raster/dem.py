"""DSM, DTM and CHM from point clouds; heights above a DTM raster.

Notes
-----
* DSM, ``method="highest"``: the highest non-noise return in each cell (lidR ``p2r``, PDAL
  ``writers.gdal`` ``output_type=max``); empty cells are filled by the TIN of the neighbouring
  cell maxima. ``method="tin"``: a TIN of the highest first return per cell (lidR
  ``dsmtin``).
* DTM, ``method="tin"``: ground points (ASPRS class 2 by default) are reduced to one
  representative per cell — the centroid (mean x, y, z), which is exact on planar ground and
  averages the range noise — and interpolated linearly in a triangulated irregular network at
  every cell centre (lidR ``rasterize_terrain(tin())``, LAStools ``blast2dem``); holes left by
  buildings and water inside the hull are filled by the same TIN (see
  :mod:`workstation.raster.grid`). ``method="nn"``: natural-neighbour interpolation by the
  discrete Sibson algorithm (Park et al. 2006). ``method="idw"``: inverse-distance weighting
  of the k nearest representatives (Shepard 1968). Both cover the same cells as the TIN.
* CHM = DSM − DTM, clipped at 0. ``pit_free=True``: the pit-free algorithm of Khosravipour et
  al. (2014, PE&RS 80(9)): first returns normalised by the DTM, partial TINs of the returns
  above 0, 2, 5, 10, 15 ... m with triangles longer than a freeze distance dropped, and the
  cell-wise maximum of the partial CHMs.
* Ties (a point on a cell edge, a cell centre as far from several points, co-circular points,
  an edge as long as the limit, a height at a layer threshold) are settled by fixed rules
  (:data:`~workstation.raster.grid.TIE`), not by the rounding of the coordinates, so a file
  and its copy in US feet give the same DEM cell for cell (lattices of points are full of them).
* ``resolution=None`` (``--resolution auto``): the cell is at least the nominal point spacing
  of the points used, rounded up to a round value (USGS Lidar Base Specification: QL2 data
  with an aggregate nominal pulse spacing ≤ 0.71 m gives a 1 m DEM, QL1 ≤ 0.35 m gives 0.5 m),
  and, when the vertical RMSE is known, at least three times that RMSE: a height error of ±σ
  then stays inside one cell (the "3σ" rule of the photogrammetric products lecture; the same
  factor links vertical RMSE and contour interval in ASPRS 1990 class 1 maps, RMSEz = CI/3).

Large inputs are streamed in chunks (``workstation.io.iter_chunks``): each chunk is reduced
into per-cell accumulators (count and sums, or the maximum and its position), so memory is
bounded by the raster, not by the point count; the TIN is then built tile by tile. Grids of
more than ``tile_cells``² cells from files are built out of core: one pass spills the points
into per-tile temporary files (tiles overlap by ``buffer_cells``), then each tile is gridded
alone, so memory is bounded by the tile.
"""

from __future__ import annotations

import math
import time
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Iterator

import numpy as np

from workstation.core.budget import check_grid
from workstation.core.classes import NOISE, ASPRSClass
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Raster
from workstation.io.crs import crs_units

from .grid import TIE, GridSpec, fill_voids_tin, tin_surface

log = get_logger(__name__)

KINDS = ("dsm", "dtm", "chm")
#: The gridding methods of each kind (None: the kind's default, the first listed).
KIND_METHODS = {"dsm": ("highest", "tin"), "dtm": ("tin", "nn", "idw"), "chm": ("highest", "tin")}
#: Every gridding method.
METHODS = ("tin", "nn", "idw", "highest")
#: Bytes per cell of an in-memory DEM: both accumulators (count, sums, maximum and its
#: position), the interpolated float64 surface and the float32 result.
_BYTES_PER_CELL = 96
NICE_CELLS = (0.05, 0.1, 0.2, 0.25, 0.5, 1.0, 2.0, 2.5, 5.0, 10.0, 20.0, 25.0, 50.0, 100.0)


@dataclass(frozen=True)
class DemParams:
    """Parameters of :func:`build_dem`.

    Attributes
    ----------
    kind : {"dsm", "dtm", "chm"}
    resolution : float or None
        Cell size in metres, whatever the CRS unit (a US-feet CRS gets 3.2808... ft cells for
        1 m). None chooses it from the point spacing and the vertical RMSE (see
        :func:`auto_resolution`). A ``grid`` given to :func:`build_dem` overrides it.
    method : str
        DTM: ``"tin"`` (linear TIN, default), ``"nn"`` (discrete Sibson natural neighbour)
        or ``"idw"``. DSM: ``"highest"`` (default) or
        ``"tin"`` (TIN of first returns). CHM uses the DSM and DTM defaults.
    vertical_rmse : float or None
        Known vertical RMSE of the points in metres (for the 3× cell-size rule; stored in the
        raster's meta as ``vertical_rmse`` for contour intervals).
    max_edge : float or None
        Triangles with an edge longer than this (metres, converted to CRS units) are not interpolated, leaving NaN;
        None fills every void inside the convex hull of the points (buildings, water).
    idw_power : float
        Exponent of inverse-distance weights (dimensionless).
    idw_k : int
        Neighbours for IDW.
    nn_max_radius : float
        Natural neighbour: cells farther than this many cells from every point take the TIN
        value (bounds the O(r²) scatter of the discrete algorithm).
    pit_free : bool
        CHM by the pit-free algorithm instead of DSM − DTM.
    pit_free_thresholds : tuple of float
        Height layers of the pit-free CHM in metres (converted to the CRS's vertical unit).
    pit_free_max_edge : float or None
        Freeze distance of the pit-free partial TINs in metres (default 3 cells).
    ground_classes : tuple of int
        Classes used as ground for the DTM.
    tile : int
        Tile size in cells for the TIN step (bounds temporary memory).
    """

    kind: str = "dtm"
    resolution: float | None = 1.0
    method: str | None = None
    vertical_rmse: float | None = None
    max_edge: float | None = None
    idw_power: float = 2.0
    idw_k: int = 8
    nn_max_radius: float = 24.0
    pit_free: bool = False
    pit_free_thresholds: tuple = (0.0, 2.0, 5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0)
    pit_free_max_edge: float | None = None
    ground_classes: tuple = (int(ASPRSClass.GROUND),)
    tile: int = 512

    def __post_init__(self):
        if self.kind not in KINDS:
            raise InvalidInputError(f"unknown kind '{self.kind}'", "use dsm, dtm or chm", field="kind")
        if self.method is not None and self.method not in KIND_METHODS[self.kind]:
            raise InvalidInputError(
                f"method '{self.method}' does not apply to a {self.kind}",
                "DTM: tin, nn or idw; DSM/CHM: highest or tin", field="method",
            )
        if self.pit_free and self.kind != "chm":
            raise InvalidInputError("the pit-free algorithm makes a CHM", "use --kind chm", field="pit_free")
        if self.resolution is not None and not (self.resolution > 0):
            raise InvalidInputError("resolution must be positive", field="resolution")


# --------------------------------------------------------------------------- accumulators
def _cell_index(grid: GridSpec, x, y) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(row, col, inside)`` of points as :meth:`GridSpec.cell_index`, a point within the tie
    band (:data:`~workstation.raster.grid.TIE` cells) of a cell edge taken as on it: it goes
    to the cell east or south of the edge, as a point exactly on the edge does. A point on an
    edge in metres is off it by the rounding of the conversion in feet; without the band it
    would fall in the other cell and change that cell's representative."""
    col = np.floor((np.asarray(x) - grid.x0) / grid.res + TIE).astype(np.int64)
    row = np.floor((grid.y1 - np.asarray(y)) / grid.res + TIE).astype(np.int64)
    inside = (row >= 0) & (row < grid.rows) & (col >= 0) & (col < grid.cols)
    return row, col, inside


def _bounds_grid(xmin: float, ymin: float, xmax: float, ymax: float, res: float) -> GridSpec:
    """:meth:`GridSpec.from_bounds` with the tie band of :func:`_cell_index`: a bound within
    :data:`~workstation.raster.grid.TIE` cells of a multiple of ``res`` is taken as on it, so
    the grid of a file and of its copy in another unit have the same cells."""
    if not (res > 0 and math.isfinite(res)):
        raise InvalidInputError(f"cell size must be positive, got {res}", field="resolution")
    c0 = math.floor(xmin / res + TIE)
    r1 = math.floor(ymax / res + TIE) + 1
    cols = math.floor(xmax / res + TIE) - c0 + 1
    rows = r1 - math.floor(ymin / res + TIE)
    return GridSpec(float(c0 * res), float(r1 * res), float(res), int(rows), int(cols))


def _in_grid(grid: GridSpec, x, y, z):
    """Cell row/column of the points inside ``grid`` and those points; None when none is."""
    row, col, inside = _cell_index(grid, x, y)
    if not inside.all():
        row, col, x, y, z = row[inside], col[inside], x[inside], y[inside], z[inside]
    return None if len(z) == 0 else (row, col, x, y, z)


class _MeanAcc:
    """Per-cell count and sums of offsets (cells) and z: gives the centroid of each cell."""

    def __init__(self, grid: GridSpec):
        n = grid.rows * grid.cols
        self.grid = grid
        self.count = np.zeros(n, np.int64)
        self.su = np.zeros(n)
        self.sv = np.zeros(n)
        self.sz = np.zeros(n)

    def add(self, x, y, z):
        cells = _in_grid(self.grid, x, y, z)
        if cells is None:
            return
        row, col, x, y, z = cells
        u, v = self.grid.to_uv(x, y)
        idx = row * self.grid.cols + col
        n = self.count.size
        if n <= 4 * len(idx):
            self.count += np.bincount(idx, minlength=n)
            self.su += np.bincount(idx, u - col, minlength=n)
            self.sv += np.bincount(idx, v - row, minlength=n)
            self.sz += np.bincount(idx, z, minlength=n)
        else:
            uq, inv = np.unique(idx, return_inverse=True)
            self.count[uq] += np.bincount(inv)
            self.su[uq] += np.bincount(inv, u - col)
            self.sv[uq] += np.bincount(inv, v - row)
            self.sz[uq] += np.bincount(inv, z)

    def reps(self):
        shape = self.grid.shape
        valid = self.count > 0
        c = np.maximum(self.count, 1)
        du, dv, z = self.su / c, self.sv / c, np.where(valid, self.sz / c, np.nan)
        return du.reshape(shape), dv.reshape(shape), z.reshape(shape), valid.reshape(shape)


class _MaxAcc:
    """Per-cell maximum z and the position of the point that holds it."""

    def __init__(self, grid: GridSpec):
        n = grid.rows * grid.cols
        self.grid = grid
        self.z = np.full(n, -np.inf)
        self.du = np.zeros(n)
        self.dv = np.zeros(n)

    def add(self, x, y, z):
        cells = _in_grid(self.grid, x, y, z)
        if cells is None:
            return
        row, col, x, y, z = cells
        idx = row * self.grid.cols + col
        order = np.lexsort((z, idx))
        s = idx[order]
        last = np.ones(len(s), bool)
        last[:-1] = s[1:] != s[:-1]
        sel = order[last]
        cells = idx[sel]
        better = z[sel] > self.z[cells]
        sel, cells = sel[better], cells[better]
        u, v = self.grid.to_uv(x[sel], y[sel])
        self.z[cells] = z[sel]
        self.du[cells] = u - col[sel]
        self.dv[cells] = v - row[sel]

    def reps(self):
        shape = self.grid.shape
        valid = np.isfinite(self.z)
        z = np.where(valid, self.z, np.nan)
        return self.du.reshape(shape), self.dv.reshape(shape), z.reshape(shape), valid.reshape(shape)


# --------------------------------------------------------------------------- sources
def _names(source) -> str:
    """The input file names of a DEM source (or the clouds' ``source`` meta), for messages."""
    items = source if isinstance(source, (list, tuple)) else [source]
    names = [str(s.meta.get("source", "cloud")) if isinstance(s, Cloud) else str(s) for s in items]
    return ", ".join(names[:3]) + (f" (+{len(names) - 3} more)" if len(names) > 3 else "")


class _Selected(list):
    """Input files (or clouds) of a DEM with the reading options every pass over them applies:
    ``bounds`` (CRS units; a COPC file queried, a LAS/LAZ file filtered chunk by chunk) and the
    COPC ``resolution`` (CRS units) or ``level``."""

    def __init__(self, items, read_opts: dict):
        super().__init__(items)
        self.read_opts = read_opts


def _select(source, read_opts: dict | None):
    """``source`` with the reading options that are set (:class:`_Selected`), or as it is."""
    opts = {k: v for k, v in (read_opts or {}).items() if v is not None}
    if not opts:
        return source
    items = [source] if isinstance(source, (str, Path, Cloud)) else list(source)
    if any(isinstance(c, Cloud) for c in items) and set(opts) != {"bounds"}:
        raise InvalidInputError("resolution and level pick levels of a COPC file; a cloud in memory has none",
                                "give bounds alone", field="read_opts")
    return _Selected(items, opts)


def _iter_clouds(source, chunk_size: int) -> Iterator[Cloud]:
    if isinstance(source, Cloud):
        yield source
        return
    paths = [source] if isinstance(source, (str, Path)) else list(source)
    opts = getattr(source, "read_opts", {})
    from workstation.io import iter_chunks
    from workstation.io.registry import inside_bounds

    for p in paths:
        if isinstance(p, Cloud):
            yield inside_bounds(p, opts["bounds"]) if opts else p
        else:
            yield from iter_chunks(p, chunk_size, **opts)


def _noise_free(c: Cloud) -> np.ndarray:
    cls = c.get("classification")
    if cls is None:
        return np.ones(c.n, bool)
    return ~np.isin(cls, [int(k) for k in NOISE])


def _first_returns(c: Cloud) -> np.ndarray:
    rn = c.get("return_number")
    keep = _noise_free(c)
    return keep if rn is None else keep & (rn <= 1)


def _ground(c: Cloud, classes) -> np.ndarray:
    cls = c.get("classification")
    if cls is None:
        raise InvalidInputError(
            "the cloud has no classification, so ground points are unknown",
            "classify ground first (ws ground IN -o OUT) or build a DSM", field="classification",
        )
    return np.isin(cls, list(classes))


@dataclass(frozen=True)
class _Survey:
    bounds: tuple
    n_all: int
    n_first: int
    n_ground: int
    area: float
    crs: str | None
    vertical_rmse: float | None


def _header_survey(source) -> _Survey | None:
    """Bounds and CRS from LAS/LAZ headers alone (no point read), or None for other inputs."""
    if isinstance(source, Cloud):
        return None
    paths = [source] if isinstance(source, (str, Path)) else list(source)
    if not paths or not all(isinstance(p, (str, Path)) and Path(p).suffix.lower() in (".las", ".laz") for p in paths):
        return None
    from workstation.io.las import read_header

    heads = [read_header(p) for p in paths]
    lo = np.min([h["mins"] for h in heads], axis=0)
    hi = np.max([h["maxs"] for h in heads], axis=0)
    n = sum(h["point_count"] for h in heads)
    if n == 0:
        raise InvalidInputError("no points to grid", "check the input files")
    crs = next((h["crs"] for h in heads if h["crs"]), None)
    return _Survey((lo[0], lo[1], hi[0], hi[1]), n, 0, 0, 0.0, crs, None)


def _survey(source, params: DemParams, chunk_size: int, need_area: bool = True) -> _Survey:
    """One pass: bounds, counts and (``need_area``) occupied area (5 m coverage cells).

    When only the bounds are needed and the inputs are LAS/LAZ files, the headers suffice.
    """
    if not need_area:
        head = _header_survey(source)
        if head is not None:
            return head
    lo = np.full(3, np.inf)
    hi = np.full(3, -np.inf)
    n_all = n_first = n_ground = 0
    keys = np.empty(0, np.int64)
    crs = None
    vrmse = None
    cov = None
    for c in _iter_clouds(source, chunk_size):
        if c.n == 0:
            continue
        crs = crs or c.crs
        cov = cov or crs_units(crs).h_from_m(COVERAGE_CELL_M)
        vrmse = vrmse or c.meta.get("vertical_rmse")
        keep = _noise_free(c)
        xyz = c.xyz[keep]
        if len(xyz) == 0:
            continue
        lo = np.minimum(lo, xyz.min(0))
        hi = np.maximum(hi, xyz.max(0))
        n_all += len(xyz)
        if not need_area:
            continue
        n_first += int(_first_returns(c).sum())
        if c.get("classification") is not None:
            n_ground += int(np.isin(c.get("classification"), list(params.ground_classes)).sum())
        k = (np.floor(xyz[:, 0] / cov + TIE).astype(np.int64) << 32) + (np.floor(xyz[:, 1] / cov + TIE).astype(np.int64) + _KEY_BIAS)
        keys = np.union1d(keys, np.unique(k))
    if n_all == 0:
        raise InvalidInputError("no points (after removing noise classes) to grid", "check the input file")
    area = _occupied_area(keys, cov, (hi[0] - lo[0]) * (hi[1] - lo[1]), n_all) if need_area else 0.0
    return _Survey((lo[0], lo[1], hi[0], hi[1]), n_all, n_first, n_ground, area, crs, vrmse)


#: Coverage cells of the occupied-area estimate (metres), and the bias that keeps the packed
#: row key non-negative.
COVERAGE_CELL_M = 5.0
_KEY_BIAS = 1 << 31


def _occupied_area(keys: np.ndarray, cov: float, bbox_area: float, n: int) -> float:
    """Area (square CRS units) of the occupied coverage cells, on cells at least as large as the
    mean point spacing over the bounding box: on sparse data (a few thousand points over
    kilometres) every point would otherwise fill its own small cell, the spacing would come
    out as the coverage cell and the grid would be sized by the box, not by the points."""
    k = max(1, int(math.ceil(math.sqrt(max(bbox_area, 0.0) / max(n, 1)) / cov)))
    if k > 1:
        ix, iy = keys >> 32, keys & 0xFFFFFFFF
        keys = np.unique(((ix // k) << 32) + iy // k)
    return float(len(keys)) * (k * cov) ** 2


def nice_ceil(value: float) -> float:
    """Smallest round cell size (0.1, 0.2, 0.25, 0.5, 1, 2, 2.5, 5 ... m) ≥ value."""
    for v in NICE_CELLS:
        if v >= value - 1e-9:
            return v
    return float(math.ceil(value))


def auto_resolution(n_points: int, area: float, vertical_rmse: float | None = None) -> tuple[float, str]:
    """Cell size from the nominal point spacing and, when known, the vertical RMSE.

    Parameters
    ----------
    n_points : int
        Points that define the surface (ground points for a DTM, first returns for a DSM).
    area : float
        Area they cover in m².
    vertical_rmse : float, optional
        Vertical RMSE of the points in metres.

    Returns
    -------
    (float, str)
        The cell size in metres and the reason, in words.

    Examples
    --------
    >>> auto_resolution(1_000_000, 1_000_000)[0]     # 1 pt/m² -> NPS 1 m -> 1 m cells
    1.0
    >>> auto_resolution(8_000_000, 1_000_000, vertical_rmse=0.15)[0]  # NPS 0.35 m, 3×0.15 m
    0.5
    """
    if n_points <= 0 or area <= 0:
        raise InvalidInputError("cannot choose a cell size without points", "give --resolution")
    nps = math.sqrt(area / n_points)
    res = nice_ceil(nps)
    reason = f"nominal point spacing {nps:.2f} m ({n_points} points over {area:.0f} m²) -> cell ≥ NPS: {res:g} m"
    if vertical_rmse:
        acc = nice_ceil(3.0 * float(vertical_rmse))
        reason += f"; 3 × vertical RMSE {vertical_rmse:g} m = {3 * vertical_rmse:.2f} m -> {acc:g} m"
        if acc > res:
            res = acc
            reason += " (accuracy governs)"
        else:
            reason += " (point spacing governs)"
    return res, reason


# --------------------------------------------------------------------------- surfaces
def _tied(d: np.ndarray, ref: np.ndarray) -> np.ndarray:
    """Whether distances ``d`` (cells) equal ``ref`` within the tie band of
    :data:`~workstation.raster.grid.TIE` (relative, and absolute for distances near 0)."""
    return np.abs(d - ref) <= TIE * (ref + 1.0)


def _query_shells(tree, q: np.ndarray, k: int) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """The ``k`` nearest points of each query and every point tied (:func:`_tied`) with the
    k-th: ``[(rows, d, nb)]`` blocks, the first of the queries with no tie for the k-th place
    (``k`` columns), then blocks whose last column lies beyond the k-th distance (or that hold
    every point). On a lattice of points several are often equally far; which of them
    the k-d tree returns first follows the rounding of the coordinates, so the whole shell is
    kept and :func:`_shell_weights` shares it out."""
    n = tree.n
    kk = min(k + 1, n)
    d, nb = tree.query(q, k=kk)
    d, nb = d.reshape(len(q), kk), nb.reshape(len(q), kk)
    rows = np.arange(len(q))
    out = []
    while True:
        tie = _tied(d[:, -1], d[:, k - 1]) if kk > k else np.zeros(len(rows), bool)
        open_ = tie & (kk < n)
        done = ~open_
        if not out:  # the first query: those with no tie need their first k alone
            out.append((rows[~tie], d[~tie, :k], nb[~tie, :k]))
            done = tie & ~open_
        if done.any():
            out.append((rows[done], d[done], nb[done]))
        if not open_.any():
            return out
        rows, kk = rows[open_], min(2 * kk, n)
        d, nb = tree.query(q[rows], k=kk)
        d, nb = d.reshape(len(rows), kk), nb.reshape(len(rows), kk)


def _shell_weights(d: np.ndarray, k: int, w: np.ndarray) -> np.ndarray:
    """Weights ``w`` of the neighbours (columns, nearest first) with the k-th shell shared out:
    the points tied with the k-th distance fill the slots the closer ones leave, each with the
    fraction ``slots / shell size`` of its weight (the mean over every way of breaking the tie);
    farther points get 0."""
    kth = d[:, k - 1 : k]
    shell = _tied(d, kth)
    inner = (d < kth) & ~shell
    slots = k - inner.sum(1, keepdims=True)
    share = slots / np.maximum(shell.sum(1, keepdims=True), 1)
    return np.where(inner, w, np.where(shell, w * share, 0.0))


def _idw(du, dv, z, valid, cells: np.ndarray, k: int, power: float) -> np.ndarray:
    """Inverse-distance weighting of the ``k`` nearest representatives at the cell centres
    ``cells``; a tie for the k-th place is shared out (:func:`_shell_weights`)."""
    from scipy.spatial import cKDTree

    ii, jj = np.nonzero(valid)
    pts = np.column_stack([jj + du[ii, jj], ii + dv[ii, jj]])
    vals = z[ii, jj]
    qi, qj = np.nonzero(cells)
    out = np.full(z.shape, np.nan)
    if len(pts) == 0 or len(qi) == 0:
        return out
    k = min(k, len(pts))
    tree = cKDTree(pts)
    res = np.empty(len(qi))
    step = 1_000_000
    for s in range(0, len(qi), step):
        q = np.column_stack([qj[s : s + step], qi[s : s + step]]).astype(float)
        for rows, d, nb in _query_shells(tree, q, k):
            w = 1.0 / np.maximum(d, 1e-6) ** power
            w = w if d.shape[1] == k else _shell_weights(d, k, w)
            res[s + rows] = (w * vals[nb]).sum(1) / w.sum(1)
    out[qi, qj] = res
    return out


def _nearest_value(tree, q: np.ndarray, vals: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Distance to the nearest point of each query and its value; a query equally near several
    points (a Voronoi edge or corner, within the tie band) takes the mean of their values, so
    the choice does not follow the rounding of the coordinates."""
    d, val = np.empty(len(q)), np.empty(len(q))
    for rows, dd, nb in _query_shells(tree, q, 1):
        d[rows] = dd[:, 0]
        if dd.shape[1] == 1:
            val[rows] = vals[nb[:, 0]]
            continue
        tied = _tied(dd, dd[:, :1])
        val[rows] = np.where(tied, vals[nb], 0.0).sum(1) / tied.sum(1)
    return d, val


def _discrete_sibson(du, dv, z, valid, cells: np.ndarray, fallback: np.ndarray, max_radius: float) -> np.ndarray:
    """Discrete Sibson (natural-neighbour) interpolation of Park et al. (2006, IEEE TVCG 12(2)).

    Every cell takes the value of its nearest data point and scatters it to all cells within
    the distance to that point; a cell's value is the mean of what it receives. This equals
    Sibson's area-stealing weights in the limit of fine cells. Cells farther than
    ``max_radius`` cells from any point keep ``fallback`` (the TIN) and scatter only that far.
    """
    from scipy.spatial import cKDTree

    R, C = z.shape
    ii, jj = np.nonzero(valid)
    tree = cKDTree(np.column_stack([jj + du[ii, jj], ii + dv[ii, jj]]))
    qi, qj = np.nonzero(cells)
    d, val = _nearest_value(tree, np.column_stack([qj, qi]).astype(float), z[ii, jj])
    n = R * C
    flat = qi * C + qj
    total = np.bincount(flat, val, minlength=n)
    count = np.bincount(flat, minlength=n).astype(float)
    # a cell scatters to the offsets within its distance, those at the same distance included
    # (within the tie band): d on a lattice is often exactly an offset's length
    reach = max_radius + TIE * (max_radius + 1.0)
    far = d > reach
    order = np.argsort(-np.minimum(d + TIE * (d + 1.0), reach))
    ds = np.minimum(d + TIE * (d + 1.0), reach)[order]
    r = int(math.floor(ds[0])) if len(ds) else 0
    oi, oj = np.mgrid[-r : r + 1, -r : r + 1]
    L = np.hypot(oi, oj).ravel()
    keep = (L > 0) & (L <= r)
    offs = sorted(zip(L[keep], oi.ravel()[keep], oj.ravel()[keep]))
    bt, bv = [], []
    pending = 0
    for length, di, dj in offs:
        m = int(np.searchsorted(-ds, -length, side="right"))  # cells whose disc reaches this offset
        if m == 0:
            continue
        src = order[:m]
        ti, tj = qi[src] + di, qj[src] + dj
        ok = (ti >= 0) & (ti < R) & (tj >= 0) & (tj < C)
        bt.append(ti[ok] * C + tj[ok])
        bv.append(val[src][ok])
        pending += int(ok.sum())
        if pending > 4_000_000:
            t, v = np.concatenate(bt), np.concatenate(bv)
            total += np.bincount(t, v, minlength=n)
            count += np.bincount(t, minlength=n)
            bt, bv, pending = [], [], 0
    if bt:
        t, v = np.concatenate(bt), np.concatenate(bv)
        total += np.bincount(t, v, minlength=n)
        count += np.bincount(t, minlength=n)
    out = np.full(n, np.nan)
    out[flat] = total[flat] / count[flat]
    out = out.reshape(R, C)
    out[qi[far], qj[far]] = fallback[qi[far], qj[far]]
    return out


def _surface(acc, method: str, params: DemParams, res: float) -> np.ndarray:
    du, dv, z, valid = acc.reps()
    max_edge = None if params.max_edge is None else params.max_edge / res
    tin = tin_surface(du, dv, z, valid, max_edge, params.tile)
    if method == "idw":
        return _idw(du, dv, z, valid, np.isfinite(tin), params.idw_k, params.idw_power)
    if method == "nn":
        return _discrete_sibson(du, dv, z, valid, np.isfinite(tin), tin, params.nn_max_radius)
    return tin


def _highest(acc: _MaxAcc, params: DemParams, res: float) -> np.ndarray:
    du, dv, z, valid = acc.reps()
    out = np.where(valid, z, np.nan)
    max_edge = None if params.max_edge is None else params.max_edge / res
    return fill_voids_tin(out, du, dv, z, valid, max_edge)


def _snap01(f: np.ndarray) -> np.ndarray:
    """Fractions in [0, 1] with those within the tie band of 0 or 1 set to it exactly."""
    return np.where(f < TIE, 0.0, np.where(f > 1.0 - TIE, 1.0, f))


def _term(value: np.ndarray, weight: np.ndarray) -> np.ndarray:
    """``value * weight``, 0 where the weight is 0 (a missing value with no weight adds 0)."""
    return np.where(weight > 0, value * weight, 0.0)


def sample_bilinear(raster: Raster, x, y) -> np.ndarray:
    """Bilinear interpolation of a single-band raster at world points.

    Parameters
    ----------
    raster : Raster
        North-up, square cells; NaN (or ``nodata``) cells are missing.
    x, y : (n,) float
        World coordinates in the raster's CRS.

    Returns
    -------
    (n,) float64
        Values; NaN outside the grid of cell centres' hull or next to a missing cell (one
        with a weight above 0). Within half a cell of the outer edge the nearest edge cells
        are used (clamped).
    """
    a = np.asarray(raster.array, dtype=np.float64)
    if a.ndim == 3:
        a = a[0]
    if raster.nodata is not None and not np.isnan(raster.nodata):
        a = np.where(a == raster.nodata, np.nan, a)
    grid = GridSpec.from_transform(raster.transform, a.shape)
    u, v = grid.to_uv(np.asarray(x, float), np.asarray(y, float))
    R, C = a.shape
    out = np.full(u.shape, np.nan)
    inside = (u >= -0.5) & (u <= C - 0.5) & (v >= -0.5) & (v <= R - 0.5)
    uc = np.clip(u[inside], 0, C - 1)
    vc = np.clip(v[inside], 0, R - 1)
    j0 = np.minimum(np.floor(uc).astype(np.int64), max(C - 2, 0))
    i0 = np.minimum(np.floor(vc).astype(np.int64), max(R - 2, 0))
    j1 = np.minimum(j0 + 1, C - 1)
    i1 = np.minimum(i0 + 1, R - 1)
    # a point on a row or column of cell centres (within the tie band) uses that row or column
    # alone: a missing cell beyond it, with weight 0, leaves the value defined whichever side
    # the rounding of the coordinates puts the point
    fu = _snap01(uc - j0)
    fv = _snap01(vc - i0)
    with np.errstate(invalid="ignore"):
        val = (_term(a[i0, j0], (1 - fu) * (1 - fv)) + _term(a[i0, j1], fu * (1 - fv))
               + _term(a[i1, j0], (1 - fu) * fv) + _term(a[i1, j1], fu * fv))
    out[inside] = val
    return out


def height_above_ground(cloud: Cloud, dtm: Raster) -> Cloud:
    """A new cloud with ``hag`` = z − DTM(x, y) (bilinear), NaN where the DTM has no value.

    Use this when a DTM raster exists (fast, no triangulation); a TIN of ground points gives
    heights of the same quality when the DTM cell is about the ground point spacing.
    """
    t0 = time.perf_counter()
    ground = sample_bilinear(dtm, cloud.xyz[:, 0], cloud.xyz[:, 1])
    hag = (cloud.xyz[:, 2] - ground).astype(np.float32)
    missing = int(np.isnan(hag).sum())
    if missing == cloud.n and cloud.n:
        raise StageError("hag", "no point lies on the DTM", "check that the DTM covers the cloud and has the same CRS")
    if missing:
        log.warning("hag: %d of %d points are off the DTM (NaN)", missing, cloud.n)
    return cloud.with_attrs(hag=hag).with_history("hag", {"dtm": str(dtm.meta.get("source", "raster"))}, time.perf_counter() - t0)


#: Relative tie band of a height compared with a threshold: float64 elevations carry a rounding
#: of about 1e-16 x |z| per operation (1e-13 after gridding and bilinear sampling), and 1e-9 x
#: |z| (0.1 µm at 100 m) holds it with room to spare while real heights almost never fall in it.
_Z_TIE = 1e-9


def _pit_free(source, grid: GridSpec, dtm: np.ndarray, params: DemParams, chunk_size: int) -> np.ndarray:
    """Khosravipour et al. (2014) pit-free CHM from first returns normalised by ``dtm``."""
    dtm_r = Raster(dtm, grid.transform)
    ths = sorted(params.pit_free_thresholds)
    accs = [_MaxAcc(grid) for _ in ths]
    for c in _iter_clouds(source, chunk_size):
        keep = _first_returns(c)
        xyz = c.xyz[keep]
        if len(xyz) == 0:
            continue
        h = xyz[:, 2] - sample_bilinear(dtm_r, xyz[:, 0], xyz[:, 1])
        ok = np.isfinite(h)
        # a height at a threshold within the height tie band is in the layer (a point on the
        # DTM has h = 0 up to the rounding of its elevation)
        tol = _Z_TIE * np.abs(xyz[:, 2])
        for t, acc in zip(ths, accs):
            m = ok & (h >= t - tol)
            if m.any():
                acc.add(xyz[m, 0], xyz[m, 1], h[m])
    freeze = (params.pit_free_max_edge / grid.res) if params.pit_free_max_edge else 3.0
    chm = np.full(grid.shape, np.nan)
    for k, acc in enumerate(accs):
        du, dv, z, valid = acc.reps()
        if not valid.any():
            break
        layer = tin_surface(du, dv, z, valid, None if k == 0 else freeze, params.tile)
        chm = np.fmax(chm, layer)
    return np.maximum(chm, 0.0)


_REC = np.dtype([("x", "f8"), ("y", "f8"), ("z", "f8"), ("cls", "u1"), ("rn", "u1")])


def _build_tiled(source, params: DemParams, grid: GridSpec, method: str, chunk_size: int, tile: int,
                 buffer: int) -> tuple[np.ndarray, int]:
    """Out-of-core gridding: points are spilled to one temporary file per tile (with a
    ``buffer``-cell overlap) in a single streaming pass, then each tile is gridded on its own
    and its core written into the output. Memory: one tile's points and grids, plus the
    float32 output. The TIN of a cell depends on its neighbourhood only (lattice) and on the
    rims of the voids around it, so tiles agree with the untiled result wherever voids are
    smaller than the buffer."""
    import tempfile

    tiles = [(r0, min(r0 + tile, grid.rows), c0, min(c0 + tile, grid.cols))
             for r0 in range(0, grid.rows, tile) for c0 in range(0, grid.cols, tile)]
    out = np.full(grid.shape, np.nan, np.float32)
    n_used = 0
    has_cls = has_rn = False
    with tempfile.TemporaryDirectory(prefix="ws_dem_tiles_") as tmp:
        files = [Path(tmp) / f"t{k}.bin" for k in range(len(tiles))]
        for c in _iter_clouds(source, chunk_size):
            if c.n == 0:
                continue
            keep = _noise_free(c)
            cls_a, rn_a = c.get("classification"), c.get("return_number")
            has_cls |= cls_a is not None
            has_rn |= rn_a is not None
            rec = np.empty(int(keep.sum()), _REC)
            xyz = c.xyz[keep]
            rec["x"], rec["y"], rec["z"] = xyz[:, 0], xyz[:, 1], xyz[:, 2]
            rec["cls"] = cls_a[keep] if cls_a is not None else 0
            rec["rn"] = rn_a[keep] if rn_a is not None else 1
            row, col, inside = _cell_index(grid, rec["x"], rec["y"])
            n_used += int((_used(c, params, method)[keep] & inside).sum())  # each point once, not per tile
            for k, (r0, r1, c0, c1) in enumerate(tiles):
                m = inside & (row >= r0 - buffer) & (row < r1 + buffer) & (col >= c0 - buffer) & (col < c1 + buffer)
                if m.any():
                    with open(files[k], "ab") as f:
                        rec[m].tofile(f)
        for k, (r0, r1, c0, c1) in enumerate(tiles):
            if not files[k].exists():
                continue
            rec = np.fromfile(files[k], _REC)
            files[k].unlink()
            attrs = {}
            if has_cls:
                attrs["classification"] = rec["cls"]
            if has_rn:
                attrs["return_number"] = rec["rn"]
            ra, rb = max(r0 - buffer, 0), min(r1 + buffer, grid.rows)
            ca, cb = max(c0 - buffer, 0), min(c1 + buffer, grid.cols)
            sub = GridSpec(grid.x0 + ca * grid.res, grid.y1 - ra * grid.res, grid.res, rb - ra, cb - ca)
            cloud = Cloud(np.column_stack([rec["x"], rec["y"], rec["z"]]), attrs)
            try:
                r = build_dem(cloud, params, chunk_size=chunk_size, grid=sub, tile_cells=0)
            except StageError:
                continue  # no ground or no valid cell in this tile: it stays nodata
            out[r0:r1, c0:c1] = r.array[r0 - ra : r1 - ra, c0 - ca : c1 - ca]
    if (params.kind in ("dtm", "chm")) and not has_cls:
        raise InvalidInputError(
            "the cloud has no classification, so ground points are unknown",
            "classify ground first (ws ground IN -o OUT) or build a DSM", field="classification",
        )
    return out, n_used


def _in_crs_units(params: DemParams, units) -> DemParams:
    """The lengths of ``params`` (metres) in CRS units, as the gridding code uses them: max edge
    and freeze distance horizontally, pit-free layers vertically."""
    from dataclasses import replace

    def h(x):
        return None if x is None else units.h_from_m(x)

    return replace(params, max_edge=h(params.max_edge), pit_free_max_edge=h(params.pit_free_max_edge),
                   pit_free_thresholds=tuple(units.v_from_m(t) for t in params.pit_free_thresholds))


def _box_grid(box, res: float) -> GridSpec:
    """The grid of a ``--bounds`` box (CRS units): its edges snapped outward to multiples of the
    cell ``res`` (CRS units), so its cells are cells of the whole DEM's grid (also aligned to
    multiples) and a box already on multiples is the grid exactly (as ``gdalwarp -te``)."""
    eps = 1e-9
    c0, r0 = math.floor(box[0] / res + eps), math.floor(box[1] / res + eps)
    c1, r1 = max(math.ceil(box[2] / res - eps), c0 + 1), max(math.ceil(box[3] / res - eps), r0 + 1)
    return GridSpec(c0 * res, r1 * res, res, r1 - r0, c1 - c0)


def _read_meta(source) -> dict:
    """``{"read": {...}}``: the reading options (bounds, COPC resolution/level) a DEM was built with."""
    opts = getattr(source, "read_opts", None)
    return {"read": {k: list(v) if k == "bounds" else v for k, v in opts.items()}} if opts else {}


def _unit_meta(res: float, res_m: float, units) -> dict:
    """Raster meta saying what the numbers mean: ``resolution`` is the cell in CRS units
    (``resolution_unit``), ``resolution_m`` the same in metres, ``units`` the CRS units (the
    raster's values are heights in ``units['vertical']``)."""
    return {"resolution": float(res), "resolution_unit": units.h_name, "resolution_m": float(res_m),
            "z_unit": units.v_name, "units": units.to_dict()}


def _resolution(grid: GridSpec | None, params: DemParams, survey: _Survey | None, units,
                vrmse) -> tuple[float, float, str]:
    """The cell size as ``(res, res_m, reason)``: in CRS units, in metres, and why it was chosen.

    A given grid fixes the cell; otherwise a given ``params.resolution`` (metres) is used;
    otherwise :func:`auto_resolution` derives it from the point density of the points the
    product uses (ground points for a DTM, first returns for a DSM/CHM) and the vertical RMSE.
    """
    if grid is not None:
        return grid.res, units.h_to_m(grid.res), "given grid"
    if params.resolution is None:
        n = survey.n_ground if params.kind == "dtm" else (survey.n_first or survey.n_all)
        if n == 0:
            raise InvalidInputError("no ground points to choose a cell size from", "classify ground first or give --resolution")
        res_m, reason = auto_resolution(n, units.area_to_m2(survey.area), vrmse)
        log.info("resolution %s: %s", units.describe_h(res_m), reason)
        return units.h_from_m(res_m), res_m, reason
    res_m = float(params.resolution)
    return units.h_from_m(res_m), res_m, "given"


def _accumulate(source, params: DemParams, grid: GridSpec, method: str, chunk_size: int, crs):
    """One streaming pass reducing every chunk into per-cell accumulators.

    Ground points (DTM, CHM) go into a :class:`_MeanAcc` (cell centroids); the top surface
    (DSM, CHM unless pit-free) into a :class:`_MaxAcc` of first returns (``method="tin"``) or of
    all non-noise returns (``"highest"``). Returns ``(ground_acc, top_acc, n_used, crs)``; an
    accumulator is ``None`` when the product does not need it, ``n_used`` counts the ground
    points, or the top points when there is no ground, and ``crs`` falls back to the chunks'.
    """
    kind = params.kind
    need_ground = kind in ("dtm", "chm")
    need_top = kind in ("dsm", "chm") and not (kind == "chm" and params.pit_free)
    top_first = method == "tin"
    gacc = _MeanAcc(grid) if need_ground else None
    tacc = _MaxAcc(grid) if need_top else None
    n_used = 0
    for c in _iter_clouds(source, chunk_size):
        if c.n == 0:
            continue
        crs = crs or c.crs
        if gacc is not None:
            g = _ground(c, params.ground_classes)
            gacc.add(c.xyz[g, 0], c.xyz[g, 1], c.xyz[g, 2])
        if tacc is not None:
            m = _first_returns(c) if top_first else _noise_free(c)
            tacc.add(c.xyz[m, 0], c.xyz[m, 1], c.xyz[m, 2])
        n_used += int(_used(c, params, method).sum())
    return gacc, tacc, n_used, crs


def _used(c: Cloud, params: DemParams, method: str) -> np.ndarray:
    """The points a DEM counts as used (``meta["points"]``): the ground points of a DTM or CHM,
    else the top surface's (first returns for ``method="tin"``, all non-noise returns else)."""
    if params.kind in ("dtm", "chm"):
        return _ground(c, params.ground_classes)
    return _first_returns(c) if method == "tin" else _noise_free(c)


def _kind_surface(source, params: DemParams, grid: GridSpec, method: str, res: float, gacc, tacc,
                  chunk_size: int) -> np.ndarray:
    """The product's float64 surface from the accumulators: the DTM interpolated from ground
    centroids, the DSM as cell maxima (``highest``) or a TIN of them, and the CHM as DSM − DTM
    clipped at 0, or the pit-free CHM (a second pass over ``source``)."""
    kind = params.kind
    if kind == "dtm":
        return _surface(gacc, method, params, res)
    if kind == "dsm":
        return _highest(tacc, params, res) if method == "highest" else _surface(tacc, "tin", params, res)
    dtm = _surface(gacc, "tin", params, res)
    if params.pit_free:
        return _pit_free(source, grid, dtm, params, chunk_size)
    dsm = _highest(tacc, params, res) if method == "highest" else _surface(tacc, "tin", params, res)
    return np.maximum(dsm - dtm, 0.0)


def _build_in_memory(source, params: DemParams, grid: GridSpec, method: str, res: float, chunk_size: int,
                     box, crs) -> tuple[np.ndarray, int, object]:
    """In-memory gridding: accumulate the whole input (:func:`_accumulate`), check that there is
    something to grid (points inside ``box``, ground points for a DTM/CHM), then interpolate the
    product (:func:`_kind_surface`). Returns ``(float64 surface, points used, crs)``."""
    gacc, tacc, n_used, crs = _accumulate(source, params, grid, method, chunk_size, crs)
    if box is not None and n_used == 0:
        raise InvalidInputError(f"no points to grid inside --bounds {','.join(f'{v:g}' for v in box)}",
                                "compare the box with the files' bounds (ws info --summary FILE)", field="--bounds")
    if gacc is not None and not (gacc.count > 0).any():
        raise StageError("dem", "no ground points in the input", "classify ground first (ws ground) or check --ground-classes")
    return _kind_surface(source, params, grid, method, res, gacc, tacc, chunk_size), n_used, crs


def build_dem(source, params: DemParams = DemParams(), *, chunk_size: int = 2_000_000, grid: GridSpec | None = None,
              tile_cells: int = 4096, buffer_cells: int = 128, read_opts: dict | None = None) -> Raster:
    """Grid a DSM, DTM or CHM from a cloud, a file or several files (one mosaic).

    Parameters
    ----------
    source : Cloud, path or sequence of paths/clouds
        Files are streamed in chunks of ``chunk_size`` points.
    params : DemParams
    grid : GridSpec, optional
        Output grid; default: aligned to multiples of the cell size over the data bounds.
    tile_cells : int
        File inputs whose grid has more than ``tile_cells``² cells are gridded out of core by
        tiles of that many cells a side, overlapping by ``buffer_cells`` (0: never tile).
    buffer_cells : int
        Overlap of the tiles in cells; voids (buildings, lakes) narrower than this are filled
        exactly as in a single pass.
    read_opts : dict, optional
        ``bounds`` (xmin, ymin, xmax, ymax[, zmin, zmax], CRS units, inclusive): only the points
        inside are read, and the grid covers the box (aligned to multiples of the cell, as a
        whole DEM's cells are, so the two agree cell for cell away from the box's edges);
        ``resolution`` (CRS units) / ``level``: a COPC file's levels of detail (see
        :func:`workstation.io.read_cloud`).

    Returns
    -------
    Raster
        float32 array, NaN (nodata -9999) where there is no surface; ``meta`` has ``kind``,
        ``method``, ``resolution``, ``resolution_reason``, ``vertical_rmse``, ``points``.

    Raises
    ------
    InvalidInputError
        No points, or no classification for a DTM.
    StageError
        The result has no valid cell.
    """
    t0 = time.perf_counter()
    source = _select(source, read_opts)
    box = getattr(source, "read_opts", {}).get("bounds")
    kind = params.kind
    method = params.method or ("tin" if kind == "dtm" else "highest")
    survey = None
    if grid is None or params.resolution is None:
        survey = _survey(source, params, chunk_size, need_area=grid is None and params.resolution is None)
    vrmse = params.vertical_rmse or (survey.vertical_rmse if survey else None)
    crs = survey.crs if survey else (source.crs if isinstance(source, Cloud) else None)
    units = crs_units(crs)
    res, res_m, reason = _resolution(grid, params, survey, units, vrmse)
    if grid is None:
        grid = _box_grid(box, res) if box is not None else _bounds_grid(*survey.bounds, res)
    tiled = bool(tile_cells) and not isinstance(source, Cloud) and grid.rows * grid.cols > tile_cells * tile_cells
    # out of core only the float32 result spans the grid; in memory the per-cell accumulators too;
    # a grid is sized by its points too (CELLS_PER_POINT), never by a bounding box alone
    check_grid(grid.rows, grid.cols, what=f"the {kind} grid", option="--resolution", cell=units.h_to_m(res),
               bytes_per_cell=4 if tiled else _BYTES_PER_CELL, path=_names(source),
               n_points=survey.n_all if survey else None)
    user_params, params = params, _in_crs_units(params, units)
    if tiled:
        arr, n_used = _build_tiled(source, params, grid, method, chunk_size, tile_cells, buffer_cells)
        extra = {"tiles": f"{tile_cells} cells + {buffer_cells} overlap"}
    else:
        arr, n_used, crs = _build_in_memory(source, params, grid, method, res, chunk_size, box, crs)
        extra = {}
    if not np.isfinite(arr).any():
        raise StageError("dem", f"{_names(source)}: the {kind} has no valid cell", "check the input extent and resolution")
    meta = {
        "kind": kind, "method": "pit_free" if (kind == "chm" and params.pit_free) else method,
        **_unit_meta(res, res_m, units), "resolution_reason": reason, "points": n_used, **extra,
        "seconds": round(time.perf_counter() - t0, 3),
        "params": {k: v for k, v in asdict(user_params).items() if v is not None},
        **_read_meta(source),
    }
    if vrmse:
        meta["vertical_rmse"] = float(vrmse)
    return Raster(arr if tiled else arr.astype(np.float32), grid.transform, crs, -9999.0, meta)


def dem_from_arrays(xyz: np.ndarray, classification: np.ndarray | None = None, **kw) -> Raster:
    """Convenience: :func:`build_dem` on a bare (n, 3) array (and classes)."""
    attrs = {} if classification is None else {"classification": classification}
    return build_dem(Cloud(np.asarray(xyz, float), attrs), DemParams(**kw))


__all__ = [
    "DemParams", "build_dem", "auto_resolution", "sample_bilinear", "height_above_ground", "nice_ceil",
    "dem_from_arrays", "GridSpec",
]

