"""Georeferencing with ground control points and an independent accuracy check.

Control points fix a 7-parameter similarity (scale, rotation, translation) from the model frame
to the survey frame by the closed-form least-squares solution of Umeyama (1991, "Least-squares
estimation of transformation parameters between two point patterns", IEEE TPAMI 13(4)), the
same as Horn's (1987) quaternion solution. **Check points are never used in the fit**; their
residuals give the accuracy report:

* RMSE X, Y, Z, horizontal ``RMSE_r = sqrt(RMSE_x² + RMSE_y²)`` and 3-D;
* CE90 = 1.5175 · RMSE_r and LE90 = 1.6449 · RMSE_z (circular and linear errors at 90 %
  confidence for normally distributed errors with RMSE_x ≈ RMSE_y; FGDC-STD-007.3-1998 NSSDA
  Appendix 3-A, and Greenwalt & Schultz 1968);
* the 95 % figures of ASPRS *Positional Accuracy Standards for Digital Geospatial Data*
  (Ed. 1, 2014, §7.5 and §7.6 / NSSDA): horizontal 1.7308 · RMSE_r, vertical 1.9600 · RMSE_z;
* the DEM cell size and contour interval the accuracy supports, by the "3× rule" of the
  photogrammetric-products lecture (/work/shared/seeds/photogrammetric_products_lecture.txt:
  a product's cell must be at least three times the accuracy reported for it, so a point
  known to ±s lies in its cell; contours every 3 × s_z — the 20 m interval of 6.66 m accurate
  Survey of India sheets): cell ≥ 3 · RMSE_r, vertical resolution and contour interval
  ≥ 3 · RMSE_z.

Points given by image observations are triangulated first by space intersection from the
oriented images of the reconstruction (:func:`~.collinearity.intersect`).

When the reconstruction carries its tie-point tracks and at least 3 control points have ≥ 2
image observations, the similarity is followed by a bundle adjustment with GCP constraints
(:mod:`.bundle`): it removes the bends and scale drifts of the SfM model that a similarity
cannot. Check points stay out of it too; the report then gives their RMSE after the
adjustment (``check_*``) and with the similarity alone (``similarity_check_*``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping, Sequence

import numpy as np

from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Image, Pose, QCReport, Reconstruction

from .collinearity import intersect

log = get_logger(__name__)

CE90_FACTOR = 1.5175
LE90_FACTOR = 1.6449
H95_FACTOR = 1.7308
V95_FACTOR = 1.9600


@dataclass(frozen=True)
class Similarity:
    """``X_target = scale · R @ X_source + t``.

    Attributes
    ----------
    scale : float
    R : (3, 3) float
    t : (3,) float
    """

    scale: float
    R: np.ndarray
    t: np.ndarray

    def apply(self, X: np.ndarray) -> np.ndarray:
        """Transform (n, 3) points."""
        return self.scale * np.asarray(X, dtype=float) @ np.asarray(self.R).T + self.t

    @property
    def matrix(self) -> np.ndarray:
        """(4, 4) homogeneous matrix."""
        m = np.eye(4)
        m[:3, :3] = self.scale * self.R
        m[:3, 3] = self.t
        return m

    def apply_pose(self, pose: Pose) -> Pose:
        """The pose of the same camera in the target frame."""
        Rc = np.asarray(pose.R) @ np.asarray(self.R).T
        return Pose(Rc, self.scale * np.asarray(pose.t) - Rc @ self.t)

    def to_dict(self) -> dict:
        return {"scale": float(self.scale), "R": np.asarray(self.R).tolist(), "t": np.asarray(self.t).tolist()}


def fit_similarity(src: np.ndarray, dst: np.ndarray, with_scale: bool = True) -> Similarity:
    """Least-squares similarity ``dst ≈ s R src + t`` (Umeyama 1991).

    Parameters
    ----------
    src, dst : (n, 3) float
        Corresponding points, n ≥ 3 and not collinear.
    with_scale : bool
        Estimate the scale (7 parameters) or keep it 1 (6, rigid).

    Returns
    -------
    Similarity

    Raises
    ------
    InvalidInputError
        Fewer than 3 points, or collinear points (the rotation about their line is free).

    Examples
    --------
    >>> from workstation.photogrammetry.collinearity import opk_to_matrix
    >>> src = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
    >>> R = opk_to_matrix(0.1, 0.2, 0.3)
    >>> sim = fit_similarity(src, 2.5 * src @ R.T + [10, 20, 30])
    >>> round(sim.scale, 9), np.allclose(sim.R, R), np.round(sim.t, 9).tolist()
    (2.5, True, [10.0, 20.0, 30.0])
    """
    src = np.asarray(src, dtype=float)
    dst = np.asarray(dst, dtype=float)
    if src.shape != dst.shape or src.ndim != 2 or src.shape[1] != 3:
        raise InvalidInputError(f"need two (n, 3) arrays of equal shape, got {src.shape} and {dst.shape}")
    n = src.shape[0]
    if n < 3:
        raise InvalidInputError(
            f"a 7-parameter similarity needs at least 3 control points, got {n}: {n} points give "
            f"{3 * n} equations for 7 unknowns (3 shifts, 3 rotations, 1 scale), and with 2 points the "
            "rotation about the line joining them stays free",
            "survey at least 3 well-spread control points (5 or more recommended), not on one line",
        )
    mu_s, mu_d = src.mean(0), dst.mean(0)
    a, b = src - mu_s, dst - mu_d
    sv = np.linalg.svd(a, compute_uv=False)
    if sv[0] <= 0 or sv[1] < 1e-9 * sv[0]:
        raise InvalidInputError(
            "the control points are collinear: the rotation about their line is undetermined",
            "add a control point off the line",
        )
    Sigma = b.T @ a / n
    U, D, Vt = np.linalg.svd(Sigma)
    S = np.eye(3)
    if np.linalg.det(U) * np.linalg.det(Vt) < 0:
        S[2, 2] = -1
    R = U @ S @ Vt
    var_s = np.mean(np.sum(a**2, axis=1))
    s = float(np.trace(np.diag(D) @ S) / var_s) if with_scale else 1.0
    t = mu_d - s * R @ mu_s
    return Similarity(s, R, t)


def accuracy_report(estimated: np.ndarray, surveyed: np.ndarray) -> dict[str, float]:
    """RMSE, CE90/LE90, ASPRS/NSSDA 95 % figures and 3×-rule product limits from check points.

    Parameters
    ----------
    estimated, surveyed : (n, 3) float
        Check point coordinates from the georeferenced model and from the survey.

    Returns
    -------
    dict
        ``n``, ``rmse_x``, ``rmse_y``, ``rmse_z``, ``rmse_h``, ``rmse_3d``, ``mean_dx`` ...,
        ``ce90``, ``le90``, ``accuracy_h95``, ``accuracy_v95``, ``dem_cell_size_min``,
        ``dem_vertical_resolution_min``, ``contour_interval_min`` (all in survey units).

    Examples
    --------
    >>> est = np.array([[0.1, 0, 0.2], [-0.1, 0, -0.2], [0, 0.1, 0.2], [0, -0.1, -0.2]])
    >>> r = accuracy_report(est, np.zeros((4, 3)))
    >>> round(r["rmse_h"], 4), round(r["rmse_z"], 4), round(r["ce90"], 4), round(r["contour_interval_min"], 4)
    (0.1, 0.2, 0.1518, 0.6)
    """
    e = np.asarray(estimated, dtype=float) - np.asarray(surveyed, dtype=float)
    n = e.shape[0]
    if n == 0:
        raise InvalidInputError("no check points to measure accuracy with")
    rx, ry, rz = np.sqrt(np.mean(e**2, axis=0))
    rh = float(np.hypot(rx, ry))
    return {
        "n": int(n),
        "mean_dx": float(e[:, 0].mean()),
        "mean_dy": float(e[:, 1].mean()),
        "mean_dz": float(e[:, 2].mean()),
        "rmse_x": float(rx),
        "rmse_y": float(ry),
        "rmse_z": float(rz),
        "rmse_h": rh,
        "rmse_3d": float(np.sqrt(rx**2 + ry**2 + rz**2)),
        "max_h": float(np.max(np.hypot(e[:, 0], e[:, 1]))),
        "max_abs_z": float(np.max(np.abs(e[:, 2]))),
        "ce90": CE90_FACTOR * rh,
        "le90": LE90_FACTOR * float(rz),
        "accuracy_h95": H95_FACTOR * rh,
        "accuracy_v95": V95_FACTOR * float(rz),
        "dem_cell_size_min": 3.0 * rh,
        "dem_vertical_resolution_min": 3.0 * float(rz),
        "contour_interval_min": 3.0 * float(rz),
    }


@dataclass(frozen=True)
class GeorefResult:
    """Outcome of :func:`georeference`.

    Attributes
    ----------
    similarity : Similarity
        Model -> survey frame.
    report : QCReport
        ``metrics``: accuracy of the check points (:func:`accuracy_report`, prefixed ``check_``)
        and of the control points (``control_rmse_*``, a fit statistic, not an accuracy);
        ``tables["points"]``: per-point residuals (name, role, dX, dY, dZ, dH, d3D, and the
        triangulation std and ray count when triangulated); ``notes``.
    reconstruction : Reconstruction or None
        The input reconstruction moved into the survey frame (and adjusted when the bundle
        adjustment ran).
    meta : mapping
        ``adjustment``: "bundle" or "similarity"; ``bundle``: the adjustment's statistics
        (:class:`.bundle.BundleResult` ``stats``) when it ran.
    """

    similarity: Similarity
    report: QCReport
    reconstruction: Reconstruction | None = None
    meta: Mapping[str, Any] = field(default_factory=dict)

    def to_dict(self) -> dict:
        out = {
            "adjustment": self.meta.get("adjustment", "similarity"),
            "similarity": self.similarity.to_dict(),
            "metrics": dict(self.report.metrics),
            "points": list(self.report.tables.get("points", [])),
            "notes": list(self.report.notes),
        }
        if "bundle" in self.meta:
            out["bundle"] = dict(self.meta["bundle"])
        return out


def image_lookup(rec: Reconstruction) -> dict[str, Image]:
    """Images by name and by file name (a name given without its sub-folder still matches)."""
    out: dict[str, Image] = {}
    for im in rec.images.values():
        out[im.name] = im
        out.setdefault(im.name.rsplit("/", 1)[-1], im)
    return out


def triangulate_gcps(gcps: Sequence, rec: Reconstruction, sigma_px: float = 1.0):
    """Model-frame positions of GCPs from their image observations (space intersection).

    Returns
    -------
    positions : dict name -> (3,) model coordinates (also for points given with model_xyz)
    info : dict name -> {"rays", "std_model", "rms_px", "angle_deg"} for triangulated points
    problems : dict name -> reason for points that cannot be placed in the model
    """
    lookup = image_lookup(rec) if rec is not None else {}
    positions, info, problems = {}, {}, {}
    for g in gcps:
        if g.model_xyz is not None:
            positions[g.name] = np.asarray(g.model_xyz, dtype=float)
            continue
        cams, poses, uv, missing = [], [], [], []
        for img, u, v in g.observations:
            im = lookup.get(img) or lookup.get(str(img).rsplit("/", 1)[-1])
            if im is None:
                missing.append(img)
                continue
            cams.append(rec.cameras[im.camera_id])
            poses.append(im.pose)
            uv.append((u, v))
        if missing:
            log.warning("GCP %s: image(s) not in the reconstruction: %s", g.name, ", ".join(missing))
        if len(uv) < 2:
            why = "no model position (mx, my, mz) and " if not g.observations else ""
            problems[g.name] = why + f"{len(uv)} observation(s) in oriented images (≥ 2 needed)" + (
                f"; missing image(s): {', '.join(missing)}" if missing else ""
            )
            continue
        res = intersect(np.array(uv), cams, poses, sigma_px=sigma_px)
        positions[g.name] = res.point
        info[g.name] = {"rays": len(uv), "std_model": res.std.tolist(), "rms_px": res.rms_px, "angle_deg": res.max_angle_deg}
    return positions, info, problems


def transform_reconstruction(rec: Reconstruction, sim: Similarity, crs: str | None = None) -> Reconstruction:
    """A new reconstruction with poses and points mapped by ``sim`` (tracks carried over)."""
    images = {
        k: Image(im.name, im.camera_id, sim.apply_pose(im.pose), im.path) for k, im in rec.images.items()
    }
    pts = None if rec.points is None else sim.apply(rec.points)
    meta = dict(rec.meta)
    meta["georeference"] = sim.to_dict()
    return Reconstruction(dict(rec.cameras), images, pts, rec.colors, crs if crs is not None else rec.crs, meta, rec.tracks)


ADJUSTMENTS = ("auto", "similarity", "bundle")


def _residual_rows(points: Sequence, positions: Mapping[str, np.ndarray], info: Mapping[str, dict], to_survey, scale: float) -> list[dict]:
    rows = []
    for g in points:
        est = to_survey(positions[g.name][None])[0]
        d = est - np.asarray(g.xyz)
        row = {
            "name": g.name,
            "role": g.role,
            "X": float(g.xyz[0]),
            "Y": float(g.xyz[1]),
            "Z": float(g.xyz[2]),
            "dX": float(d[0]),
            "dY": float(d[1]),
            "dZ": float(d[2]),
            "dH": float(np.hypot(d[0], d[1])),
            "d3D": float(np.linalg.norm(d)),
        }
        if g.name in info:
            row["rays"] = info[g.name]["rays"]
            row["std_xyz"] = [scale * s for s in info[g.name]["std_model"]]
            row["image_rms_px"] = info[g.name]["rms_px"]
        rows.append(row)
    return rows


def _metrics(rows: list[dict], prefix_check: str = "check_") -> dict[str, Any]:
    out: dict[str, Any] = {}
    ctrl = np.array([[r["dX"], r["dY"], r["dZ"]] for r in rows if r["role"] == "control"])
    if len(ctrl):
        c = accuracy_report(ctrl, np.zeros_like(ctrl))
        out.update({f"control_{k}": c[k] for k in ("rmse_x", "rmse_y", "rmse_z", "rmse_h", "rmse_3d")})
    chk = np.array([[r["dX"], r["dY"], r["dZ"]] for r in rows if r["role"] == "check"])
    if len(chk):
        out.update({f"{prefix_check}{k}": v for k, v in accuracy_report(chk, np.zeros_like(chk)).items()})
    else:
        out[f"{prefix_check}n"] = 0
    return out


def bundle_possible(gcps: Sequence, reconstruction: Reconstruction | None, info: Mapping[str, dict]) -> tuple[bool, str]:
    """Whether :func:`georeference` can run the bundle adjustment, and why not.

    It runs when the reconstruction carries tie-point tracks and at least 3 control points
    were intersected from ≥ 2 image observations in its oriented images.
    """
    if reconstruction is None:
        return False, "no reconstruction (control points given in model coordinates only)"
    if reconstruction.tracks is None or reconstruction.points is None or len(reconstruction.tracks) == 0:
        return False, "the reconstruction carries no tie-point observations (tracks)"
    n = sum(1 for g in gcps if g.role == "control" and g.name in info)
    if n < 3:
        return False, f"only {n} control point(s) have ≥ 2 image observations in oriented images (3 needed)"
    return True, ""


def _model_positions(gcps: Sequence, reconstruction: Reconstruction | None, sigma_px: float):
    """(positions, info, problems) as :func:`triangulate_gcps`; without a reconstruction only
    the points given in model coordinates have a position."""
    if reconstruction is not None:
        return triangulate_gcps(gcps, reconstruction, sigma_px)
    return (
        {g.name: np.asarray(g.model_xyz, dtype=float) for g in gcps if g.model_xyz is not None},
        {},
        {g.name: "no model position (mx, my, mz) and no reconstruction to triangulate in" for g in gcps if g.model_xyz is None},
    )


def _report(control, check, positions, info, to_survey, sim: Similarity, scale: float | None = None):
    """Residual rows of the control and check points at ``positions`` mapped by ``to_survey``
    (triangulation std scaled by ``scale``, default the similarity's) and their metrics."""
    rows = _residual_rows(control + check, positions, info, to_survey, sim.scale if scale is None else scale)
    metrics: dict[str, Any] = {"control_n": len(control), "scale": sim.scale}
    metrics.update(_metrics(rows))
    return rows, metrics


def _fit_control(control: Sequence, positions: Mapping[str, np.ndarray], notes: list) -> Similarity:
    """The model -> survey similarity of the control points (≥ 3 needed)."""
    if len(control) <= 2:
        raise InvalidInputError(
            f"only {len(control)} usable control point(s): a 7-parameter similarity (3 shifts, 3 rotations, "
            "1 scale) needs at least 3 control points not on one line — 2 points leave the rotation about "
            "their joining line free, 1 point fixes only the shift"
            + (f" ({'; '.join(notes)})" if notes else ""),
            "add control points (5+ spread over the site recommended) or change the role of some check points",
        )
    src = np.array([positions[g.name] for g in control])
    dst = np.array([g.xyz for g in control])
    sim = fit_similarity(src, dst)
    if not np.isfinite(sim.scale) or sim.scale <= 0:
        raise StageError("georeference", "the similarity has a non-positive scale", "check the GCP names and coordinates")
    return sim


def _bundle_refinement(control, check, sim: Similarity, positions, info, rec: Reconstruction, sigma_px: float, bundle,
                       sim_metrics: dict, notes: list):
    """Run :func:`.bundle.bundle_adjust` on the similarity-transformed model ``rec`` and
    intersect the control and check points again from the adjusted images.

    Returns the residual rows, the metrics (with the similarity-only RMSEs as
    ``similarity_*``), the result meta and the adjusted reconstruction; appends to ``notes``.
    """
    import dataclasses

    from .bundle import BundleParams, bundle_adjust

    bp = dataclasses.replace(bundle if bundle is not None else BundleParams(), sigma_px=sigma_px)
    ba = bundle_adjust(rec, [g for g in control if g.name in info], bp)
    pos2, info2, problems2 = triangulate_gcps(control + check, ba.reconstruction, sigma_px)
    lost = [g for g in control + check if g.name not in pos2]
    for g in lost:
        notes.append(f"{g.name}: not intersected after the bundle adjustment ({problems2.get(g.name, '')}); similarity position kept")
        pos2[g.name] = sim.apply(positions[g.name][None])[0]
    rows, metrics = _report(control, check, pos2, info2, lambda X: np.asarray(X, dtype=float), sim, 1.0)
    metrics.update({f"similarity_{k}": v for k, v in sim_metrics.items() if k.startswith(("check_rmse", "control_rmse"))})
    notes.append(
        f"bundle adjustment with {ba.stats['control_points']} control points, {ba.stats['tie_points']} tie points and "
        f"{ba.stats['free_images']} images: image RMS {ba.stats['rms_px_before']:.3f} -> {ba.stats['rms_px_after']:.3f} px"
        + (
            f"; check RMSE 3D {sim_metrics['check_rmse_3d']:.4g} (similarity) -> {metrics['check_rmse_3d']:.4g}"
            if check else ""
        )
    )
    return rows, metrics, {"adjustment": "bundle", "bundle": dict(ba.stats)}, ba.reconstruction


def _check_point_notes(check: Sequence) -> list[str]:
    """Notes on the number of check points behind the accuracy figures."""
    notes = []
    if not check:
        notes.append(
            "no check points: the accuracy is unknown (control residuals measure the fit only); "
            "mark some surveyed points as role=check"
        )
    if len(check) and len(check) < 20:
        notes.append(f"{len(check)} check points: ASPRS (2014) asks for at least 20 for a formal accuracy statement")
    return notes


def georeference(
    gcps: Sequence,
    reconstruction: Reconstruction | None = None,
    sigma_px: float = 1.0,
    crs: str | None = None,
    adjustment: str = "auto",
    bundle: Any = None,
) -> GeorefResult:
    """Fix the model -> survey similarity from control points, refine by a bundle adjustment
    with GCP constraints where the observations allow, and report check-point accuracy.

    1. Every GCP with image observations is intersected in the model (space intersection);
       control points fix the 7-parameter similarity (Umeyama 1991).
    2. With ``adjustment`` "auto" or "bundle", and when :func:`bundle_possible`, the
       similarity-transformed model goes through :func:`.bundle.bundle_adjust` (check points
       never enter it). Otherwise (or with "similarity") the similarity alone georeferences
       the model, and a note says why.
    3. Check points are intersected from the final images and compared with their survey
       coordinates; with the bundle adjustment the similarity-only figures are kept as
       ``similarity_check_*`` (before) beside ``check_*`` (after).

    Parameters
    ----------
    gcps : sequence of :class:`workstation.io.gcp.GCP`
    reconstruction : Reconstruction, optional
        Needed for points given by image observations; returned transformed (and adjusted).
    sigma_px : float
        A-priori image measurement precision for the intersections and the adjustment, pixels.
    crs : str, optional
        CRS of the survey coordinates, recorded on the result.
    adjustment : {"auto", "similarity", "bundle"}
        "bundle" raises when the bundle adjustment cannot run.
    bundle : BundleParams, optional
        Options of the adjustment (``sigma_px`` is taken from the argument above).

    Returns
    -------
    GeorefResult

    Raises
    ------
    InvalidInputError
        ≤ 2 usable control points (no similarity can be fixed), collinear control points, an
        unknown ``adjustment``, or "bundle" asked where it cannot run.

    Examples
    --------
    >>> from workstation.io.gcp import GCP
    >>> rng = np.random.default_rng(1)
    >>> true = rng.uniform(0, 100, (8, 3))
    >>> model = (true - 50) / 20 + rng.normal(0, 0.001, (8, 3))
    >>> pts = [GCP(f"P{i}", true[i], "control" if i < 5 else "check", model_xyz=model[i]) for i in range(8)]
    >>> res = georeference(pts)
    >>> round(res.similarity.scale, 1), res.report.metrics["check_n"], res.report.metrics["check_rmse_3d"] < 0.1
    (20.0, 3, True)
    >>> res.meta["adjustment"]
    'similarity'
    """
    if adjustment not in ADJUSTMENTS:
        raise InvalidInputError(f"adjustment {adjustment!r} is not one of {', '.join(ADJUSTMENTS)}", field="adjustment")
    if not gcps:
        raise InvalidInputError("no ground control points")
    positions, info, problems = _model_positions(gcps, reconstruction, sigma_px)
    notes = [f"{name}: not used, {why}" for name, why in problems.items()]
    control = [g for g in gcps if g.role == "control" and g.name in positions]
    check = [g for g in gcps if g.role == "check" and g.name in positions]
    sim = _fit_control(control, positions, notes)
    rows, metrics = _report(control, check, positions, info, sim.apply, sim)
    rec_out = transform_reconstruction(reconstruction, sim, crs) if reconstruction is not None else None
    meta: dict[str, Any] = {"adjustment": "similarity"}
    ok, why = bundle_possible(gcps, reconstruction, info)
    if adjustment == "bundle" and not ok:
        raise InvalidInputError(f"the bundle adjustment cannot run: {why}", "use adjustment='similarity' (the default 'auto' falls back to it)")
    if adjustment != "similarity" and ok:
        rows, metrics, meta, rec_out = _bundle_refinement(control, check, sim, positions, info, rec_out, sigma_px, bundle,
                                                          metrics, notes)
    else:
        notes.append("similarity only (bundle adjustment not asked)" if adjustment == "similarity" else f"similarity only: {why}")
    notes += _check_point_notes(check)
    return GeorefResult(sim, QCReport(metrics=metrics, tables={"points": rows}, notes=tuple(notes)), rec_out, meta)
