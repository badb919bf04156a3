r"""Bundle adjustment with ground control points (control points only; check points stay out).

After the 7-parameter similarity has brought an SfM model into the survey frame
(:mod:`.georef`), the model can still be *deformed*: a slight scale drift along a strip, or the
"doming" that a poorly estimated radial distortion leaves in a block of near-parallel images
(James & Robson 2014, "Mitigating systematic error in topographic models derived from UAV and
ground-based image networks", ESPL 39(10)). A similarity cannot remove a bend. A bundle
adjustment that also holds the control points' image observations and ground coordinates
can: it refines the camera poses (and optionally the intrinsics), the tie points and the
control points together, minimising

.. math::

    \sum_{obs} \rho\Big(\big\| (\hat{\mathbf u}(\mathbf X_j, \mathrm{cam}_i) - \mathbf u_{ij}) / \sigma_{px} \big\|^2\Big)
    + \sum_{g \in \mathrm{control}} \rho\Big(\big\| (\mathbf X_g - \mathbf X_g^{survey}) / \sigma_g \big\|^2\Big)

with the collinearity equations and OpenCV distortion (:func:`.collinearity.project`), a
robust loss ρ (soft-L1, ``2(√(1 + z) − 1)``, by default; Triggs et al. 2000, "Bundle
adjustment — a modern synthesis", §3 and §6) and each control point's surveyed σ as the weight
of its ground coordinates (a weighted, not a fixed, datum); as in scipy, ρ acts on each
whitened residual component (u, v, X, Y, Z) separately. It is solved by
:func:`scipy.optimize.least_squares` (trust-region reflective, LSMR on the sparse system) with
the analytic sparse Jacobian (block-sparse: each observation touches one pose, one camera and
one point), or, as a check, finite differences over the same sparsity pattern
(``jac_sparsity``, grouping independent columns; Curtis, Powell & Reid 1974); no dense matrix
is formed. Residuals and Jacobian are computed for all observations at once (no Python loop
over observations). Two safeguards against gross errors: the loss starts at the spread of the
starting residuals and ends at 3σ (graduated robustness), then tie observations beyond 5σ are
dropped and the adjustment repeated.

Only points whose role is ``control`` may enter; :func:`bundle_adjust` refuses any other, so
check points remain independent (they are intersected afterwards from the adjusted images).

Gauge and weak parts: the control points fix the datum (≥ 3 with ≥ 2 image observations
each are required). Images with fewer than ``min_image_observations`` observations and tie
points seen in fewer than 2 images are held as they are (not parameters).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Any, Mapping, Sequence

import numpy as np

from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Camera, Image, Pose, Reconstruction

log = get_logger(__name__)

_LOSSES = ("linear", "huber", "soft_l1", "cauchy", "arctan")
_INTR = 6  # fx, fy, cx, cy, k1, k2 refined per camera


@dataclass(frozen=True)
class BundleParams:
    """Options of :func:`bundle_adjust`.

    Attributes
    ----------
    sigma_px : float
        A-priori standard deviation of an image measurement (tie and control points), pixels.
    refine_intrinsics : bool
        Also refine fx, fy, cx, cy, k1 and k2 of every camera (p1, p2, k3 and skew stay fixed).
    loss : str
        Robust loss of :func:`scipy.optimize.least_squares` ("huber", "soft_l1", "cauchy",
        "arctan" or "linear" for plain least squares).
    loss_scale : float
        Where the loss turns robust, in units of the a-priori σ (3 = residuals beyond 3σ are
        down-weighted).
    default_gcp_sigma : float or None
        σ of a control point's surveyed coordinates when the GCP file gives none, survey
        units. None: ``sigma_px`` times the point's mean ground sampling distance in its
        images (the survey counted as precise as one image measurement on the ground).
    min_image_observations : int
        Images with fewer observations keep their pose (not enough to refine 6 parameters).
    max_evaluations : int
        Cap on residual evaluations of one solver run (Jacobian evaluations not counted).
    reject_sigma : float or None
        After the robust solution, tie observations whose residual exceeds this many
        ``sigma_px`` are dropped and the adjustment is run again (None: keep all). A bounded
        influence alone still lets gross errors bend the weak modes of a block.
    reject_rounds : int
        At most this many rejection rounds.
    jacobian : {"analytic", "2-point"}
        The analytic sparse Jacobian, or scipy's finite differences over the same sparsity
        pattern (``jac_sparsity``: independent columns perturbed together); both give the
        same solution, the analytic one in fewer, cheaper iterations.
    lsmr_tolerance : float
        ``atol`` = ``btol`` of the LSMR solve of each trust-region step.
    tolerance : float
        ``ftol`` = ``xtol`` of the solver (relative change of cost and parameters).
    """

    sigma_px: float = 1.0
    refine_intrinsics: bool = False
    loss: str = "soft_l1"
    loss_scale: float = 3.0
    default_gcp_sigma: float | None = None
    min_image_observations: int = 6
    max_evaluations: int = 200
    reject_sigma: float | None = 5.0
    jacobian: str = "analytic"
    lsmr_tolerance: float = 1e-10
    reject_rounds: int = 3
    tolerance: float = 1e-6


@dataclass(frozen=True)
class BundleResult:
    """Outcome of :func:`bundle_adjust`.

    Attributes
    ----------
    reconstruction : Reconstruction
        Adjusted cameras, poses and tie points, survey frame (tracks carried over).
    control_xyz : mapping of str to (3,) float
        Adjusted positions of the control points.
    stats : mapping
        ``observations``, ``tie_points``, ``control_points``, ``free_images``,
        ``fixed_images``, ``parameters``, ``rms_px_before``/``after`` (all image residuals),
        ``tie_rms_px_before``/``after``, ``control_rms_px_before``/``after``,
        ``control_ground_rms_before``/``after`` (survey units), ``cost_before``/``after``,
        ``evaluations``, ``status``, ``message``, ``seconds``, ``refine_intrinsics``.
    """

    reconstruction: Reconstruction
    control_xyz: Mapping[str, np.ndarray]
    stats: Mapping[str, Any] = field(default_factory=dict)


def _camera_array(cam: Camera) -> np.ndarray:
    d = (list(cam.dist) + [0.0] * 5)[:5]
    return np.array([cam.fx, cam.fy, cam.cx, cam.cy, cam.skew, *d], dtype=float)


def project_many(X: np.ndarray, R: np.ndarray, C: np.ndarray, K: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Vectorised collinearity projection of one point per row, each with its own camera.

    Parameters
    ----------
    X : (m, 3) float
        World points.
    R : (m, 3, 3) float
        World -> camera rotations.
    C : (m, 3) float
        Projection centres (world).
    K : (m, 10) float
        Interior orientation per row: fx, fy, cx, cy, skew, k1, k2, p1, p2, k3 (OpenCV).

    Returns
    -------
    uv : (m, 2) float pixels
    depth : (m,) float camera z

    Examples
    --------
    >>> from workstation.photogrammetry.collinearity import project, pose_from_opk
    >>> cam = Camera(640, 480, 500.0, 505.0, 320.0, 240.0, dist=(-0.2, 0.05, 0.001, -0.002, 0.01))
    >>> pose = pose_from_opk(0.1, -0.2, 0.3, [1.0, 2.0, 10.0])
    >>> X = np.array([[0.5, 1.0, 0.0], [2.0, 3.0, 1.0]])
    >>> uv, _ = project_many(X, np.repeat(pose.R[None], 2, 0), np.repeat(pose.center[None], 2, 0),
    ...                      np.repeat(_camera_array(cam)[None], 2, 0))
    >>> bool(np.allclose(uv, project(X, cam, pose)))
    True
    """
    Xc = np.einsum("mij,mj->mi", R, X - C)
    z = Xc[:, 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        x = Xc[:, 0] / z
        y = Xc[:, 1] / z
    k1, k2, p1, p2, k3 = K[:, 5], K[:, 6], K[:, 7], K[:, 8], K[:, 9]
    r2 = x * x + y * y
    radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3))
    xd = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x)
    yd = y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y
    u = K[:, 0] * xd + K[:, 4] * yd + K[:, 2]
    v = K[:, 1] * yd + K[:, 3]
    return np.column_stack([u, v]), z


def _skew(v: np.ndarray) -> np.ndarray:
    """(m, 3) vectors -> (m, 3, 3) cross-product matrices."""
    S = np.zeros(v.shape[:-1] + (3, 3))
    S[..., 0, 1], S[..., 0, 2], S[..., 1, 2] = -v[..., 2], v[..., 1], -v[..., 0]
    S[..., 1, 0], S[..., 2, 0], S[..., 2, 1] = v[..., 2], -v[..., 1], v[..., 0]
    return S


def _left_jacobian_so3(phi: np.ndarray) -> np.ndarray:
    """(m, 3) rotation vectors -> (m, 3, 3) left Jacobians of SO(3):
    ``Exp(φ + ε) ≈ Exp(J_l(φ) ε) Exp(φ)`` (Barfoot 2017, *State Estimation for Robotics*, §7.1.3)."""
    th = np.linalg.norm(phi, axis=1)
    small = th < 1e-8
    ts = np.where(small, 1.0, th)
    a = np.where(small, 0.5 - th**2 / 24, (1 - np.cos(ts)) / ts**2)
    b = np.where(small, 1 / 6 - th**2 / 120, (ts - np.sin(ts)) / ts**3)
    S = _skew(phi)
    return np.eye(3) + a[:, None, None] * S + b[:, None, None] * (S @ S)


def projection_jacobians(X: np.ndarray, R: np.ndarray, C: np.ndarray, K: np.ndarray):
    """Analytic derivatives of :func:`project_many` (one point and camera per row).

    Returns
    -------
    d_rot : (m, 2, 3)
        w.r.t. a rotation ω applied on the left, ``R -> Exp(ω) R`` at ω = 0.
    d_centre : (m, 2, 3)
    d_point : (m, 2, 3)
    d_intr : (m, 2, 6)
        w.r.t. fx, fy, cx, cy, k1, k2.
    """
    Xc = np.einsum("mij,mj->mi", R, X - C)
    z = Xc[:, 2]
    x, y = Xc[:, 0] / z, Xc[:, 1] / z
    fx, fy, s = K[:, 0], K[:, 1], K[:, 4]
    k1, k2, p1, p2, k3 = K[:, 5], K[:, 6], K[:, 7], K[:, 8], K[:, 9]
    r2 = x * x + y * y
    rad = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3))
    drad = k1 + r2 * (2 * k2 + 3 * k3 * r2)
    xd = x * rad + 2 * p1 * x * y + p2 * (r2 + 2 * x * x)
    yd = y * rad + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y
    D = np.empty((X.shape[0], 2, 2))  # d(xd, yd) / d(x, y)
    D[:, 0, 0] = rad + 2 * x * x * drad + 2 * p1 * y + 6 * p2 * x
    D[:, 0, 1] = 2 * x * y * drad + 2 * p1 * x + 2 * p2 * y
    D[:, 1, 0] = 2 * x * y * drad + 2 * p1 * x + 2 * p2 * y
    D[:, 1, 1] = rad + 2 * y * y * drad + 6 * p1 * y + 2 * p2 * x
    A = np.zeros((X.shape[0], 2, 2))  # d(u, v) / d(xd, yd)
    A[:, 0, 0], A[:, 0, 1], A[:, 1, 1] = fx, s, fy
    P = np.zeros((X.shape[0], 2, 3))  # d(x, y) / d Xc
    P[:, 0, 0] = 1 / z
    P[:, 0, 2] = -x / z
    P[:, 1, 1] = 1 / z
    P[:, 1, 2] = -y / z
    G = A @ D @ P  # d(u, v) / d Xc
    d_point = G @ R
    d_rot = -G @ _skew(Xc)
    d_intr = np.zeros((X.shape[0], 2, 6))
    d_intr[:, 0, 0], d_intr[:, 0, 2], d_intr[:, 1, 1], d_intr[:, 1, 3] = xd, 1.0, yd, 1.0
    dxy_dk = np.stack([x * r2, y * r2], axis=1), np.stack([x * r2 * r2, y * r2 * r2], axis=1)
    for j, dk in enumerate(dxy_dk):
        d_intr[:, :, 4 + j] = np.einsum("mij,mj->mi", A, dk)
    return d_rot, -d_point, d_point, d_intr


def _image_ids_by_name(rec: Reconstruction) -> dict[str, int]:
    out: dict[str, int] = {}
    for iid, im in rec.images.items():
        out[im.name] = int(iid)
        out.setdefault(im.name.rsplit("/", 1)[-1], int(iid))
    return out


def _single_threaded_blas():
    """Limit BLAS to one thread: LSMR does level-1 BLAS only (dot products, norms), where
    threads bring no speed and OpenBLAS's spinning threads slow a loaded machine down."""
    try:
        from threadpoolctl import threadpool_limits
    except ImportError:  # pragma: no cover - threadpoolctl comes with scikit-learn
        import contextlib

        return contextlib.nullcontext()
    return threadpool_limits(limits=1, user_api="blas")


def _solve(least_squares, prob: "_Problem", x, stages, params):
    """The solver runs of :func:`bundle_adjust`: graduated loss scales, then rejection rounds
    (tie observations beyond ``reject_sigma`` get weight 0 in ``prob.weight``)."""
    nfev, rejected, rounds, sol = 0, 0, 0, None
    while stages:
        f_scale = stages.pop(0)
        sol = least_squares(
            prob.fun,
            x,
            jac=prob.jac if params.jacobian == "analytic" else "2-point",
            jac_sparsity=None if params.jacobian == "analytic" else prob.sparsity,
            method="trf",
            tr_solver="lsmr",
            loss=params.loss,
            f_scale=f_scale,
            x_scale="jac",
            ftol=params.tolerance,
            xtol=params.tolerance,
            gtol=params.tolerance,
            max_nfev=params.max_evaluations,
            # LSMR's default 1e-6 stopping tolerances leave the weak modes of a block (a bend)
            # out of each step, so the solver stops early on ftol; an accurate solve of each
            # trust-region step lets it converge
            tr_options={"atol": params.lsmr_tolerance, "btol": params.lsmr_tolerance},
        )
        x, nfev = sol.x, nfev + sol.nfev
        if stages or params.reject_sigma is None or rounds >= params.reject_rounds:
            continue
        # bounded influence is not enough for the weak modes of a block (the dome is one):
        # drop tie observations beyond reject_sigma and adjust again, as COLMAP filters
        # observations after each bundle adjustment
        e = np.linalg.norm(prob.image_residuals(x), axis=1) / params.sigma_px
        bad = (e > params.reject_sigma) & (prob.weight > 0)
        bad[prob.n_tie_obs:] = False  # control measurements are reported, never silently dropped
        if bad.any():
            prob.weight[bad] = 0.0
            rejected += int(bad.sum())
            rounds += 1
            stages.append(params.loss_scale)
    return x, nfev, rejected, sol


def _check_inputs(rec: Reconstruction, control: Sequence, params: BundleParams) -> None:
    """Refuse unknown options, points that are not control points and a model without tracks."""
    if params.jacobian not in ("analytic", "2-point"):
        raise InvalidInputError(f"jacobian {params.jacobian!r} is not 'analytic' or '2-point'", field="jacobian")
    if params.loss not in _LOSSES:
        raise InvalidInputError(f"loss {params.loss!r} is not one of {', '.join(_LOSSES)}", field="loss")
    if params.sigma_px <= 0 or params.loss_scale <= 0:
        raise InvalidInputError("sigma_px and loss_scale must be positive")
    bad = [g.name for g in control if g.role != "control"]
    if bad:
        raise InvalidInputError(
            f"only control points enter the bundle adjustment; {', '.join(bad)} are not (check points must stay independent)",
            "pass the control points only",
        )
    if rec.tracks is None or rec.points is None:
        raise InvalidInputError("the reconstruction has no tie-point tracks", "load it with its observations (read_model(..., with_tracks=True))")


@dataclass
class _Control:
    """Control points observed in ≥ 2 oriented images and their image observations.

    ``xyz`` is relative to ``origin`` (the mean of the surveyed points: a local frame keeps
    finite-difference steps and sums well scaled); ``sigma`` is NaN where the GCP gives none;
    ``point``/``image``/``uv`` are per observation (control point index, image position in the
    sorted image ids, pixel).
    """

    gcps: list
    xyz: np.ndarray
    sigma: np.ndarray
    point: np.ndarray
    image: np.ndarray
    uv: np.ndarray
    origin: np.ndarray


def _control_observations(rec: Reconstruction, control: Sequence, ids: np.ndarray) -> _Control:
    """The control points with ≥ 2 observations in images of ``rec`` (≥ 3 of them needed)."""
    by_name = _image_ids_by_name(rec)
    g_used, g_xyz, g_sig, co_g, co_img, co_uv = [], [], [], [], [], []
    for g in control:
        rows = [(by_name.get(img, by_name.get(str(img).rsplit("/", 1)[-1])), u, v) for img, u, v in g.observations]
        rows = [r for r in rows if r[0] is not None]
        if len(rows) < 2:
            continue
        k = len(g_used)
        g_used.append(g)
        g_xyz.append(np.asarray(g.xyz, dtype=float))
        g_sig.append(np.nan if g.sigma is None else float(g.sigma))
        for iid, u, v in rows:
            co_g.append(k)
            co_img.append(int(np.searchsorted(ids, iid)))
            co_uv.append((u, v))
    n_g = len(g_used)
    if n_g < 3:
        raise InvalidInputError(
            f"{n_g} control point(s) observed in ≥ 2 oriented images: the bundle adjustment needs 3 to fix its datum",
            "measure the control points in more images, or use the similarity alone",
        )
    origin = np.mean(g_xyz, axis=0)
    return _Control(g_used, np.array(g_xyz) - origin, np.array(g_sig), np.array(co_g, dtype=np.int64),
                    np.array(co_img, dtype=np.int64), np.array(co_uv, dtype=float), origin)


@dataclass
class _Ties:
    """Tie points seen in ≥ 2 images of the reconstruction and their observations.

    ``active``: indices of those points in ``rec.points``; ``X0``: their coordinates relative
    to the control origin; ``point``/``image``/``uv``: per observation (index into ``active``,
    image position in the sorted image ids, pixel).
    """

    active: np.ndarray
    X0: np.ndarray
    point: np.ndarray
    image: np.ndarray
    uv: np.ndarray


def _tie_observations(rec: Reconstruction, ids: np.ndarray, origin: np.ndarray) -> _Ties:
    """Observations of tie points in images of ``rec`` (points seen in < 2 images are left out)."""
    tr = rec.tracks
    pts_world = np.asarray(rec.points, dtype=float)
    known = np.isin(tr.image, ids)
    t_pt_all, t_img_all, t_uv_all = tr.point[known], np.searchsorted(ids, tr.image[known]), tr.uv[known]
    counts = np.bincount(t_pt_all, minlength=pts_world.shape[0])
    active = np.flatnonzero(counts >= 2)
    remap = np.full(pts_world.shape[0], -1, dtype=np.int64)
    remap[active] = np.arange(active.shape[0])
    keep = remap[t_pt_all] >= 0
    return _Ties(active, pts_world[active] - origin, remap[t_pt_all[keep]], t_img_all[keep], t_uv_all[keep])


def _control_sigma(ctrl: _Control, R0, C0, K0, img_cam, params: BundleParams) -> np.ndarray:
    """σ of each control point's surveyed coordinates: the GCP's own, else
    ``default_gcp_sigma``, else ``sigma_px`` times the point's mean ground sampling distance."""
    n_g = len(ctrl.gcps)
    co_g, co_img = ctrl.point, ctrl.image
    depth0 = np.einsum("mij,mj->mi", R0[co_img], ctrl.xyz[co_g] - C0[co_img])[:, 2]
    gsd = np.abs(depth0) / K0[img_cam[co_img], 0]
    gsd_mean = np.bincount(co_g, weights=gsd, minlength=n_g) / np.bincount(co_g, minlength=n_g)
    g_sig = ctrl.sigma.copy()
    unset = ~np.isfinite(g_sig)
    g_sig[unset] = params.default_gcp_sigma if params.default_gcp_sigma is not None else params.sigma_px * gsd_mean[unset]
    if np.any(g_sig <= 0):
        raise InvalidInputError("control point σ must be positive", field="sigma")
    return g_sig


class _Problem:
    """The least-squares problem of :func:`bundle_adjust`.

    The unknowns ``x`` are corrections to the starting values (all zero at the start), laid
    out as [6 per free image (rotation vector, centre shift) | ``_INTR`` per camera when the
    intrinsics are refined | 3 per tie point | 3 per control point]: the solver's relative step
    tolerance then measures the corrections themselves, not the size of the coordinates (with
    absolute coordinates a 1e-6 relative tolerance would stop a 100 m block at centimetre
    steps). Residuals are the image residuals (tie observations first, then control) divided
    by ``sigma_px`` and weighted by ``weight`` (0 for rejected observations), then the control
    points' ground corrections divided by their σ.
    """

    _intr = [0, 1, 2, 3, 5, 6]  # positions of fx, fy, cx, cy, k1, k2 in a _camera_array row

    def __init__(self, rec: Reconstruction, ids: np.ndarray, cam_ids: list, ctrl: _Control, ties: _Ties, params: BundleParams):
        n_img = ids.shape[0]
        cam_pos = {c: k for k, c in enumerate(cam_ids)}
        img_cam = np.array([cam_pos[int(rec.images[i].camera_id)] for i in ids], dtype=np.int64)
        self.K0 = np.stack([_camera_array(rec.cameras[c]) for c in cam_ids])
        self.R0 = np.stack([np.asarray(rec.images[i].pose.R, dtype=float) for i in ids])
        self.C0 = np.stack([rec.images[i].pose.center for i in ids]) - ctrl.origin
        self.X0, self.g_xyz = ties.X0, ctrl.xyz
        n_t = ties.active.shape[0]
        self.o_pt = np.concatenate([ties.point, n_t + ctrl.point])
        self.o_img = np.concatenate([ties.image, ctrl.image])
        self.o_uv = np.vstack([ties.uv.reshape(-1, 2), ctrl.uv])
        self.o_cam = img_cam[self.o_img]
        self.m = self.o_pt.shape[0]
        self.n_tie_obs = ties.point.shape[0]
        self._free_images(n_img, params)
        self.g_sig = _control_sigma(ctrl, self.R0, self.C0, self.K0, img_cam, params)
        self.sigma_px = params.sigma_px
        self.n_intr = _INTR * len(cam_ids) if params.refine_intrinsics else 0
        self.off_cam = 6 * self.n_free
        self.off_pt = self.off_cam + self.n_intr
        self.off_g = self.off_pt + 3 * n_t
        self.n_par = self.off_g + 3 * len(ctrl.gcps)
        self.x0 = np.zeros(self.n_par)
        self.weight = np.ones(self.m)  # 0 for tie observations rejected as gross errors
        self._sparsity_pattern()

    def _free_images(self, n_img: int, params: BundleParams) -> None:
        """Images with ≥ ``min_image_observations`` observations get pose parameters."""
        per_img = np.bincount(self.o_img, minlength=n_img)
        self.free = np.flatnonzero(per_img >= params.min_image_observations)
        self.fixed = np.setdiff1d(np.arange(n_img), self.free)
        self.free_pos = np.full(n_img, -1, dtype=np.int64)
        self.free_pos[self.free] = np.arange(self.free.shape[0])
        self.n_free = self.free.shape[0]
        if self.n_free == 0:
            raise InvalidInputError(
                f"no image has {params.min_image_observations} observations to refine its pose",
                "check that the tracks belong to this reconstruction",
            )

    def unpack(self, x):
        """Rotations, centres, camera arrays and points (ties then control) at corrections ``x``."""
        from scipy.spatial.transform import Rotation

        pp = x[: self.off_cam].reshape(-1, 6)
        R = self.R0.copy()
        R[self.free] = Rotation.from_rotvec(pp[:, :3]).as_matrix() @ self.R0[self.free]
        C = self.C0.copy()
        C[self.free] += pp[:, 3:]
        K = self.K0.copy()
        if self.n_intr:
            K[:, self._intr] += x[self.off_cam : self.off_pt].reshape(-1, _INTR)
        X = np.vstack([self.X0 + x[self.off_pt : self.off_g].reshape(-1, 3), self.g_xyz + x[self.off_g :].reshape(-1, 3)])
        return R, C, K, X

    def image_residuals(self, x):
        """Projected minus observed pixels, (m, 2), unweighted."""
        R, C, K, X = self.unpack(x)
        uv, _ = project_many(X[self.o_pt], R[self.o_img], C[self.o_img], K[self.o_cam])
        return uv - self.o_uv

    def fun(self, x):
        ri = self.image_residuals(x) * (self.weight / self.sigma_px)[:, None]
        rg = x[self.off_g :].reshape(-1, 3) / self.g_sig[:, None]
        return np.concatenate([ri.ravel(), rg.ravel()])

    def _sparsity_pattern(self) -> None:
        """Rows and columns of the Jacobian's non-zeros: an image residual (u, v) depends on its
        image's pose (when free), its camera's intrinsics (when refined) and its point; a
        ground residual on its control point."""
        from scipy.sparse import coo_matrix

        m, n_g3 = self.m, self.n_par - self.off_g
        blocks = []  # (observation rows, (m', k) parameter columns)
        self.fp = self.free_pos[self.o_img]
        self.sel = np.flatnonzero(self.fp >= 0)
        blocks.append((self.sel, 6 * self.fp[self.sel][:, None] + np.arange(6)))
        if self.n_intr:
            blocks.append((np.arange(m), self.off_cam + _INTR * self.o_cam[:, None] + np.arange(_INTR)))
        blocks.append((np.arange(m), self.off_pt + 3 * self.o_pt[:, None] + np.arange(3)))
        rr, cc = [2 * m + np.arange(n_g3)], [self.off_g + np.arange(n_g3)]
        for obs, cols in blocks:
            for j in (0, 1):  # u row 2k, v row 2k + 1
                rr.append(np.repeat(2 * obs + j, cols.shape[1]))
                cc.append(cols.ravel())
        self.rows = np.concatenate(rr)
        self.cols = np.concatenate(cc)
        self.shape = (2 * m + n_g3, self.n_par)
        self.sparsity = coo_matrix((np.ones(self.rows.shape[0], dtype=np.int8), (self.rows, self.cols)), shape=self.shape).tocsr()

    def jac(self, x):
        """The analytic Jacobian, entries in the order of the sparsity pattern (rows, cols)."""
        from scipy.sparse import coo_matrix

        R, C, K, X = self.unpack(x)
        d_rot, d_c, d_x, d_k = projection_jacobians(X[self.o_pt], R[self.o_img], C[self.o_img], K[self.o_cam])
        w = (self.weight / self.sigma_px)[:, None, None]
        sel, fp = self.sel, self.fp
        Jl = _left_jacobian_so3(x[: self.off_cam].reshape(-1, 6)[:, :3])
        d_pose = np.concatenate([d_rot[sel] @ Jl[fp[sel]], d_c[sel]], axis=2) * w[sel]
        parts = [d_pose] + ([d_k * w] if self.n_intr else []) + [d_x * w]
        data = [np.repeat(1.0 / self.g_sig, 3)]
        for d in parts:
            for j in (0, 1):
                data.append(d[:, j, :].ravel())
        return coo_matrix((np.concatenate(data), (self.rows, self.cols)), shape=self.shape).tocsr()

    def summary(self, x) -> dict:
        """RMS image residuals (all, tie, control; rejected observations left out) and the RMS
        ground correction of the control points."""
        e = np.sum(self.image_residuals(x) ** 2, axis=1)
        e = np.where(self.weight > 0, e, np.nan)
        dg = x[self.off_g :].reshape(-1, 3)
        n_tie_obs = self.n_tie_obs
        return {
            "rms_px": float(np.sqrt(np.nanmean(e))),
            "tie_rms_px": float(np.sqrt(np.nanmean(e[:n_tie_obs]))) if n_tie_obs else float("nan"),
            "control_rms_px": float(np.sqrt(np.nanmean(e[n_tie_obs:]))),
            "control_ground_rms": float(np.sqrt(np.mean(np.sum(dg**2, axis=1)))),
        }

    def loss_scales(self, params: BundleParams) -> list:
        """Graduated robustness: when the starting model is far off (a bent block starts with
        residuals of many σ), a loss that turns robust at 3σ would treat every residual as an
        outlier and crawl; start with the loss turning at the robust spread of the initial
        residuals (their 90th percentile: up to 10 % gross errors stay down-weighted) and finish
        at the nominal scale."""
        r0 = np.abs(self.fun(self.x0)[: 2 * self.m])
        start = max(params.loss_scale, float(np.quantile(r0, 0.9)))
        return [start, params.loss_scale] if params.loss != "linear" and start > 2 * params.loss_scale else [params.loss_scale]


def _adjusted_model(rec: Reconstruction, ids, cam_ids, prob: _Problem, x, ctrl: _Control, ties: _Ties):
    """Cameras, images and points of ``rec`` after the corrections ``x``, in the survey frame,
    and the adjusted control points by name."""
    R, C, K, X = prob.unpack(x)
    origin = ctrl.origin
    images = {}
    for k, iid in enumerate(ids):
        im = rec.images[int(iid)]
        Cw = C[k] + origin
        images[int(iid)] = Image(im.name, im.camera_id, Pose(R[k], -R[k] @ Cw), im.path)
    cameras = dict(rec.cameras)
    if prob.n_intr:
        for k, c in enumerate(cam_ids):
            old = rec.cameras[c]
            fx, fy, cx, cy, _, k1, k2 = (*K[k, :5], K[k, 5], K[k, 6])
            d = list((list(old.dist) + [0.0] * 5)[:5])
            d[0], d[1] = float(k1), float(k2)
            cameras[c] = Camera(old.width, old.height, float(fx), float(fy), float(cx), float(cy), old.skew, tuple(d), old.model)
    n_t = ties.active.shape[0]
    pts = np.asarray(rec.points, dtype=float).copy()
    pts[ties.active] = X[:n_t] + origin
    control_xyz = {g.name: X[n_t + k] + origin for k, g in enumerate(ctrl.gcps)}
    return cameras, images, pts, control_xyz


def _statistics(rec, ids, prob: _Problem, ctrl: _Control, ties: _Ties, params: BundleParams, before, after, scales, run) -> dict:
    """The ``stats`` of :class:`BundleResult`; ``run`` is (nfev, rejected, sol, t_start)."""
    nfev, rejected, sol, t_start = run
    m, n_tie_obs, n_t = prob.m, prob.n_tie_obs, ties.active.shape[0]
    return {
        "observations": int(m),
        "tie_observations": int(n_tie_obs),
        "control_observations": int(m - n_tie_obs),
        "tie_points": int(n_t),
        "tie_points_held": int(np.asarray(rec.points).shape[0] - n_t),
        "control_points": int(len(ctrl.gcps)),
        "control_sigma": {g.name: float(s) for g, s in zip(ctrl.gcps, prob.g_sig)},
        "free_images": int(prob.n_free),
        "fixed_images": [rec.images[int(ids[k])].name for k in prob.fixed],
        "parameters": int(prob.n_par),
        "refine_intrinsics": bool(params.refine_intrinsics),
        "loss": params.loss,
        "sigma_px": float(params.sigma_px),
        **{f"{k}_before": v for k, v in before.items()},
        **{f"{k}_after": v for k, v in after.items()},
        "cost_before": float(0.5 * np.sum(prob.fun(prob.x0) ** 2)),
        "cost_after": float(sol.cost),
        "evaluations": int(nfev),
        "rejected_observations": int(rejected),
        "loss_scales": [float(v) for v in scales],
        "status": int(sol.status),
        "message": str(sol.message),
        "seconds": time.perf_counter() - t_start,
    }


def bundle_adjust(rec: Reconstruction, control: Sequence, params: BundleParams = BundleParams()) -> BundleResult:
    """Refine poses, tie points, control points (and optionally intrinsics) with GCP constraints.

    Parameters
    ----------
    rec : Reconstruction
        Oriented images and tie points **already in the survey frame** (e.g. after the
        similarity of :func:`.georef.georeference`), with ``tracks`` (tie-point observations).
    control : sequence of :class:`workstation.io.gcp.GCP`
        Control points (role ``control``) with image observations; ``sigma`` weighs their
        surveyed coordinates (see :attr:`BundleParams.default_gcp_sigma`).
    params : BundleParams

    Returns
    -------
    BundleResult

    Raises
    ------
    InvalidInputError
        A point that is not a control point, fewer than 3 control points observed in ≥ 2
        oriented images, no tracks, a bad loss name.
    StageError
        The solver produced non-finite values.
    """
    from scipy.optimize import least_squares

    t_start = time.perf_counter()
    _check_inputs(rec, control, params)
    ids = np.array(sorted(int(i) for i in rec.images), dtype=np.int64)
    cam_ids = sorted(int(c) for c in rec.cameras)
    ctrl = _control_observations(rec, control, ids)
    ties = _tie_observations(rec, ids, ctrl.origin)
    prob = _Problem(rec, ids, cam_ids, ctrl, ties, params)
    before = prob.summary(prob.x0)
    scales = prob.loss_scales(params)
    with _single_threaded_blas():
        x, nfev, rejected, sol = _solve(least_squares, prob, prob.x0, list(scales), params)
    if not np.all(np.isfinite(x)):
        raise StageError("bundle_adjust", "the adjustment produced non-finite values", "check the GCP observations and names")
    after = prob.summary(x)
    cameras, images, pts, control_xyz = _adjusted_model(rec, ids, cam_ids, prob, x, ctrl, ties)
    stats = _statistics(rec, ids, prob, ctrl, ties, params, before, after, scales, (nfev, rejected, sol, t_start))
    log.info(
        "bundle adjustment: %d observations, %d tie + %d control points, %d images free; image RMS %.3f -> %.3f px in %d evaluations",
        prob.m, ties.active.shape[0], len(ctrl.gcps), prob.n_free, before["rms_px"], after["rms_px"], nfev,
    )
    meta = dict(rec.meta)
    meta["bundle_adjustment"] = {k: v for k, v in stats.items() if k not in ("control_sigma",)}
    out = Reconstruction(cameras, images, pts, rec.colors, rec.crs, meta, rec.tracks)
    return BundleResult(out, control_xyz, stats)
