"""Fine registration: ICP variants with robust kernels, and the 7-DoF similarity ICP.

- point-to-point (Besl & McKay 1992, "A method for registration of 3-D shapes", PAMI 14(2));
  with ``with_scale`` the Umeyama similarity is solved at every iteration (7 DoF) for SfM
  clouds whose scale is arbitrary;
- point-to-plane (Chen & Medioni 1992) with robust kernels (Tukey, Huber, Cauchy, Geman-
  McClure, L1; Babin et al. 2019, "Analysis of robust functions for registration algorithms",
  ICRA);
- coloured ICP (Park, Zhou & Koltun 2017, "Colored point cloud registration revisited", ICCV);
- generalised ICP (Segal, Haehnel & Thrun 2009, "Generalized-ICP", RSS);
- ``voxel_plane``: our point-to-plane ICP with voxel-hash correspondences
  (:mod:`workstation.registration.voxelmap`), for millions of points.

The Open3D variants run a coarse-to-fine schedule of correspondence distances, each a multiple
of one voxel size.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.core.log import get_logger
from workstation.core.products import RegistrationResult

log = get_logger(__name__)

ICP_METHODS = ("point_to_plane", "point_to_point", "colored", "generalized", "voxel_plane")
KERNELS = ("none", "tukey", "huber", "cauchy", "gm", "l1")


@dataclass(frozen=True)
class ICPParams:
    """Fine-registration parameters; distances are multiples of ``voxel`` (metres).

    Attributes
    ----------
    method : str
        One of :data:`ICP_METHODS`.
    schedule : tuple of float
        Maximum correspondence distances, coarse to fine, as multiples of the voxel size.
    max_iterations : int
        Iterations per schedule level.
    kernel : str
        Robust kernel (:data:`KERNELS`) for point-to-plane, coloured and generalised ICP.
    kernel_scale : float
        Kernel width as a share of the level's correspondence distance.
    with_scale : bool
        Estimate a similarity scale (point-to-point only): 7-DoF SfM <-> LiDAR.
    relative_fitness, relative_rmse : float
        Open3D convergence thresholds per level.
    colored_lambda : float
        Weight of the geometric term in coloured ICP (0..1).
    """

    method: str = "point_to_plane"
    schedule: tuple = (1.5, 0.6, 0.3)
    max_iterations: int = 30
    kernel: str = "tukey"
    kernel_scale: float = 0.5
    with_scale: bool = False
    relative_fitness: float = 1e-6
    relative_rmse: float = 1e-6
    colored_lambda: float = 0.968

    def __post_init__(self):
        if self.method not in ICP_METHODS:
            raise InvalidInputError(f"unknown ICP method {self.method!r}", f"use one of {', '.join(ICP_METHODS)}",
                                    field="method")
        if self.kernel not in KERNELS:
            raise InvalidInputError(f"unknown kernel {self.kernel!r}", f"use one of {', '.join(KERNELS)}", field="kernel")
        if self.with_scale and self.method != "point_to_point":
            raise InvalidInputError("scale estimation needs method='point_to_point'", field="with_scale")
        if not self.schedule or min(self.schedule) <= 0:
            raise InvalidInputError("schedule needs positive distance multiples", field="schedule")


#: The short ICP that verifies coarse pose hypotheses on the downsampled clouds: point-to-plane,
#: Tukey kernel, 1.5 then 0.75 voxel, 20 iterations a level.
QUICK_ICP = ICPParams(method="point_to_plane", schedule=(1.5, 0.75), max_iterations=20, kernel="tukey")


def _kernel(reg, name: str, k: float):
    if name == "none":
        return None
    return {"tukey": reg.TukeyLoss, "huber": reg.HuberLoss, "cauchy": reg.CauchyLoss, "gm": reg.GMLoss,
            "l1": reg.L1Loss}[name](k) if name != "l1" else reg.L1Loss()


def refine(source, target, voxel: float, init: np.ndarray | None = None, params: ICPParams = ICPParams(), *,
           information: bool = True) -> RegistrationResult:
    """ICP of a legacy Open3D source cloud onto a target (both local frame, normals present for
    the plane-based methods, colours for coloured ICP).

    Parameters
    ----------
    source, target : open3d.geometry.PointCloud
    voxel : float
        The voxel size all distances derive from (units of the clouds).
    init : (4, 4) float, optional
    params : ICPParams
    information : bool
        Compute the information matrix (False: None, for a hypothesis check that ranks poses).

    Returns
    -------
    RegistrationResult
        Fitness and RMSE at the finest level's distance; ``information`` is Open3D's 6x6
        information matrix of the final correspondences; ``meta["levels"]`` has each level.
    """
    from workstation.interop.open3d import require_open3d

    o3d = require_open3d()
    reg = o3d.pipelines.registration
    T = np.eye(4) if init is None else np.asarray(init, dtype=np.float64)
    levels = []
    res = None
    if params.method == "colored" and not (source.has_colors() and target.has_colors()):
        raise InvalidInputError("coloured ICP needs rgb on both clouds", "use --method point_to_plane", field="rgb")
    if params.method in ("point_to_plane", "colored") and not target.has_normals():
        raise InvalidInputError("the target needs normals", field="normal")
    for f in params.schedule:
        d = float(f * voxel)
        crit = reg.ICPConvergenceCriteria(params.relative_fitness, params.relative_rmse, int(params.max_iterations))
        kern = _kernel(reg, params.kernel, params.kernel_scale * d)
        if params.method == "point_to_point":
            est = reg.TransformationEstimationPointToPoint(bool(params.with_scale))
            res = reg.registration_icp(source, target, d, T, est, crit)
        elif params.method == "point_to_plane":
            est = reg.TransformationEstimationPointToPlane(kern) if kern else reg.TransformationEstimationPointToPlane()
            res = reg.registration_icp(source, target, d, T, est, crit)
        elif params.method == "colored":
            est = (reg.TransformationEstimationForColoredICP(params.colored_lambda, kern) if kern
                   else reg.TransformationEstimationForColoredICP(params.colored_lambda))
            res = reg.registration_colored_icp(source, target, d, T, est, crit)
        elif params.method == "generalized":
            est = (reg.TransformationEstimationForGeneralizedICP(1e-3, kern) if kern
                   else reg.TransformationEstimationForGeneralizedICP())
            res = reg.registration_generalized_icp(source, target, d, T, est, crit)
        else:
            raise InvalidInputError("voxel_plane runs through voxel_plane_icp()", field="method")
        T = np.asarray(res.transformation)
        levels.append({"distance": d, "fitness": float(res.fitness), "inlier_rmse": float(res.inlier_rmse),
                       "correspondences": len(res.correspondence_set)})
    d_last = float(params.schedule[-1] * voxel)
    info = np.asarray(reg.get_information_matrix_from_point_clouds(source, target, d_last, T)) if information else None
    scale = float(np.cbrt(np.linalg.det(T[:3, :3])))
    ok = res is not None and len(res.correspondence_set) >= 6 and np.isfinite(T).all()
    return RegistrationResult(transform=T, scale=scale, fitness=float(res.fitness), inlier_rmse=float(res.inlier_rmse),
                              converged=bool(ok), correspondences=len(res.correspondence_set), information=info,
                              meta={"method": params.method, "kernel": params.kernel, "levels": levels})


def voxel_plane_icp(source_xyz: np.ndarray, target_xyz: np.ndarray, voxel: float, init: np.ndarray | None = None,
                    params: ICPParams = ICPParams(method="voxel_plane")) -> RegistrationResult:
    """Point-to-plane ICP with voxel-hash correspondences on local (origin-subtracted) arrays.

    ``voxel`` is the finest plane voxel; levels ``4, 2, 1`` times it run
    ``params.max_iterations`` iterations in total. See :mod:`workstation.registration.voxelmap`.
    """
    from .voxelmap import point_to_plane_voxel

    r = point_to_plane_voxel(source_xyz, target_xyz, voxel, init=init, iterations=int(params.max_iterations))
    return RegistrationResult(transform=r.transform, scale=1.0, fitness=r.fitness, inlier_rmse=r.rmse,
                              converged=r.converged, correspondences=int(round(r.fitness * len(source_xyz))),
                              meta={"method": "voxel_plane", "iterations": r.iterations})


def _rodrigues(w: np.ndarray) -> np.ndarray:
    th = float(np.linalg.norm(w))
    if th < 1e-15:
        return np.eye(3)
    k = w / th
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(th) * K + (1 - np.cos(th)) * K @ K


def similarity_plane_icp(source_xyz: np.ndarray, target_xyz: np.ndarray, target_normals: np.ndarray,
                         distances, init: np.ndarray | None = None, max_iterations: int = 30,
                         kernel_scale: float = 0.5, tolerance: float = 1e-7) -> RegistrationResult:
    """7-DoF point-to-plane ICP: rotation, translation and scale with a Tukey kernel.

    Point-to-point ICP with scale (Umeyama at every step) is biased when the two clouds sample
    the surface differently (an SfM-dense cloud and a TLS scan): each source point is pulled
    towards the nearest target sample, not onto the surface. Here the residual is the distance
    to the target's tangent plane, ``n . (s R p + t - q)``, linearised about the corresponding
    points' centroid ``c`` as ``p' = c + (1 + sigma)(I + [omega]x)(p - c) + tau`` (the
    point-to-plane linearisation of Chen & Medioni 1992 / Low 2004 with one more column,
    ``n . (p - c)``, for the scale), solved by iteratively reweighted least squares with
    Tukey's biweight of width ``kernel_scale * d`` (Babin et al. 2019).

    Parameters
    ----------
    source_xyz : (n, 3) float64
    target_xyz : (m, 3) float64
    target_normals : (m, 3) float64
        Unit normals of the target.
    distances : sequence of float
        Maximum correspondence distances, coarse to fine (target units).
    init : (4, 4) float, optional
        Initial similarity source -> target.
    max_iterations : int
        Iterations per distance level.
    kernel_scale : float
    tolerance : float
        A level stops when the update moves the points by less than this share of ``d``.

    Returns
    -------
    RegistrationResult
        ``scale`` is the similarity's scale; fitness / RMSE (plane distances) at the last
        level; ``information`` is the 7x7 normal matrix of the last step (omega, tau, sigma).
    """
    from scipy.spatial import cKDTree

    src = np.asarray(source_xyz, dtype=np.float64)
    tgt = np.asarray(target_xyz, dtype=np.float64)
    nrm = np.asarray(target_normals, dtype=np.float64)
    T = np.eye(4) if init is None else np.asarray(init, dtype=np.float64).copy()
    tree = cKDTree(tgt)
    levels = []
    H = np.zeros((7, 7))
    fit = rmse = 0.0
    n_corr = 0
    r = None
    it_total = 0
    for d in distances:
        d = float(d)
        T, H, n_corr, r, its = _similarity_level(src, tgt, nrm, tree, T, (H, n_corr, r), d, int(max_iterations),
                                                 kernel_scale, tolerance)
        it_total += its
        inl = np.abs(r) < kernel_scale * d if n_corr >= 7 else np.zeros(0, bool)
        fit = float(n_corr / max(len(src), 1))
        rmse = float(np.sqrt(np.mean(r[inl] ** 2))) if inl.any() else float("nan")
        levels.append({"distance": d, "fitness": fit, "inlier_rmse": rmse, "correspondences": n_corr})
    scale = float(np.cbrt(np.linalg.det(T[:3, :3])))
    ok = n_corr >= 7 and np.isfinite(T).all() and scale > 0
    return RegistrationResult(transform=T, scale=scale, fitness=fit, inlier_rmse=rmse, converged=bool(ok),
                              correspondences=n_corr, information=H,
                              meta={"method": "similarity_point_to_plane", "kernel": "tukey", "levels": levels,
                                    "iterations": it_total})


def _similarity_level(src, tgt, nrm, tree, T: np.ndarray, state, d: float, max_iterations: int, kernel_scale: float,
                      tolerance: float):
    """The iterations of :func:`similarity_plane_icp` at one correspondence distance ``d``:
    nearest target point within ``d`` of each moved source point, one reweighted Gauss-Newton
    step on the plane distances, until the update moves the points by less than
    ``tolerance * d``, fewer than 7 correspondences remain or the system is singular.

    ``state`` is ``(H, n_corr, r)`` of the previous level (normal matrix, correspondence count,
    plane residuals), returned updated as ``(T, H, n_corr, r, iterations)``.
    """
    H, n_corr, r = state
    its = 0
    for _ in range(max_iterations):
        its += 1
        p = src @ T[:3, :3].T + T[:3, 3]
        dist, j = tree.query(p, distance_upper_bound=d, workers=-1)
        ok = np.isfinite(dist)
        n_corr = int(ok.sum())
        if n_corr < 7:
            break
        pp, q, n = p[ok], tgt[j[ok]], nrm[j[ok]]
        r = np.einsum("ij,ij->i", n, pp - q)
        H, g, c, x = _tukey_normal_equations(pp, n, r, kernel_scale * d)
        try:
            delta = -np.linalg.solve(H + 1e-12 * np.eye(7), g)
        except np.linalg.LinAlgError:
            break
        T = _similarity_update(delta, c) @ T
        spread = np.sqrt((x**2).sum(1).mean())
        move = np.linalg.norm(delta[:3]) * spread + np.linalg.norm(delta[3:6]) + abs(delta[6]) * spread
        if move < tolerance * d:
            break
    return T, H, n_corr, r, its


def _tukey_normal_equations(pp: np.ndarray, n: np.ndarray, r: np.ndarray, k: float):
    """The weighted normal equations ``H delta = -g`` of the linearised plane residuals ``r`` of
    the points ``pp`` with target normals ``n``: Jacobian columns ``(x × n, n, n . x)`` for
    (omega, tau, sigma), ``x = pp - c`` about the centroid ``c``, Tukey weights of width ``k``.
    Returns ``(H (7, 7), g (7,), c, x)``."""
    w = np.where(np.abs(r) < k, (1 - (r / k) ** 2) ** 2, 0.0)
    c = pp.mean(axis=0)
    x = pp - c
    J = np.column_stack([np.cross(x, n), n, np.einsum("ij,ij->i", n, x)])
    H = J.T @ (J * w[:, None])
    g = J.T @ (w * r)
    return H, g, c, x


def _similarity_update(delta: np.ndarray, c: np.ndarray) -> np.ndarray:
    """(4, 4) similarity of the step ``delta = (omega, tau, sigma)`` about the centroid ``c``:
    ``p' = c + (1 + sigma) R(omega) (p - c) + tau``."""
    R = _rodrigues(delta[:3])
    s = 1.0 + delta[6]
    D = np.eye(4)
    D[:3, :3] = s * R
    D[:3, 3] = c + delta[3:6] - s * R @ c
    return D
