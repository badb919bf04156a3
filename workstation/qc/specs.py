"""Delivery specifications and the verdict: each criterion measured, its threshold, pass or fail.

Two families:

* **USGS Lidar Base Specification** quality levels QL0–QL3 (LBS 2.x, tables 1, 2, 4 and 6):
  aggregate nominal pulse density and spacing, the 2×ANPS spatial distribution (90 % of cells
  filled), relative accuracy (intraswath smooth-surface precision, interswath RMSDz and maximum
  difference), absolute vertical accuracy (RMSEz and NVA = 1.96·RMSEz on non-vegetated
  checkpoints, VVA as the 95th percentile on vegetated ones) and the minimum DEM cell size.
* **ASPRS vertical accuracy classes** ``asprs-<X>cm`` (Positional Accuracy Standards, Edition 2,
  2023): RMSEv ≤ X on non-vegetated checkpoints with the checkpoints' own accuracy combined in,
  at least 30 checkpoints, VVA reported without pass/fail; the relative accuracy of lidar swaths
  as Edition 1 (2014) table B.3 relates it to X (intraswath 0.6·X, interswath RMSDz 0.8·X,
  maximum difference 1.6·X).

A criterion that could not be measured (no checkpoints, a single swath) has ``value`` None and
``pass`` None: the verdict passes only when every measured criterion passes, and says whether it
is complete.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from workstation.core.errors import InvalidInputError


@dataclass(frozen=True)
class Spec:
    """The thresholds of one delivery specification (metres, points/m²; None: not required).

    Attributes
    ----------
    name : str
        As given on the command line (``usgs-ql2``, ``asprs-10cm``).
    anpd_min : float or None
        Aggregate nominal point density, first returns of single swaths (points/m²).
    anps_max : float or None
        Aggregate nominal point spacing (m).
    coverage_min : float
        Share of 2×ANPS cells holding at least one first return (USGS: 0.90).
    intraswath_max : float or None
        Smooth-surface precision within a swath (m).
    rmsdz_max, max_dz : float or None
        Interswath RMSDz and largest absolute difference on smooth surfaces (m).
    rmsez_max : float or None
        Non-vegetated RMSEz (m).
    nva_max, vva_max : float or None
        ASPRS 2014 forms: NVA = 1.96·RMSEz and VVA = 95th percentile (m); None where the
        specification does not test them.
    min_checkpoints : int
        Fewest non-vegetated checkpoints for an accuracy statement.
    dem_cell_min : float or None
        Smallest DEM cell the specification allows (m).
    """

    name: str
    anpd_min: float | None = None
    anps_max: float | None = None
    coverage_min: float = 0.90
    intraswath_max: float | None = None
    rmsdz_max: float | None = None
    max_dz: float | None = None
    rmsez_max: float | None = None
    nva_max: float | None = None
    vva_max: float | None = None
    min_checkpoints: int = 20
    dem_cell_min: float | None = None
    source: str = ""


_LBS = "USGS Lidar Base Specification 2.x, tables 1, 2, 4 and 6"
USGS = {
    "usgs-ql0": Spec("usgs-ql0", 8.0, 0.35, 0.90, 0.04, 0.05, 0.10, 0.05, 0.098, 0.15, 20, 0.5, _LBS),
    "usgs-ql1": Spec("usgs-ql1", 8.0, 0.35, 0.90, 0.06, 0.08, 0.16, 0.10, 0.196, 0.30, 20, 0.5, _LBS),
    "usgs-ql2": Spec("usgs-ql2", 2.0, 0.71, 0.90, 0.06, 0.08, 0.16, 0.10, 0.196, 0.30, 20, 1.0, _LBS),
    "usgs-ql3": Spec("usgs-ql3", 0.5, 1.41, 0.90, 0.12, 0.16, 0.32, 0.20, 0.392, 0.60, 20, 2.0, _LBS),
}
SPEC_NAMES = (*USGS, "asprs-<X>cm")


def asprs_class(x_cm: float) -> Spec:
    """The ASPRS Edition 2 vertical accuracy class of X cm (RMSEv ≤ X, ≥ 30 checkpoints), with
    the 2014 relative-accuracy ratios for lidar swaths."""
    x = x_cm / 100.0
    return Spec(f"asprs-{x_cm:g}cm", None, None, 0.90, 0.6 * x, 0.8 * x, 1.6 * x, x, None, None, 30, None,
                "ASPRS Positional Accuracy Standards, Edition 2 (2023), with Edition 1 table B.3 ratios")


def get_spec(name: str) -> Spec:
    """The specification called ``name`` (case-insensitive)."""
    key = name.strip().lower()
    if key in USGS:
        return USGS[key]
    m = re.fullmatch(r"asprs-(\d+(?:\.\d+)?)cm", key)
    if m and 0 < float(m.group(1)) <= 1000:
        return asprs_class(float(m.group(1)))
    raise InvalidInputError(f"unknown specification {name!r}",
                            "use usgs-ql0, usgs-ql1, usgs-ql2, usgs-ql3 or asprs-<X>cm (e.g. asprs-10cm)",
                            field="--spec")


def criterion(name: str, value, threshold, op: str, unit: str = "") -> dict:
    """One row of the verdict: ``value op threshold`` (op "<=" or ">="), None when unmeasured."""
    if value is None or threshold is None:
        ok = None
    else:
        ok = bool(value <= threshold) if op == "<=" else bool(value >= threshold)
    return {"name": name, "value": value, "threshold": threshold, "op": op, "unit": unit, "pass": ok}


def dig(d: dict | None, *keys):
    """``d[k1][k2]...``, or None where a level is missing or None."""
    for k in keys:
        if not isinstance(d, dict) or d.get(k) is None:
            return None
        d = d[k]
    return d


def verdict(spec: Spec, results: dict) -> dict:
    """The specification's table measured on ``results`` (the QC result document, lengths in m)."""
    density, coverage, swath = results.get("density"), results.get("coverage_detail"), results.get("swath")
    acc, dem = results.get("accuracy"), results.get("dem_accuracy")
    pairs = [p for p in (dig(swath, "swaths") or []) if p.get("cells", 0) > 0]
    intra = [s["precision_m"] for s in (dig(swath, "intraswath") or []) if s.get("precision_m") is not None]
    rows = []
    if spec.anpd_min is not None:
        rows.append(criterion("ANPD, first returns of single swaths", dig(density, "anpd"), spec.anpd_min, ">=", "pts/m²"))
        rows.append(criterion("ANPS", dig(density, "anps"), spec.anps_max, "<=", "m"))
    rows.append(criterion("cells of 2×ANPS holding a first return", dig(coverage, "coverage"), spec.coverage_min, ">=", ""))
    rows.append(criterion("intraswath smooth-surface precision (worst swath)", max(intra) if intra else None,
                          spec.intraswath_max, "<=", "m"))
    rows.append(criterion("interswath RMSDz (worst pair)", max(p["rmsdz"] for p in pairs) if pairs else None,
                          spec.rmsdz_max, "<=", "m"))
    rows.append(criterion("interswath max |dz| (worst pair)", max(p["max_abs_dz"] for p in pairs) if pairs else None,
                          spec.max_dz, "<=", "m"))
    rows += _accuracy_rows(spec, acc)
    if dem is not None and spec.dem_cell_min is not None:
        rows.append(criterion("DEM cell size", dig(dem, "cell_m"), spec.dem_cell_min, ">=", "m"))
    measured = [r for r in rows if r["pass"] is not None]
    return {"spec": spec.name, "source": spec.source, "pass": all(r["pass"] for r in measured),
            "complete": len(measured) == len(rows), "criteria": rows}


def _accuracy_rows(spec: Spec, acc: dict | None) -> list[dict]:
    """Absolute vertical accuracy rows: RMSEz (Edition 2 combines the checkpoints' own accuracy),
    NVA/VVA (2014 forms) where the specification tests them, and the checkpoint count."""
    n_nva = dig(acc, "n_nonvegetated")
    rmse = dig(acc, "edition2", "rmsev") if spec.name.startswith("asprs") else dig(acc, "asprs2014", "rmsez")
    rows = [criterion("non-vegetated checkpoints", n_nva, spec.min_checkpoints, ">=", ""),
            criterion("RMSEz, non-vegetated" + (" (checkpoint accuracy included)" if spec.name.startswith("asprs") else ""),
                      rmse, spec.rmsez_max, "<=", "m")]
    if spec.nva_max is not None:
        rows.append(criterion("NVA = 1.96·RMSEz", dig(acc, "asprs2014", "nva"), spec.nva_max, "<=", "m"))
    if spec.vva_max is not None:
        rows.append(criterion("VVA, 95th percentile", dig(acc, "asprs2014", "vva"), spec.vva_max, "<=", "m"))
    return rows
