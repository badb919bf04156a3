"""Coarse (global) registration from FPFH features: RANSAC, Fast Global Registration and a
correspondence-graph max-clique estimator.

- RANSAC on feature matches with edge-length and distance pre-checks (Rusu et al. 2009;
  Open3D's ``registration_ransac_based_on_feature_matching``).
- Fast Global Registration (Zhou, Park & Koltun 2016, "Fast Global Registration", ECCV).
- ``clique``: mutual nearest FPFH matches, a pairwise length-consistency graph and greedy
  maximum cliques grown from the best-connected matches, each clique's Umeyama fit scored by
  its inlier matches (the pruning idea of TEASER, Yang, Shi & Carlone 2020, IEEE T-RO, and of
  the max-clique registration of Zhang et al. 2023, CVPR). Deterministic, and insensitive to
  the inlier ratio as long as the inliers form the largest consistent set.

All inputs are :class:`~workstation.registration.preprocess.Prepared` clouds in a shared
local frame; results are 4x4 transforms in that frame.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from workstation.core.log import get_logger
from workstation.core.products import RegistrationResult

from .planes import plane_registration
from .preprocess import Prepared
from .transforms import apply_transform, make_transform, umeyama

log = get_logger(__name__)


@dataclass(frozen=True)
class CoarseParams:
    """Parameters of the coarse stage (distances are multiples of the voxel size).

    Attributes
    ----------
    ransac_iterations : int
        Maximum RANSAC hypotheses.
    ransac_confidence : float
        Stop RANSAC once this probability of having drawn an all-inlier sample is reached.
    seed : int
        Random seed of RANSAC (Open3D's global generator) for repeatable runs.
    clique_seeds : int
        Number of best-connected matches the clique search starts from.
    max_matches : int
        Cap on the matches of the clique graph (memory is ``max_matches**2`` bytes).
    clique_hypotheses : int
        Distinct clique transforms (best first) returned in ``meta["hypotheses"]`` for the
        ``auto`` method to verify; a repetitive scene (parallel walls, flat ground) can give a
        wrong pose more consistent matches than the right one.
    """

    ransac_iterations: int = 100_000
    ransac_confidence: float = 0.999
    seed: int = 0
    clique_seeds: int = 40
    max_matches: int = 4000
    clique_hypotheses: int = 24


def _result(T, fitness, rmse, n_corr, method, **meta) -> RegistrationResult:
    return RegistrationResult(transform=np.asarray(T), scale=1.0, fitness=float(fitness), inlier_rmse=float(rmse),
                              converged=True, correspondences=int(n_corr), meta={"method": method, **meta})


def fpfh_ransac(src: Prepared, tgt: Prepared, params: CoarseParams = CoarseParams()) -> RegistrationResult:
    """FPFH + RANSAC (Open3D), mutual feature filter, inlier distance ``1.5 * voxel``."""
    from workstation.interop.open3d import require_open3d

    o3d = require_open3d()
    reg = o3d.pipelines.registration
    d = src.radii.coarse_distance
    o3d.utility.random.seed(int(params.seed))
    res = reg.registration_ransac_based_on_feature_matching(
        src.down, tgt.down, src.fpfh, tgt.fpfh, True, d,
        reg.TransformationEstimationPointToPoint(False), 3,
        [reg.CorrespondenceCheckerBasedOnEdgeLength(0.9), reg.CorrespondenceCheckerBasedOnDistance(d)],
        reg.RANSACConvergenceCriteria(int(params.ransac_iterations), float(params.ransac_confidence)))
    return _result(res.transformation, res.fitness, res.inlier_rmse, len(res.correspondence_set), "fpfh_ransac")


def fgr(src: Prepared, tgt: Prepared, params: CoarseParams = CoarseParams()) -> RegistrationResult:
    """Fast Global Registration (Zhou et al. 2016) on FPFH matches (Open3D)."""
    from workstation.interop.open3d import require_open3d

    o3d = require_open3d()
    reg = o3d.pipelines.registration
    opt = reg.FastGlobalRegistrationOption(maximum_correspondence_distance=src.radii.coarse_distance,
                                           use_absolute_scale=True, decrease_mu=True)
    res = reg.registration_fgr_based_on_feature_matching(src.down, tgt.down, src.fpfh, tgt.fpfh, opt)
    return _result(res.transformation, res.fitness, res.inlier_rmse, len(res.correspondence_set), "fgr")


def _nearest(a: np.ndarray, b: np.ndarray, block: int = 2048) -> np.ndarray:
    """Index of the nearest row of ``b`` for every row of ``a`` (brute force, float32 BLAS,
    in row blocks: a KD-tree is no faster than this in 33 dimensions)."""
    import contextlib

    try:  # threadpoolctl comes with scikit-learn
        from threadpoolctl import threadpool_limits
    except ImportError:  # pragma: no cover
        threadpool_limits = None

    a = np.asarray(a, dtype=np.float32)
    b = np.asarray(b, dtype=np.float32)
    bb = np.einsum("ij,ij->i", b, b)
    out = np.empty(a.shape[0], dtype=np.int64)
    limit = threadpool_limits(1) if threadpool_limits else contextlib.nullcontext()
    with limit:  # idle BLAS threads spinning on a shared machine cost more than they gain
        for s in range(0, a.shape[0], block):
            d = bb[None, :] - 2.0 * (a[s:s + block] @ b.T)
            out[s:s + block] = np.argmin(d, axis=1)
    return out


def mutual_matches(f_src: np.ndarray, f_tgt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Indices ``(i, j)`` of mutual nearest neighbours between two feature sets (n, d), (m, d)."""
    j = _nearest(f_src, f_tgt)
    i = _nearest(f_tgt, f_src)
    keep = np.flatnonzero(i[j] == np.arange(j.size))
    return keep, j[keep]


def clique_registration(src: Prepared, tgt: Prepared, params: CoarseParams = CoarseParams(), *,
                        rel_tol: float = 0.0, with_scale: bool = False) -> RegistrationResult:
    """Max-clique estimator on mutual FPFH matches (see the module docstring).

    Two matches (a, b) are consistent when the distance between their source points equals
    that between their target points within ``2 * coarse_distance`` and both distances exceed
    ``3 * voxel`` (short edges constrain rotation poorly). From each of the ``clique_seeds``
    best-connected matches a clique is grown greedily (always adding the candidate with most
    consistent neighbours); each clique gives a Umeyama fit, scored by the number of all
    matches it explains within ``coarse_distance``; the best is refitted on those inliers.

    ``rel_tol`` widens the length test by that share of the length and ``with_scale`` fits a
    similarity (7 DoF) instead: for a source whose scale is known only within ``rel_tol``.
    """
    ps = np.asarray(src.down.points)
    pt = np.asarray(tgt.down.points)
    fs = np.asarray(src.fpfh.data).T
    ft = np.asarray(tgt.fpfh.data).T
    i, j = mutual_matches(fs, ft)
    if i.size > params.max_matches:  # keep the matches with the most distinctive features
        dist = np.linalg.norm(fs[i] - ft[j], axis=1)
        keep = np.argsort(dist)[: params.max_matches]
        i, j = i[keep], j[keep]
    cs, ct = ps[i], pt[j]
    m = cs.shape[0]
    d = src.radii.coarse_distance
    if m < 3:
        return _result(np.eye(4), 0.0, float("nan"), 0, "clique", matches=int(m))
    ds = np.sqrt(((cs[:, None, :] - cs[None, :, :]) ** 2).sum(-1)).astype(np.float32)
    dt = np.sqrt(((ct[:, None, :] - ct[None, :, :]) ** 2).sum(-1)).astype(np.float32)
    A = (np.abs(ds - dt) < 2.0 * d + rel_tol * ds) & (ds > 3.0 * src.radii.voxel)
    del ds, dt
    np.fill_diagonal(A, False)
    deg = A.sum(axis=1)
    found = []  # (score, T, clique size) of every seed's clique
    for seed in np.argsort(-deg)[: params.clique_seeds]:
        if deg[seed] < 2:
            break
        mask = A[seed].copy()
        clique = [int(seed)]
        while mask.any():
            cand = np.flatnonzero(mask)
            inner = A[np.ix_(cand, cand)].sum(axis=1) if cand.size <= 256 else deg[cand]
            c = int(cand[np.argmax(inner)])
            clique.append(c)
            mask &= A[c]
        if len(clique) < 3:
            continue
        R, t, sc = umeyama(cs[clique], ct[clique], with_scale=with_scale)
        T = make_transform(R, t, sc)
        score = int((np.linalg.norm(apply_transform(T, cs) - ct, axis=1) < d).sum())
        found.append((score, T, len(clique)))
    found = [f for f in found if f[0] >= 3]
    if not found:
        return _result(np.eye(4), 0.0, float("nan"), 0, "clique", matches=int(m))
    fits = _distinct([_refit(cs, ct, f[1], d, with_scale) + (f[2],) for f in found], d)
    fits = fits[: max(1, params.clique_hypotheses)]
    T, rmse, n_inl, sc, size = fits[0]
    fit = _point_fitness(ps, pt, T, d)
    log.info("clique: %d mutual matches, clique %d, %d inlier matches, fitness %.3f", m, size, n_inl, fit)
    out = _result(T, fit, rmse, n_inl, "clique", matches=int(m), clique=int(size),
                  hypotheses=[f[0] for f in fits], hypothesis_matches=[f[2] for f in fits])
    return replace(out, scale=float(sc)) if with_scale else out


def _refit(cs: np.ndarray, ct: np.ndarray, T: np.ndarray, d: float, with_scale: bool):
    """Umeyama refit of ``T`` on the matches it explains within ``d``: (transform, RMSE, inlier count, scale)."""
    inl = np.linalg.norm(apply_transform(T, cs) - ct, axis=1) < d
    R, t, sc = umeyama(cs[inl], ct[inl], with_scale=with_scale)
    T = make_transform(R, t, sc)
    res = np.linalg.norm(apply_transform(T, cs[inl]) - ct[inl], axis=1)
    return T, float(np.sqrt(np.mean(res**2))), int(inl.sum()), sc


def _distinct(fits: list, d: float, angle_deg: float = 5.0) -> list:
    """The ``(T, rmse, inliers, scale, size)`` fits by decreasing inlier count, dropping each
    one within ``angle_deg`` of rotation and ``3 * d`` of translation of a better one kept."""
    kept = []
    for f in sorted(fits, key=lambda f: -f[2]):
        R = f[0][:3, :3] / f[3]
        same = [np.degrees(np.arccos(np.clip((np.trace(R @ k[0][:3, :3].T / k[3]) - 1) / 2, -1, 1))) < angle_deg
                and np.linalg.norm(f[0][:3, 3] - k[0][:3, 3]) < 3.0 * d for k in kept]
        if not any(same):
            kept.append(f)
    return kept


def _point_fitness(ps: np.ndarray, pt: np.ndarray, T: np.ndarray, d: float) -> float:
    from scipy.spatial import cKDTree

    dist, _ = cKDTree(pt).query(apply_transform(T, ps), distance_upper_bound=d, workers=-1)
    return float(np.mean(np.isfinite(dist)))


def scale_search(xs: np.ndarray, tgt: Prepared, params: CoarseParams = CoarseParams(), *, scale0: float | None = None,
                 span: float = 8.0, step: float = 1.35, viewpoint=None, remove_outliers: bool = True):
    """Coarse similarity (7 DoF) for a source of unknown scale, such as an SfM cloud without
    control points, by a search over scale hypotheses.

    FPFH is not scale invariant, so the source is scaled by each hypothesis
    ``scale0 * step**k`` (``scale0 / span`` to ``scale0 * span``) about its centroid,
    described at the target's voxel size, and registered by the max-clique estimator with
    a length tolerance of ``step - 1`` and a similarity fit (:func:`clique_registration`).
    Each hypothesis is checked by a short point-to-plane ICP of the downsampled clouds and
    scored by its overlap (fitness at ``0.75 * voxel``) times its plane-inlier share
    (overlapping source points within ``0.3 * voxel`` of the target's tangent plane), which
    punishes a shrunken source lying on flat ground. This is the hypothesise-and-verify
    strategy of the rigid ``auto`` method over one more dimension; TEASER (Yang, Shi & Carlone
    2020) votes on ratios of match distances instead, which needs scale-invariant features.

    Parameters
    ----------
    xs : (n, 3) float64
        Source points (local frame, any scale).
    tgt : Prepared
        Target with FPFH, in metres.
    scale0 : float, optional
        Central scale hypothesis; default the ratio of the voxel sizes that leave about 4000
        points in each cloud (equal when both clouds cover the same surface).
    span, step : float
        Search range factor and ratio between neighbouring hypotheses.

    Returns
    -------
    T : (4, 4) float64
        Source -> target similarity (local frame), scale included.
    meta : dict
        ``coarse_method``, ``scale0`` and every hypothesis' ``scale``, ``score``.
    """
    from scipy.spatial import cKDTree

    from .icp import QUICK_ICP, refine
    from .preprocess import estimate_voxel_size, prepare

    xs = np.asarray(xs, dtype=np.float64)
    radii = tgt.radii
    pt = np.asarray(tgt.down.points)
    nt = np.asarray(tgt.down.normals)
    tree = cKDTree(pt)
    if scale0 is None:
        scale0 = estimate_voxel_size(pt) / estimate_voxel_size(xs)
    c = xs.mean(axis=0)
    n_side = int(np.ceil(np.log(span) / np.log(step)))
    cands = []
    for k in range(-n_side, n_side + 1):
        s = float(scale0 * step**k)
        S = make_transform(np.eye(3), c - s * c, s)  # scale about the centroid
        try:
            ps = prepare(apply_transform(S, xs), radii, features=True, remove_outliers=remove_outliers,
                         viewpoint=None if viewpoint is None else apply_transform(S, np.asarray(viewpoint)[None])[0])
            r = clique_registration(ps, tgt, params, rel_tol=step - 1.0, with_scale=True)
        except RuntimeError as e:  # Open3D on degenerate input
            log.info("scale %.4g: %s", s, e)
            continue
        if r.correspondences < 3:
            continue
        q = refine(ps.down, tgt.down, radii.voxel, r.transform, QUICK_ICP, information=False)
        p = apply_transform(q.transform, np.asarray(ps.down.points))
        dist, j = tree.query(p, distance_upper_bound=0.75 * radii.voxel, workers=-1)
        near = np.isfinite(dist)
        fit = float(near.mean())
        share = float(np.mean(np.abs(np.einsum("ij,ij->i", nt[j[near]], p[near] - pt[j[near]])) < 0.3 * radii.voxel)) if near.any() else 0.0
        cands.append((fit * share, s, q.transform @ S, fit, share))
        log.info("scale %.4g: clique scale %.4f, fitness %.3f, plane share %.3f", s, r.scale, fit, share)
    if not cands:
        return np.eye(4), {"coarse_method": "scale_search", "scale0": scale0, "hypotheses": []}
    best = max(cands, key=lambda x: x[0])
    return best[2], {"coarse_method": "scale_search", "scale0": float(scale0), "coarse_fitness": best[3],
                     "hypotheses": [{"scale": round(x[1], 6), "score": round(x[0], 4)} for x in cands]}


#: The coarse methods by name, each called as ``method(src, tgt, params)`` (``planes`` keeps its
#: own :class:`~workstation.registration.planes.PlaneCoarseParams` defaults: this stage's
#: ``params`` do not apply to it).
COARSE_METHODS = {"fpfh_ransac": fpfh_ransac, "fgr": fgr, "clique": clique_registration, "planes": plane_registration}
