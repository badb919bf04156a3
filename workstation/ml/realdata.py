"""Scores of a point classifier on real scans (used by the benchmark, the model card and tests).

* ISPRS filter test samples (Sithole & Vosselman 2004): Type I, Type II, total error, kappa
  of ground vs object (:func:`workstation.ground.evaluate.ground_errors`).
* Vendor-classified tiles: the terrain under the predicted ground against the terrain under
  the file's own ground class, both as 1 m TIN DTMs, RMSE in metres over the cells inside both
  TINs' hulls (vendor ground classes are not point-wise references); building, water and
  vegetation (3-5 together) F1 against the file's classes.

References
----------
G. Sithole, G. Vosselman (2004). Experimental comparison of filter algorithms for bare-Earth
extraction from airborne laser scanning point clouds. ISPRS J. 59(1-2):85-101.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from workstation.core.classes import ASPRSClass as C

ISPRS_SAMPLES = ("samp11", "samp21", "samp31", "samp42", "samp51", "samp61")
DTM_FILES = ("Topography.laz", "bcts_1.laz", "bcts_2.laz", "autzen_trim.las", "MixedConifer.laz")
BUILDING_FILES = ("sample_c.las", "lidarhd_extra_bytes.laz")
#: other files with vegetation classes (scored for vegetation F1 as well)
VEGETATION_FILES = ("warsaw_small.las",)
VEG = (int(C.LOW_VEGETATION), int(C.MEDIUM_VEGETATION), int(C.HIGH_VEGETATION))


def isprs_scores(predict_ground, root) -> dict[str, dict]:
    """Per-sample ISPRS errors (%) of ``predict_ground(cloud) -> (n,) bool``.

    Returns
    -------
    dict
        sample -> {"type1", "type2", "total", "kappa"} in percent, plus "mean_total".
    """
    from workstation.ground.evaluate import ground_errors, read_isprs_text

    out = {}
    for s in ISPRS_SAMPLES:
        p = Path(root) / f"{s}.txt"
        if not p.exists():
            continue
        ref = read_isprs_text(p)
        ref_g = np.asarray(ref.attrs["label"]) == 0
        pred = predict_ground(ref.without_attrs("label", "classification"))
        e = ground_errors(ref_g, pred)
        out[s] = {"type1": 100 * e.type1, "type2": 100 * e.type2, "total": 100 * e.total_error, "kappa": 100 * e.kappa}
    if out:
        out["mean_total"] = float(np.mean([v["total"] for v in out.values()]))
    return out


def dtm_rmse(xyz: np.ndarray, ref_ground: np.ndarray, pred_ground: np.ndarray, v_factor: float = 1.0,
             h_factor: float = 1.0, cell: float = 1.0) -> float:
    """RMSE (m) between two 1 m TIN DTMs: from the reference and the predicted ground points.

    Both TINs are sampled at the centres of ``cell``-metre cells (in metres, converted with the
    CRS factors); cells outside either TIN's hull are left out.
    """
    lo = xyz[:, :2].min(axis=0)
    xy = (xyz[:, :2] - lo) * h_factor
    z = xyz[:, 2] * v_factor
    if ref_ground.sum() < 3 or pred_ground.sum() < 3:
        return float("nan")
    ext = xy.max(axis=0)
    gx, gy = np.meshgrid(np.arange(cell / 2, ext[0], cell), np.arange(cell / 2, ext[1], cell))
    q = np.column_stack([gx.ravel(), gy.ravel()])
    a = _tin(xy[ref_ground], z[ref_ground], q)
    b = _tin(xy[pred_ground], z[pred_ground], q)
    ok = np.isfinite(a) & np.isfinite(b)
    return float(np.sqrt(np.mean((a[ok] - b[ok]) ** 2))) if ok.any() else float("nan")


def _tin(xy: np.ndarray, z: np.ndarray, q: np.ndarray) -> np.ndarray:
    """Linear TIN interpolation at ``q`` (NaN outside the hull). matplotlib's trapezoid-map
    triangle finder: scipy's ``find_simplex`` walks slowly on scan-line slivers."""
    import matplotlib.tri as mtri

    # one point per 1 cm (duplicates make Delaunay degenerate), lowest kept
    key = np.round(xy * 100).astype(np.int64)
    order = np.lexsort((z, key[:, 1], key[:, 0]))
    k = key[order]
    first = np.r_[True, (k[1:] != k[:-1]).any(axis=1)]
    sel = order[first]
    tri = mtri.Triangulation(xy[sel, 0], xy[sel, 1])
    out = mtri.LinearTriInterpolator(tri, z[sel])(q[:, 0], q[:, 1])
    return np.ma.filled(out.astype(np.float64), np.nan)


def f1(ref: np.ndarray, pred: np.ndarray) -> float:
    """F1 of two boolean masks (NaN when the reference is empty)."""
    tp = float((ref & pred).sum())
    if ref.sum() == 0:
        return float("nan")
    den = float(ref.sum() + pred.sum())
    return 2 * tp / den if den else float("nan")


def tile_scores(classify, path) -> dict:
    """Scores of ``classify(cloud) -> (n,) uint8 codes`` on one classified real file."""
    from workstation.ground.common import crs_unit_factors
    from workstation.io import read_cloud

    cloud = read_cloud(path)
    ref = np.asarray(cloud.attrs["classification"])
    pred = classify(cloud)
    try:
        hf, vf = crs_unit_factors(cloud.crs)
    except Exception:
        hf, vf = 1.0, 1.0
    out: dict = {"points": cloud.n}
    name = Path(path).name
    if name in DTM_FILES and (ref == C.GROUND).sum() >= 3:
        out["dtm_rmse_m"] = dtm_rmse(np.asarray(cloud.xyz), ref == C.GROUND, pred == C.GROUND, vf, hf)
    if (ref == C.BUILDING).any():
        out["building_f1"] = f1(ref == C.BUILDING, pred == C.BUILDING)
    if (ref == C.WATER).any():
        out["water_f1"] = f1(ref == C.WATER, pred == C.WATER)
    if np.isin(ref, VEG).any():
        out["vegetation_f1"] = f1(np.isin(ref, VEG), np.isin(pred, VEG))
    out["ground_f1"] = f1(ref == C.GROUND, pred == C.GROUND)
    return out
