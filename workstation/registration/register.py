"""The pairwise registration stage: SOURCE cloud onto TARGET cloud, coarse then fine.

``register(source, target, params)`` subtracts one origin from both clouds (float precision),
derives every radius from one voxel size (estimated from the target when not given), finds a
coarse alignment from FPFH features unless an initial transform is given, refines it with
ICP, checks the result and returns a :class:`RegistrationResult` whose transform maps source
coordinates into the target's frame (world units, origin already put back).

``method="auto"`` runs global estimators that fail differently, the max-clique estimator
(its distinct cliques, not only the best) and FPFH + RANSAC (and Fast Global Registration when
all look poor), refines each hypothesis by a short point-to-plane ICP on the downsampled clouds
and keeps the one whose surfaces agree best in both directions (:func:`consistency`). This is
the "several hypotheses verified by ICP" strategy recommended when single RANSAC runs are
unreliable (e.g. Choi, Zhou & Koltun 2015, "Robust reconstruction of indoor scenes", CVPR).
Scoring by overlap alone is not enough on scenes dominated by flat ground: a pose turned by
150-180 degrees lays one ground onto the other over a larger area than the right pose of a
partly overlapping pair. When a distinct runner-up scores nearly as well, ``meta["ambiguous"]``
is set and a warning logged.

Known limit: scenes made only of flat boxes (walls, flat roofs, flat ground) give FPFH few
distinctive matches; when no hypothesis is right, a wrong alignment can still pass the overlap
and plane checks. Give an initial transform (``init``) or point pairs for such scenes.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field, replace

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.color import rgb_to_unit
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.geometry import default_origin
from workstation.core.log import get_logger
from workstation.core.products import RegistrationResult

from .coarse import COARSE_METHODS, CoarseParams, scale_search
from .icp import QUICK_ICP, ICPParams, refine, similarity_plane_icp, voxel_plane_icp
from .preprocess import Radii, estimate_spacing, estimate_voxel_size, prepare

log = get_logger(__name__)

METHODS = ("auto", "fpfh_ransac", "fgr", "clique", "planes", "icp", "similarity")
STAGE = "register"
#: Consistency (:func:`consistency`) difference under which two distinct coarse poses are
#: reported as ambiguous.
AMBIGUOUS_MARGIN = 0.02


@dataclass(frozen=True)
class RegisterParams:
    """Parameters of :func:`register`.

    Attributes
    ----------
    method : str
        ``auto`` (clique + RANSAC hypotheses verified by ICP), ``fpfh_ransac``, ``fgr``,
        ``clique``, ``planes`` (matched planes, for rooms and other scenes of large planes:
        :mod:`~workstation.registration.planes`) (coarse then fine), ``icp`` (fine only, from
        ``init`` or identity) or
        ``similarity`` (7 DoF, for SfM <-> LiDAR: from ``init`` when given, else a coarse
        search over scale hypotheses, :func:`~workstation.registration.coarse.scale_search`;
        then 7-DoF point-to-plane ICP, :func:`~workstation.registration.icp.similarity_plane_icp`).
    voxel_size : float, optional
        Voxel edge in metres (CRS units) of the coarse stage; every radius derives from it
        (normals 2x, FPFH 5x, coarse inliers 1.5x, ICP schedule ``fine.schedule`` x).
        Estimated from the target's point spacing when None.
    fine : ICPParams
        Fine stage (method, kernel, schedule).
    coarse : CoarseParams
    fine_voxel : float, optional
        Downsample both clouds with this voxel (metres) for the fine stage; None keeps all
        points below ``fine_max_points`` and uses ``voxel / 3`` above.
    fine_max_points : int
    min_fitness : float
        Smallest accepted share of source points with a correspondence at the finest ICP
        distance; below it the overlap is judged too low and :class:`StageError` is raised.
    max_rmse : float
        Largest accepted inlier RMSE as a multiple of the voxel size.
    min_plane_inliers : float
        Smallest accepted share of overlapping source points lying on the target's tangent
        planes (within ``0.3 * voxel``); right alignments score 0.8-1.0 on our tests (0.8 for
        simulated TLS stations 45 m apart, with vegetation), wrong
        ones that still land near the target (smooth terrain turned by 90-180 degrees) 0.54-0.74,
        so this check catches most, not all, wrong alignments of smooth surfaces.
    viewpoint_source, viewpoint_target : (3,) float, optional
        Scanner positions (world coordinates) to orient normals (default: the clouds'
        ``meta["scanner_position"]`` when present); see
        :func:`~workstation.registration.preprocess.prepare`.
    remove_outliers : bool
        Statistical outlier removal on the downsampled clouds.
    similarity_schedule : tuple of float
        ICP distances (multiples of the voxel size) of the 7-DoF fine stage; it reaches half the
        rigid stage's finest distance, and above ``fine_max_points`` the target is thinned with
        ``voxel / 9`` instead of ``voxel / 3`` (on the SfM-dense vs TLS benchmark this brings the
        result from 2.1 to 0.7 cm of the best alignment to the true surface).
    """

    method: str = "auto"
    voxel_size: float | None = None
    fine: ICPParams = field(default_factory=ICPParams)
    coarse: CoarseParams = field(default_factory=CoarseParams)
    fine_voxel: float | None = None
    fine_max_points: int = 300_000
    min_fitness: float = 0.2
    max_rmse: float = 1.0
    min_plane_inliers: float = 0.7
    viewpoint_source: tuple | None = None
    viewpoint_target: tuple | None = None
    remove_outliers: bool = True
    similarity_schedule: tuple = (1.5, 0.6, 0.3, 0.15)

    def __post_init__(self):
        if self.method not in METHODS:
            raise InvalidInputError(f"unknown registration method {self.method!r}",
                                    f"use one of {', '.join(METHODS)}", field="method")
        if self.voxel_size is not None and not self.voxel_size > 0:
            raise InvalidInputError(f"voxel size must be > 0, got {self.voxel_size}", field="voxel_size")
        if not 0.0 <= self.min_fitness <= 1.0:
            raise InvalidInputError("min_fitness must be in [0, 1]", field="min_fitness")


#: Voxels a side Open3D can index (a signed 32-bit voxel coordinate).
_MAX_VOXELS_A_SIDE = 2**31 - 1


def _check_cloud(c: Cloud, name: str) -> None:
    """Refuse a cloud registration cannot use: not a Cloud, under 10 points, or one point repeated."""
    if not isinstance(c, Cloud):
        raise InvalidInputError(f"{name} must be a Cloud, got {type(c).__name__}", field=name)
    src = c.meta.get("source")
    if c.n < 10:
        raise InvalidInputError(f"{name} has {c.n} points; registration needs at least 10", path=src, field=name)
    if not np.ptp(c.xyz, axis=0).any():
        raise InvalidInputError(f"all {c.n} points of the {name} are the same point", "check the input file",
                                path=src, field=name)


def _check_voxel(xyz: np.ndarray, voxel: float, smallest: float, name: str) -> None:
    """Refuse a voxel so small that Open3D cannot index the cloud's extent with it.

    ``smallest`` is the finest voxel any step uses (the fine stage's ``voxel / 3`` or ``/ 9``).
    """
    ext = float(np.max(np.ptp(xyz, axis=0)))
    if ext / smallest >= _MAX_VOXELS_A_SIDE:
        raise InvalidInputError(
            f"voxel size {voxel:g} is too small for the {name} ({ext:.4g} across: {ext / smallest:.3g} voxels a side, "
            f"Open3D indexes at most {_MAX_VOXELS_A_SIDE})",
            f"give --voxel-size of at least {ext / 2**30 * voxel / smallest:.3g}, or omit it to estimate one from the spacing",
            field="voxel_size")


def _check_downsampled(prep, voxel: float, name: str) -> None:
    """Refuse a voxel that leaves fewer than 3 points for the coarse (feature) stage."""
    m = len(prep.down.points)
    if m < 3:
        raise InvalidInputError(
            f"voxel size {voxel:g} leaves {m} point(s) of the {name} after downsampling; the coarse stage needs at least 3",
            "give a smaller --voxel-size, or omit it to estimate one from the spacing", field="voxel_size")


def _colors(c: Cloud):
    if "rgb" not in c.attrs:
        return None
    return rgb_to_unit(c.attrs["rgb"])


def register(source: Cloud, target: Cloud, params: RegisterParams = RegisterParams(),
             init: np.ndarray | None = None) -> RegistrationResult:
    """Register ``source`` onto ``target``.

    Parameters
    ----------
    source, target : Cloud
        Same units (metres or CRS units); CRS must agree when both are set.
    params : RegisterParams
    init : (4, 4) float, optional
        Initial source -> target transform (world frame). With it, ``auto`` skips the
        coarse stage.

    Returns
    -------
    RegistrationResult
        ``transform`` maps source coordinates into the target frame; ``meta`` holds the voxel
        size, the coarse method chosen, candidate scores (``coarse_candidates``: verified
        fitness, ``coarse_consistency``), ``ambiguous`` when two distinct coarse poses scored
        alike, and timings (seconds).

    Raises
    ------
    StageError
        When the result does not converge, the overlap (fitness) is below
        ``params.min_fitness`` or the RMSE is above ``params.max_rmse * voxel``.
    """
    from workstation.interop.open3d import local_transform, world_transform

    _check_pair(source, target)
    t_start = time.perf_counter()
    origin = default_origin(target.xyz)
    xs = source.xyz - origin
    xt = target.xyz - origin
    voxel = float(params.voxel_size) if params.voxel_size else estimate_voxel_size(xt)
    radii = Radii(voxel)
    vs, vt = _viewpoints(params, source, target, origin)
    fine_voxel = params.fine_voxel
    if fine_voxel is None and max(source.n, target.n) > params.fine_max_points:
        fine_voxel = voxel / (9.0 if params.method == "similarity" else 3.0)
    _check_voxel(xs, voxel, min(voxel, fine_voxel or voxel), "source")
    _check_voxel(xt, voxel, min(voxel, fine_voxel or voxel), "target")
    meta: dict = {"voxel_size": voxel, "origin": origin.tolist()}
    T0 = None if init is None else local_transform(np.asarray(init, float), origin, origin)
    method = params.method
    need_coarse = method in COARSE_METHODS or (method == "auto" and T0 is None)
    scale_coarse = method == "similarity" and T0 is None
    timings = {}

    t0 = time.perf_counter()
    ps, pt = _prepare_pair(source, target, xs, xt, radii, params, need_coarse, scale_coarse, fine_voxel, vs, vt)
    timings["prepare"] = time.perf_counter() - t0
    if need_coarse or scale_coarse:
        t0 = time.perf_counter()
        if need_coarse:
            T0, coarse_meta = _coarse(ps, pt, method, params)
        else:
            T0, coarse_meta = scale_search(xs, pt, params.coarse, viewpoint=vs, remove_outliers=params.remove_outliers)
        meta.update(coarse_meta)
        timings["coarse"] = time.perf_counter() - t0
    if T0 is None:
        T0 = np.eye(4)

    t0 = time.perf_counter()
    res = _fine(xs, xt, ps, pt, voxel, T0, params)
    timings["fine"] = time.perf_counter() - t0
    timings["total"] = time.perf_counter() - t_start

    T = world_transform(res.transform, origin, origin)
    fine_method = "similarity_point_to_plane" if method == "similarity" else params.fine.method
    meta.update({"method": method, "fine_method": fine_method, "seconds": timings,
                 **{k: v for k, v in res.meta.items() if k != "method"}})
    out = RegistrationResult(transform=T, scale=res.scale, fitness=res.fitness, inlier_rmse=res.inlier_rmse,
                             converged=res.converged, correspondences=res.correspondences,
                             information=res.information, meta=meta)
    check_result(out, voxel, params)
    log.info("registered: fitness %.3f, rmse %.4g, %.1f s", out.fitness, out.inlier_rmse, timings["total"])
    return out


def _check_pair(source: Cloud, target: Cloud) -> None:
    """Refuse a pair registration cannot use: either cloud unusable (:func:`_check_cloud`), or
    both with a CRS and the CRSs different."""
    _check_cloud(source, "source")
    _check_cloud(target, "target")
    if source.crs and target.crs and source.crs != target.crs:
        raise InvalidInputError("source and target have different CRSs",
                                "reproject one of them first (ws convert --to-crs)", field="crs")


def _viewpoints(params: RegisterParams, source: Cloud, target: Cloud, origin: np.ndarray):
    """The scanner positions of source and target relative to ``origin`` (or None): the given
    ``params.viewpoint_*``, else the clouds' ``meta["scanner_position"]``. They orient normals,
    and the prepared clouds carry them (``Prepared.viewpoint``) for the plane method's
    free-space tests."""
    vps = params.viewpoint_source if params.viewpoint_source is not None else source.meta.get("scanner_position")
    vpt = params.viewpoint_target if params.viewpoint_target is not None else target.meta.get("scanner_position")
    vs = None if vps is None else np.asarray(vps, float) - origin
    vt = None if vpt is None else np.asarray(vpt, float) - origin
    return vs, vt


def _prepare_pair(source: Cloud, target: Cloud, xs, xt, radii: Radii, params: RegisterParams, need_coarse: bool,
                  scale_coarse: bool, fine_voxel, vs, vt):
    """Downsample, clean and give normals (and FPFH features when a coarse stage runs) to both
    clouds (:func:`prepare`); ``(None, None)`` when the voxel-plane fine stage alone runs, as it
    works on the raw points. A source of unknown scale (``similarity``) is not prepared here:
    the scale search prepares it per scale hypothesis. The plane method uses no features."""
    if params.fine.method == "voxel_plane" and not need_coarse and params.method != "similarity":
        return None, None
    features = need_coarse and params.method != "planes"
    ps = None if params.method == "similarity" else prepare(
        xs, radii, features=features, colors=_colors(source), fine_voxel=fine_voxel,
        remove_outliers=params.remove_outliers, viewpoint=vs)
    pt = prepare(xt, radii, features=features or scale_coarse, colors=_colors(target), fine_voxel=fine_voxel,
                 remove_outliers=params.remove_outliers, viewpoint=vt)
    if need_coarse:
        _check_downsampled(ps, radii.voxel, "source")
        _check_downsampled(pt, radii.voxel, "target")
    return ps, pt


def _fine(xs, xt, ps, pt, voxel: float, T0: np.ndarray, params: RegisterParams) -> RegistrationResult:
    """The fine stage from ``T0``: similarity point-to-plane ICP (source of unknown scale, thinned
    by count), voxel-plane ICP on the raw points, or multi-scale ICP (:func:`refine`) on the
    prepared clouds; fitness is then the overlap at the widest ICP distance (:func:`_overlap`)."""
    from workstation.interop.open3d import points_to_legacy

    if params.method == "similarity":
        src_pts = xs
        if src_pts.shape[0] > params.fine_max_points:  # the source's scale is unknown: thin it by count
            src_pts = src_pts[np.random.default_rng(0).choice(src_pts.shape[0], params.fine_max_points, replace=False)]
        res = similarity_plane_icp(src_pts, np.asarray(pt.full.points), np.asarray(pt.full.normals),
                                   [f * voxel for f in params.similarity_schedule], T0, params.fine.max_iterations,
                                   params.fine.kernel_scale)
        res = _overlap(res, points_to_legacy(src_pts), pt.full, params.similarity_schedule[0] * voxel)
    elif params.fine.method == "voxel_plane":
        src_pts = xs if ps is None else np.asarray(ps.full.points)
        tgt_pts = xt if pt is None else np.asarray(pt.full.points)
        plane_voxel = max(voxel / 2.0, 4.0 * estimate_spacing(tgt_pts))
        res = voxel_plane_icp(src_pts, tgt_pts, plane_voxel, T0, params.fine)
        src_full = points_to_legacy(src_pts)
        tgt_full = points_to_legacy(tgt_pts)
        res = _with_information(res, src_full, tgt_full, params.fine.schedule[-1] * voxel)
    else:
        res = refine(ps.full, pt.full, voxel, T0, params.fine)
    if ps is not None:
        res = _overlap(res, ps.full, pt.full, params.fine.schedule[0] * voxel)
    return res


def _overlap(res: RegistrationResult, src, tgt, d: float) -> RegistrationResult:
    """Fitness as the share of source points with a target point within ``d`` (the widest ICP
    distance): an overlap measure that does not depend on how densely both clouds sample the
    surface, unlike the fitness at the finest ICP distance (kept in ``meta["fine_fitness"]``).

    ``meta["plane_inlier_share"]``: of those overlapping points, the share lying within
    ``d / 5`` of the target's local tangent plane. A right alignment of two samplings of one
    surface puts nearly all of them on the plane even when the samplings are sparse; a wrong
    alignment that still lands near the target (smooth terrain turned or shifted) does not."""
    from scipy.spatial import cKDTree

    from .transforms import apply_transform

    ps = apply_transform(res.transform, np.asarray(src.points))
    pt = np.asarray(tgt.points)
    dist, j = cKDTree(pt).query(ps, distance_upper_bound=float(d), workers=-1)
    near = np.isfinite(dist)
    fitness = float(near.mean()) if near.size else 0.0
    plane_share = 0.0
    if near.any() and tgt.has_normals():
        nt = np.asarray(tgt.normals)[j[near]]
        r = np.abs(np.einsum("ij,ij->i", nt, ps[near] - pt[j[near]]))
        plane_share = float(np.mean(r < d / 5.0))
    meta = dict(res.meta)
    meta.update({"fine_fitness": res.fitness, "fitness_distance": float(d), "plane_inlier_share": plane_share})
    return replace(res, fitness=fitness, meta=meta)


def _with_information(res: RegistrationResult, src, tgt, d: float) -> RegistrationResult:
    from workstation.interop.open3d import require_open3d

    o3d = require_open3d()
    info = np.asarray(o3d.pipelines.registration.get_information_matrix_from_point_clouds(src, tgt, d, res.transform))
    return replace(res, information=info)


def _coarse(ps, pt, method: str, params: RegisterParams) -> tuple[np.ndarray, dict]:
    """Coarse transform (local frame) and what was tried.

    ``auto``: every hypothesis (the clique estimator's distinct cliques, then RANSAC and FGR
    while the best looks poor) is refined by a short ICP and scored by :func:`consistency`,
    which, unlike the overlap alone, penalises surfaces of either cloud landing near the other
    but off its surface. The best is kept; ``meta["ambiguous"]`` is set when a distinct
    runner-up scores within ``AMBIGUOUS_MARGIN`` of it. Only hypotheses whose verified fitness
    reaches half the best one's (and ``params.min_fitness``) are ranked."""
    if method != "auto":
        r = COARSE_METHODS[method](ps, pt, params.coarse)
        return r.transform, {"coarse_method": method, "coarse_fitness": r.fitness}
    from scipy.spatial import cKDTree

    voxel = ps.radii.voxel
    cands = []  # (name, fitness, transform, score)
    target_tree = cKDTree(np.asarray(pt.down.points))  # one tree for every pose's consistency
    for name in ("clique", "fpfh_ransac", "fgr"):
        # a hypothesis explaining this share of the downsampled source is accepted as is
        if cands and max(c[1] for c in cands) >= max(0.4 if name == "fpfh_ransac" else 0.5, params.min_fitness):
            break
        try:
            r = COARSE_METHODS[name](ps, pt, params.coarse)
        except RuntimeError as e:  # Open3D raises RuntimeError on degenerate input
            log.info("coarse %s failed: %s", name, e)
            continue
        for k, T in enumerate(r.meta.get("hypotheses", [r.transform])):
            q = refine(ps.down, pt.down, voxel, T, QUICK_ICP, information=False)
            score = consistency(ps.down, pt.down, q.transform, voxel, target_tree)
            cands.append((name if k == 0 else f"{name}_{k}", float(q.fitness), q.transform, score))
            log.info("coarse %s hypothesis %d: verified fitness %.3f, consistency %.3f", name, k, q.fitness, score)
    if not cands:
        raise StageError(STAGE, "no coarse alignment could be computed", "check that both clouds overlap")
    # a pose barely touching the other cloud has neither agreement nor conflict: rank only the
    # hypotheses that explain at least half the best overlap (and the accepted minimum)
    least = min(max(c[1] for c in cands), max(params.min_fitness, 0.5 * max(c[1] for c in cands)))
    order = sorted((c for c in cands if c[1] >= least), key=lambda c: -c[3])
    best = order[0]
    meta = {"coarse_method": best[0], "coarse_candidates": {c[0]: c[1] for c in cands},
            "coarse_consistency": {c[0]: round(c[3], 4) for c in cands}}
    rival = next((c for c in order[1:] if _distinct_pose(c[2], best[2], voxel)), None)
    if rival is not None and rival[3] >= best[3] - AMBIGUOUS_MARGIN:
        meta["ambiguous"] = {"runner_up": rival[0], "score": round(rival[3], 4), "best_score": round(best[3], 4)}
        log.warning("ambiguous coarse alignment: %s scores %.3f, %s %.3f (two distinct poses fit alike)",
                    best[0], best[3], rival[0], rival[3])
    return best[2], meta


def _distinct_pose(A: np.ndarray, B: np.ndarray, voxel: float) -> bool:
    """Whether two transforms differ by more than 2 degrees or 2 voxels."""
    R = A[:3, :3] @ B[:3, :3].T
    angle = np.degrees(np.arccos(np.clip((np.trace(R) - 1) / 2, -1, 1)))
    return bool(angle > 2.0 or np.linalg.norm(A[:3, 3] - B[:3, 3]) > 2.0 * voxel)


def consistency(src, tgt, T: np.ndarray, voxel: float, target_tree=None) -> float:
    """Agreement of two clouds (Open3D, with normals) under ``T``, averaged over both directions.

    In each direction a point *agrees* when a point of the other cloud lies within
    ``1.5 * voxel`` and it lies within ``0.1 * voxel`` of that point's tangent plane; it
    *conflicts* when the other cloud comes within ``5 * voxel`` but it does not agree (a wall
    landing beside a wall or on open ground: surfaces that should coincide do not). The score
    is (agreeing - conflicting) / points. Overlap alone favours a wrong pose that lays two
    large flat grounds onto each other over a right one with a smaller true overlap; the
    conflicts, from the buildings that then stand where the other cloud has none, do not.
    ``target_tree``: a cKDTree of ``tgt``'s points, for a caller scoring many poses."""
    from scipy.spatial import cKDTree

    from .transforms import apply_transform

    a = apply_transform(T, np.asarray(src.points))
    b = np.asarray(tgt.points)
    na = np.asarray(src.normals) @ T[:3, :3].T
    nb = np.asarray(tgt.normals)
    scores = []
    trees = (cKDTree(b) if target_tree is None else target_tree, cKDTree(a))
    for (x, y, ny), tree in zip(((a, b, nb), (b, a, na)), trees):
        dist, j = tree.query(x, distance_upper_bound=5.0 * voxel, workers=-1)
        near = dist < 1.5 * voxel
        jj = np.minimum(j, y.shape[0] - 1)
        on_plane = np.abs(np.einsum("ij,ij->i", ny[jj], x - y[jj])) < 0.1 * voxel
        agree = near & on_plane
        conflict = np.isfinite(dist) & ~agree
        scores.append((agree.sum() - conflict.sum()) / max(x.shape[0], 1))
    return float(np.mean(scores))


def check_result(res: RegistrationResult, voxel: float, params: RegisterParams) -> None:
    """Raise :class:`StageError` unless the result converged with enough overlap and a small RMSE."""
    hint = ("give an initial alignment (--init), pick >= 3 point pairs (--pairs), try another --method "
            "or a larger --voxel-size; check that the clouds overlap")
    if not res.converged or not np.isfinite(res.transform).all():
        raise StageError(STAGE, "the registration did not converge", hint)
    if res.fitness < params.min_fitness:
        raise StageError(STAGE, f"overlap too low: fitness {res.fitness:.3f} < {params.min_fitness}", hint)
    share = res.meta.get("plane_inlier_share")
    if share is not None and share < params.min_plane_inliers:
        raise StageError(STAGE, f"only {share:.0%} of the overlapping points lie on the target surface "
                                f"(< {params.min_plane_inliers:.0%}): the alignment is probably wrong", hint)
    if not np.isfinite(res.inlier_rmse) or res.inlier_rmse > params.max_rmse * voxel:
        raise StageError(STAGE, f"inlier RMSE {res.inlier_rmse:.4g} above {params.max_rmse} voxel ({voxel:.4g})", hint)
