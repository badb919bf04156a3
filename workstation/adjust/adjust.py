r"""Strip adjustment: estimate the corrections from the patches, apply them to every point.

Gauss-Newton over the correspondences of :mod:`workstation.adjust.patches`: at the current
parameters every patch's plane is refitted to its corrected points, each correspondence gives
the signed distance :math:`d = \mathbf n^\top(\mathbf c_b - \mathbf c_a)` between its two
planes and the row :math:`\mathbf n^\top(\bar J_b - \bar J_a)` (:math:`\bar J` the mean
derivative of the patch's points, which is the derivative of its centroid), and
:func:`workstation.adjust.lsq.solve` gives the step that drives :math:`d` to zero in the
weighted least-squares sense, with the rank test and MAD rejection described there. The
iterations stop when the step moves no point by more than a thousandth of the noise and the
inliers no longer change (at most ``max_iterations``).

The datum of the strip shifts is one strip held fixed (by default the one in the most
correspondences): relative adjustment cannot find an absolute offset. Boresight and range
offset are absolute: they are the same for every strip and change the geometry of each.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field

import numpy as np

from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.lidar.georef import GeorefChain

from .lsq import correlations, robust_inliers, solve
from .models import BORESIGHT, ESTIMABLE, Rigorous, StripShifts
from .patches import Patches, PatchParams, find_patches, plane_fit, usable_points
from .trajectory import Navigation

log = get_logger(__name__)


@dataclass(frozen=True)
class AdjustParams:
    """Parameters of the strip adjustment.

    Attributes
    ----------
    estimate : tuple of str
        Unknowns among ``boresight`` (3 angles, rad), ``leverarm`` (3, m, body frame), ``range``
        (range offset, m), ``scan-angle`` (scan-angle scale, unitless) — these four need a
        trajectory — and ``strip-shift`` (3 per strip but the datum, m). Default: strip shifts.
    fixed_strip : int or None
        Point source id of the datum strip; None: the one in the most correspondences.
    lever_arm : (3,) float
        Nominal lever arm the points were georeferenced with (body frame x fwd, y right,
        z down; m).
    boresight_deg : (3,) float
        Nominal boresight roll, pitch, yaw the points were georeferenced with (degrees).
    max_iterations : int
        Gauss-Newton iterations at most. Default 10.
    patches : PatchParams
    """

    estimate: tuple = ("strip-shift",)
    fixed_strip: int | None = None
    lever_arm: tuple = (0.0, 0.0, 0.0)
    boresight_deg: tuple = (0.0, 0.0, 0.0)
    max_iterations: int = 10
    patches: PatchParams = field(default_factory=PatchParams)

    def __post_init__(self):
        bad = set(self.estimate) - set(ESTIMABLE)
        if bad or not self.estimate:
            raise InvalidInputError(f"cannot estimate {sorted(bad) or 'nothing'}", f"choose from {', '.join(ESTIMABLE)}",
                                    field="estimate")
        if self.max_iterations < 1:
            raise InvalidInputError("max_iterations must be at least 1", field="max_iterations")

    @property
    def rigorous(self) -> bool:
        return bool(set(self.estimate) - {"strip-shift"})


@dataclass(frozen=True)
class AdjustResult:
    """Estimated corrections and their quality.

    Attributes
    ----------
    model : str
        ``rigorous`` or ``strip``.
    names : list of str
        Unknowns (angles in rad, lengths in m).
    values, sigmas : (u,) float
        Estimates and a-posteriori standard deviations (NaN where not determined).
    correlation : (u, u) float
    determined : (u,) bool
    null_directions : list of dict
        Combinations of unknowns the data do not determine: {name: component}.
    fixed_strip : int
    strips : list of int
    correspondences, inliers, iterations : int
    rms_before_m, rms_after_m : float
        RMS of the inlier plane-to-plane distances before and after, metres.
    noise_m, cell_m, seconds : float
    sigma0 : float
        A-posteriori standard deviation of unit weight: about 1 when the model and the noise
        explain the distances; well above 1 when errors outside the model remain (per-line GNSS
        offsets, range walk, an unmodelled scan-angle error), and then the sigmas, though
        scaled by it, are optimistic because such errors are correlated across patches.
    pairs : list of dict
        Per strip pair (a < b): ``a``, ``b``, ``correspondences`` (inliers) and the RMS of their
        plane-to-plane distances before and after, ``rms_before_m``, ``rms_after_m``.
    """

    model: str
    names: list
    values: np.ndarray
    sigmas: np.ndarray
    correlation: np.ndarray
    determined: np.ndarray
    null_directions: list
    fixed_strip: int
    strips: list
    correspondences: int
    inliers: int
    iterations: int
    rms_before_m: float
    rms_after_m: float
    noise_m: float
    cell_m: float
    seconds: float
    sigma0: float = float("nan")
    pairs: list = field(default_factory=list)

    def value(self, name: str, default: float = 0.0) -> float:
        return float(self.values[self.names.index(name)]) if name in self.names else default


class _Model:
    """The unknowns of one adjustment: the rigorous block (optional) then the strip shifts."""

    def __init__(self, rig: Rigorous | None, shifts: StripShifts | None, xyz: np.ndarray, sid: np.ndarray):
        self.rig, self.shifts, self.xyz, self.sid = rig, shifts, xyz, sid
        self.nr = len(rig.names) if rig else 0
        self.names = (rig.names if rig else []) + (shifts.names if shifts else [])
        self.scale = np.r_[rig.scale if rig else [], shifts.scale if shifts else []]

    def _patch_derivatives(self, theta, P: Patches) -> list:
        """Mean derivative (m, 3) of each patch per rigorous unknown, computed at the first call
        only: the corrections are small (a modified Newton step; the derivatives change by the
        relative size of the corrections, about 1e-3)."""
        if getattr(self, "_jm", None) is None:
            m = P.n_slots
            cnt = np.maximum(np.bincount(P.slot, minlength=m), 1)
            self._jm = [np.column_stack([np.bincount(P.slot, J[:, i], m) / cnt for i in range(3)])
                        for J in self.rig.derivatives(theta[:self.nr])]
        return self._jm

    def coords(self, theta: np.ndarray, origin: np.ndarray) -> np.ndarray:
        X = self.rig.coords(theta[:self.nr]) - origin if self.rig else self.xyz.copy()
        if self.shifts:
            X += self.shifts.offsets(theta[self.nr:], self.sid)
        return X

    def design(self, theta, normal, P: Patches) -> np.ndarray:
        cols = []
        if self.rig:
            for Jm in self._patch_derivatives(theta, P):
                cols.append(np.sum(normal * (Jm[P.pair_b] - Jm[P.pair_a]), axis=1)[:, None])
        if self.shifts:
            cols.append(self.shifts.design(normal, P.strip[P.pair_a], P.strip[P.pair_b]))
        return np.hstack(cols)


def _distances(X: np.ndarray, P: Patches, noise: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Plane-to-plane distances (p,), their sigmas (p,) and mean normals (p, 3)."""
    pl = plane_fit(X, P.slot, P.n_slots)
    a, b = P.pair_a, P.pair_b
    n = pl.normal[a] + pl.normal[b]
    n /= np.linalg.norm(n, axis=1, keepdims=True)
    d = np.sum(n * (pl.centroid[b] - pl.centroid[a]), axis=1)
    s2 = np.maximum(pl.s2, (0.1 * noise) ** 2)  # a plane through few exact points is not exact
    return d, np.sqrt(s2[a] / pl.count[a] + s2[b] / pl.count[b]), n


def _datum(P: Patches, fixed: int | None) -> int:
    strips, counts = np.unique(np.r_[P.strip[P.pair_a], P.strip[P.pair_b]], return_counts=True)
    if fixed is None:
        return int(strips[np.argmax(counts)])
    if fixed not in set(np.unique(P.strip).tolist()):
        raise InvalidInputError(f"datum strip {fixed} has no patches in an overlap",
                                f"strips with patches: {sorted(set(P.strip.tolist()))}", field="fixed_strip")
    return int(fixed)


def estimate_corrections(xyz: np.ndarray, attrs: dict, params: AdjustParams = AdjustParams(),
                         nav: Navigation | None = None) -> AdjustResult:
    """Estimate the corrections of ``params.estimate`` from overlapping strips.

    Parameters
    ----------
    xyz : (n, 3) float
        Points of every strip, map metres.
    attrs : dict
        Per-point ``point_source_id`` (required), ``gps_time`` (with a trajectory) and
        optionally ``number_of_returns``, ``classification``, ``withheld`` (to pick single,
        valid returns).
    params : AdjustParams
    nav : Navigation, optional
        The trajectory; required when ``params`` asks for boresight, lever arm or range.
    """
    t0 = time.perf_counter()
    if "point_source_id" not in attrs:
        raise InvalidInputError("the points have no point_source_id", "strips are told apart by their flight line id",
                                field="point_source_id")
    if params.rigorous and (nav is None or "gps_time" not in attrs):
        raise InvalidInputError(f"estimating {', '.join(sorted(set(params.estimate) - {'strip-shift'}))} needs a "
                                "trajectory and per-point GPS time", "give --trajectory CSV", field="trajectory")
    sid = np.asarray(attrs["point_source_id"]).astype(np.int64)
    P = find_patches(xyz, sid, params.patches, usable_points(attrs))
    fixed = _datum(P, params.fixed_strip)
    strips = np.unique(P.strip)
    rig = None
    if params.rigorous:
        mount = GeorefChain(params.lever_arm, tuple(np.radians(params.boresight_deg)))
        rig = Rigorous(xyz[P.index], np.asarray(attrs["gps_time"])[P.index], nav, mount, params.estimate)
    shifts = StripShifts(strips, fixed) if "strip-shift" in params.estimate else None
    model = _Model(rig, shifts, xyz[P.index] - P.origin, sid[P.index])
    theta, inl, before, it, step = np.zeros(len(model.names)), np.ones(P.pair_a.size, bool), None, 0, None
    for it in range(1, params.max_iterations + 1):
        d, sig, n = _distances(model.coords(theta, P.origin), P, P.noise_m)
        before = (d, sig) if before is None else before
        step = solve(model.design(theta, n, P), -d, sig, model.scale, P.noise_m, inl)
        theta = theta + step.delta
        new = robust_inliers(step.residuals, sig)
        done = np.max(np.abs(step.delta * model.scale), initial=0.0) < 1e-3 * P.noise_m and np.array_equal(new, inl)
        inl = new
        if done:
            break
    d_after, _, _ = _distances(model.coords(theta, P.origin), P, P.noise_m)
    return _result(model, theta, step, P, fixed, strips, inl, before[0], d_after, it, time.perf_counter() - t0)


def _pair_rms(P: Patches, inl: np.ndarray, d0: np.ndarray, d1: np.ndarray) -> list[dict]:
    a, b = P.strip[P.pair_a][inl], P.strip[P.pair_b][inl]
    out = []
    for sa, sb in sorted(set(zip(a.tolist(), b.tolist()))):
        m = (a == sa) & (b == sb)
        out.append({"a": sa, "b": sb, "correspondences": int(m.sum()), "rms_before_m": float(np.sqrt(np.mean(d0[inl][m] ** 2))),
                    "rms_after_m": float(np.sqrt(np.mean(d1[inl][m] ** 2)))})
    return out


def _result(model, theta, step, P, fixed, strips, inl, d0, d1, it, seconds) -> AdjustResult:
    sig = np.sqrt(np.clip(np.diag(step.cov), 0, None))
    sig = np.where(step.determined, sig, np.nan)
    nulls = [{model.names[i]: float(v[i]) for i in np.flatnonzero(np.abs(v) > 0.1)} for v in step.null_directions]
    res = AdjustResult("rigorous" if model.rig else "strip", list(model.names), theta, sig, correlations(step.cov),
                       step.determined, nulls, fixed, [int(s) for s in strips], int(P.pair_a.size), int(inl.sum()), it,
                       float(np.sqrt(np.mean(d0[inl] ** 2))), float(np.sqrt(np.mean(d1[inl] ** 2))), P.noise_m,
                       P.cell_m, seconds, step.sigma0, _pair_rms(P, inl, d0, d1))
    log.info("strip adjustment (%s): %d/%d correspondences, rms %.4f -> %.4f m in %d iterations, sigma0 %.2f",
             res.model, res.inliers, res.correspondences, res.rms_before_m, res.rms_after_m, it, res.sigma0)
    if nulls:
        log.warning("not determined by the overlaps: %s", "; ".join(", ".join(d) for d in nulls))
    return res


def apply_corrections(xyz: np.ndarray, attrs: dict, result: AdjustResult, params: AdjustParams = AdjustParams(),
                      nav: Navigation | None = None, chunk: int = 1 << 20) -> np.ndarray:
    """Corrected coordinates (n, 3) of points ``xyz`` under ``result`` (the input is not modified).

    The rigorous block re-georeferences every point from its GPS time (``chunk`` points at a
    time, so memory stays bounded); the strip shifts move each strip's points. Points of a strip
    the adjustment did not reach keep their coordinates.
    """
    out = np.array(xyz, dtype=np.float64, copy=True)
    names = result.names
    nr = sum(1 for n in names if not n.startswith("strip_"))
    if nr:
        if nav is None or "gps_time" not in attrs:
            raise InvalidInputError("applying a rigorous correction needs the trajectory and GPS time", field="trajectory")
        mount = GeorefChain(params.lever_arm, tuple(np.radians(params.boresight_deg)))
        est = tuple(e for e in params.estimate if e != "strip-shift")
        t = np.asarray(attrs["gps_time"])
        for i in range(0, len(out), chunk):
            rows = slice(i, min(i + chunk, len(out)))
            rig = Rigorous(out[rows], t[rows], nav, mount, est)
            if rig.names != names[:nr]:
                raise InvalidInputError(f"the result has {names[:nr]}, the parameters give {rig.names}",
                                        "apply a result with the parameters that estimated it", field="estimate")
            out[rows] = rig.coords(np.asarray(result.values[:nr]))
    if nr < len(names):
        shifts = StripShifts(np.asarray(result.strips), result.fixed_strip)
        sid = np.asarray(attrs["point_source_id"]).astype(np.int64)
        known = np.isin(sid, shifts.strips)
        out[known] += shifts.offsets(np.asarray(result.values[nr:]), sid[known])
    return out
