r"""Swath separation (interswath DZ) and intraswath precision on smooth surfaces.

The relative vertical accuracy of the USGS Lidar Base Specification (LBS 2024, v2.x,
"Relative vertical accuracy"; the same within-swath and swath-to-swath measures appear in the
ASPRS Positional Accuracy Standards, 2014 and Edition 2 (2023)) is measured on *smooth*, open
surfaces with single returns:

* **intraswath** (smooth-surface precision): how tightly one swath's points lie on the
  surface;
* **interswath** (swath separation): the height difference DZ between overlapping swaths on
  the same smooth surface, summarised per pair as RMSDz (the root mean square of DZ, bias
  included) and the largest :math:`|DZ|`, and shown as a colour-coded "DZ ortho" at a cell of
  2 × ANPS.

Method (a swath is a point source id: LAS 1.4 R15 gives each point the id of the flight line
it was collected on; the same id in several files is the same swath):

1. Single returns (``number_of_returns == 1``) that are not withheld nor noise (classes 7, 18)
   are binned into the delivery's :class:`~workstation.qc.context.QCGrid`. Per occupied
   (swath, cell) pair the plane-fit sums :math:`n, \Sigma x, \Sigma y, \Sigma z, \Sigma x^2,
   \Sigma xy, \Sigma y^2, \Sigma xz, \Sigma yz, \Sigma z^2` are accumulated with x, y relative to
   the cell centre and z relative to one reference height, all in metres. The pairs are kept
   as sorted sparse keys, merged log-structured (a chunk's pairs are merged into the total when
   the pending ones outnumber it), so memory follows the occupied (swath, cell) pairs — about
   the overlap factor times the occupied cells — and the cost per point is amortised
   :math:`O(\log)`; a dense grid per swath would cost swaths × cells.
2. A 2 × ANPS cell holds at most about four points of one swath, too few for a plane, so
   each cell's plane is fitted to the sums of the ``window`` × ``window`` cells around it
   (sums shifted to the centre cell's origin exactly), by least squares :math:`z = a x + b y + c`
   ("fit a least squares plane, take perpendicular distances, compute the deviation").
3. The cell is smooth for that swath when the fit is well posed (≥ ``min_points`` points,
   spread over the window), its slope is at most ``max_slope_deg`` and its residual RMS,
   measured perpendicular to the plane with n − 3 degrees of freedom, is at most the
   roughness limit (see :class:`SwathParams`).
4. DZ of a pair (a < b) in a cell smooth in both = :math:`c_b - c_a`, the difference of the
   two planes at the cell centre (positive: b above a). RMSDz = :math:`\sqrt{\overline{DZ^2}}`.
5. Intraswath precision of a swath = the median (and 95th percentile) of the residual RMS of
   its smooth cells' planes. Being measured on cells chosen by that same RMS, it cannot show
   a swath noisier than the roughness limit; such a swath shows instead as rough on most of
   the cells that another swath finds smooth (``rough_where_others_smooth``).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.classes import NOISE
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError

from .context import Finding, QCGrid

#: Columns of the plane-fit sums, in this order.
SUMS = ("n", "x", "y", "z", "xx", "xy", "yy", "xz", "yz", "zz")
#: Colours of the DZ ortho (RGB): within the RMSDz limit, within the max-difference limit, beyond.
GREEN, YELLOW, RED = (0, 176, 80), (255, 220, 0), (220, 0, 0)
_SID = 1 << 16  # point source ids are u16


@dataclass(frozen=True)
class SwathParams:
    """Parameters of the swath-overlap and precision check; every length in metres.

    Attributes
    ----------
    window : int
        Cells a side (odd) of the square window each cell's plane is fitted over. Default 3:
        a 2 × ANPS cell holds about four points of the delivery, two to four of one swath, so
        a 3 × 3 window holds some 18 to 36.
    min_points : int
        Single returns of one swath in the window for a plane. Default 10.
    max_slope_deg : float
        Steepest plane that counts as smooth (degrees). Default 10: swath separation is
        measured on flat, open terrain (the LBS and ASPRS guidance: slopes under about 10°),
        where a horizontal offset h between the swaths moves DZ by at most h·tan 10° = 0.18 h.
    roughness_m : float or None
        Largest residual RMS (m, perpendicular to the plane) of a smooth surface. Default None:
        the intraswath precision limit ``precision_limit_m``. A surface whose scatter about its
        plane exceeds the whole height spread the specification allows a swath on a smooth
        surface is not the smooth surface the measure is defined on (vegetation, edges,
        objects), so it is not used for DZ.
    min_pair_windows : int
        A pair needs DZ in at least this many independent windows (``min_pair_windows`` ×
        ``window``² cells); fewer are reported but flagged. Default 10.
    rmsdz_limit_m, max_dz_limit_m : float
        Interswath limits: RMSDz and largest |DZ| (m). Defaults 0.08 and 0.16 (LBS 2024
        quality level QL2); also the colour breaks of ``dz.tif``.
    precision_limit_m : float
        Intraswath smooth-surface precision limit (m). Default 0.06 (LBS QL1/QL2). The LBS
        states it as the largest difference on a smooth surface; here it bounds the residual
        RMS of the planes (median and 95th percentile), a more lenient reading.
    """

    window: int = 3
    min_points: int = 10
    max_slope_deg: float = 10.0
    roughness_m: float | None = None
    min_pair_windows: int = 10
    rmsdz_limit_m: float = 0.08
    max_dz_limit_m: float = 0.16
    precision_limit_m: float = 0.06

    def __post_init__(self):
        if self.window < 1 or self.window % 2 == 0:
            raise InvalidInputError(f"window must be an odd number of cells >= 1, got {self.window}", field="window")
        if self.min_points < 4:
            raise InvalidInputError("min_points must be at least 4 (a plane has 3 unknowns)", field="min_points")
        for name in ("max_slope_deg", "rmsdz_limit_m", "max_dz_limit_m", "precision_limit_m", "roughness_m"):
            v = getattr(self, name)
            if v is not None and not (np.isfinite(v) and v > 0):
                raise InvalidInputError(f"{name} must be a positive number, got {v}", field=name)
        if not 0 < self.max_slope_deg < 90:
            raise InvalidInputError("max_slope_deg must be in (0, 90)", field="max_slope_deg")

    @property
    def roughness(self) -> float:
        """The roughness limit in metres."""
        return self.precision_limit_m if self.roughness_m is None else self.roughness_m


class _SparseSums:
    """Sums per sorted int64 key, merged log-structured: chunks wait in a list and join the
    total when they outnumber it, so each entry is re-sorted O(log chunks) times."""

    def __init__(self, width: int, min_merge: int = 1 << 18):
        self.min_merge = min_merge
        self.keys = np.empty(0, np.int64)
        self.sums = np.empty((width, 0))  # one contiguous row per sum
        self._pending: list[tuple[np.ndarray, np.ndarray]] = []
        self._n_pending = 0

    def add(self, keys: np.ndarray, sums: np.ndarray) -> None:
        self._pending.append((keys, sums))
        self._n_pending += keys.size
        if self._n_pending > max(self.keys.size, self.min_merge):
            self.merge()

    def merge(self) -> None:
        if not self._pending:
            return
        keys = np.concatenate([self.keys, *(k for k, _ in self._pending)])
        sums = np.concatenate([self.sums, *(s for _, s in self._pending)], axis=1)
        self._pending, self._n_pending = [], 0
        order = np.argsort(keys, kind="stable")
        keys = keys[order]
        start = np.flatnonzero(np.r_[True, keys[1:] != keys[:-1]])
        self.keys, self.sums = keys[start], np.add.reduceat(sums[:, order], start, axis=1)


class SwathPass:
    """Pass-2 check: interswath DZ per overlapping pair and intraswath precision per swath.

    Parameters
    ----------
    grid : QCGrid
        The delivery grid, cell 2 × ANPS (the DZ ortho's cell).
    params : SwathParams
    z0 : float, optional
        The reference height the z sums are taken from (CRS vertical units); default the median
        of the first chunk. Parts of one delivery checked apart share one, so that their sums add.

    Examples
    --------
    >>> from workstation.core.units import METRES
    >>> rng = np.random.default_rng(0)
    >>> xy = rng.uniform(0, 40, (20000, 2))
    >>> sid = np.where(rng.random(20000) < 0.5, 1, 2).astype(np.uint16)
    >>> z = 100 + 0.05 * (sid == 2) + rng.normal(0, 0.01, 20000)
    >>> c = Cloud(np.column_stack([xy, z]), {"point_source_id": sid, "number_of_returns": np.ones(20000, np.uint8)})
    >>> p = SwathPass(QCGrid.over((0, 0, 40, 40), 1.0, METRES))
    >>> p.add(c, "a.laz")
    >>> pair = p.result()["swaths"][0]
    >>> (pair["a"], pair["b"], round(pair["mean_dz"], 2), round(pair["rmsdz"], 2))
    (1, 2, 0.05, 0.05)
    """

    check = "swath"

    def __init__(self, grid: QCGrid, params: SwathParams = SwathParams(), z0: float | None = None):
        self.grid, self.params = grid, params
        self._ncells = grid.rows * grid.cols
        if self._ncells * _SID >= 2**63:
            raise InvalidInputError(f"a {grid.rows} x {grid.cols} grid is too large to key per swath",
                                    "use a larger QC cell", field="cell")
        self._sums = _SparseSums(len(SUMS))
        self._z0: float | None = z0
        self._points = 0
        self._no_source: set[str] = set()
        self._no_returns: set[str] = set()
        self._final: dict | None = None

    def add(self, chunk: Cloud, source=None) -> None:
        """Add the plane-fit sums of ``chunk``'s usable single returns per (swath, cell)."""
        self._final = None
        keep = self._usable(chunk, str(source))
        xyz = chunk.xyz[keep]
        flat, inside = self.grid.flat(xyz[:, :2])
        xyz, flat = xyz[inside], flat[inside]
        if flat.size == 0:
            return
        sid = chunk.attrs["point_source_id"][keep][inside] if "point_source_id" in chunk.attrs else np.zeros(flat.size)
        if self._z0 is None:
            self._z0 = float(np.median(xyz[:, 2]))
        g, u = self.grid, self.grid.units
        row, col = np.divmod(flat, g.cols)
        x = u.h_to_m(xyz[:, 0] - (g.x0 + (col + 0.5) * g.cell))
        y = u.h_to_m(xyz[:, 1] - (g.y1 - (row + 0.5) * g.cell))
        z = u.v_to_m(xyz[:, 2] - self._z0)
        key = sid.astype(np.int64) * self._ncells + flat
        order = np.argsort(key, kind="stable")
        key = key[order]
        start = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
        x, y, z = x[order], y[order], z[order]
        cols = (np.ones_like(x), x, y, z, x * x, x * y, y * y, x * z, y * z, z * z)
        sums = np.empty((len(SUMS), start.size))
        for i, v in enumerate(cols):
            sums[i] = np.add.reduceat(v, start)
        self._sums.add(key[start], sums)
        self._points += flat.size

    def _usable(self, chunk: Cloud, source: str) -> np.ndarray:
        """Single returns, not withheld, not noise; notes files without return counts or ids."""
        a = chunk.attrs
        keep = np.ones(chunk.n, bool)
        if "number_of_returns" in a:
            keep &= a["number_of_returns"] == 1
        else:
            self._no_returns.add(source)
        if "withheld" in a:
            keep &= a["withheld"] == 0
        if "classification" in a:
            keep &= ~np.isin(a["classification"], np.asarray(NOISE, np.uint8))
        if "point_source_id" not in a:
            self._no_source.add(source)
        return keep

    def _evaluate(self) -> dict:
        """Planes, smooth cells, DZ per pair and precision per swath (cached until ``add``)."""
        if self._final is None:
            self._sums.merge()
            self._final = merge_fits([fit_state(self._sums.keys, self._sums.sums, self.grid, self.params)],
                                     self.params)
        return self._final

    def sums(self) -> tuple[np.ndarray, np.ndarray]:
        """The merged (swath, cell) keys (sorted, int64) and their plane-fit sums (10, k)."""
        self._sums.merge()
        return self._sums.keys, self._sums.sums

    def state(self) -> dict:
        """What :meth:`from_fits` needs besides the fits: points used, files without ids or counts."""
        return {"points": int(self._points), "no_source": sorted(self._no_source),
                "no_returns": sorted(self._no_returns)}

    @classmethod
    def from_fits(cls, grid: QCGrid, params: SwathParams, fits: list[dict], states: list[dict]) -> "SwathPass":
        """The check of a whole delivery from :func:`fit_state` of disjoint sets of cells and the
        :meth:`state` of every part: its results, findings and maps are those of one pass over
        all the points (sums of floating values aside, added in another order)."""
        sw = cls(grid, params)
        sw._final = merge_fits(fits, params)
        sw._points = sum(int(s["points"]) for s in states)
        sw._no_source = {f for s in states for f in s["no_source"]}
        sw._no_returns = {f for s in states for f in s["no_returns"]}
        return sw

    def result(self) -> dict:
        """JSON-ready figures, every length in metres.

        Returns
        -------
        dict
            ``cell_m`` (DZ cell), ``window_cells``, ``points_used`` (single returns binned),
            ``swath_ids``, ``swaths`` (one dict per overlapping pair sorted by (a, b): ``a``,
            ``b``, ``rmsdz``, ``mean_dz`` (plane of b minus plane of a, m), ``max_abs_dz``,
            ``cells`` (2 × ANPS cells with DZ), ``enough_cells``), ``intraswath`` (per swath:
            ``id``, ``precision_m`` (median residual RMS), ``p95_m``, ``cells`` (smooth
            cells), ``fitted_cells``, ``cells_where_others_smooth`` (its flat cells in which
            another swath is smooth) and ``rough_where_others_smooth`` (the share of those
            rough in this swath: high for a noisy swath; None without overlap)),
            ``rmsdz_all`` (pooled over every pair's cells; None without overlap), ``limits``
            (the parameters' limits, m and degrees).
        """
        f, p = self._evaluate(), self.params
        return {
            "cell_m": self.grid.cell_m, "window_cells": p.window, "points_used": int(self._points),
            "swath_ids": [int(i) for i in f["ids"]], "swaths": f["pairs"], "intraswath": f["intraswath"],
            "rmsdz_all": float(np.sqrt(f["sum_dz2"] / f["n_dz"])) if f["n_dz"] else None,
            "limits": {"rmsdz_m": p.rmsdz_limit_m, "max_dz_m": p.max_dz_limit_m, "precision_m": p.precision_limit_m,
                       "roughness_m": p.roughness, "max_slope_deg": p.max_slope_deg,
                       "min_pair_cells": p.min_pair_windows * p.window ** 2},
        }

    def findings(self) -> list[Finding]:
        """Pairs beyond the RMSDz (error) or max |DZ| limits (warning), pairs with too few cells,
        swaths less precise than the limit, and what made the check impossible."""
        out = [Finding("swath", "warning", f, "point_source_id", "flight line ids", "absent",
                       "no point source ids: every point counts as one swath, so no swath overlap is measured")
               for f in sorted(self._no_source)]
        out += [Finding("swath", "warning", f, "number_of_returns", "return counts", "absent",
                        "no return counts: all returns are used, vegetation may inflate DZ")
                for f in sorted(self._no_returns)]
        r, p = self.result(), self.params
        if not r["swaths"]:
            out.append(Finding("swath", "info", None, "swath_overlap", "overlapping swaths on smooth surfaces",
                               f"{len(r['swath_ids'])} swath(s), no common smooth cells",
                               "interswath DZ could not be measured"))
        for s in r["swaths"]:
            out += _pair_findings(s, p)
        for s in r["intraswath"]:
            out += _precision_findings(s, p)
        return out

    def write(self, out_dir: Path, crs) -> dict[str, Path]:
        """``dz.tif`` (RGB DZ ortho: green |DZ| <= RMSDz limit, yellow <= max-difference limit,
        red beyond, black without DZ) and ``dz_values.tif`` (float32 max |DZ| over the pairs
        of each cell in metres, NaN where none)."""
        from workstation.core.products import Raster
        from workstation.io.geotiff import write_raster

        f, g, p = self._evaluate(), self.grid, self.params
        cells, vals = f["dz"]
        dz = np.full(g.rows * g.cols, np.nan, np.float32)
        dz[cells] = vals
        dz = dz.reshape(g.shape)
        rgb = np.zeros((3, *g.shape), np.uint8)
        for colour, sel in ((GREEN, dz <= p.rmsdz_limit_m), (YELLOW, (dz > p.rmsdz_limit_m) & (dz <= p.max_dz_limit_m)),
                            (RED, dz > p.max_dz_limit_m)):
            rgb[:, sel] = np.asarray(colour, np.uint8)[:, None]
        out_dir = Path(out_dir)
        out_dir.mkdir(parents=True, exist_ok=True)
        t = tuple(g.transform())[:6]
        meta = {"kind": "swath DZ", "unit": "metre", "limits_m": [p.rmsdz_limit_m, p.max_dz_limit_m]}
        rgb_path = write_raster(Raster(rgb, t, crs, meta=meta), out_dir / "dz.tif", overwrite=True, photometric="RGB")
        val_path = write_raster(Raster(dz, t, crs, nodata=float("nan"), meta=meta), out_dir / "dz_values.tif",
                                overwrite=True)
        return {"dz": rgb_path, "dz_values": val_path}


def _precision_findings(s: dict, p: SwathParams) -> list[Finding]:
    """A swath rough on most surfaces that other swaths find smooth, or whose smooth cells
    scatter beyond the precision limit (possible when ``roughness_m`` exceeds it)."""
    what, lim = f"swath {s['id']} precision", f"<= {p.precision_limit_m:g} m"
    share, checked = s["rough_where_others_smooth"], s["cells_where_others_smooth"]
    out = []
    if share is not None and checked >= p.min_pair_windows * p.window ** 2 and share > 0.5:
        out.append(Finding("swath", "warning", None, what, lim, f"rough on {share:.0%} of {checked} smooth cells",
                           f"swath {s['id']} scatters more than {p.roughness:g} m about planes that other swaths "
                           "fit within it: a noisy swath"))
    if s["cells"] and s["p95_m"] > p.precision_limit_m:
        out.append(Finding("swath", "warning", None, what, lim, f"p95 {s['p95_m']:.3f} m",
                           f"swath {s['id']}: 5 % of its smooth cells scatter more than the limit about their plane"))
    return out


def _pair_findings(s: dict, p: SwathParams) -> list[Finding]:
    what = f"swaths {s['a']}-{s['b']}"
    if not s["enough_cells"]:
        return [Finding("swath", "info", None, f"{what} DZ", f">= {p.min_pair_windows * p.window ** 2} cells",
                        f"{s['cells']} cells", f"{what}: too little common smooth surface for a reliable RMSDz")]
    out = []
    if s["rmsdz"] > p.rmsdz_limit_m:
        out.append(Finding("swath", "error", None, f"{what} RMSDz", f"<= {p.rmsdz_limit_m:g} m", f"{s['rmsdz']:.3f} m",
                           f"{what} are vertically {s['mean_dz']:+.3f} m apart on average (b minus a)"))
    if s["max_abs_dz"] > p.max_dz_limit_m:
        out.append(Finding("swath", "warning", None, f"{what} max |DZ|", f"<= {p.max_dz_limit_m:g} m",
                           f"{s['max_abs_dz']:.3f} m", f"{what}: some smooth cells differ by more than the limit"))
    return out


def _add_shifted(out: np.ndarray, s: np.ndarray, ox: float, oy: float) -> None:
    """Add plane sums ``s`` (10, m) into ``out``, re-expressed relative to an origin (-ox, -oy)
    away: x' = x + ox, y' = y + oy (z unchanged)."""
    n, x, y, z, xx, xy, yy, xz, yz, zz = s
    out += s
    out[1] += ox * n
    out[2] += oy * n
    out[4] += (2 * ox) * x + (ox * ox) * n
    out[5] += ox * y + oy * x + (ox * oy) * n
    out[6] += (2 * oy) * y + (oy * oy) * n
    out[7] += ox * z
    out[8] += oy * z


def _window_sums(keys: np.ndarray, sums: np.ndarray, grid: QCGrid, window: int, block: slice) -> np.ndarray:
    """For the occupied (swath, cell) keys ``keys[block]``, the sums (10, k) of that swath over
    the ``window`` × ``window`` cells around the cell, relative to the cell's centre."""
    base, cell = np.divmod(keys[block], grid.rows * grid.cols)
    base *= grid.rows * grid.cols
    row, col = np.divmod(cell, grid.cols)
    out = np.zeros((sums.shape[0], cell.size))
    r = window // 2
    for dr in range(-r, r + 1):
        for dc in range(-r, r + 1):
            rr, cc = row + dr, col + dc
            nk = base + rr * grid.cols + cc
            pos = np.minimum(np.searchsorted(keys, nk), keys.size - 1)
            hit = np.flatnonzero((rr >= 0) & (rr < grid.rows) & (cc >= 0) & (cc < grid.cols) & (keys[pos] == nk))
            # the neighbour's centre lies (dc, -dr) cells from the target's (rows grow southward)
            part = np.zeros((sums.shape[0], hit.size))
            _add_shifted(part, sums[:, pos[hit]], dc * grid.cell_m, -dr * grid.cell_m)
            out[:, hit] += part
    return out


def _fit_all(keys: np.ndarray, sums: np.ndarray, grid: QCGrid, p: SwathParams, sel: np.ndarray | None = None,
             block: int = 1 << 20) -> dict:
    """:func:`_planes` of the window of every key (or of the keys at the positions ``sel``), a
    block of keys at a time (the window sums are the largest temporary); keeps the plane height,
    residual RMS and the flags."""
    n = keys.size if sel is None else sel.size
    out = {"height": np.empty(n), "rms": np.empty(n, np.float32),
           "fitted": np.empty(n, bool), "flat": np.empty(n, bool), "smooth": np.empty(n, bool)}
    for i0 in range(0, n, block):
        sl = slice(i0, min(i0 + block, n))
        fit = _planes(_window_sums(keys, sums, grid, p.window, sl if sel is None else sel[sl]), p,
                      p.window * grid.cell_m)
        for k, v in out.items():
            v[sl] = fit[k]
    return out


def fit_state(keys: np.ndarray, sums: np.ndarray, grid: QCGrid, p: SwathParams, sel: np.ndarray | None = None) -> dict:
    """The planes of the (swath, cell) ``keys`` (sorted; those at positions ``sel``, default
    all) reduced to what adds up over disjoint sets of cells: per pair of swaths the count,
    sum, sum of squares and largest absolute value of DZ; per swath the residual RMS of its
    smooth cells, its fitted cells and its rough-where-others-smooth counts; the largest
    |DZ| per cell. ``keys`` must hold every key of the window around the selected ones.
    Arrays only, so that it is saved as it is (:func:`merge_fits` adds them up)."""
    sel_keys = keys if sel is None else keys[sel]
    fit = _fit_all(keys, sums, grid, p, sel)
    sid, cell = np.divmod(sel_keys, grid.rows * grid.cols)
    ok = np.flatnonzero(fit["smooth"])
    i, j = _pairs(cell[ok], sid[ok])
    i, j = ok[i], ok[j]
    dz = fit["height"][j] - fit["height"][i]
    pk = sid[i] * _SID + sid[j]
    order = np.argsort(pk, kind="stable")
    pk, d = pk[order], dz[order]
    start = np.flatnonzero(np.r_[True, pk[1:] != pk[:-1]]) if pk.size else np.zeros(0, np.int64)
    red = (lambda f, v: f.reduceat(v, start)) if pk.size else (lambda f, v: np.zeros(0))
    rough = _rough_share(sid, cell, fit)
    ids = np.unique(sid)
    fitted = np.bincount(np.searchsorted(ids, sid), weights=fit["fitted"], minlength=ids.size).astype(np.int64)
    dz_cells, dz_vals = _cell_max(cell[i], np.abs(dz))
    return {"pair": pk[start], "pair_n": np.diff(np.r_[start, pk.size]), "pair_sum": red(np.add, d),
            "pair_sum2": red(np.add, d * d), "pair_max": red(np.maximum, np.abs(d)),
            "ids": ids, "fitted": fitted,
            "rough": np.array([rough.get(int(k), (0, 0)) for k in ids], np.int64).reshape(-1, 2),
            "smooth_sid": sid[fit["smooth"]].astype(np.int32), "smooth_rms": fit["rms"][fit["smooth"]],
            "dz_cells": dz_cells, "dz_vals": dz_vals, "sum_dz2": np.array([np.sum(dz * dz)]),
            "n_dz": np.array([dz.size])}


def merge_fits(fits: list[dict], p: SwathParams) -> dict:
    """The figures of the whole delivery from :func:`fit_state` of disjoint sets of cells."""
    cat = {k: np.concatenate([np.asarray(f[k]) for f in fits]) if fits else np.zeros(0)
           for k in ("pair", "pair_n", "pair_sum", "pair_sum2", "pair_max", "ids", "fitted", "smooth_sid",
                     "smooth_rms", "dz_cells", "dz_vals")}
    rough = np.concatenate([np.asarray(f["rough"]).reshape(-1, 2) for f in fits]) if fits else np.zeros((0, 2))
    ids = np.unique(cat["ids"]).astype(np.int64)
    pos = np.searchsorted(ids, cat["ids"])
    fitted = np.bincount(pos, weights=cat["fitted"], minlength=ids.size)
    checked = np.bincount(pos, weights=rough[:, 0], minlength=ids.size)
    n_rough = np.bincount(pos, weights=rough[:, 1], minlength=ids.size)
    by = np.argsort(cat["smooth_sid"], kind="stable")
    bounds = np.searchsorted(cat["smooth_sid"][by], np.r_[ids, np.iinfo(np.int64).max])
    intra = []
    for k, sid in enumerate(ids):  # one entry per swath
        rms = cat["smooth_rms"][by[bounds[k]:bounds[k + 1]]]
        intra.append({"id": int(sid), "precision_m": float(np.median(rms)) if rms.size else None,
                      "p95_m": float(np.percentile(rms, 95)) if rms.size else None, "cells": int(rms.size),
                      "fitted_cells": int(fitted[k]),
                      "rough_where_others_smooth": float(n_rough[k] / checked[k]) if checked[k] else None,
                      "cells_where_others_smooth": int(checked[k])})
    order = np.argsort(cat["dz_cells"], kind="stable")
    return {"ids": ids, "pairs": _pair_stats(cat, p), "intraswath": intra,
            "dz": (cat["dz_cells"][order].astype(np.int64), cat["dz_vals"][order]),
            "sum_dz2": float(sum(float(np.asarray(f["sum_dz2"]).sum()) for f in fits)),
            "n_dz": int(sum(int(np.asarray(f["n_dz"]).sum()) for f in fits))}


def _planes(w: np.ndarray, p: SwathParams, window_m: float) -> dict:
    """Least-squares planes z = a x + b y + c from window sums (10, m), in metres.

    Returns ``height`` (c: the plane at the cell centre), ``rms`` (residual RMS perpendicular
    to the plane, n - 3 degrees of freedom), ``slope_deg``, ``fitted`` (a well-posed fit: at
    least ``min_points``, a spread (standard deviation) of at least a tenth of the window
    across its narrowest direction, and a centre height whose variance is at most twice that of
    the points' mean height: leverage 1 + dᵀC⁻¹d <= 2, d the centroid's offset from the centre,
    C the plan covariance), ``flat`` (fitted, slope within the limit) and ``smooth`` (flat,
    residual RMS within the roughness limit).
    """
    n = w[0]
    m = np.maximum(n, 1.0)
    mx, my, mz = w[1] / m, w[2] / m, w[3] / m
    cxx, cxy, cyy = w[4] / m - mx * mx, w[5] / m - mx * my, w[6] / m - my * my
    cxz, cyz, czz = w[7] / m - mx * mz, w[8] / m - my * mz, w[9] / m - mz * mz
    det = cxx * cyy - cxy * cxy
    lam_min = (cxx + cyy) / 2 - np.sqrt(((cxx - cyy) / 2) ** 2 + cxy * cxy)
    fitted = (n >= p.min_points) & (lam_min >= (window_m / 10) ** 2)
    with np.errstate(divide="ignore", invalid="ignore"):
        a = np.where(fitted, (cxz * cyy - cyz * cxy) / det, 0.0)
        b = np.where(fitted, (cyz * cxx - cxz * cxy) / det, 0.0)
        leverage = 1 + (mx * mx * cyy - 2 * mx * my * cxy + my * my * cxx) / np.where(fitted, det, 1.0)
    fitted &= leverage <= 2.0
    sse = np.maximum(n * (czz - a * cxz - b * cyz), 0.0)
    g2 = a * a + b * b
    rms = np.sqrt(sse / np.maximum(n - 3, 1) / (1 + g2))
    slope = np.degrees(np.arctan(np.sqrt(g2)))
    flat = fitted & (slope <= p.max_slope_deg)
    return {"height": mz - a * mx - b * my, "rms": rms, "slope_deg": slope, "fitted": fitted, "flat": flat,
            "smooth": flat & (rms <= p.roughness)}


def _pairs(cell: np.ndarray, sid: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Index pairs (i, j) of entries in a common cell with sid[i] < sid[j] (ids unique per cell)."""
    order = np.lexsort((sid, cell))
    cs = cell[order]
    parts = []
    for d in range(1, max(cs.size, 1)):  # a cell with k swaths has entries d = 1 .. k-1 apart
        i = np.flatnonzero(cs[d:] == cs[:-d])
        if i.size == 0:
            break
        parts.append((order[i], order[i + d]))
    if not parts:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    return np.concatenate([i for i, _ in parts]), np.concatenate([j for _, j in parts])


def _rough_share(sid: np.ndarray, cell: np.ndarray, fit: dict) -> dict[int, tuple[int, int]]:
    """Per swath: (flat cells where another swath is smooth, those of them rough in this swath).

    A cell smooth for one swath is a smooth surface whatever the other swaths say, so a swath
    that is rough there is noisy itself: this tells a noisy swath from vegetation without the
    censoring of measuring precision on cells selected by that same precision."""
    flat = np.flatnonzero(fit["flat"])
    i, j = _pairs(cell[flat], sid[flat])
    i, j = flat[i], flat[j]
    sm = fit["smooth"]
    me = np.concatenate([i[sm[j]], j[sm[i]]])  # this swath's entries where the other one is smooth
    out: dict[int, tuple[int, int]] = {}
    ids, checked = np.unique(sid[me], return_counts=True)
    rough = dict(zip(*np.unique(sid[me[~sm[me]]], return_counts=True)))
    for k, n in zip(ids, checked):
        out[int(k)] = (int(n), int(rough.get(k, 0)))
    return out


def _pair_stats(cat: dict, p: SwathParams) -> list[dict]:
    """Per pair (sorted by (a, b)) from the per-pair sums of :func:`fit_state`: RMSDz, mean DZ,
    max |DZ| (m), cells, enough_cells."""
    if cat["pair"].size == 0:
        return []
    key = cat["pair"].astype(np.int64)
    order = np.argsort(key, kind="stable")
    key = key[order]
    start = np.flatnonzero(np.r_[True, key[1:] != key[:-1]])
    cells = np.add.reduceat(cat["pair_n"][order].astype(np.int64), start)
    mean = np.add.reduceat(cat["pair_sum"][order], start) / cells
    rms = np.sqrt(np.add.reduceat(cat["pair_sum2"][order], start) / cells)
    mx = np.maximum.reduceat(cat["pair_max"][order], start)
    need = p.min_pair_windows * p.window ** 2
    return [{"a": int(k // _SID), "b": int(k % _SID), "rmsdz": float(r), "mean_dz": float(mu), "max_abs_dz": float(x),
             "cells": int(c), "enough_cells": bool(c >= need)}
            for k, r, mu, x, c in zip(key[start], rms, mean, mx, cells)]


def _cell_max(cell: np.ndarray, value: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(cells, max value per cell) of unsorted (cell, value) pairs."""
    if cell.size == 0:
        return cell, value
    order = np.argsort(cell, kind="stable")
    cell, value = cell[order], value[order]
    start = np.flatnonzero(np.r_[True, cell[1:] != cell[:-1]])
    return cell[start], np.maximum.reduceat(value, start)
