"""Collinearity tools: projection, ω-φ-κ rotations, space resection and intersection, and the
classical single-photo and stereo formulas (relief displacement, parallax heights, GSD, B/H, σZ).

Numpy only (the optional pose initialisation of :func:`resect` uses OpenCV when no first guess
is given).

Conventions
-----------
* Pixels: OpenCV convention, origin at the centre of the top-left pixel, u to the right, v down.
* Camera frame (as :class:`~workstation.core.products.Pose`): x right, y down, z forward (viewing
  direction); ``x_cam = R @ X_world + t``.
* Photogrammetric angles ω, φ, κ (radians) follow Wolf, Dewitt & Wilkinson, *Elements of
  Photogrammetry* (4th ed., 2014, §C-7): ``M = M_κ · M_φ · M_ω`` rotates object-space
  vectors into the photo frame (x right, y up, z towards the viewer; a level nadir photo with
  ω = φ = κ = 0 has x = East, y = North). The OpenCV rotation is ``R = diag(1, -1, -1) @ M``.
* Distortion: OpenCV's Brown–Conrady model with coefficients (k1, k2, p1, p2, k3) applied to
  normalised coordinates (Brown 1971, "Close-range camera calibration", PE&RS 37(8)).

Examples
--------
A nadir camera 100 m above the origin looking straight down:

>>> import numpy as np
>>> from workstation.core.products import Camera
>>> cam = Camera(width=1000, height=800, fx=1000.0, fy=1000.0, cx=499.5, cy=399.5)
>>> pose = pose_from_opk(0.0, 0.0, 0.0, [0.0, 0.0, 100.0])
>>> project(np.array([[0.0, 0.0, 0.0], [10.0, 5.0, 0.0]]), cam, pose).round(3)
array([[499.5, 399.5],
       [599.5, 349.5]])
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Mapping, Sequence

import numpy as np

from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Camera, Pose

log = get_logger(__name__)

#: Photo frame (x right, y up, z back) -> OpenCV camera frame (x right, y down, z forward).
_FLIP = np.diag([1.0, -1.0, -1.0])


# --------------------------------------------------------------------------------------------
# rotations
# --------------------------------------------------------------------------------------------
def opk_to_matrix(omega: float, phi: float, kappa: float) -> np.ndarray:
    """Photogrammetric rotation matrix ``M = M_κ M_φ M_ω`` (object space -> photo frame).

    Parameters
    ----------
    omega, phi, kappa : float
        Sequential rotations about the x, y' and z'' axes, radians (Wolf et al. 2014, eq. C-33).

    Returns
    -------
    (3, 3) float64

    Examples
    --------
    >>> M = opk_to_matrix(0.1, -0.2, 0.3)
    >>> np.allclose(M @ M.T, np.eye(3)), np.allclose(matrix_to_opk(M), (0.1, -0.2, 0.3))
    (True, True)
    """
    so, co = np.sin(omega), np.cos(omega)
    sp, cp = np.sin(phi), np.cos(phi)
    sk, ck = np.sin(kappa), np.cos(kappa)
    return np.array(
        [
            [cp * ck, so * sp * ck + co * sk, -co * sp * ck + so * sk],
            [-cp * sk, -so * sp * sk + co * ck, co * sp * sk + so * ck],
            [sp, -so * cp, co * cp],
        ]
    )


def matrix_to_opk(M: np.ndarray) -> tuple[float, float, float]:
    """Inverse of :func:`opk_to_matrix`: (ω, φ, κ) in radians, φ in [-π/2, π/2].

    At φ = ±90° (gimbal lock) only ω ± κ is defined; κ is then set to 0.
    """
    M = np.asarray(M, dtype=float)
    phi = float(np.arcsin(np.clip(M[2, 0], -1.0, 1.0)))
    if abs(np.cos(phi)) < 1e-12:
        return float(np.arctan2(M[0, 1], M[1, 1])), phi, 0.0
    return float(np.arctan2(-M[2, 1], M[2, 2])), phi, float(np.arctan2(-M[1, 0], M[0, 0]))


def pose_from_opk(omega: float, phi: float, kappa: float, centre) -> Pose:
    """OpenCV pose from photogrammetric angles (radians) and the projection centre (X, Y, Z)."""
    R = _FLIP @ opk_to_matrix(omega, phi, kappa)
    C = np.asarray(centre, dtype=float).reshape(3)
    return Pose(R=R, t=-R @ C)


def opk_from_pose(pose: Pose) -> tuple[float, float, float]:
    """(ω, φ, κ) in radians of an OpenCV pose (inverse of :func:`pose_from_opk`).

    Examples
    --------
    >>> p = pose_from_opk(0.05, 0.02, 1.2, [1, 2, 3])
    >>> np.round(opk_from_pose(p), 6).tolist(), np.round(p.center, 6).tolist()
    ([0.05, 0.02, 1.2], [1.0, 2.0, 3.0])
    """
    return matrix_to_opk(_FLIP @ np.asarray(pose.R, dtype=float))


def rotvec_to_matrix(rvec) -> np.ndarray:
    """Rodrigues' formula: rotation vector (axis × angle, radians) -> (3, 3) rotation matrix."""
    r = np.asarray(rvec, dtype=float).reshape(3)
    th = np.linalg.norm(r)
    if th < 1e-15:
        Kx = np.array([[0, -r[2], r[1]], [r[2], 0, -r[0]], [-r[1], r[0], 0]])
        return np.eye(3) + Kx
    k = r / th
    Kx = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(th) * Kx + (1 - np.cos(th)) * (Kx @ Kx)


def rotation_angle_deg(Ra: np.ndarray, Rb: np.ndarray) -> float:
    """Angle in degrees of the rotation ``Ra @ Rb.T`` (0 when the two are equal)."""
    c = (np.trace(np.asarray(Ra) @ np.asarray(Rb).T) - 1.0) / 2.0
    return float(np.degrees(np.arccos(np.clip(c, -1.0, 1.0))))


# --------------------------------------------------------------------------------------------
# projection and distortion
# --------------------------------------------------------------------------------------------
def distort_normalized(xy: np.ndarray, dist) -> np.ndarray:
    """Apply OpenCV (k1, k2, p1, p2, k3) distortion to (n, 2) normalised coordinates."""
    k1, k2, p1, p2, k3 = (list(np.asarray(dist, dtype=float).ravel()) + [0.0] * 5)[:5]
    x, y = xy[:, 0], xy[:, 1]
    r2 = x * x + y * y
    radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3))
    xd = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x)
    yd = y * radial + p1 * (r2 + 2 * y * y) + 2 * p2 * x * y
    return np.column_stack([xd, yd])


def undistort_normalized(xyd: np.ndarray, dist, iterations: int = 20) -> np.ndarray:
    """Invert :func:`distort_normalized` by fixed-point iteration (as OpenCV's undistortPoints)."""
    k1, k2, p1, p2, k3 = (list(np.asarray(dist, dtype=float).ravel()) + [0.0] * 5)[:5]
    xyd = np.asarray(xyd, dtype=float)
    x, y = xyd[:, 0].copy(), xyd[:, 1].copy()
    if not any((k1, k2, p1, p2, k3)):
        return np.column_stack([x, y])
    for _ in range(iterations):
        r2 = x * x + y * y
        radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3))
        dx = 2 * p1 * x * y + p2 * (r2 + 2 * x * x)
        dy = p1 * (r2 + 2 * y * y) + 2 * p2 * x * y
        x = (xyd[:, 0] - dx) / radial
        y = (xyd[:, 1] - dy) / radial
    return np.column_stack([x, y])


def pixels_to_normalized(uv: np.ndarray, camera: Camera) -> np.ndarray:
    """(n, 2) pixels -> (n, 2) undistorted normalised coordinates (x/z, y/z in the camera frame)."""
    uv = np.asarray(uv, dtype=float).reshape(-1, 2)
    yd = (uv[:, 1] - camera.cy) / camera.fy
    xd = (uv[:, 0] - camera.cx - camera.skew * yd) / camera.fx
    return undistort_normalized(np.column_stack([xd, yd]), camera.dist)


def camera_rays(camera: Camera, supersample: int = 1) -> np.ndarray:
    """Unit ray directions in the camera frame through every (sub-)pixel, (h·s, w·s, 3).

    Sub-pixel (r, c) passes through the distorted image point u = (c + 0.5)/s − 0.5,
    v = (r + 0.5)/s − 0.5 (pixel centres at integers).
    """
    s = supersample
    us = (np.arange(camera.width * s) + 0.5) / s - 0.5
    vs = (np.arange(camera.height * s) + 0.5) / s - 0.5
    U, V = np.meshgrid(us, vs)
    und = pixels_to_normalized(np.column_stack([U.ravel(), V.ravel()]), camera)
    d = np.column_stack([und, np.ones(len(und))])
    d /= np.linalg.norm(d, axis=1, keepdims=True)
    return d.reshape(camera.height * s, camera.width * s, 3)


def project(X: np.ndarray, camera: Camera, pose: Pose, return_depth: bool = False, return_normalized: bool = False):
    """Project world points into an image with the collinearity equations and OpenCV distortion.

    Parameters
    ----------
    X : (n, 3) float
        World coordinates.
    camera : Camera
    pose : Pose
        World -> camera.
    return_depth : bool
        Also return the depth (camera z, same unit as X) of every point; points behind the camera
        have a negative depth and meaningless pixels.
    return_normalized : bool
        Also return the undistorted normalised image coordinates (x/z, y/z), e.g. to reject
        points beyond the radius where the distortion polynomial folds back.

    Returns
    -------
    uv : (n, 2) float64 pixels
    depth : (n,) float64, only when ``return_depth``
    xy : (n, 2) float64, only when ``return_normalized``

    Examples
    --------
    >>> cam = Camera(640, 480, 500.0, 500.0, 320.0, 240.0, dist=(-0.2, 0.05, 0.0, 0.0, 0.0))
    >>> pose = Pose(np.eye(3), np.zeros(3))
    >>> project(np.array([[0.2, 0.1, 1.0]]), cam, pose).round(4)
    array([[419.0125, 289.5062]])
    """
    X = np.asarray(X, dtype=float).reshape(-1, 3)
    Xc = X @ np.asarray(pose.R, dtype=float).T + np.asarray(pose.t, dtype=float)
    z = Xc[:, 2]
    with np.errstate(divide="ignore", invalid="ignore"):
        xy = Xc[:, :2] / z[:, None]
    xyd = distort_normalized(xy, camera.dist)
    u = camera.fx * xyd[:, 0] + camera.skew * xyd[:, 1] + camera.cx
    v = camera.fy * xyd[:, 1] + camera.cy
    uv = np.column_stack([u, v])
    if not (return_depth or return_normalized):
        return uv
    return (uv,) + ((z,) if return_depth else ()) + ((xy,) if return_normalized else ())


# --------------------------------------------------------------------------------------------
# space resection
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class ResectionParams:
    """Options of :func:`resect`.

    Attributes
    ----------
    sigma_px : float
        A-priori standard deviation of an image measurement, pixels; scales the covariance when
        there is no redundancy (3 points).
    max_iterations : int
        Levenberg–Marquardt iterations.
    tolerance : float
        Stop when the update of the centre is below this fraction of the mean object distance
        and the rotation update below the same value in radians.
    """

    sigma_px: float = 1.0
    max_iterations: int = 50
    tolerance: float = 1e-12


@dataclass(frozen=True)
class ResectionResult:
    """A resected camera pose with its precision.

    Attributes
    ----------
    pose : Pose
    omega, phi, kappa : float
        Photogrammetric angles, radians.
    centre : (3,) float
        Projection centre in world units.
    covariance : (6, 6) float
        Covariance of (δrx, δry, δrz, X, Y, Z): small rotations (radians) about the world axes,
        then the centre (world units²). Scaled by the a-posteriori variance factor when
        redundant, by ``sigma_px²`` otherwise.
    std_centre : (3,) float
        Standard deviations of X, Y, Z of the centre, world units.
    std_angles_deg : (3,) float
        Standard deviations of the small rotations about the world X, Y, Z axes, degrees.
    sigma0_px : float
        A-posteriori standard deviation of unit weight (pixels); NaN without redundancy.
    residuals : (n, 2) float
        Observed minus projected pixels.
    rms_px : float
    iterations : int
    converged : bool
    """

    pose: Pose
    omega: float
    phi: float
    kappa: float
    centre: np.ndarray
    covariance: np.ndarray
    std_centre: np.ndarray
    std_angles_deg: np.ndarray
    sigma0_px: float
    residuals: np.ndarray
    rms_px: float
    iterations: int
    converged: bool

    def to_dict(self) -> dict:
        return {
            "omega_deg": float(np.degrees(self.omega)),
            "phi_deg": float(np.degrees(self.phi)),
            "kappa_deg": float(np.degrees(self.kappa)),
            "centre": [float(c) for c in self.centre],
            "std_centre": [float(c) for c in self.std_centre],
            "std_angles_deg": [float(c) for c in self.std_angles_deg],
            "sigma0_px": float(self.sigma0_px),
            "rms_px": float(self.rms_px),
            "iterations": int(self.iterations),
            "converged": bool(self.converged),
        }


def _pose_params(R: np.ndarray, C: np.ndarray, d: np.ndarray) -> Pose:
    """Pose after a small world-frame rotation d[:3] and a centre shift d[3:]."""
    Rn = R @ rotvec_to_matrix(d[:3]).T
    Cn = C + d[3:]
    return Pose(Rn, -Rn @ Cn)


def numeric_jacobian(fun, n_params: int, steps: np.ndarray) -> np.ndarray:
    cols = []
    for j in range(n_params):
        e = np.zeros(n_params)
        e[j] = steps[j]
        cols.append((fun(e) - fun(-e)) / (2 * steps[j]))
    return np.stack(cols, axis=-1)


def _initial_pose_opencv(X: np.ndarray, uv: np.ndarray, camera: Camera) -> Pose:
    import cv2

    xy = pixels_to_normalized(uv, camera)
    flag = cv2.SOLVEPNP_SQPNP if X.shape[0] >= 3 else cv2.SOLVEPNP_ITERATIVE
    ok, rvec, tvec = cv2.solvePnP(
        X.astype(np.float64), xy.astype(np.float64).reshape(-1, 1, 2), np.eye(3), None, flags=flag
    )
    if not ok:
        raise StageError("resection", "no initial pose found", "give an approximate pose (initial=...)")
    R, _ = cv2.Rodrigues(rvec)
    return Pose(R, tvec.ravel())


def points_and_pixels(X, uv) -> tuple[np.ndarray, np.ndarray]:
    """``X`` as (n, 3) and ``uv`` as (n, 2) float arrays; refuses other shapes."""
    X = np.asarray(X, dtype=float)
    uv = np.asarray(uv, dtype=float)
    if X.ndim != 2 or X.shape[1] != 3 or uv.shape != (X.shape[0], 2):
        raise InvalidInputError(f"need (n, 3) points and (n, 2) pixels, got {X.shape} and {uv.shape}")
    return X, uv


def _resection_result(final: Pose, C: np.ndarray, cov: np.ndarray, sigma0: float, r: np.ndarray,
                      iterations: int) -> ResectionResult:
    """The :class:`ResectionResult` of a converged resection: pose, centre ``C``, residuals ``r``."""
    std = np.sqrt(np.clip(np.diag(cov), 0, None))
    om, ph, ka = opk_from_pose(final)
    res2 = r.reshape(-1, 2)
    return ResectionResult(
        pose=final,
        omega=om,
        phi=ph,
        kappa=ka,
        centre=C.copy(),
        covariance=cov,
        std_centre=std[3:],
        std_angles_deg=np.degrees(std[:3]),
        sigma0_px=sigma0,
        residuals=res2,
        rms_px=float(np.sqrt(np.mean(np.sum(res2**2, axis=1)))),
        iterations=iterations,
        converged=True,
    )


def _resection_lm(resid, R: np.ndarray, C: np.ndarray, steps: np.ndarray, scale: float, params: ResectionParams):
    """Levenberg–Marquardt on the pose: each step is a small world-frame rotation and a centre
    shift (:func:`_pose_params`) applied to the current (R, C). ``resid(d, R, C)`` gives the
    pixel residuals after step ``d``. Stops when no damping lowers the cost or the step is
    below ``params.tolerance`` (rotation, radians; centre, times ``scale``).

    Returns the rotation, the centre, the residuals and the iteration count.

    Raises
    ------
    StageError
        Not converged in ``params.max_iterations``.
    """
    lam = 1e-3
    it = 0
    r = resid(np.zeros(6), R, C)
    for it in range(1, params.max_iterations + 1):
        J = numeric_jacobian(lambda d: resid(d, R, C), 6, steps)
        A = J.T @ J
        g = J.T @ r
        improved = False
        for _ in range(20):
            step = np.linalg.solve(A + lam * np.diag(np.diag(A) + 1e-12), -g)
            r_new = resid(step, R, C)
            if r_new @ r_new <= r @ r:
                pose_new = _pose_params(R, C, step)
                R, C = np.asarray(pose_new.R), np.asarray(pose_new.center)
                r = r_new
                lam = max(lam / 10, 1e-12)
                improved = True
                break
            lam *= 10
        small = np.all(np.abs(step[:3]) < max(params.tolerance, 1e-15)) and np.all(
            np.abs(step[3:]) < max(params.tolerance, 1e-15) * scale
        )
        if not improved or small:
            return R, C, r, it
    raise StageError("resection", f"did not converge in {params.max_iterations} iterations", "check the point ids")


def _covariance(J: np.ndarray, r: np.ndarray, dof: int, a_posteriori: bool, sigma_px: float) -> tuple[np.ndarray, float]:
    """``var · (JᵀJ)⁻¹`` and the a-posteriori σ0 of residuals ``r`` with ``dof`` degrees of
    freedom (NaN without redundancy); ``var`` is σ0² when ``a_posteriori``, else
    ``sigma_px²``. A singular JᵀJ gives a NaN covariance."""
    sigma0 = float(np.sqrt(r @ r / dof)) if dof > 0 else float("nan")
    var = sigma0**2 if a_posteriori else sigma_px**2
    try:
        cov = var * np.linalg.inv(J.T @ J)
    except np.linalg.LinAlgError:
        cov = np.full((J.shape[1], J.shape[1]), np.nan)
    return cov, sigma0


def resect(
    X: np.ndarray,
    uv: np.ndarray,
    camera: Camera,
    initial: Pose | None = None,
    params: ResectionParams = ResectionParams(),
) -> ResectionResult:
    """Space resection: the exterior orientation of one image from ≥ 3 known points.

    Levenberg–Marquardt on the collinearity equations (Wolf et al. 2014, §11-6; Kraus,
    *Photogrammetry* vol. 1, §5.3), with the interior orientation and distortion of ``camera``
    held fixed. The first guess, when not given, comes from OpenCV's SQPnP (Terzakis & Lourakis,
    ECCV 2020). Three points give up to four solutions: the one nearest the first guess is found.

    Parameters
    ----------
    X : (n, 3) float
        World coordinates of the control points, n ≥ 3.
    uv : (n, 2) float
        Their measured pixel coordinates.
    camera : Camera
    initial : Pose, optional
        First guess.
    params : ResectionParams

    Returns
    -------
    ResectionResult

    Raises
    ------
    InvalidInputError
        Fewer than 3 points or mismatched shapes.
    StageError
        The adjustment does not converge or a point ends behind the camera.

    Examples
    --------
    >>> cam = Camera(1000, 800, 1200.0, 1200.0, 500.0, 400.0)
    >>> true = pose_from_opk(0.02, -0.03, 0.4, [5.0, -3.0, 60.0])
    >>> X = np.array([[0, 0, 0], [20, 0, 1], [0, 20, 2], [20, 20, 0], [10, 5, 4], [3, 15, 1.0]])
    >>> res = resect(X, project(X, cam, true), cam)
    >>> np.round(res.centre, 6).tolist(), round(float(np.degrees(res.kappa)), 6)
    ([5.0, -3.0, 60.0], 22.918312)
    """
    X, uv = points_and_pixels(X, uv)
    n = X.shape[0]
    if n < 3:
        raise InvalidInputError(
            f"space resection needs at least 3 points, got {n}", "measure more control points in this image"
        )
    pose = initial if initial is not None else _initial_pose_opencv(X, uv, camera)
    R = np.asarray(pose.R, dtype=float)
    C = np.asarray(pose.center, dtype=float)
    scale = float(np.mean(np.linalg.norm(X - C, axis=1))) or 1.0
    steps = np.array([1e-7, 1e-7, 1e-7, 1e-7 * scale, 1e-7 * scale, 1e-7 * scale])

    def resid(d, R=None, C=None):
        return (uv - project(X, camera, _pose_params(R, C, d))).ravel()

    R, C, r, it = _resection_lm(resid, R, C, steps, scale, params)
    final = Pose(R, -R @ C)
    _, depth = project(X, camera, final, return_depth=True)
    if np.any(depth <= 0):
        raise StageError("resection", "some control points lie behind the resected camera", "check the observations")
    J = numeric_jacobian(lambda d: resid(d, R, C), 6, steps)
    dof = 2 * n - 6
    cov, sigma0 = _covariance(J, r, dof, dof > 0, params.sigma_px)
    return _resection_result(final, C, cov, sigma0, r, it)


# --------------------------------------------------------------------------------------------
# space intersection
# --------------------------------------------------------------------------------------------
@dataclass(frozen=True)
class IntersectionResult:
    """A point intersected from several rays.

    Attributes
    ----------
    point : (3,) float
        World coordinates.
    covariance : (3, 3) float
        World units²; scaled by the a-posteriori variance factor when there are ≥ 3 rays
        (≥ 3 redundant equations), by ``sigma_px²`` otherwise.
    std : (3,) float
        Standard deviations of X, Y, Z.
    residuals : (m, 2) float
        Observed minus projected pixels per ray.
    rms_px : float
    sigma0_px : float
    max_angle_deg : float
        Largest intersection angle between two rays (small angles mean a weak geometry).
    """

    point: np.ndarray
    covariance: np.ndarray
    std: np.ndarray
    residuals: np.ndarray
    rms_px: float
    sigma0_px: float
    max_angle_deg: float
    meta: Mapping[str, Any] = field(default_factory=dict)


def _linear_intersection(uv: np.ndarray, cameras: Sequence[Camera], poses: Sequence[Pose]) -> tuple[np.ndarray, float]:
    """The homogeneous linear triangulation of one point (rows normalised) and the largest
    angle between two of its rays, degrees."""
    rows = []
    dirs = []
    for k in range(uv.shape[0]):
        xy = pixels_to_normalized(uv[k : k + 1], cameras[k])[0]
        R = np.asarray(poses[k].R, dtype=float)
        t = np.asarray(poses[k].t, dtype=float)
        P = np.hstack([R, t[:, None]])
        rows.append(xy[0] * P[2] - P[0])
        rows.append(xy[1] * P[2] - P[1])
        d = R.T @ np.array([xy[0], xy[1], 1.0])
        dirs.append(d / np.linalg.norm(d))
    A = np.array(rows)
    A = A / np.linalg.norm(A, axis=1, keepdims=True)
    _, _, Vt = np.linalg.svd(A)
    h = Vt[-1]
    if abs(h[3]) < 1e-15:
        raise StageError("intersection", "rays are parallel: the point is at infinity", "use images with a wider base")
    D = np.array(dirs)
    cosang = np.clip(D @ D.T, -1, 1)
    return h[:3] / h[3], float(np.degrees(np.arccos(cosang.min())))


def intersect(
    uv: np.ndarray,
    cameras: Sequence[Camera],
    poses: Sequence[Pose],
    sigma_px: float = 1.0,
    iterations: int = 10,
    a_posteriori: bool = True,
) -> IntersectionResult:
    """Space intersection: one object point from its pixels in ≥ 2 oriented images.

    A linear least-squares solution of the collinearity equations (the homogeneous DLT
    triangulation of Hartley & Zisserman 2004, §12.2, on undistorted normalised coordinates) is
    refined by Gauss–Newton on the pixel residuals (Wolf et al. 2014, §11-7). The covariance is
    ``σ0² (JᵀJ)⁻¹``.

    Parameters
    ----------
    uv : (m, 2) float
        The point's pixel coordinates in m images.
    cameras, poses : sequences of m Camera / Pose
    sigma_px : float
        A-priori image measurement precision, pixels (used when there is no redundancy).
    iterations : int
        Gauss–Newton iterations.
    a_posteriori : bool
        Scale the covariance by the a-posteriori variance factor when there are ≥ 2 redundant
        equations (≥ 3 rays); False always uses ``sigma_px²`` (the expected precision).

    Returns
    -------
    IntersectionResult

    Examples
    --------
    >>> cam = Camera(1000, 800, 1000.0, 1000.0, 500.0, 400.0)
    >>> p1 = pose_from_opk(0, 0, 0, [0, 0, 100.0]); p2 = pose_from_opk(0, 0, 0, [60, 0, 100.0])
    >>> X = np.array([[30.0, 10.0, 5.0]])
    >>> obs = np.vstack([project(X, cam, p1), project(X, cam, p2)])
    >>> intersect(obs, [cam, cam], [p1, p2]).point.round(6).tolist()
    [30.0, 10.0, 5.0]
    """
    uv = np.asarray(uv, dtype=float).reshape(-1, 2)
    m = uv.shape[0]
    if m < 2 or len(cameras) != m or len(poses) != m:
        raise InvalidInputError(
            f"space intersection needs ≥ 2 rays with one camera and pose each, got {m} pixels, "
            f"{len(cameras)} cameras, {len(poses)} poses",
            "observe the point in at least two oriented images",
        )
    Xp, max_angle = _linear_intersection(uv, cameras, poses)
    scale = max(float(np.mean([np.linalg.norm(Xp - p.center) for p in poses])), 1e-9)
    step = 1e-7 * scale * np.ones(3)

    def resid(Xq):
        return np.concatenate([uv[k] - project(Xq[None], cameras[k], poses[k])[0] for k in range(m)])

    for _ in range(iterations):  # Gauss–Newton
        r = resid(Xp)
        J = numeric_jacobian(lambda d: resid(Xp + d), 3, step)
        dx, *_ = np.linalg.lstsq(J, -r, rcond=None)
        Xp = Xp + dx
        if np.linalg.norm(dx) < 1e-12 * scale:
            break
    r = resid(Xp)
    J = numeric_jacobian(lambda d: resid(Xp + d), 3, step)
    dof = 2 * m - 3
    cov, sigma0 = _covariance(J, r, dof, dof >= 3 and a_posteriori, sigma_px)
    res2 = r.reshape(-1, 2)
    return IntersectionResult(
        point=Xp,
        covariance=cov,
        std=np.sqrt(np.clip(np.diag(cov), 0, None)),
        residuals=res2,
        rms_px=float(np.sqrt(np.mean(np.sum(res2**2, axis=1)))),
        sigma0_px=sigma0,
        max_angle_deg=max_angle,
    )


# --------------------------------------------------------------------------------------------
# single photo and stereo formulas
# --------------------------------------------------------------------------------------------
def relief_displacement(r: float, h: float, flying_height: float):
    """Relief displacement on a vertical photo: ``d = r h / H`` (Wolf et al. 2014, eq. 6-11).

    Parameters
    ----------
    r : float or array
        Radial distance of the displaced image point from the principal (nadir) point, in image
        units (mm or pixels); d comes out in the same unit.
    h : float or array
        Height of the point above the datum, metres.
    flying_height : float
        Flying height H above the same datum, metres.

    Examples
    --------
    >>> relief_displacement(80.0, 50.0, 1000.0)
    4.0
    >>> height_from_relief_displacement(4.0, 80.0, 1000.0)
    50.0
    """
    return r * h / flying_height


def height_from_relief_displacement(d: float, r: float, flying_height: float):
    """Object height from its relief displacement: ``h = d H / r`` (Wolf et al. 2014, eq. 6-12).

    ``d`` and ``r`` in the same image unit, H in metres; h in metres.
    """
    return d * flying_height / r


def height_from_parallax(parallax: float, base: float, focal: float, flying_height: float):
    """Elevation of a point from its x-parallax: ``h = H - B f / p`` (Wolf et al. 2014, eq. 8-5).

    Parameters
    ----------
    parallax, focal : float
        x-parallax p and focal length f in the same image unit (mm or pixels).
    base : float
        Air base B, metres.
    flying_height : float
        H above the datum, metres.

    Examples
    --------
    >>> height_from_parallax(90.0, 600.0, 152.4, 1233.0)
    217.0
    """
    return flying_height - base * focal / parallax


def height_difference_from_parallax(dp: float, pa: float, flying_height_above_a: float):
    """Height of B above A from their parallax difference Δp = p_b - p_a:
    ``Δh = (H - h_A) Δp / (p_a + Δp)`` (Wolf et al. 2014, eq. 8-11).

    Examples
    --------
    >>> round(height_difference_from_parallax(2.0, 88.0, 900.0), 3)
    20.0
    """
    return flying_height_above_a * dp / (pa + dp)


def gsd(distance: float, focal_px: float | None = None, *, focal_mm: float | None = None, pixel_um: float | None = None):
    """Ground sampling distance ``GSD = H / f`` (f in pixels) or ``H · pixel pitch / f``.

    Parameters
    ----------
    distance : float
        Flying height above ground (or object distance), metres.
    focal_px : float, optional
        Focal length in pixels.
    focal_mm, pixel_um : float, optional
        Focal length in millimetres and pixel pitch in micrometres (instead of focal_px).

    Returns
    -------
    float
        Metres per pixel.

    Examples
    --------
    >>> gsd(100.0, 4000.0)
    0.025
    >>> round(gsd(100.0, focal_mm=8.8, pixel_um=2.41), 5)
    0.02739
    """
    if focal_px is None:
        if focal_mm is None or pixel_um is None:
            raise InvalidInputError("give focal_px, or focal_mm and pixel_um")
        focal_px = focal_mm * 1000.0 / pixel_um
    return distance / focal_px


@dataclass(frozen=True)
class StereoPrecision:
    """Expected precision of a normal-case stereo pair (Kraus 2007, §4.1; Wolf et al. 2014, §8-8).

    Attributes
    ----------
    base_to_height : float
        B/H ratio.
    sigma_xy : float
        Planimetric standard deviation ``(H/f) σ_px``, metres.
    sigma_z : float
        Depth standard deviation ``(H/B)(H/f) σ_px``, metres.
    gsd : float
        H/f, metres per pixel.
    """

    base_to_height: float
    sigma_xy: float
    sigma_z: float
    gsd: float

    def to_dict(self) -> dict:
        return {k: float(getattr(self, k)) for k in ("base_to_height", "sigma_xy", "sigma_z", "gsd")}


def stereo_precision(distance: float, base: float, focal_px: float, sigma_px: float = 0.5) -> StereoPrecision:
    """B/H, σXY and σZ of a normal-case stereo pair.

    Parameters
    ----------
    distance : float
        Object distance (flying height above ground) H, metres.
    base : float
        Stereo base B, metres.
    focal_px : float
        Focal length, pixels.
    sigma_px : float
        Precision of the measured x-parallax, pixels (two image points each measured to σ give
        a parallax precision of √2·σ).

    Examples
    --------
    >>> sp = stereo_precision(100.0, 60.0, 4000.0, 0.5)
    >>> round(sp.base_to_height, 3), round(sp.sigma_xy, 4), round(sp.sigma_z, 4)
    (0.6, 0.0125, 0.0208)
    """
    if base <= 0 or distance <= 0 or focal_px <= 0:
        raise InvalidInputError("distance, base and focal length must be positive")
    g = distance / focal_px
    return StereoPrecision(base / distance, g * sigma_px, (distance / base) * g * sigma_px, g)
