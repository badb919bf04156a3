"""Absolute accuracy from surveyed checkpoints: NVA/VVA (ASPRS 2014), RMSE (ASPRS Edition 2,
2023), horizontal RMSEr and the NSSDA 95 % forms, and the accuracy of a DEM.

Method, as the USGS Lidar Base Specification (2024, v2.x) and the ASPRS Positional Accuracy
Standards prescribe for lidar:

* each checkpoint (id, x, y, z, land cover; CRS units of the delivery) is compared with a
  **TIN of the ground points** around it (:class:`CheckpointPass`, streamed chunk by chunk:
  only the ground points within ``radius_m`` of a checkpoint are kept, at most ``max_points``
  per checkpoint); a checkpoint outside that TIN, or with too few ground points near it, is
  reported, never silently dropped;
* the error of a checkpoint is ``dz = z_lidar − z_checkpoint`` (product minus reference);
* **ASPRS 2014** (Edition 1): on non-vegetated checkpoints RMSEz and
  NVA = 1.96·RMSEz (95 % confidence for normally distributed errors); on vegetated checkpoints
  VVA = the 95th percentile of |dz| (errors under vegetation are not normal). The percentile is
  interpolated linearly between ranks, rank = (P/100)·(N − 1) + 1 of the sorted |dz|
  (numpy's default ``"linear"`` method);
* **ASPRS Edition 2** (2023): accuracy is the RMSE alone; the checkpoints' own accuracy is
  combined into the product's, RMSE_V = √(RMSE_V1² + RMSE_V2²) and RMSE_H = √(RMSE_H1² + RMSE_H2²)
  (V1/H1 measured against the checkpoints, V2/H2 those of the checkpoint survey); at least 30
  checkpoints; VVA is reported as an RMSE without pass/fail;
* horizontally RMSEr = √(RMSEx² + RMSEy²) and the NSSDA (FGDC-STD-007.3-1998, Appendix 3-A)
  95 % radial accuracy 1.7308·RMSEr, valid when RMSEx = RMSEy; when they differ and
  RMSEmin/RMSEmax lies in 0.6–1.0 the NSSDA approximation 2.4477·0.5·(RMSEx + RMSEy) applies,
  below 0.6 neither;
* outliers are listed with a stated rule (|dz − mean| > 3·RMSE within their land-cover group)
  and stay in every figure;
* a DEM is sampled bilinearly at the checkpoints (:func:`dem_accuracy`), and its cell size is
  checked (:func:`three_x_rule`) against three times the vertical accuracy (photogrammetric
  products lecture: a cell of at least 3·s_z keeps a ±s_z error within one cell) and against
  the point spacing (USGS Lidar Base Specification: DEM cell no less than the ANPS).

Checkpoint coordinates stay in CRS units as given; every difference, RMSE, distance and cell
size in the results is in metres (:class:`~workstation.core.units.Units` converts).

Examples
--------
>>> import numpy as np
>>> acc = vertical_accuracy(np.array([0.1, -0.1, 0.1, -0.1]), np.zeros(4, bool))
>>> round(acc["asprs2014"]["rmsez"], 3), round(acc["asprs2014"]["nva"], 3)
(0.1, 0.196)
>>> round(horizontal_accuracy([0.03, -0.03], [0.04, -0.04])["rmser"], 3)
0.05
"""

from __future__ import annotations

import csv
import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from workstation.core.classes import ASPRSClass
from workstation.core.errors import InvalidInputError
from workstation.core.units import METRES, Units

from .context import Finding

__all__ = [
    "Checkpoints", "CheckpointParams", "CheckpointPass", "read_checkpoints", "land_cover_is_vegetated",
    "vertical_accuracy", "horizontal_accuracy", "outliers", "dem_accuracy", "three_x_rule",
]

#: z of a normal distribution at 95 % two-sided (NVA = 1.96·RMSEz, ASPRS 2014 / NSSDA).
Z95 = 1.9600
#: NSSDA radial 95 % factor when RMSEx = RMSEy (2.4477/√2).
R95 = 1.7308
#: NSSDA radial 95 % factor on the mean of RMSEx and RMSEy (chi distribution, 2 d.o.f.).
R95_MEAN = 2.4477
#: Fewest checkpoints: ASPRS 2014 (§C.2, non-vegetated) and Edition 2 (2023).
MIN_CHECKPOINTS_2014 = 20
MIN_CHECKPOINTS_ED2 = 30

# ----------------------------------------------------------------------------- land cover
_NONVEG = {
    "nva", "open", "open terrain", "open ground", "bare", "bare earth", "bare ground", "bare soil", "soil",
    "dirt", "urban", "urban terrain", "urban area", "paved", "pavement", "asphalt", "concrete", "road",
    "hard surface", "sand", "beach", "rock", "rocky", "gravel", "short grass", "low grass", "mowed grass",
    "lawn", "non vegetated", "nonvegetated",
}
_VEG = {
    "vva", "forest", "forested", "fully forested", "trees", "tree", "low trees", "woods", "woodland", "brush",
    "brush lands", "brushland", "shrub", "shrubs", "scrub", "tall grass", "weeds", "tall weeds", "crops", "crop",
    "cropland", "vegetated", "vegetation",
}


def _norm_word(word: str) -> str:
    return " ".join(re.sub(r"[^0-9a-z]+", " ", str(word).lower()).split())


def land_cover_is_vegetated(word: str) -> bool | None:
    """Whether a land-cover word is vegetated (True), non-vegetated (False) or unknown (None).

    Non-vegetated: open terrain, bare earth, urban, paved, sand, rock, short grass, "NVA" ...;
    vegetated: forest, trees, brush, shrub, tall grass, weeds, crops, "VVA" ... (ASPRS 2014
    land-cover classes). Case, hyphens and underscores do not matter; "grass" alone is unknown.

    >>> land_cover_is_vegetated("Open_Terrain"), land_cover_is_vegetated("tall-grass"), land_cover_is_vegetated("grass")
    (False, True, None)
    """
    w = _norm_word(word)
    if w in _NONVEG:
        return False
    if w in _VEG:
        return True
    return None


# ----------------------------------------------------------------------------- checkpoints
def _frozen(a, dtype) -> np.ndarray:
    out = np.array(a, dtype=dtype)
    out.setflags(write=False)
    return out


@dataclass(frozen=True, eq=False)
class Checkpoints:
    """Surveyed checkpoints, one entry per point (read-only arrays of equal length n).

    Attributes
    ----------
    id : (n,) str
    x, y : (n,) float64
        Plan coordinates in the CRS units of the delivery.
    z : (n,) float64
        Elevation in the vertical CRS units of the delivery.
    cover : (n,) str
        Land-cover word as given ("unspecified" when the file has no land-cover column).
    vegetated : (n,) bool
        ASPRS group: True for vegetated (VVA), False for non-vegetated (NVA) land cover.
    path : str or None
        The file they came from.
    """

    id: np.ndarray
    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    cover: np.ndarray
    vegetated: np.ndarray
    path: str | None = None

    def __post_init__(self):
        n = len(self.id)
        for name in ("x", "y", "z", "cover", "vegetated"):
            if len(getattr(self, name)) != n:
                raise InvalidInputError(f"checkpoint arrays differ in length ({name})", field=name, path=self.path)
        for name, dtype in (("id", object), ("x", float), ("y", float), ("z", float), ("cover", object),
                            ("vegetated", bool)):
            object.__setattr__(self, name, _frozen(getattr(self, name), dtype))

    def __len__(self) -> int:
        return len(self.id)

    @classmethod
    def from_arrays(cls, id, x, y, z, cover=None) -> "Checkpoints":
        """Checkpoints from arrays; ``cover`` words map to the vegetated flag (None: all
        "unspecified", non-vegetated). An unknown word is an :class:`InvalidInputError`."""
        n = len(x)
        cover = ["unspecified"] * n if cover is None else [str(c) for c in cover]
        veg = []
        for i, c in enumerate(cover):
            v = False if c == "unspecified" else land_cover_is_vegetated(c)
            if v is None:
                raise InvalidInputError(f"checkpoint {id[i]}: unknown land cover {c!r}", _COVER_HINT, field="cover")
            veg.append(v)
        return cls(np.array([str(i) for i in id], object), x, y, z, np.array(cover, object), np.array(veg, bool))


_COVER_HINT = ("use a non-vegetated word (open terrain, bare earth, urban, paved, sand, rock, short grass, NVA) "
               "or a vegetated one (forest, trees, brush, shrub, tall grass, weeds, crops, VVA)")
_ALIASES = {
    "id": ("id", "name", "point", "point id", "pointid", "pt", "cp", "checkpoint", "station", "label"),
    "x": ("x", "easting", "east", "e"),
    "y": ("y", "northing", "north", "n"),
    "z": ("z", "elevation", "elev", "height", "h"),
    "cover": ("cover", "land cover", "landcover", "class", "land class", "landclass", "type", "category"),
}


def _column_of(name: str) -> str | None:
    n = _norm_word(name)
    return next((col for col, names in _ALIASES.items() if n in names), None)


def _split(line: str, delim: str | None, maxcols: int) -> list[str]:
    if delim is None:
        return line.split(None, maxcols - 1)
    return [f.strip() for f in next(csv.reader([line], delimiter=delim))]


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def read_checkpoints(path) -> Checkpoints:
    """Read a checkpoint CSV: ``id, x, y, z[, land cover]`` in the delivery's CRS units.

    A header row names the columns in any order (id/name/point, x/easting, y/northing,
    z/elevation/height, cover/land_cover/landcover/class; case-insensitive); without a header
    the columns are id, x, y, z[, cover] in that order. Commas, semicolons, tabs or blanks
    separate the fields; ``#`` starts a comment line. Without a land-cover column every point
    is "unspecified" and counted as non-vegetated; without an id column the id is the line number.

    Raises
    ------
    InvalidInputError
        Missing file, no checkpoints, a missing x/y/z column, a bad or non-finite number or an
        unknown land-cover word (naming the line and column), a duplicate id.
    """
    from workstation.io.textfile import read_text

    p = Path(path)
    if not p.is_file():
        raise InvalidInputError("checkpoint file not found", "check the --checkpoints path", path=p)
    lines = [(i, ln) for i, ln in enumerate(read_text(p).splitlines(), 1)
             if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise InvalidInputError("no checkpoints in the file", "one line per point: id, x, y, z, land cover", path=p)
    first = lines[0][1]
    delim = next((d for d in (",", ";", "\t") if d in first), None)
    cols, body = _header(lines, delim, p)
    return _rows(body, cols, delim, p)


def _header(lines, delim, p) -> tuple[list[str | None], list]:
    """(column names or None for unused columns, data lines) from the first line."""
    ln, text = lines[0]
    fields = _split(text, delim, 64)
    cols = [_column_of(f) for f in fields]
    named = any(c in cols for c in ("x", "y", "z")) and not all(_is_number(f) for f in fields[1:4])
    if not named and len(fields) >= 4:
        return ["id", "x", "y", "z", "cover"][: min(len(fields), 5)], lines
    missing = [c for c in ("x", "y", "z") if c not in cols]
    if missing:
        raise InvalidInputError(f"line {ln}: the header {fields} names no {'/'.join(missing)} column",
                                "name the columns id, x, y, z, cover (or easting, northing, elevation, land_cover), "
                                "or give no header and the columns in that order", path=p, field=missing[0])
    return cols, lines[1:]


def _rows(body, cols, delim, p) -> Checkpoints:
    ids, xyz, cover, veg, seen = [], [], [], [], {}
    has_cover = "cover" in cols
    for ln, text in body:
        f = _split(text, delim, len(cols))
        need = max(cols.index(c) for c in ("x", "y", "z")) + 1
        if len(f) < need:
            raise InvalidInputError(f"line {ln}: {len(f)} fields, expected at least {need}", path=p)
        row = {c: f[i] for i, c in enumerate(cols) if c is not None and i < len(f)}
        cid = row.get("id") or str(ln)
        if cid in seen:
            raise InvalidInputError(f"line {ln}: checkpoint id {cid!r} repeats line {seen[cid]}", path=p, field="id")
        seen[cid] = ln
        ids.append(cid)
        xyz.append([_number(row.get(c, ""), c, ln, p) for c in ("x", "y", "z")])
        word = (row.get("cover") or "").strip() if has_cover else "unspecified"
        v = False if not has_cover else land_cover_is_vegetated(word)
        if v is None:
            raise InvalidInputError(f"line {ln}, column 'cover': unknown land cover {word!r}", _COVER_HINT,
                                    path=p, field="cover")
        cover.append(word)
        veg.append(v)
    if not ids:
        raise InvalidInputError("no checkpoints in the file (only a header)", path=p)
    a = np.array(xyz, float)
    return Checkpoints(np.array(ids, object), a[:, 0], a[:, 1], a[:, 2], np.array(cover, object),
                       np.array(veg, bool), str(p))


def _number(text: str, col: str, ln: int, p) -> float:
    try:
        v = float(text)
    except ValueError:
        raise InvalidInputError(f"line {ln}, column '{col}': {text!r} is not a number", path=p, field=col) from None
    if not math.isfinite(v):
        raise InvalidInputError(f"line {ln}, column '{col}': {text!r} is not finite", path=p, field=col)
    return v


# ----------------------------------------------------------------------------- statistics
def _f(v) -> float | None:
    return None if v is None or not np.isfinite(v) else float(v)


def percentile_abs(e, p: float = 95.0) -> float | None:
    """The ``p``-th percentile of |e|, linear between ranks (rank = p/100·(N−1) + 1), as ASPRS
    2014 computes the VVA; None for no values.

    >>> percentile_abs([0.1, -0.2, 0.3, -0.4, 0.5])
    0.48
    """
    a = np.abs(np.asarray(e, float))
    return round(float(np.percentile(a, p, method="linear")), 12) if a.size else None


def error_stats(e) -> dict:
    """Descriptive statistics of errors ``e`` (m): n, mean, std (sample, n−1), rmse, min, max,
    median, NMAD (1.4826·median|e − median|, Höhle & Höhle 2009), p95_abs, skew, kurtosis
    (excess); None where undefined."""
    e = np.asarray(e, float)
    n = int(e.size)
    if n == 0:
        return {"n": 0, **{k: None for k in ("mean", "std", "rmse", "min", "max", "median", "nmad", "p95_abs",
                                               "skew", "kurtosis")}}
    med = float(np.median(e))
    return {
        "n": n, "mean": float(e.mean()), "std": float(e.std(ddof=1)) if n > 1 else None,
        "rmse": float(np.sqrt(np.mean(e**2))), "min": float(e.min()), "max": float(e.max()), "median": med,
        "nmad": float(1.4826 * np.median(np.abs(e - med))), "p95_abs": percentile_abs(e), **_shape(e),
    }


def _shape(e: np.ndarray) -> dict:
    """Sample skewness G1 and excess kurtosis G2 (the bias-corrected moment estimators, as
    ``scipy.stats.skew/kurtosis(bias=False)``); None for too few or identical values."""
    n = e.size
    d = e - e.mean()
    m2, m3, m4 = (float(np.mean(d**k)) for k in (2, 3, 4))
    if n < 3 or np.ptp(e) == 0:
        return {"skew": None, "kurtosis": None}
    g1 = m3 / m2**1.5
    skew = g1 * math.sqrt(n * (n - 1)) / (n - 2)
    kurt = None if n < 4 else ((n + 1) * (m4 / m2**2 - 3) + 6) * (n - 1) / ((n - 2) * (n - 3))
    return {"skew": float(skew), "kurtosis": None if kurt is None else float(kurt)}


def outliers(dz, *, k: float = 3.0, ids=None) -> dict:
    """The errors with |dz − mean| > k·RMSE (RMSE of ``dz`` itself), listed for review; they
    are never removed from any figure.

    With n errors no single error can exceed √n·RMSE, so fewer than k² + 1 checkpoints cannot
    show an outlier by this rule.

    Returns
    -------
    dict
        ``rule`` (text), ``k``, ``mean_m``, ``rmse_m``, ``threshold_m`` (k·RMSE) and ``items``:
        [{index, id, dz_m, deviation_m}] in input order.
    """
    e = np.asarray(dz, float)
    if e.size == 0:
        return {"rule": f"|dz - mean| > {k:g}·RMSE", "k": k, "mean_m": None, "rmse_m": None, "threshold_m": None,
                "items": []}
    mean, rmse = float(e.mean()), float(np.sqrt(np.mean(e**2)))
    dev = e - mean
    hit = np.flatnonzero(np.abs(dev) > k * rmse)
    names = [None] * e.size if ids is None else [str(i) for i in ids]
    items = [{"index": int(i), "id": names[i], "dz_m": float(e[i]), "deviation_m": float(dev[i])} for i in hit]
    return {"rule": f"|dz - mean| > {k:g}·RMSE", "k": k, "mean_m": mean, "rmse_m": rmse, "threshold_m": k * rmse,
            "items": items}


def _combine(rmse: float | None, cp: float) -> float | None:
    return None if rmse is None else float(math.hypot(rmse, cp))


def _criterion(name: str, value, threshold, ok, unit: str = "", source: str = "") -> dict:
    return {"name": name, "value": value, "threshold": threshold, "pass": ok, "unit": unit, "source": source}


def vertical_accuracy(dz, vegetated=None, *, checkpoint_rmse_m: float = 0.0, ids=None, outlier_k: float = 3.0) -> dict:
    """Vertical accuracy of checkpoint errors ``dz`` (m, product − checkpoint) by ASPRS 2014 and
    Edition 2 (2023).

    Parameters
    ----------
    dz : (n,) float
        Errors in metres.
    vegetated : (n,) bool, optional
        Land-cover group of each checkpoint (None: all non-vegetated).
    checkpoint_rmse_m : float
        The checkpoint survey's own vertical RMSE (m), RMSE_V2 of Edition 2.
    ids : (n,) str, optional
        Names for the outlier list.
    outlier_k : float
        Outlier rule |dz − mean| > k·RMSE, applied within each land-cover group.

    Returns
    -------
    dict
        ``n``, ``n_nonvegetated``, ``n_vegetated``; ``nonvegetated`` and ``vegetated``
        (:func:`error_stats`); ``asprs2014``: rmsez, nva (1.96·RMSEz), vva (95th percentile of
        |dz|, vegetated), mean, std, criteria; ``edition2``: rmsev_data, checkpoint_rmse,
        rmsev (combined), vva_rmsev_data, vva_rmsev (reported, no pass/fail), criteria;
        ``outliers``: the listed outliers of both groups. All lengths in metres, None where
        there are no checkpoints of a group.
    """
    e = np.asarray(dz, float).ravel()
    veg = np.zeros(e.size, bool) if vegetated is None else np.asarray(vegetated, bool).ravel()
    if veg.size != e.size:
        raise InvalidInputError(f"{e.size} errors but {veg.size} land-cover flags", field="vegetated")
    if not np.isfinite(e).all():
        raise InvalidInputError("checkpoint errors must be finite", "leave unmatched checkpoints out", field="dz")
    if not checkpoint_rmse_m >= 0:
        raise InvalidInputError(f"checkpoint RMSE {checkpoint_rmse_m} must be >= 0 m", field="checkpoint_rmse_m")
    nv, vg = error_stats(e[~veg]), error_stats(e[veg])
    names = np.array([str(i) for i in (ids if ids is not None else range(e.size))], object)
    return {
        "n": int(e.size), "n_nonvegetated": nv["n"], "n_vegetated": vg["n"],
        "nonvegetated": nv, "vegetated": vg,
        "asprs2014": _asprs2014(nv, vg),
        "edition2": _edition2(nv, vg, float(checkpoint_rmse_m)),
        "outliers": _group_outliers(e, veg, names, outlier_k),
    }


def _asprs2014(nv: dict, vg: dict) -> dict:
    src = "ASPRS Positional Accuracy Standards, Edition 1 (2014)"
    rmsez = nv["rmse"]
    return {
        "rmsez": rmsez, "nva": None if rmsez is None else Z95 * rmsez, "vva": vg["p95_abs"],
        "mean": nv["mean"], "std": nv["std"],
        "nva_form": "NVA = 1.96·RMSEz (non-vegetated)",
        "vva_form": "VVA = 95th percentile of |dz| (vegetated), linear between ranks (N-1)·0.95 + 1",
        "criteria": [_criterion("non-vegetated checkpoints", nv["n"], MIN_CHECKPOINTS_2014,
                                nv["n"] >= MIN_CHECKPOINTS_2014, "", src + " §C.2")],
    }


def _edition2(nv: dict, vg: dict, cp: float) -> dict:
    src = "ASPRS Positional Accuracy Standards, Edition 2 (2023)"
    return {
        "rmsev_data": nv["rmse"], "checkpoint_rmse": cp, "rmsev": _combine(nv["rmse"], cp),
        "vva_rmsev_data": vg["rmse"], "vva_rmsev": _combine(vg["rmse"], cp),
        "form": "RMSE_V = sqrt(RMSE_V1^2 + RMSE_V2^2): V1 against the checkpoints, V2 the checkpoints' own",
        "vva_note": "vegetated accuracy is reported as an RMSE without pass/fail",
        "criteria": [_criterion("non-vegetated checkpoints", nv["n"], MIN_CHECKPOINTS_ED2,
                                nv["n"] >= MIN_CHECKPOINTS_ED2, "", src)],
    }


def _group_outliers(e, veg, names, k) -> dict:
    items = []
    for group in (False, True):
        idx = np.flatnonzero(veg == group)
        o = outliers(e[idx], k=k, ids=names[idx])
        for it in o["items"]:
            items.append({**it, "index": int(idx[it["index"]]), "vegetated": group,
                          "threshold_m": o["threshold_m"]})
    items.sort(key=lambda it: it["index"])
    return {"rule": f"|dz - mean| > {k:g}·RMSE within each land-cover group; kept in every figure", "items": items}


def horizontal_accuracy(dx, dy, *, checkpoint_rmse_m: float = 0.0) -> dict:
    """Horizontal accuracy of checkpoint errors ``dx``, ``dy`` (m, product − checkpoint).

    ``checkpoint_rmse_m`` is the checkpoint survey's horizontal (radial) RMSE, RMSE_H2 of
    Edition 2 (from per-axis σ: √2·σ).

    Returns
    -------
    dict
        ``n``, ``x`` and ``y`` (:func:`error_stats`), ``rmsex``, ``rmsey``, ``rmser``
        (√(RMSEx² + RMSEy²)); ``nssda``: ``ratio`` (RMSEmin/RMSEmax), ``ratio_ok`` (0.6–1.0),
        ``accuracy_r_1_7308`` (1.7308·RMSEr, exact when RMSEx = RMSEy), ``accuracy_r``
        (2.4477·0.5·(RMSEx + RMSEy) when the ratio is 0.6–1.0, else None), ``form``;
        ``edition2``: rmseh_data, checkpoint_rmse, rmseh (combined), criteria (≥ 30). Metres.
    """
    ex, ey = np.asarray(dx, float).ravel(), np.asarray(dy, float).ravel()
    if ex.size != ey.size:
        raise InvalidInputError(f"{ex.size} x errors but {ey.size} y errors", field="dy")
    if not (np.isfinite(ex).all() and np.isfinite(ey).all()):
        raise InvalidInputError("horizontal errors must be finite", field="dx")
    sx, sy = error_stats(ex), error_stats(ey)
    rx, ry = sx["rmse"], sy["rmse"]
    rr = None if rx is None else float(math.hypot(rx, ry))
    return {"n": int(ex.size), "x": sx, "y": sy, "rmsex": rx, "rmsey": ry, "rmser": rr,
            "nssda": _nssda(rx, ry, rr), "edition2": _edition2_h(rr, float(checkpoint_rmse_m), int(ex.size))}


def _nssda(rx, ry, rr) -> dict:
    if rr is None:
        return {"ratio": None, "ratio_ok": None, "accuracy_r_1_7308": None, "accuracy_r": None, "form": None}
    lo, hi = min(rx, ry), max(rx, ry)
    ratio = 1.0 if hi == 0 else lo / hi
    ok = bool(ratio >= 0.6)
    return {
        "ratio": ratio, "ratio_ok": ok, "accuracy_r_1_7308": R95 * rr,
        "accuracy_r": R95_MEAN * 0.5 * (rx + ry) if ok else None,
        "form": ("Accuracy_r = 2.4477·0.5·(RMSEx + RMSEy) (= 1.7308·RMSEr when RMSEx = RMSEy), "
                 "valid for RMSEmin/RMSEmax in 0.6-1.0" if ok else
                 "RMSEmin/RMSEmax < 0.6: neither NSSDA approximation holds (elliptical error)"),
        "source": "FGDC-STD-007.3-1998 (NSSDA) Appendix 3-A; ASPRS 2014",
    }


def _edition2_h(rr, cp: float, n: int) -> dict:
    return {"rmseh_data": rr, "checkpoint_rmse": cp, "rmseh": _combine(rr, cp),
            "form": "RMSE_H = sqrt(RMSE_H1^2 + RMSE_H2^2), RMSE_H1 = sqrt(RMSEx^2 + RMSEy^2)",
            "criteria": [_criterion("checkpoints", n, MIN_CHECKPOINTS_ED2, n >= MIN_CHECKPOINTS_ED2, "",
                                    "ASPRS Positional Accuracy Standards, Edition 2 (2023)")]}


# ----------------------------------------------------------------------------- the streamed pass
@dataclass(frozen=True)
class CheckpointParams:
    """How ground points are gathered around checkpoints.

    Attributes
    ----------
    radius_m : float
        Ground points within this plan distance (m) of a checkpoint are kept for its TIN.
    ground_classes : tuple of int
        ASPRS classes forming the bare-earth TIN: ground (2) and road surface (11).
    max_points : int
        At most this many nearest ground points are kept per checkpoint (the radius of that
        checkpoint shrinks), so memory stays bounded on dense data.
    """

    radius_m: float = 5.0
    ground_classes: tuple = (int(ASPRSClass.GROUND), int(ASPRSClass.ROAD_SURFACE))
    max_points: int = 2000

    def __post_init__(self):
        if not (self.radius_m > 0 and math.isfinite(self.radius_m)):
            raise InvalidInputError(f"radius {self.radius_m} m must be > 0", field="radius_m")
        if self.max_points < 3:
            raise InvalidInputError("max_points must be at least 3 (a triangle)", field="max_points")


class CheckpointPass:
    """Streams chunks, keeping the ground points near checkpoints; :meth:`result` compares each
    checkpoint with a TIN of its ground points.

    Parameters
    ----------
    cps : Checkpoints
        In the CRS units of the chunks.
    units : Units
        Units of that CRS (:func:`workstation.io.crs.crs_units`).
    radius_m : float, optional
        Overrides ``params.radius_m``.
    params : CheckpointParams
    """

    def __init__(self, cps: Checkpoints, units: Units = METRES, radius_m: float | None = None,
                 params: CheckpointParams = CheckpointParams()):
        from scipy.spatial import cKDTree

        if radius_m is not None:
            params = CheckpointParams(radius_m, params.ground_classes, params.max_points)
        if len(cps) == 0:
            raise InvalidInputError("no checkpoints to compare", field="checkpoints", path=cps.path)
        self.cps, self.units, self.params = cps, units, params
        self._xy = np.column_stack([cps.x, cps.y])
        self._tree = cKDTree(self._xy)
        self._r = units.h_from_m(params.radius_m)
        self._radius = np.full(len(cps), self._r)
        self._cell_keys = self._disc_cells()
        self._idx = np.empty(0, np.int64)
        self._pts = np.empty((0, 3))
        self._result = None
        self.points_seen = 0

    def _disc_cells(self) -> np.ndarray:
        """Sorted keys of the cells (side = radius) holding any point within the radius of a
        checkpoint: a coarse prefilter (a rare key collision only sends a point on to the exact
        KD-tree test)."""
        ij = np.floor(self._xy / self._r).astype(np.int64)
        off = np.array([(a, b) for a in (-1, 0, 1) for b in (-1, 0, 1)])
        nb = (ij[:, None, :] + off[None]).reshape(-1, 2)
        return np.unique(nb[:, 0] * 2**31 + nb[:, 1])

    def _near(self, xy: np.ndarray) -> np.ndarray:
        ij = np.floor(xy / self._r).astype(np.int64)
        keys = ij[:, 0] * 2**31 + ij[:, 1]
        pos = np.clip(np.searchsorted(self._cell_keys, keys), 0, self._cell_keys.size - 1)
        return self._cell_keys[pos] == keys

    def add(self, chunk, source: str | None = None) -> None:
        """Keep the chunk's ground points within the radius of a checkpoint (a point near
        several checkpoints is kept for each of its 8 nearest)."""
        self.points_seen += chunk.n
        self._result = None
        cls = chunk.attrs.get("classification")
        if cls is None or chunk.n == 0:
            return
        keep = np.isin(cls, self.params.ground_classes)
        if "withheld" in chunk.attrs:
            keep &= np.asarray(chunk.attrs["withheld"]) == 0
        keep[keep] = self._near(chunk.xyz[keep, :2])
        pts = chunk.xyz[keep]
        if not len(pts):
            return
        k = min(8, len(self.cps))
        d, i = self._tree.query(pts[:, :2], k=k, distance_upper_bound=self._r)
        d, i = d.reshape(len(pts), k), i.reshape(len(pts), k)
        ok = np.isfinite(d)
        ok[ok] = d[ok] <= self._radius[i[ok]]
        rows, cols = np.nonzero(ok)
        self._idx = np.concatenate([self._idx, i[rows, cols]])
        self._pts = np.vstack([self._pts, pts[rows]])
        self._cap()

    def state(self) -> dict:
        """The kept points, the checkpoint each is kept for, the radii and the points seen."""
        return {"idx": self._idx, "pts": self._pts, "radius": self._radius,
                "seen": np.array([self.points_seen], np.int64)}

    @classmethod
    def from_states(cls, cps: Checkpoints, units: Units, states: list[dict],
                    params: CheckpointParams = CheckpointParams()) -> "CheckpointPass":
        """The pass over several files from the :meth:`state` of each: the kept points joined,
        each radius the smallest, then the nearest ``max_points`` kept as one pass keeps them."""
        p = cls(cps, units, params=params)
        if states:
            p._idx = np.concatenate([np.asarray(s["idx"], np.int64) for s in states])
            p._pts = np.concatenate([np.asarray(s["pts"], float).reshape(-1, 3) for s in states])
            p._radius = np.min([np.asarray(s["radius"]) for s in states], axis=0)
            p.points_seen = int(sum(int(np.asarray(s["seen"]).sum()) for s in states))
            p._cap()
        return p

    def _cap(self) -> None:
        """Keep at most ``max_points`` nearest points per checkpoint, shrinking its radius."""
        counts = np.bincount(self._idx, minlength=len(self.cps))
        over = np.flatnonzero(counts > self.params.max_points)
        if not over.size:
            return
        drop = np.zeros(self._idx.size, bool)
        for c in over:
            sel = np.flatnonzero(self._idx == c)
            d = np.hypot(*(self._pts[sel, :2] - self._xy[c]).T)
            order = np.argsort(d, kind="stable")
            drop[sel[order[self.params.max_points:]]] = True
            self._radius[c] = d[order[self.params.max_points - 1]]
        self._idx, self._pts = self._idx[~drop], self._pts[~drop]

    def result(self) -> dict:
        """The per-checkpoint table.

        Returns
        -------
        dict
            ``checkpoints``: one row per checkpoint in file order: id, x, y, z (CRS units, as
            given), z_lidar (CRS vertical units, None when unmatched), dz (m, lidar − checkpoint),
            cover, vegetated, status ("ok", "outside_tin", "no_ground"), ground_points,
            radius_m, max_edge_m (longest edge of the TIN triangle holding it), nearest_ground_m;
            ``unmatched``: the rows without dz; ``n``, ``n_matched``, ``radius_m``,
            ``ground_classes``.
        """
        if self._result is None:
            self._result = self._table()
        return self._result

    def _table(self) -> dict:
        order = np.argsort(self._idx, kind="stable")
        idx, pts = self._idx[order], self._pts[order]
        bounds = np.searchsorted(idx, np.arange(len(self.cps) + 1))
        rows = [self._row(c, pts[bounds[c]:bounds[c + 1]]) for c in range(len(self.cps))]
        unmatched = [r for r in rows if r["dz"] is None]
        return {"checkpoints": rows, "unmatched": unmatched, "n": len(rows), "n_matched": len(rows) - len(unmatched),
                "radius_m": self.params.radius_m, "ground_classes": list(self.params.ground_classes)}

    def _row(self, c: int, pts: np.ndarray) -> dict:
        cps, u = self.cps, self.units
        z, status, edge, nearest = _tin_at(self._xy[c], pts)
        row = {"id": str(cps.id[c]), "x": float(cps.x[c]), "y": float(cps.y[c]), "z": float(cps.z[c]),
               "z_lidar": _f(z), "dz": None if z is None else float(u.v_to_m(z - cps.z[c])),
               "cover": str(cps.cover[c]), "vegetated": bool(cps.vegetated[c]), "status": status,
               "ground_points": int(len(pts)), "radius_m": float(u.h_to_m(self._radius[c])),
               "max_edge_m": None if edge is None else float(u.h_to_m(edge)),
               "nearest_ground_m": None if nearest is None else float(u.h_to_m(nearest))}
        return row

    def findings(self) -> list[Finding]:
        """A warning per checkpoint without a lidar elevation and per listed outlier."""
        res = self.result()
        out = [Finding("accuracy", "warning", None, "checkpoint", "inside a TIN of ground points",
                       r["status"].replace("_", " "),
                       f"checkpoint {r['id']} has no lidar elevation ({r['status'].replace('_', ' ')}, "
                       f"{r['ground_points']} ground points within {r['radius_m']:.3g} m); it is left out of the "
                       f"figures and listed") for r in res["unmatched"]]
        ok = [r for r in res["checkpoints"] if r["dz"] is not None]
        if ok:
            acc = vertical_accuracy([r["dz"] for r in ok], [r["vegetated"] for r in ok], ids=[r["id"] for r in ok])
            out += [Finding("accuracy", "warning", None, "dz", f"|dz - mean| <= {it['threshold_m']:.3g} m",
                            f"{it['dz_m']:.3f} m",
                            f"checkpoint {it['id']} is an outlier (dz {it['dz_m']:.3f} m, 3·RMSE rule); "
                            "it is kept in the figures") for it in acc["outliers"]["items"]]
        return out


def _tin_at(p: np.ndarray, pts: np.ndarray):
    """(z, status, longest edge, nearest distance) of the linear TIN (Delaunay, Qhull) of
    ``pts`` at plan point ``p`` (CRS units); z None when outside the TIN or with fewer than 3
    points."""
    if len(pts) == 0:
        return None, "no_ground", None, None
    rel = pts[:, :2] - p
    nearest = float(np.hypot(rel[:, 0], rel[:, 1]).min())
    if len(pts) < 3:
        return None, "no_ground", None, nearest
    from scipy.spatial import Delaunay, QhullError

    try:
        tri = Delaunay(rel)
    except QhullError:
        return None, "outside_tin", None, nearest
    w = _barycentric_origin(rel[tri.simplices])
    hit = np.flatnonzero(np.all(w >= -1e-9, axis=1))
    if not hit.size:
        return None, "outside_tin", None, nearest
    v = tri.simplices[hit[0]]
    corners = rel[v]
    edge = float(np.max(np.hypot(*(corners - np.roll(corners, 1, axis=0)).T)))
    return float(np.sum(w[hit[0]] * pts[v, 2])), "ok", edge, nearest


def _barycentric_origin(tri: np.ndarray) -> np.ndarray:
    """(m, 3) barycentric coordinates of the origin in (m, 3, 2) triangles, elementwise (no
    LAPACK call per triangle); NaN rows for degenerate triangles."""
    a, b, c = tri[:, 0], tri[:, 1], tri[:, 2]
    v0, v1, v2 = b - a, c - a, -a
    d00, d01, d11 = (v0 * v0).sum(1), (v0 * v1).sum(1), (v1 * v1).sum(1)
    d20, d21 = (v2 * v0).sum(1), (v2 * v1).sum(1)
    den = d00 * d11 - d01 * d01
    ok = den > 1e-12 * d00 * d11
    den = np.where(ok, den, np.nan)
    wb = (d11 * d20 - d01 * d21) / den
    wc = (d00 * d21 - d01 * d20) / den
    return np.column_stack([1.0 - wb - wc, wb, wc])


# ----------------------------------------------------------------------------- DEM accuracy
def dem_accuracy(dem, cps: Checkpoints, *, checkpoint_rmse_m: float = 0.0) -> dict:
    """The accuracy of a DEM (path or :class:`~workstation.core.products.Raster`, same CRS as
    the checkpoints) sampled bilinearly at the checkpoints.

    Returns
    -------
    dict
        :func:`vertical_accuracy` of dz = DEM − checkpoint (m), plus ``rmsez`` (non-vegetated
        RMSEz, m), ``cell_m`` (cell side, the finer axis, m), ``checkpoints`` (id, x, y, z,
        z_dem, dz, cover, vegetated) and ``unmatched`` (off the DEM or next to a nodata cell).
    """
    from workstation.io.crs import raster_units
    from workstation.raster.dem import sample_bilinear

    r = dem
    if not hasattr(dem, "array"):
        from workstation.io.geotiff import read_raster

        r = read_raster(dem, band=1)
    u = raster_units(r)
    zd = sample_bilinear(r, cps.x, cps.y)
    ok = np.isfinite(zd)
    dz = u.v_to_m(zd - cps.z)
    rows = [{"id": str(cps.id[i]), "x": float(cps.x[i]), "y": float(cps.y[i]), "z": float(cps.z[i]),
             "z_dem": _f(zd[i]), "dz": float(dz[i]) if ok[i] else None, "cover": str(cps.cover[i]),
             "vegetated": bool(cps.vegetated[i])} for i in range(len(cps))]
    acc = vertical_accuracy(dz[ok], cps.vegetated[ok], checkpoint_rmse_m=checkpoint_rmse_m, ids=cps.id[ok])
    cell_m = float(min(r.resolution) * u.h)
    return {**acc, "rmsez": acc["asprs2014"]["rmsez"], "cell_m": cell_m, "checkpoints": rows,
            "unmatched": [row for row in rows if row["dz"] is None]}


def three_x_rule(cell_m: float, rmse_m: float | None, anps_m: float | None, *,
                 checkpoint_rmse_m: float | None = None) -> list[dict]:
    """The cell-size rules of a DEM as criteria {name, value, threshold, pass, unit, source}.

    * cell ≥ 3·s_z, s_z the measured vertical RMSE: a height error of ±s_z then stays within
      one cell (photogrammetric products lecture, "three times the vertical accuracy");
    * cell ≥ ANPS: a finer cell interpolates more than it measures (USGS Lidar Base
      Specification: DEM cell size no less than the design aggregate nominal pulse spacing);
    * with ``checkpoint_rmse_m``: checkpoints at least three times as accurate as the product,
      checkpoint RMSE ≤ s_z / 3 (ASPRS 2014, independent source of higher accuracy).

    ``pass`` is None when a quantity is unknown (None).

    Examples
    --------
    >>> [r["pass"] for r in three_x_rule(1.0, 0.1, 0.7)]
    [True, True]
    """
    def known(v):
        return v is not None and math.isfinite(v)

    rules = [
        _criterion("DEM cell >= 3 x vertical RMSE (s_z)", cell_m, 3.0 * rmse_m if known(rmse_m) else None,
                   bool(cell_m >= 3.0 * rmse_m) if known(rmse_m) else None, "m",
                   "photogrammetric products lecture: DEM cell at least 3 x s_z"),
        _criterion("DEM cell >= ANPS", cell_m, anps_m if known(anps_m) else None,
                   bool(cell_m >= anps_m) if known(anps_m) else None, "m",
                   "USGS Lidar Base Specification: DEM cell no less than the ANPS"),
    ]
    if checkpoint_rmse_m is not None:
        thr = rmse_m / 3.0 if known(rmse_m) else None
        rules.append(_criterion("checkpoint RMSE <= vertical RMSE / 3", checkpoint_rmse_m, thr,
                                bool(checkpoint_rmse_m <= thr) if thr is not None else None, "m",
                                "ASPRS 2014: checkpoints at least three times more accurate than the data"))
    return rules
