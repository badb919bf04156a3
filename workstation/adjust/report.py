"""Before/after figures of a strip adjustment: the swath separation of ``ws qc`` and the estimates.

The swath separation (RMSDz per overlapping pair on smooth surfaces, USGS Lidar Base
Specification) is measured by :class:`workstation.qc.swath.SwathPass` on a grid of 2 × the
aggregate nominal point spacing (ANPS = 1/sqrt(points per occupied square metre)), the cell of
its DZ ortho, once on the delivered and once on the adjusted points.
"""

from __future__ import annotations

import numpy as np

from workstation.core.cloud import Cloud

from .adjust import AdjustResult
from .models import BORESIGHT, LEVERARM


def swath_pass(xyz: np.ndarray, attrs: dict, cell_m: float | None = None):
    """A filled :class:`~workstation.qc.swath.SwathPass` of the points (metres)."""
    from workstation.core.units import METRES
    from workstation.qc.context import QCGrid
    from workstation.qc.swath import SwathPass

    if cell_m is None:
        q = np.floor(xyz[:, :2]).astype(np.int64)
        q -= q.min(axis=0)
        occupied = np.unique(q[:, 0] * (int(q[:, 1].max()) + 1) + q[:, 1]).size
        cell_m = 2.0 / np.sqrt(len(xyz) / max(occupied, 1))
    lo, hi = xyz.min(axis=0), xyz.max(axis=0)
    p = SwathPass(QCGrid.over((lo[0], lo[1], hi[0], hi[1]), float(cell_m), METRES))
    keep = [k for k in ("point_source_id", "number_of_returns", "classification", "withheld") if k in attrs]
    p.add(Cloud(xyz, {k: attrs[k] for k in keep}))
    return p


def pair_table(before: dict, after: dict) -> list[dict]:
    """Per strip pair: RMSDz and mean DZ before and after (m) and the cells measured."""
    aft = {(s["a"], s["b"]): s for s in after["swaths"]}
    out = []
    for s in before["swaths"]:
        t = aft.get((s["a"], s["b"]))
        out.append({"a": s["a"], "b": s["b"], "rmsdz_before_m": s["rmsdz"], "rmsdz_after_m": t["rmsdz"] if t else None,
                    "mean_dz_before_m": s["mean_dz"], "mean_dz_after_m": t["mean_dz"] if t else None,
                    "cells_before": s["cells"], "cells_after": t["cells"] if t else 0})
    return out


def _triple(res: AdjustResult, names, conv) -> tuple[list | None, list | None]:
    if not all(n in res.names for n in names):
        return None, None
    idx = [res.names.index(n) for n in names]
    val = [conv(res.values[i]) if res.determined[i] else None for i in idx]
    sig = [conv(res.sigmas[i]) if res.determined[i] else None for i in idx]
    return val, sig


def result_dict(res: AdjustResult) -> dict:
    """JSON-ready estimates: headline keys (angles in degrees, lengths in metres, the scan-angle
    scale unitless; None where not estimated or not determined), every unknown with its unit,
    correlations, strips and per strip pair the RMS of the patch distances before and after."""
    deg = lambda v: float(np.degrees(v))  # noqa: E731
    m = float
    bore, bore_s = _triple(res, BORESIGHT, deg)
    lever, lever_s = _triple(res, LEVERARM, m)
    rng, rng_s = _triple(res, ("range_offset",), m)
    scan, scan_s = _triple(res, ("scan_angle_scale",), m)
    unit = lambda n: "degree" if n in BORESIGHT else "1" if n == "scan_angle_scale" else "metre"  # noqa: E731
    params = [{"name": n, "value": deg(v) if n in BORESIGHT else float(v),
               "sigma": (deg(s) if n in BORESIGHT else float(s)) if d else None, "unit": unit(n), "determined": bool(d)}
              for n, v, s, d in zip(res.names, res.values, res.sigmas, res.determined)]
    strips, shifted = [], any(n.startswith("strip_") for n in res.names)
    for sid in res.strips:
        if not shifted:
            strips.append({"id": sid, "fixed": False, "shift_m": [0.0, 0.0, 0.0], "shift_sigma_m": None})
            continue
        names = [f"strip_{sid}_{a}" for a in "xyz"]
        if sid == res.fixed_strip or not all(n in res.names for n in names):
            strips.append({"id": sid, "fixed": sid == res.fixed_strip, "shift_m": [0.0, 0.0, 0.0], "shift_sigma_m": None})
            continue
        v, s = _triple(res, names, m)
        strips.append({"id": sid, "fixed": False, "shift_m": v, "shift_sigma_m": s})
    return {
        "model": res.model, "boresight_deg": bore, "boresight_sigma_deg": bore_s,
        "range_offset_m": rng[0] if rng else None, "range_offset_sigma_m": rng_s[0] if rng_s else None,
        "lever_arm_m": lever, "lever_arm_sigma_m": lever_s, "scan_angle_scale": scan[0] if scan else None,
        "scan_angle_scale_sigma": scan_s[0] if scan_s else None, "strips": strips, "fixed_strip": res.fixed_strip if shifted else None,
        "parameters": params, "correlation": {"names": res.names, "matrix": np.round(res.correlation, 4).tolist()},
        "not_determined": res.null_directions, "correspondences": res.correspondences, "inliers": res.inliers,
        "iterations": res.iterations, "sigma0": res.sigma0, "noise_m": res.noise_m, "cell_m": res.cell_m,
        "patch_rms_before_m": res.rms_before_m, "patch_rms_after_m": res.rms_after_m, "patch_pairs": res.pairs, "seconds_estimate": res.seconds,
    }
