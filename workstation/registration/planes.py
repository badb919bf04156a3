"""Coarse registration from planes, for scenes made of planar surfaces (rooms, buildings).

Indoor fragments are dominated by a few large planes (floor, worktops, walls, cabinet
fronts) on which point features such as FPFH are not distinctive, and a fragment often
shows only one plane direction well (a worktop and the floor below it), too few for
plane-pair rotations. One plane seen in both clouds still fixes three of the six degrees of
freedom; the other three are searched exhaustively:

1. **Extraction.** Planes are peeled off the downsampled cloud one at a time by RANSAC
   (:func:`ransac_plane`, seeded: one input always gives the same planes), keeping the
   inliers whose normal agrees with the plane's, and described by unit normal ``n``, offset
   ``d`` (``n . x = d``), centroid and point count.
2. **Plane alignment.** For each of the largest source planes, each of the largest target
   planes and both normal signs, the source is turned and shifted so that the two planes
   coincide (the gravity prior of indoor scenes when the planes are floors or worktops).
   When both scanner positions are known, only planes whose scanners lie on the same side
   of them are paired (a floor seen from above is not laid on a floor seen from below).
3. **Turn and shift in the plane** (:func:`plane_yaw_search`). Each cloud becomes a stack of
   2-D occupancy images, one per height slice above the plane, high-pass filtered so that
   edges (a worktop's border, a cabinet's side) count rather than areas; for every turn
   about the normal (3 degree steps) the in-plane shift is read off the peaks of the FFT
   cross-correlation of the two stacks.
4. **Verification.** Every pose is scored by the surface agreement of a source subsample,
   less its free-space violations (below) when the scanners are known (:class:`_Scorer`);
   the best distinct ones are refined by a short point-to-plane ICP and ranked by two-way
   surface consistency
   (:func:`~workstation.registration.register.consistency`), which penalises surfaces of
   either cloud that come near the other but off its surface, less the share of points
   that land in the other scan's free space when the scanner positions are known
   (:class:`RangeImage`: a point of one cloud lying in front of a surface the other sensor
   saw, along that sensor's ray, would have hidden that surface).

Plane correspondences drive plane-based SLAM and range-image registration (e.g. Pathak et
al. 2010, "Fast registration based on noisy planes with unknown correspondences for 3-D
mapping", IEEE T-RO; Taguchi et al. 2013, "Point-plane SLAM using supporting planes for 3D
mapping", ICRA); the remaining 3-DoF search by correlation of height-slice images is the
phase-correlation idea of 2.5-D map matching, applied above a matched plane.

Limits: in rooms whose views are mostly floor and plain walls, a turn by 90 or 180 degrees
can lay floor on floor and wall on wall with more overlap than the true pose and with the
moved points outside the other sensor's observed free space, so neither consistency nor the
free-space test rejects it. In such views the floor pins neither the turn nor the shift in
the plane: a near-true hypothesis can rank below the verified few on agreement, and the short
ICP can slide it along the floor towards more overlap. The method is opt-in
(``--method planes``) and its result should be checked.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import RegistrationResult

from .preprocess import Prepared
from .transforms import make_transform

log = get_logger(__name__)


@dataclass(frozen=True)
class PlaneCoarseParams:
    """Parameters of :func:`plane_registration` (distances are multiples of the voxel size).

    Attributes
    ----------
    max_planes : int
        Largest number of planes extracted per cloud (largest first).
    min_share : float
        Smallest plane, as a share of the downsampled points (and at least 30 points).
    distance : float
        RANSAC inlier distance of plane extraction.
    normal_angle_deg : float
        Largest angle between a point's normal and its plane's normal for the point to count.
    align_planes : int
        The plane directions (families of parallel planes, most points first) of each cloud
        tried against each other, both normal signs and every pair of their offsets.
    step_deg : float
        Turn step about the plane normal.
    peaks : int
        Cross-correlation peaks (in-plane shifts) kept per turn.
    sample : int
        Source points of the fast agreement score.
    verify : int
        Distinct best-scoring poses refined by ICP and ranked by consistency.
    least_overlap : float
        Only verified poses whose overlap (ICP fitness) reaches this share of the best one's
        are ranked: a pose barely touching the other cloud has neither agreement nor
        conflict. Low, because in views that are mostly floor a wrong turn laying floor on
        floor can overlap 2-3 times more than the true pose.
    free_margin : float
        Depth by which a point must lie in front of the other sensor's observed surface to
        count as a free-space violation (absorbs range noise and fused-fragment blur).
    free_cell : float
        Pixel of the range images (:class:`RangeImage`), as an arc of this many voxels at
        the cloud's median range.
    """

    max_planes: int = 8
    min_share: float = 0.02
    distance: float = 0.75
    normal_angle_deg: float = 30.0
    align_planes: int = 2
    step_deg: float = 3.0
    peaks: int = 3
    sample: int = 800
    verify: int = 32
    least_overlap: float = 0.25
    free_margin: float = 3.0
    free_cell: float = 2.0

    def __post_init__(self):
        least = {"max_planes": 1, "align_planes": 1, "peaks": 1, "sample": 4, "verify": 1}  # a quarter of the sample scores
        for name, low in least.items():
            value = getattr(self, name)
            if not isinstance(value, (int, np.integer)) or value < low:
                raise InvalidInputError(f"{name} must be a whole number of at least {low}, got {value!r}", field=name)
        for name in ("distance", "step_deg", "free_cell"):
            if not float(getattr(self, name)) > 0:
                raise InvalidInputError(f"{name} must be positive, got {getattr(self, name)}", field=name)
        if not 0.0 <= self.min_share < 1.0:
            raise InvalidInputError(f"min_share must lie in [0, 1), got {self.min_share}", field="min_share")
        if not 0.0 <= self.normal_angle_deg <= 90.0:
            raise InvalidInputError(f"normal_angle_deg must lie in [0, 90], got {self.normal_angle_deg}",
                                    field="normal_angle_deg")
        if not 0.0 <= self.least_overlap <= 1.0:
            raise InvalidInputError(f"least_overlap must lie in [0, 1], got {self.least_overlap}", field="least_overlap")
        if not self.free_margin >= 0:
            raise InvalidInputError(f"free_margin must not be negative, got {self.free_margin}", field="free_margin")


@dataclass(frozen=True)
class Planes:
    """Planes of one cloud, largest first: ``normal`` (k, 3) unit, ``offset`` (k,) with
    ``normal . x = offset`` on the plane, ``centroid`` (k, 3) and ``count`` (k,) points."""

    normal: np.ndarray
    offset: np.ndarray
    centroid: np.ndarray
    count: np.ndarray


def ransac_plane(x: np.ndarray, threshold: float, iterations: int, rng: np.random.Generator):
    """The plane of most points of ``x`` (n, 3) within ``threshold``, by RANSAC (Fischler and
    Bolles 1981) over ``iterations`` random point triples drawn from ``rng``, fewer inliers'
    mean squared distance breaking ties, as Open3D's ``segment_plane`` draws them: ``(unit
    normal refitted by least squares on the inliers, inlier indices)``. Open3D's own draws
    run in threads and differ between runs even when seeded; these are vectorised and
    follow ``rng`` alone."""
    tri = x[rng.integers(0, x.shape[0], size=(iterations, 3))]
    n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
    norm = np.linalg.norm(n, axis=1)
    ok = norm > 0  # collinear or repeated triples give no plane
    n, p0 = n[ok] / norm[ok, None], tri[ok, 0]
    best, key = None, (-1, 0.0)
    m = max(1, min(64, 2**22 // x.shape[0]))  # triples a block: at most 4 M distances
    for k in range(0, n.shape[0], m):
        d = np.abs(x @ n[k:k + m].T - np.einsum("ij,ij->i", n[k:k + m], p0[k:k + m]))
        inl = d < threshold
        cnt = inl.sum(axis=0)
        top = np.flatnonzero(cnt == cnt.max())  # the most inliers; the least mean square among them
        mse = np.where(inl[:, top], d[:, top] ** 2, 0.0).sum(axis=0) / max(cnt[top[0]], 1)
        j = top[np.argmin(mse)]
        if (cnt[j], -mse.min()) > key:
            best, key = k + j, (cnt[j], -mse.min())
    if best is None:
        return np.array([0.0, 0.0, 1.0]), np.zeros(0, dtype=np.int64)
    inl = np.flatnonzero(np.abs((x - p0[best]) @ n[best]) < threshold)
    c = x[inl].mean(axis=0)
    w = np.linalg.eigh(np.cov((x[inl] - c).T))[1][:, 0] if inl.size >= 3 else n[best]
    return w * (np.sign(w @ n[best]) or 1.0), inl


def extract_planes(xyz: np.ndarray, normals: np.ndarray, voxel: float,
                   params: PlaneCoarseParams = PlaneCoarseParams(), seed: int = 0) -> Planes:
    """Peel planes off a downsampled cloud by repeated RANSAC (see the module docstring).

    A RANSAC plane (:func:`ransac_plane`, 200 triples, random draws from ``seed``) keeps only
    its inliers whose normal lies within ``normal_angle_deg`` of the plane normal (a plane
    cutting through a curved or slanted surface keeps few); extraction stops at
    ``max_planes``, when the remaining points are too few, or after several planes in a row
    fall below ``min_share``.
    """
    rng = np.random.default_rng(seed)
    xyz = np.asarray(xyz, dtype=np.float64)
    normals = np.asarray(normals, dtype=np.float64)
    least = max(30, int(params.min_share * xyz.shape[0]))
    cos_n = np.cos(np.radians(params.normal_angle_deg))
    left = np.arange(xyz.shape[0])
    out, misses = [], 0
    while len(out) < params.max_planes and left.size >= least and misses < 3:
        n, inl = ransac_plane(xyz[left], float(params.distance * voxel), 200, rng)
        good = inl[np.abs(normals[left[inl]] @ n) >= cos_n]
        if good.size < least:
            misses += 1
            left = np.delete(left, inl)  # drop the slice so the next RANSAC sees other surfaces
            continue
        p = xyz[left[good]]
        c = p.mean(axis=0)
        w, v = np.linalg.eigh(np.cov((p - c).T))  # refit on the kept points
        n = v[:, 0] * np.sign(v[:, 0] @ n)
        out.append((n, float(n @ c), c, good.size))
        left = np.delete(left, good)
        misses = 0
    if not out:
        return Planes(np.zeros((0, 3)), np.zeros(0), np.zeros((0, 3)), np.zeros(0, dtype=np.int64))
    out.sort(key=lambda o: -o[3])
    return Planes(np.array([o[0] for o in out]), np.array([o[1] for o in out]),
                  np.array([o[2] for o in out]), np.array([o[3] for o in out], dtype=np.int64))


class _Scorer:
    """Fast surface agreement of a source subsample with the target under many poses.

    A sampled source point *agrees* when a target point lies within ``1.5 * voxel`` with a
    normal within 37 degrees (either sign) and the point within ``voxel`` of its tangent
    plane (loose enough for a pose before ICP); it *conflicts* when the target comes within
    ``3 * voxel`` but it does not agree. The score of a pose is (agreeing - conflicting) /
    sampled points, less the share of a source and a target subsample lying more than
    ``margin`` in the other scanner's observed free space (:class:`RangeImage`; ``images``
    of source and target, None where the scanner is unknown)."""

    def __init__(self, src: Prepared, tgt: Prepared, n: int, seed: int = 0, images=(None, None), margin: float = 0.0):
        from scipy.spatial import cKDTree

        rng = np.random.default_rng(seed)
        ps = np.asarray(src.down.points)
        idx = rng.choice(ps.shape[0], size=min(n, ps.shape[0]), replace=False)
        self.q, self.qn = ps[idx], np.asarray(src.down.normals)[idx]
        self.y, self.yn = np.asarray(tgt.down.points), np.asarray(tgt.down.normals)
        self.p = self.y[rng.choice(self.y.shape[0], size=min(n, self.y.shape[0]), replace=False)]
        self.tree = cKDTree(self.y)
        self.voxel = src.radii.voxel
        self.images, self.margin = images, margin

    def __call__(self, Ts: np.ndarray, n: int | None = None) -> np.ndarray:
        """Scores of the poses ``Ts`` (k, 4, 4) on the first ``n`` sampled points (all by
        default; the sample is random, so any prefix is too)."""
        v = self.voxel
        q, qn, p = self.q[:n], self.qn[:n], self.p[:n]
        Rt = np.transpose(Ts[:, :3, :3], (0, 2, 1))
        x = (q @ Rt + Ts[:, None, :3, 3]).reshape(-1, 3)
        nx = (qn @ Rt).reshape(-1, 3)
        dist, j = self.tree.query(x, distance_upper_bound=3.0 * v, workers=-1)
        found = np.isfinite(dist)
        near = np.flatnonzero(dist < 1.5 * v)  # only these can agree
        jn, ny = j[near], self.yn[j[near]]
        agree = np.zeros(x.shape[0], dtype=bool)
        agree[near] = ((np.abs(np.einsum("ij,ij->i", ny, x[near] - self.y[jn])) < v)
                       & (np.abs(np.einsum("ij,ij->i", ny, nx[near])) > 0.8))
        score = (agree.astype(np.float64) - (found & ~agree)).reshape(Ts.shape[0], -1).sum(axis=1) / q.shape[0]
        free = np.zeros(Ts.shape[0])
        if self.images[1] is not None:
            free += self.images[1].in_free_space(x, self.margin).reshape(Ts.shape[0], -1).sum(axis=1)
        if self.images[0] is not None:  # target points under the inverse poses: R^T (y - t)
            xb = np.einsum("kij,nj->kni", Rt, p) - np.einsum("kij,kj->ki", Rt, Ts[:, :3, 3])[:, None]
            free += self.images[0].in_free_space(xb.reshape(-1, 3), self.margin).reshape(Ts.shape[0], -1).sum(axis=1)
        return score - free / (q.shape[0] + p.shape[0])


def plane_hypotheses(src: Prepared, tgt: Prepared, params: PlaneCoarseParams = PlaneCoarseParams(),
                     viewpoints=None, images=None):
    """Poses laying a large source plane onto a large target plane (module docstring, steps
    1-3), with their fast agreement scores: ``(scores (k,), transforms (k, 4, 4), source
    planes, target planes)``, best first. With both scanner positions (``viewpoints``, local
    frames; by default those the prepared clouds carry) known, a plane is laid only on planes whose scanner lies on the same side of it
    (:func:`_same_side_offsets`): a floor seen from above is not laid on one seen from below.
    The agreement score counts free-space violations (:class:`_Scorer`) in ``images``, the
    :class:`RangeImage` of source and target (None where the scanner is unknown), built
    from ``viewpoints`` when not given."""
    v = src.radii.voxel
    xs, xt = np.asarray(src.down.points), np.asarray(tgt.down.points)
    viewpoints = (src.viewpoint, tgt.viewpoint) if viewpoints is None else tuple(viewpoints)
    if images is None:
        images = range_images(src, tgt, viewpoints, params)
    ps = extract_planes(xs, np.asarray(src.down.normals), v, params)
    pt = extract_planes(xt, np.asarray(tgt.down.normals), v, params)
    log.info("planes: %d in the source, %d in the target", len(ps.count), len(pt.count))
    Ts = []
    for a, da, _ in _direction_groups(ps)[: params.align_planes]:
        for b, db, _ in _direction_groups(pt)[: params.align_planes]:
            for sg in (1.0, -1.0):
                allowed = _same_side_offsets(a, da, sg * b, sg * db, *viewpoints)
                Ts += [T for _, T in plane_yaw_search(xs, xt, a, da, sg * b, sg * db, v, params.step_deg, params.peaks,
                                                      allowed=allowed)]
    if not Ts:
        return np.zeros(0), np.zeros((0, 4, 4)), ps, pt
    Ts = np.array(Ts)
    score = _Scorer(src, tgt, params.sample, images=images, margin=params.free_margin * v)
    first = np.concatenate([score(Ts[k:k + 512], params.sample // 4) for k in range(0, len(Ts), 512)])
    Ts = Ts[np.argsort(-first, kind="stable")[: max(10 * params.verify, len(Ts) // 10)]]  # the rest cannot compete
    sc = np.concatenate([score(Ts[k:k + 512]) for k in range(0, len(Ts), 512)])
    order = np.argsort(-sc, kind="stable")
    return sc[order], Ts[order], ps, pt


def _same_side_offsets(a: np.ndarray, da: np.ndarray, b: np.ndarray, db: np.ndarray, vs, vt) -> np.ndarray:
    """Which source offsets ``da`` (planes ``a . x = da``) may be laid on which target offsets
    ``db`` (planes ``b . y = db``): a boolean mask (len(da), len(db)), all True when either
    scanner position is unknown, else True where both scanners lie on the same side of their
    planes (a scanner sees a surface from one side, and the pose keeps each scanner on its
    side of the plane)."""
    da, db = np.atleast_1d(np.asarray(da, float)), np.atleast_1d(np.asarray(db, float))
    if vs is None or vt is None:
        return np.ones((da.size, db.size), dtype=bool)
    sa = a @ np.asarray(vs, float) >= da
    sb = b @ np.asarray(vt, float) >= db
    return sa[:, None] == sb[None, :]


def range_images(src: Prepared, tgt: Prepared, viewpoints, params: PlaneCoarseParams = PlaneCoarseParams()):
    """The :class:`RangeImage` of the downsampled source and target seen from their scanner
    positions ``viewpoints`` (local frames), None for a cloud whose scanner is unknown."""
    v = src.radii.voxel
    return [None if p is None else RangeImage(np.asarray(c.down.points), p, v, params.free_cell)
            for c, p in zip((src, tgt), viewpoints)]


def plane_registration(src: Prepared, tgt: Prepared, params=None, viewpoints=None) -> RegistrationResult:
    """Coarse registration from planes (module docstring): the hypotheses of
    :func:`plane_hypotheses`, verified by :func:`verify_plane_hypotheses`.

    ``params`` may be a :class:`PlaneCoarseParams`; anything else (the coarse stage's
    :class:`~workstation.registration.coarse.CoarseParams`) uses the defaults. ``viewpoints``
    holds the scanner positions of source and target in their own (local) frames (each None
    when unknown), by default those the prepared clouds carry (``Prepared.viewpoint``).

    ``meta["hypotheses"]`` holds the verified poses, best first, with their ``consistency``
    and ``free_space`` shares. Raises :class:`~workstation.core.errors.StageError` when no
    plane pair gives a pose (a cloud with no plane, or no slice of the two clouds at matching
    heights)."""
    params = params if isinstance(params, PlaneCoarseParams) else PlaneCoarseParams()
    viewpoints = (src.viewpoint, tgt.viewpoint) if viewpoints is None else tuple(viewpoints)
    images = range_images(src, tgt, viewpoints, params)
    scores, Ts, ps, pt = plane_hypotheses(src, tgt, params, viewpoints, images)
    if not len(Ts):
        raise StageError("register", f"no common planes to align ({len(ps.count)} planes found in the source, "
                         f"{len(pt.count)} in the target)", "try --method auto")
    r = verify_plane_hypotheses(src, tgt, scores, Ts, params, images)
    found = {"planes_source": int(len(ps.count)), "planes_target": int(len(pt.count)), "plane_poses": len(Ts)}
    return replace(r, meta={"method": "planes", **found, **r.meta})


def verify_plane_hypotheses(src: Prepared, tgt: Prepared, scores: np.ndarray, Ts: np.ndarray,
                            params: PlaneCoarseParams = PlaneCoarseParams(), images=(None, None)) -> RegistrationResult:
    """The best of the ``verify`` best distinct poses ``Ts`` (k >= 1, 4, 4; best first by their
    agreement ``scores``), each refined by a short point-to-plane ICP, by two-way surface
    consistency less the free-space violation share (:func:`free_space_violations` in
    ``images``, the :class:`RangeImage` of source and target; zero for a cloud whose image is
    None). Only poses whose verified overlap reaches ``least_overlap`` of the best one's are
    ranked (a pose barely touching the other cloud has neither agreement nor conflict).
    ``meta`` holds the ranked poses (``hypotheses``), best first, with their ``consistency``
    and ``free_space``."""
    from .icp import QUICK_ICP, refine
    from .register import _distinct_pose, consistency

    if len(Ts) == 0:
        raise InvalidInputError("no pose hypotheses to verify", field="Ts")
    v = src.radii.voxel
    picked = []
    for s, T in zip(scores, Ts):
        if all(_distinct_pose(T, k[1], v) for k in picked):
            picked.append((s, T))
        if len(picked) >= params.verify:
            break
    from scipy.spatial import cKDTree

    cands = []
    target_tree = cKDTree(np.asarray(tgt.down.points))  # one tree for every pose's consistency
    for s, T in picked:
        q = refine(src.down, tgt.down, v, T, QUICK_ICP, information=False)
        free = free_space_violations(src.down, tgt.down, q.transform, images, params.free_margin * v)
        cands.append((consistency(src.down, tgt.down, q.transform, v, target_tree), free, float(q.fitness), q))
        log.info("planes hypothesis: agreement %.3f, verified fitness %.3f, consistency %.3f, free-space %.3f",
                 s, q.fitness, cands[-1][0], free)
    least = params.least_overlap * max(c[2] for c in cands)
    order = sorted((c for c in cands if c[2] >= least), key=lambda c: c[1] - c[0])
    best = order[0][3]
    meta = {"consistency": [round(c[0], 4) for c in order], "free_space": [round(c[1], 4) for c in order],
            "hypotheses": [c[3].transform for c in order]}
    return RegistrationResult(transform=best.transform, scale=1.0, fitness=best.fitness, inlier_rmse=best.inlier_rmse,
                              converged=True, correspondences=best.correspondences, meta={"method": "planes", **meta})


class RangeImage:
    """What one sensor saw: the nearest range in each pixel of a spherical image (azimuth,
    elevation) around the sensor ``position``, then the least over each pixel's 3 x 3
    neighbourhood, so that a pixel straddling a depth edge keeps its near side.

    The pixel is an arc of ``cell`` voxels at the median range of ``points``, but no smaller
    than keeps the image within ``MAX_PIXELS`` (a small voxel far from the sensor would
    otherwise ask for a finer image than the points can fill). A pixel with no point is
    unknown (outside the field of view, beyond the range, or no return), not free."""

    #: Largest number of pixels of the image (float64: 8 bytes each).
    MAX_PIXELS = 4_000_000

    def __init__(self, points: np.ndarray, position, voxel: float, cell: float = 2.0):
        from scipy.ndimage import minimum_filter

        self.position = np.asarray(position, dtype=np.float64).reshape(3)
        r = np.linalg.norm(np.asarray(points, dtype=np.float64) - self.position, axis=1)
        # at this step the image holds at most sqrt(MAX_PIXELS / 2) rows of 2 sqrt(MAX_PIXELS / 2) pixels
        self.step = max(cell * voxel / max(float(np.median(r)), voxel), np.pi / (np.sqrt(self.MAX_PIXELS / 2.0) - 2.0))
        self.shape = (int(np.ceil(np.pi / self.step)) + 1, int(np.ceil(2 * np.pi / self.step)))
        i, j, r = self.pixels(points)
        img = np.full(self.shape, np.inf)
        np.minimum.at(img, (i, j), r)
        # azimuth wraps; elevation does not (repeating the edge row leaves a minimum unchanged)
        self.image = minimum_filter(img, size=3, mode=("nearest", "wrap"))

    def pixels(self, x: np.ndarray):
        """Pixel rows, columns and ranges of points ``x`` (n, 3)."""
        d = np.asarray(x, dtype=np.float64) - self.position
        r = np.linalg.norm(d, axis=1)
        el = np.arcsin(np.clip(d[:, 2] / np.maximum(r, 1e-12), -1.0, 1.0))
        az = np.arctan2(d[:, 1], d[:, 0])
        i = np.minimum(np.floor((el + np.pi / 2) / self.step).astype(np.int64), self.shape[0] - 1)
        j = np.floor((az + np.pi) / self.step).astype(np.int64) % self.shape[1]
        return i, j, r

    def in_free_space(self, x: np.ndarray, margin: float) -> np.ndarray:
        """Whether each point of ``x`` lies more than ``margin`` in front of the observed range."""
        i, j, r = self.pixels(x)
        seen = self.image[i, j]
        return np.isfinite(seen) & (r < seen - margin)


def free_space_violations(src, tgt, T: np.ndarray, images, margin: float) -> float:
    """Share of the points of both clouds (Open3D) that, under ``T`` (source -> target), lie
    more than ``margin`` inside the free space the other sensor observed (``images``: the
    :class:`RangeImage` of source and target, None where the sensor is unknown)."""
    from .transforms import apply_transform, invert

    a, b = np.asarray(src.points), np.asarray(tgt.points)
    bad = 0
    if images[1] is not None:
        bad += int(images[1].in_free_space(apply_transform(T, a), margin).sum())
    if images[0] is not None:
        bad += int(images[0].in_free_space(apply_transform(invert(T), b), margin).sum())
    return bad / max(a.shape[0] + b.shape[0], 1)


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def _align(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The smallest rotation taking unit vector ``a`` onto unit vector ``b``."""
    v, c = np.cross(a, b), float(a @ b)
    if c < -1.0 + 1e-9:  # opposite: half a turn about any axis normal to a
        p = _unit(np.cross(a, np.eye(3)[np.argmin(np.abs(a))]))
        return 2.0 * np.outer(p, p) - np.eye(3)
    K = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + K + K @ K / (1.0 + c)


def _height_images(uv: np.ndarray, ch: np.ndarray, n_ch: int, lo: np.ndarray, shape, cell: float) -> np.ndarray:
    """Occupancy images (n_ch, *shape), float32, of points at plane coordinates ``uv`` (n, 2)
    in channels ``ch`` (n,; -1 for none) on a grid of ``cell`` from ``lo``."""
    ij = np.floor((uv - lo) / cell).astype(np.int64)
    ok = (ij >= 0).all(axis=1) & (ij[:, 0] < shape[0]) & (ij[:, 1] < shape[1]) & (ch >= 0)
    img = np.zeros((n_ch, *shape), dtype=np.float32)
    img[ch[ok], ij[ok, 0], ij[ok, 1]] = 1.0
    return img


def _edge_filter(P) -> np.ndarray:
    """Squared magnitude of the transfer function, on an ``rfft2`` grid of shape ``P``, of the
    high-pass filter "occupancy minus its 3 x 3 mean": applied to both images of a
    cross-correlation it makes the interior of an area cancel and its edges count."""
    from scipy.fft import rfft2

    k = np.zeros(P, dtype=np.float32)
    k[np.ix_([0, 1, -1], [0, 1, -1])] = -1.0 / 9.0
    k[0, 0] += 1.0
    return np.abs(rfft2(k)) ** 2


def _direction_groups(pl: Planes, angle_deg: float = 5.0) -> list[tuple[np.ndarray, np.ndarray, int]]:
    """Planes grouped by direction (normals within ``angle_deg``, either sign), heaviest group
    first: ``(normal of the group's largest plane, offsets of its planes in that normal's sign,
    total point count)``."""
    cos_tol = np.cos(np.radians(angle_deg))
    group = np.full(len(pl.count), -1)
    for k in range(len(pl.count)):  # planes come largest first: each seeds the group of its parallels
        if group[k] < 0:
            group[(group < 0) & (np.abs(pl.normal @ pl.normal[k]) >= cos_tol)] = k
    out = []
    for k in np.unique(group):
        sel = group == k
        sgn = np.sign(pl.normal[sel] @ pl.normal[k])
        out.append((pl.normal[k], sgn * pl.offset[sel], int(pl.count[sel].sum())))
    return sorted(out, key=lambda g: -g[2])


def plane_yaw_search(xs: np.ndarray, xt: np.ndarray, a: np.ndarray, da: np.ndarray, b: np.ndarray, db: np.ndarray,
                     voxel: float, step_deg: float = 3.0, peaks: int = 3,
                     allowed: np.ndarray | None = None) -> list[tuple[float, np.ndarray]]:
    """Poses laying a source plane ``a . x = da[i]`` onto a target plane ``b . y = db[j]`` (every
    pair of offsets of the two parallel families, or those where the boolean mask ``allowed``
    (len(da), len(db)) is True): the three remaining degrees of freedom (the
    turn about the normal and the shift in the plane) by an exhaustive search over the turn in
    ``step_deg`` steps and, for each, the in-plane shifts at the ``peaks`` highest peaks of the
    FFT cross-correlation of the two clouds' occupancy images in height slices along the
    normal, high-passed (:func:`_edge_filter`; cell and slice ``2 * voxel``; slices holding 10
    points of each cloud). The turn does not change the heights, so each turn's source
    spectra serve every offset pair (a shift of the slices). The source image is centred on
    the source's own centroid, so its size is that of the source, wherever its frame lies.
    Returns ``(correlation, T)`` pairs."""
    from scipy.fft import irfft2, next_fast_len, rfft2

    cell = 2.0 * voxel
    R0 = _align(a, b)
    e1 = _unit(np.cross(b, np.eye(3)[np.argmin(np.abs(b))]))
    E = np.stack([e1, np.cross(b, e1)])  # in-plane axes of the target plane
    xr = xs @ R0.T
    ys, us = xt @ E.T, xr @ E.T
    vt, ct = _slices(xt @ b, cell)
    vs, cs = _slices(xr @ b, cell)
    diff = np.subtract.outer(np.atleast_1d(db), np.atleast_1d(da))  # (len(db), len(da)): the lift of each pair
    diff = diff.ravel() if allowed is None else diff[np.asarray(allowed, dtype=bool).T]
    shifts = np.unique(np.round(diff / cell).astype(int))
    pairs = [(d, np.flatnonzero(np.isin(vs + d, vt)), np.searchsorted(vt, vs[np.isin(vs + d, vt)] + d)) for d in shifts]
    pairs = [p for p in pairs if p[1].size]
    if not pairs:
        return []
    used = np.unique(np.concatenate([p[1] for p in pairs]))  # only these source slices need spectra
    remap = np.full(vs.size, -1)
    remap[used] = np.arange(used.size)
    cs = np.where(cs >= 0, remap[cs], -1)
    pairs = [(d, remap[i_s], i_t) for d, i_s, i_t in pairs]
    lo_t = ys.min(axis=0)
    nt = np.ceil((ys.max(axis=0) - lo_t) / cell).astype(int) + 1
    cu = us.mean(axis=0)  # the source image is centred on its own centroid, wherever its frame lies
    us = us - cu
    rs = float(np.sqrt((us**2).sum(axis=1).max()))
    ns = int(np.ceil(2 * rs / cell)) + 1
    P = np.array([next_fast_len(int(nt[0] + ns), real=True), next_fast_len(int(nt[1] + ns), real=True)])
    FT = rfft2(_height_images(ys, ct, vt.size, lo_t, nt, cell), tuple(P)) * _edge_filter(tuple(P))
    lo_s = -np.array([rs, rs])
    # offset pairs in one slice shift share its correlation; the pose lifts by their mean offset
    lift = {d: float(diff[np.round(diff / cell).astype(int) == d].mean()) for d in shifts}
    out = []
    for th in np.radians(np.arange(0.0, 360.0, step_deg)):
        c, s = np.cos(th), np.sin(th)
        M = np.array([[c, s], [-s, c]])  # the turn, on row vectors
        FS = np.conj(rfft2(_height_images(us @ M, cs, used.size, lo_s, (ns, ns), cell), tuple(P)))
        R = (E.T @ np.array([[c, -s], [s, c]]) @ E + np.outer(b, b)) @ R0  # the turn about b, after R0
        base = lo_t - lo_s - cu @ M  # the shift at lag 0, with the source's centroid added back
        corr = irfft2(np.stack([(FT[i_t] * FS[i_s]).sum(axis=0) for _, i_s, i_t in pairs]), tuple(P))
        for (d, _, _), val, k in zip(pairs, *_top_peaks(corr, peaks)):
            # lags run from -(ns - 1) to nt - 1 and P >= nt + ns: indices from nt up are negative lags
            shift = base + np.where(k >= nt, k - P, k) * cell
            out += [(float(c_), make_transform(R, lift[d] * b + t @ E)) for c_, t in zip(val, shift)]
    return out


def _top_peaks(corr: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """The ``n`` highest peaks of each circular cross-correlation in ``corr`` (b, P0, P1),
    overwritten: values (b, n) and indices (b, n, 2), each the maximum left after masking the
    3 x 3 neighbourhoods of those before it (the first in row-major order among equals); the
    neighbourhoods wrap around the edges, as the lags do (index 0 neighbours index -1)."""
    b, (p0, p1) = np.arange(corr.shape[0]), corr.shape[1:]
    flat = corr.reshape(b.size, p0 * p1)  # a view: masking it masks corr
    val, idx = np.empty((b.size, n)), np.empty((b.size, n, 2), dtype=np.int64)
    near = np.arange(-1, 2)
    for m in range(n):
        f = np.argmax(flat, axis=1)
        val[:, m] = flat[b, f]
        i, j = np.divmod(f, p1)
        idx[:, m, 0], idx[:, m, 1] = i, j
        rows, cols = (i[:, None] + near) % p0, (j[:, None] + near) % p1
        flat[b[:, None], (rows[:, :, None] * p1 + cols[:, None, :]).reshape(b.size, -1)] = -np.inf
    return val, idx


def _slices(h: np.ndarray, cell: float) -> tuple[np.ndarray, np.ndarray]:
    """Height slices of thickness ``cell`` holding at least 10 points: their indices (sorted)
    and each point's channel among them (-1 for a point in a sparser slice)."""
    k = np.floor(h / cell + 0.5).astype(np.int64)
    v, n = np.unique(k, return_counts=True)
    v = v[n >= 10]
    ch = np.searchsorted(v, k)
    ok = (ch < v.size) & (v[np.minimum(ch, max(v.size - 1, 0))] == k) if v.size else np.zeros(k.size, bool)
    return v, np.where(ok, ch, -1)
