"""Roof plane segmentation: normals, region growing, RANSAC, coplanar merging.

The method follows the textbook chain for airborne laser scanning (Vosselman & Maas 2010,
*Airborne and Terrestrial Laser Scanning*, ch. 2; Rabbani et al. 2006, "Segmentation of point
clouds using smoothness constraint"; Fischler & Bolles 1981 for RANSAC):

1. Normals and a local noise figure from the principal components of each point's k nearest
   neighbours (the smallest eigenvalue is the variance along the normal).
2. Region growing on normals: neighbours are joined when both are locally planar, their normals
   agree within ``angle_deg`` and the neighbour lies within the distance threshold of the
   point's tangent plane. Growing is the connected components of that neighbour graph
   (scipy.sparse.csgraph), so it runs without a Python loop over points.
3. Sequential RANSAC inside each region with the textbook iteration bound
   ``k = log(1 - p) / log(1 - w^m)`` (p the wanted confidence, w the inlier ratio, m = 3 points
   per plane), adaptively tightened as better consensus sets are found (Hartley & Zisserman
   2004, alg. 4.5), then a least-squares refit on the inliers.
4. Planes that are coplanar (normals within ``angle_deg``, each other's points within the
   threshold) and touch are merged; points left over (ridges, edges) join the nearest plane of
   their neighbours when within the threshold.
5. A finer pass over the points still left (:func:`_fine_pass`): normals from a third of the
   neighbours, searched among those points only, find faces too narrow for the first pass's
   neighbourhoods (dormer cheeks of 1-2 m); their planes go through steps 3-4 as well.
6. Faces under ``min_points`` among the points still left (:func:`_residual_faces`): RANSAC
   proposals accepted on statistical grounds (tilt standard error at the pooled noise, a
   chi-square test of the residuals, a surface test and the Bayesian information criterion
   against the planes already there) instead of a point count.
7. Regularisation of a building's planes (:func:`regularise_planes`, used by
   :mod:`workstation.buildings.models` and by step 6): azimuths along the building's dominant
   direction and its quarter turns (tested for the two sides of a level ridge together where
   one alone fails), and one tilt for the two sides of a ridge, each imposed where the Bayes
   factor of the constrained against the free fit favours it.
8. Edges settled (:func:`settle_edges`): a point near the line where two planes meet, which the
   distance threshold lets either plane take, stays on its plane only when on that face's side
   of the line (ridge or valley) and not within two noise sigmas of it, else it is left out of
   the fits; a point off its plane and on one other moves there; the planes are refitted (two
   rounds).

The distance threshold combines the noise and the spacing: ``eps = sqrt((3 sigma)^2 +
(s tan(angle))^2)``: 3 sigma keeps 99.7 % of Gaussian noise and the second term is the offset a
plane tilted by the angle tolerance makes over one point spacing ``s``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from workstation.core.errors import InvalidInputError
from workstation.core.pca import group_moments, grouped_plane_fit, local_pca


@dataclass(frozen=True)
class PlaneParams:
    """Parameters of :func:`segment_planes`.

    Attributes
    ----------
    k_neighbors : int
        Neighbours used for normals and region growing (points).
    noise : float or None
        Standard deviation of the points along the surface normal (m); None estimates it from
        the median local PCA residual.
    spacing : float or None
        Mean 3-D point spacing (m); None estimates it as the median nearest-neighbour distance.
    angle_deg : float
        Largest angle between normals of one plane (degrees), for growing and merging.
    confidence : float
        RANSAC probability p of drawing at least one all-inlier sample (0-1).
    inlier_ratio : float
        Initial guess w of the inlier fraction (0-1) for the iteration bound; adapted upwards.
    min_points : int
        Smallest plane kept (points).
    max_planes_per_region : int
        Planes extracted by sequential RANSAC from one grown region at most.
    seed : int
        Random seed of the RANSAC samples.
    """

    k_neighbors: int = 24
    noise: float | None = None
    spacing: float | None = None
    angle_deg: float = 10.0
    confidence: float = 0.999
    inlier_ratio: float = 0.5
    min_points: int = 20
    max_planes_per_region: int = 6
    seed: int = 0


@dataclass(frozen=True)
class RoofPlanes:
    """Planes found in a cloud.

    Attributes
    ----------
    labels : (n,) int64
        Plane (face) index per point, -1 for points on no plane. Near where two planes meet, a
        point that :func:`settle_edges` leaves out of its plane's fit keeps its face here.
    normals : (p, 3) float64
        Unit normals pointing up (z >= 0).
    offsets : (p,) float64
        Plane offsets d with ``normal . (x - origin) + d = 0`` (m).
    origin : (3,) float64
        Local origin subtracted from the coordinates before fitting (m).
    rmse : (p,) float64
        RMS distance to each plane of the points it was fitted to (``fitted``) (m).
    counts : (p,) int64
        Points each plane was fitted to (``labels == q`` and ``fitted``); the face's points
        (``labels == q``) may be more.
    threshold : float
        Distance threshold used (m).
    noise, spacing : float
        Noise sigma and point spacing used (m).
    angle_deg : float
        Angle tolerance used (degrees).
    regular : (p,) bool or None
        Small faces accepted only because their regularised tilt is determined (azimuth along
        the building's directions, tilt shared across their ridge; :func:`_residual_faces`):
        the model regularises them whatever its own Bayes factors say (``force`` of
        :func:`regularise_planes`). None where not recorded (as all False).
    fitted : (n,) bool or None
        Points each plane is fitted to: the labelled points less those near a line where two
        planes meet that :func:`settle_edges` leaves out (too close to the line to tell the
        faces apart, or on the other face's side of it). The models refit their planes to
        these points and let the refitted planes claim the others
        (:func:`workstation.buildings.models.build_building`). None where not recorded (every
        labelled point).
    """

    labels: np.ndarray
    normals: np.ndarray
    offsets: np.ndarray
    origin: np.ndarray
    rmse: np.ndarray
    counts: np.ndarray
    threshold: float
    noise: float
    spacing: float
    angle_deg: float = 10.0
    regular: np.ndarray | None = None
    fitted: np.ndarray | None = None

    @property
    def tilt_deg(self) -> np.ndarray:
        """(p,) angle of each plane to the horizontal (degrees)."""
        return np.degrees(np.arccos(np.clip(np.abs(self.normals[:, 2]), 0.0, 1.0)))

    @property
    def azimuth_deg(self) -> np.ndarray:
        """(p,) direction each plane faces (downslope), clockwise from north (degrees, 0-360)."""
        return azimuth_of(self.normals)

    def height_at(self, plane: np.ndarray, xy: np.ndarray) -> np.ndarray:
        """z (m) of planes ``plane`` (m,) at absolute positions ``xy`` (m, 2)."""
        n = self.normals[plane]
        d = self.offsets[plane]
        x = xy - self.origin[:2]
        return self.origin[2] - (n[:, 0] * x[:, 0] + n[:, 1] * x[:, 1] + d) / n[:, 2]


def azimuth_of(normals: np.ndarray) -> np.ndarray:
    """(p,) azimuth (degrees clockwise from north, 0-360) of up-pointing normals (p, 3)."""
    return np.degrees(np.arctan2(normals[:, 0], normals[:, 1])) % 360.0


def ransac_iterations(confidence: float, inlier_ratio: float, sample_size: int = 3) -> int:
    """Iterations k so that a sample of ``sample_size`` inliers is drawn with probability
    ``confidence``: k = log(1 - p) / log(1 - w^m) (Fischler & Bolles 1981).

    Examples
    --------
    >>> ransac_iterations(0.99, 0.5, 3)
    35
    >>> ransac_iterations(0.999, 1.0, 3)
    1
    """
    if not (0.0 < confidence < 1.0) or not (0.0 < inlier_ratio <= 1.0) or sample_size < 1:
        raise InvalidInputError("needs 0 < confidence < 1, 0 < inlier_ratio <= 1 and sample_size >= 1",
                                field="ransac")
    good = inlier_ratio ** sample_size
    if good >= 1.0:
        return 1
    return max(1, math.ceil(math.log(1.0 - confidence) / math.log(1.0 - good)))


def distance_threshold(noise: float, spacing: float, angle_deg: float) -> float:
    """eps = sqrt((3 noise)^2 + (spacing tan(angle))^2) (m), see the module docstring.

    >>> round(distance_threshold(0.03, 0.5, 10.0), 4)
    0.126
    """
    return float(math.hypot(3.0 * noise, spacing * math.tan(math.radians(angle_deg))))


def scan_frame(xy: np.ndarray, k: int = 8):
    """Anisotropy of airborne sampling: (unit scan-line direction (2,), along-line spacing a,
    across-line spacing b, density) in metres and points/m2. Along scan lines the ``k`` nearest
    neighbours lie nearly all in one direction; then a is the median distance of the k-th
    neighbour over k / 2 (points on both sides), and b = 1 / (density a) with the density
    counted over 2 m cells. Sampling without a dominant direction gives b = a, direction (1, 0)
    and density 1 / a^2. Where more than half the points have k others on their spot (repeated
    returns) the median distance is 0: then a = b = 1 / sqrt(density), the spacing of the cell
    density, isotropic."""
    from scipy.spatial import cKDTree

    d, i = cKDTree(xy).query(xy, k=k + 1)
    v = (xy[i[:, 1:]] - xy[:, None, :]) / np.maximum(d[:, 1:, None], 1e-12)
    w, e = np.linalg.eigh(np.einsum("nki,nkj->ij", v, v) / v.shape[0] / k)
    a = float(np.median(d[:, k]) / (k / 2))
    if not a > 0:  # most points on one spot: no spacing between neighbours, that of the density
        density = _cell_density(xy)
        return np.array([1.0, 0.0]), 1.0 / math.sqrt(density), 1.0 / math.sqrt(density), density
    if w[1] < ANISOTROPY:  # offsets spread over directions: isotropic enough
        return np.array([1.0, 0.0]), a, a, 1.0 / (a * a)
    density = _cell_density(xy)
    return e[:, 1], a, float(max(a, 1.0 / (density * max(a, 1e-9)))), density


def _cell_density(xy: np.ndarray) -> float:
    """Points per m2 of plan points (n, 2) over the 2 m cells they occupy."""
    cell = np.floor(xy / 2.0).astype(np.int64)
    cell -= cell.min(axis=0)
    occupied = len(np.unique(cell[:, 0] * (int(cell[:, 1].max()) + 1) + cell[:, 1]))  # distinct 2 m cells
    return len(xy) / (4.0 * occupied)


#: Share of the neighbour directions along one axis above which sampling counts as scan lines
#: (1 for perfectly aligned offsets, 0.5 for isotropic ones; the simulator's zigzag ALS gives 0.68).
ANISOTROPY = 0.65


def local_geometry(xyz: np.ndarray, k: int, chunk: int = 200_000, frame=None):
    """Normals (n, 3, up), local residual sigma (n,) and the neighbour index (n, k).

    PCA of each point's k nearest neighbours (itself included); the normal is the eigenvector
    of the smallest eigenvalue, the residual its square root scaled by sqrt(k / (k - 3)) for the
    three degrees of freedom of the fitted plane. With a scan ``frame`` from :func:`scan_frame`
    the neighbours are searched with the along-line axis stretched by f = 4 pi density b^2 / k
    (at most b / a): the k neighbours then span about two line spacings across, so they come
    from several scan lines instead of one. A neighbourhood whose second eigenvalue is under 9
    times the smallest (its spread across under 3 noise sigmas) has no defined normal and gets
    an infinite sigma. Processed in chunks (memory bounded).
    """
    k = int(min(k, len(xyz)))
    q = None
    if frame is not None and frame[2] > frame[1]:
        u, a, b, density = frame
        f = min(b / a, max(1.0, 4 * math.pi * density * b * b / k))
        along = xyz[:, :2] @ u
        q = xyz + np.outer(along * (f - 1.0), np.r_[u, 0.0])
    r = local_pca(xyz, k=k, search_xyz=q, chunk=chunk)
    w = r.eigenvalues
    sigma = np.sqrt(np.maximum(w[:, 0], 0.0)) * math.sqrt(k / max(k - 3, 1))
    # a neighbourhood along one scan line has no defined normal: call it non-planar
    sigma[w[:, 1] < 9.0 * w[:, 0]] = np.inf
    return r.normals, sigma, r.indices


def fit_plane(pts: np.ndarray):
    """Least-squares plane of (m, 3) points: unit normal (up) and offset d (n . x + d = 0)."""
    c = pts.mean(axis=0)
    _, _, vt = np.linalg.svd(pts - c, full_matrices=False)
    n = vt[-1]
    if n[2] < 0:
        n = -n
    return n, -float(n @ c)


def ransac_plane(pts: np.ndarray, eps: float, params: PlaneParams, rng: np.random.Generator):
    """Best plane of ``pts`` (m, 3) by RANSAC with the adaptive textbook bound, refitted by
    least squares on its inliers. Returns (normal, d, inlier mask)."""
    m = len(pts)
    w = params.inlier_ratio
    k_max = ransac_iterations(params.confidence, w)
    best_n, best_d, best_count = None, 0.0, -1
    drawn = 0
    while drawn < k_max:
        batch = min(k_max - drawn, 256)
        drawn += batch
        s = rng.integers(0, m, size=(batch, 3))
        a, b, c = pts[s[:, 0]], pts[s[:, 1]], pts[s[:, 2]]
        n = np.cross(b - a, c - a)
        nn = np.linalg.norm(n, axis=1)
        ok = nn > 1e-12
        if not ok.any():
            continue
        n = n[ok] / nn[ok, None]
        d = -np.einsum("ij,ij->i", n, a[ok])
        counts = (np.abs(pts @ n.T + d) < eps).sum(axis=0)
        j = int(np.argmax(counts))
        if counts[j] > best_count:
            best_n, best_d, best_count = n[j], d[j], int(counts[j])
            w = max(w, best_count / m)
            k_max = min(k_max, ransac_iterations(params.confidence, min(w, 1.0)))
    if best_n is None:
        return None, 0.0, np.zeros(m, bool)
    inl = np.abs(pts @ best_n + best_d) < eps
    for _ in range(2):  # refit on the consensus set, then re-select with the refined plane
        n, d = fit_plane(pts[inl])
        new = np.abs(pts @ n + d) < eps
        if new.sum() < 3:
            break
        inl = new
    return n, d, inl


def _grow_regions(xyz, normals, sigma, idx, eps, spacing, angle_deg):
    """Region growing as connected components of the smooth-neighbour graph (labels (n,), -1 off)."""
    from scipy.sparse import csr_matrix
    from scipy.sparse.csgraph import connected_components

    n, k = idx.shape
    planar = sigma < eps / 1.5
    i = np.repeat(np.arange(n), k - 1)
    j = idx[:, 1:].ravel()
    both = planar[i] & planar[j]  # the other tests only for pairs of planar points
    i, j = i[both], j[both]
    # the three tests in turn, each on the pairs that passed the ones before
    ok = np.einsum("ij,ij->i", normals[i], normals[j]) > math.cos(math.radians(angle_deg))
    i, j = i[ok], j[ok]
    diff = xyz[j] - xyz[i]
    ok = np.abs(np.einsum("ij,ij->i", normals[i], diff)) < eps
    ok &= np.einsum("ij,ij->i", diff, diff) < (3.0 * spacing) ** 2
    i, j = i[ok], j[ok]  # still grouped by i, and no pair twice (distinct neighbours per row)
    indptr = np.concatenate([[0], np.cumsum(np.bincount(i, minlength=n))])
    _, lab = connected_components(csr_matrix((np.ones(len(j)), j, indptr), shape=(n, n)), directed=False)
    lab = np.where(planar, lab, -1)
    return lab


def _ransac_regions(xyz, regions, eps, params):
    """Sequential RANSAC in every grown region; returns point labels and (normals, offsets)."""
    rng = np.random.default_rng(params.seed)
    labels = np.full(len(xyz), -1, np.int64)
    normals, offsets = [], []
    valid = regions >= 0
    order = np.argsort(regions[valid], kind="stable")
    ids = np.flatnonzero(valid)[order]
    uniq, start, count = np.unique(regions[valid][order], return_index=True, return_counts=True)
    for s, c in zip(start[count >= params.min_points], count[count >= params.min_points]):
        members = ids[s:s + c]
        for _ in range(params.max_planes_per_region):
            if len(members) < params.min_points:
                break
            nrm, d, inl = ransac_plane(xyz[members], eps, params, rng)
            if nrm is None or inl.sum() < params.min_points:
                break
            labels[members[inl]] = len(normals)
            normals.append(nrm)
            offsets.append(d)
            members = members[~inl]
    return labels, np.array(normals).reshape(-1, 3), np.array(offsets, float)


#: Largest graph labelled with the dense propagation of :func:`small_components` (nodes): about
#: where scipy's sparse set-up (a few hundred microseconds) costs less than the dense rounds.
DENSE_COMPONENTS = 64


def small_components(p: int, i: np.ndarray, j: np.ndarray) -> np.ndarray:
    """Connected-component label (p,) int32 of the undirected graph of ``p`` nodes with edges
    ``(i[e], j[e])``, numbered as scipy.sparse.csgraph.connected_components numbers them (in the
    order of each component's lowest node).

    Graphs of planes are small (tens of nodes): every node takes the lowest index among itself
    and its neighbours until nothing changes, on a dense adjacency matrix, which spares the
    sparse-matrix set-up. Larger graphs go to scipy.

    >>> small_components(5, np.array([3, 1]), np.array([4, 2])).tolist()
    [0, 1, 1, 2, 2]
    """
    if p > DENSE_COMPONENTS:
        from scipy.sparse import coo_matrix
        from scipy.sparse.csgraph import connected_components

        return connected_components(coo_matrix((np.ones(len(i)), (i, j)), shape=(p, p)), directed=False)[1]
    adj = np.zeros((p, p), bool)
    adj[i, j] = adj[j, i] = True
    low = np.arange(p)
    while True:
        new = np.minimum(low, np.where(adj, low[None, :], p).min(axis=1, initial=p))
        if np.array_equal(new, low):
            break
        low = new
    return np.unique(low, return_inverse=True)[1].astype(np.int32)


def _merge_coplanar(xyz, labels, normals, offsets, idx, eps, angle_deg):
    """Union touching planes whose normals agree and where the smaller plane's centroid lies on
    the larger plane (the larger one is the better determined)."""
    p = len(normals)
    if p < 2:
        return labels
    a = np.repeat(labels, idx.shape[1] - 1)
    b = labels[idx[:, 1:].ravel()]
    keep = (a >= 0) & (b >= 0) & (a != b)
    key = np.unique(np.minimum(a[keep], b[keep]) * p + np.maximum(a[keep], b[keep]))  # sorted pairs (lo, hi)
    if not len(key):
        return labels
    pairs = np.column_stack([key // p, key % p])
    on = labels >= 0
    cnt = np.bincount(labels[on], minlength=p).astype(float)
    cen = np.column_stack([np.bincount(labels[on], xyz[on, c], minlength=p) for c in range(3)]) / np.maximum(cnt, 1)[:, None]
    pa, pb = pairs[:, 0], pairs[:, 1]
    same = np.einsum("ij,ij->i", normals[pa], normals[pb]) > math.cos(math.radians(angle_deg))
    big = np.where(cnt[pa] >= cnt[pb], pa, pb)  # the better-determined plane
    small = np.where(cnt[pa] >= cnt[pb], pb, pa)
    same &= np.abs(np.einsum("ij,ij->i", normals[big], cen[small]) + offsets[big]) < eps
    comp = small_components(p, pa[same], pb[same])
    return np.where(labels >= 0, comp[np.maximum(labels, 0)], -1)


def _refit(xyz, labels, min_points):
    """Contiguous labels, least-squares planes, counts and RMS of every plane with enough points."""
    cnt = np.bincount(labels[labels >= 0]) if (labels >= 0).any() else np.zeros(0, int)
    keep = np.flatnonzero(cnt >= min_points)
    remap = np.full(len(cnt) + 1, -1, np.int64)
    remap[keep] = np.arange(len(keep))
    labels = remap[labels]  # -1 maps through the last entry
    g = grouped_plane_fit(xyz, labels, len(keep))
    return labels, g.normals, g.offsets, g.rms, g.counts


def _assign_leftovers(xyz, labels, normals, offsets, idx, eps, rounds: int = 2):
    """Give unlabelled points the closest plane among their neighbours' planes when within eps."""
    for _ in range(rounds):
        free = np.flatnonzero(labels < 0)
        if not len(free) or not len(normals):
            break
        cand = labels[idx[free]]  # (u, k)
        has = cand >= 0
        c = np.maximum(cand, 0)
        dist = np.abs(np.einsum("ukj,uj->uk", normals[c], xyz[free]) + offsets[c])
        dist[~has] = np.inf
        best = np.argmin(dist, axis=1)
        dmin = dist[np.arange(len(free)), best]
        ok = dmin < eps
        if not ok.any():
            break
        new = labels.copy()
        new[free[ok]] = cand[ok, best[ok]]
        labels = new
    return labels


def _fine_pass(xyz, labels, eps, spacing, frame, params):
    """Planes among the points no plane took, found at a finer scale: normals from the
    ``k_neighbors // 3`` nearest *unassigned* points (at least 6), then region growing and RANSAC
    as in the first pass. A roof face narrower than about two neighbourhood radii of the first
    pass (a dormer cheek of 1-2 m at 10 points/m^2, where k = 24 spans a disc of about 0.9 m
    radius) has almost no neighbourhood that stays on it, so none of its points counts as planar;
    a third of the neighbours spans 1 / sqrt(3) of that radius, and searching only among the
    leftovers keeps the planes already found out of the neighbourhoods. A region of half
    ``min_points`` seeds a plane (a third of the neighbours leaves fewer planar points on a small
    face); it is kept only if it reaches ``min_points`` once the unassigned points within the
    threshold of it join (:func:`segment_planes`). Returns the labels with the new planes
    numbered after the existing ones."""
    free = np.flatnonzero(labels < 0)
    if len(free) < params.min_points:
        return labels
    k = max(6, params.k_neighbors // 3)
    normals, sigma, idx = local_geometry(xyz[free], k, frame=frame)
    regions = _grow_regions(xyz[free], normals, sigma, idx, eps, spacing, params.angle_deg)
    seed = replace(params, min_points=max(3, params.min_points // 2))
    sub, _, _ = _ransac_regions(xyz[free], regions, eps, seed)
    out = labels.copy()
    hit = sub >= 0
    out[free[hit]] = sub[hit] + (labels.max() + 1)
    return out


#: Largest standard error (degrees) of the tilt of a face recovered by :func:`_residual_faces`:
#: the roof-plane tilt goal of issue 26 (1 degree) as one standard deviation.
MAX_TILT_SE_DEG = 1.0


#: Significance level of the chi-square test of a recovered face's residuals (:func:`_residual_faces`).
PLANAR_LEVEL = 0.01


def pooled_noise(xyz, labels, normals, offsets, vertical: bool = False) -> float:
    """Noise sigma (m) along the normal, pooled over every plane's points: sqrt(RSS / (n - 3 p))
    with the three parameters of each plane taken out (the residuals of planes fitted by least
    squares; the local PCA figure of :func:`local_geometry` is biased low, being the smallest of
    three eigenvalues of small neighbourhoods). With ``vertical``, the noise along z: each
    residual over its plane's cosine of tilt (airborne ranging noise is about vertical, and a
    plane tilted by t sees sigma_z cos(t) of it along its normal), pooled over the roof planes
    only (no steeper than :data:`MAX_ROOF_TILT_DEG`): on a wall the cosine nears zero and the
    quotient grows without bound."""
    on = labels >= 0
    if vertical and on.any():
        on[on] = np.abs(normals[labels[on], 2]) >= math.cos(math.radians(MAX_ROOF_TILT_DEG))
    if not on.any():
        return float("nan")
    r = np.einsum("ij,ij->i", normals[labels[on]], xyz[on]) + offsets[labels[on]]
    if vertical:
        r = r / np.abs(normals[labels[on], 2])
    dof = on.sum() - 3 * len(np.unique(labels[on]))
    return float(np.sqrt(np.sum(r * r) / dof)) if dof > 0 else float("nan")


def tilt_standard_error(pts: np.ndarray, normal: np.ndarray, sigma: float) -> float:
    """Standard error (degrees) of the tilt of the least-squares plane of ``pts`` (m, 3) with
    unit ``normal`` (up), for noise ``sigma`` (m) along the normal: the first value of
    :func:`plane_standard_errors`.

    >>> xy = np.array([[x, y] for x in range(5) for y in range(4)], float)
    >>> round(tilt_standard_error(np.column_stack([xy, np.zeros(20)]), np.array([0.0, 0, 1]), 0.03), 3)
    0.272
    """
    return plane_standard_errors(pts, normal, sigma)[0]


def plane_standard_errors(pts: np.ndarray, normal: np.ndarray, sigma: float) -> tuple:
    """Standard errors (degrees) of the tilt and the azimuth of the least-squares plane of
    ``pts`` (m, 3) with unit ``normal`` (up), for noise ``sigma`` (m) along the normal. In the
    plane's own frame (e1 downslope, e2 level; for a level plane e1 along the points' largest
    spread) the fitted normal turns by a small vector (a, b) with covariance sigma^2 (P^T P)^-1,
    P the centred in-plane coordinates of the points. Its part a along e1 changes the tilt by a;
    its part b along e2 turns the normal's horizontal component, of length sin(tilt), about the
    vertical, so the azimuth by b / sin(tilt) (infinite for a level plane). Both are infinite
    for fewer than 4 points or points on a line.

    >>> xy = np.array([[x, y] for x in range(5) for y in range(5)], float)
    >>> t = np.radians(30.0)
    >>> pts, normal = np.column_stack([xy, xy[:, 1] * np.tan(t)]), np.array([0, -np.sin(t), np.cos(t)])
    >>> se = plane_standard_errors(pts, normal, 0.03)  # the downslope spread is 1 / cos(t) wider:
    >>> [round(x, 3) for x in se], round(float(se[1] * np.sin(t) * np.cos(t) / se[0]), 3)
    ([0.211, 0.486], 1.0)
    """
    if len(pts) < 4:
        return float("inf"), float("inf")
    c = pts - pts.mean(axis=0)
    down = np.array([0.0, 0.0, -1.0]) - normal * -normal[2]  # -z projected on the plane
    if np.linalg.norm(down) < 1e-9:  # level: the direction of the largest spread
        down = np.linalg.svd(c, full_matrices=False)[2][0]
    e1 = down / np.linalg.norm(down)
    e2 = np.cross(normal, e1)
    p = np.column_stack([c @ e1, c @ e2])
    ptp = p.T @ p
    if np.linalg.det(ptp) <= 1e-12 * np.trace(ptp) ** 2:
        return float("inf"), float("inf")
    cov = np.linalg.inv(ptp)
    sin_t = math.hypot(normal[0], normal[1])
    az = float(np.degrees(sigma * math.sqrt(cov[1, 1])) / sin_t) if sin_t > 1e-9 else float("inf")
    return float(np.degrees(sigma * math.sqrt(cov[0, 0]))), az


def _surface(xyz: np.ndarray, pts: np.ndarray, normal: np.ndarray, d: float, eps: float) -> bool:
    """Whether the plane (normal, d) of the points ``pts`` (m, 3) is a surface seen from above:
    of all points ``xyz`` (n, 3) inside the plan outline (convex hull) of ``pts``, more lie on
    it (within ``eps``) than off it. A roof face hides what is under it and carries little
    above it; a slab through a tree crown holds a minority of the crown's points."""
    import shapely

    hull = shapely.MultiPoint(pts[:, :2]).convex_hull
    x0, y0, x1, y1 = pts[:, 0].min(), pts[:, 1].min(), pts[:, 0].max(), pts[:, 1].max()
    near = np.flatnonzero((xyz[:, 0] >= x0) & (xyz[:, 0] <= x1) & (xyz[:, 1] >= y0) & (xyz[:, 1] <= y1))
    inside = near[shapely.contains_xy(hull, xyz[near, 0], xyz[near, 1])]  # only points in its box can be in it
    on = np.abs(xyz[inside] @ normal + d) < eps
    return bool(on.sum() > (~on).sum())


def _regular_tilt_se(xyz, labels, normals, offsets, members, nrm, d, sigma, reach) -> float:
    """Tilt standard error (degrees) of a proposed face (points ``members``, plane (nrm, d)) once
    regularised with the planes already found (``labels``, ``normals``, ``offsets``) by
    :func:`regularise_planes`: its azimuth fixed along the building's directions and its tilt
    shared with the other side of its ridge, where the Bayes factors favour them; inf when they
    do not (the face's own free fit then decides)."""
    trial = labels.copy()
    trial[members] = len(normals)
    _, _, se = regularise_planes(xyz, trial, np.vstack([normals, nrm]), np.r_[offsets, d], sigma, reach)
    return float(se[-1]) if np.isfinite(se[-1]) else float("inf")


def _proposals(pts, eps, sigma, params, rng):
    """Planes proposed for the points ``pts`` (m, 3) of one cluster of free points by sequential
    RANSAC (at most ``max_planes_per_region``, each of at least four points): each consensus set
    at ``eps`` is narrowed to the points within 3 sigma of its least-squares plane (twice
    refitted; sigma the vertical noise ``sigma`` times the plane's cosine of tilt) and taken out
    before the next draw. Returns (normals (k, 3), offsets (k,))."""
    normals, offsets = [], []
    rest = np.arange(len(pts))
    for _ in range(params.max_planes_per_region):
        if len(rest) < 4:
            break
        nrm, d, inl = ransac_plane(pts[rest], eps, params, rng)
        for _ in range(2 if nrm is not None else 0):  # the noise band of the fitted plane
            band = np.abs(pts[rest] @ nrm + d) < 3.0 * sigma * nrm[2]
            if band.sum() < 4:
                break
            inl = band
            nrm, d = fit_plane(pts[rest[inl]])
        if nrm is None or inl.sum() < 4:
            break
        normals.append(nrm)
        offsets.append(d)
        rest = rest[~inl]
    return np.array(normals).reshape(-1, 3), np.array(offsets, float)


def _reassign(pts, normals, offsets, band, rounds: int = 2):
    """Points ``pts`` (m, 3) given to the nearest of the planes (``normals`` (k, 3), ``offsets``
    (k,)) when within ``band`` (vertical, m: ``band`` times the plane's cosine of tilt along its
    normal; else -1), and the planes refitted to their points, ``rounds`` times: the assignment
    and re-estimation steps of multi-model fitting (Isack & Boykov 2012, PEARL, without the
    smoothness term). Sequential RANSAC gives a point within the band of two planes (near where
    two small faces meet, a dormer's ridge) to the plane drawn first, and on a face of 20 points
    the few such points of the other face turn its plane by degrees; the nearest plane once both
    are known is the better guess. A plane left with under four points in an assignment is
    dropped before its refit; the last assignment follows the last refit, so a plane may end
    with fewer than four points (the caller's tests reject it). Returns (labels (m,), normals,
    offsets)."""
    def nearest(normals, offsets):  # each point's nearest plane within the band, else -1
        r = np.abs(pts @ normals.T + offsets)
        best = np.argmin(r, axis=1)
        return np.where(r.min(axis=1) < band * normals[best, 2], best, -1)

    for _ in range(rounds):
        if not len(normals):
            break
        lab = nearest(normals, offsets)
        cnt = np.bincount(lab[lab >= 0], minlength=len(normals))
        keep = np.flatnonzero(cnt >= 4)
        fits = [fit_plane(pts[lab == q]) for q in keep]
        normals = np.array([f[0] for f in fits]).reshape(-1, 3)
        offsets = np.array([f[1] for f in fits], float)
    lab = nearest(normals, offsets) if len(normals) else np.full(len(pts), -1, np.int64)
    return lab, normals, offsets


def _residual_faces(xyz, labels, normals, offsets, idx, eps, params, spacing):
    """Faces too small for the count ``min_points`` among the points still on no plane (a dormer
    cheek of 1-3 m^2 has 10-30 points at 10 points/m^2), accepted on statistical grounds
    instead of a count. The free points are joined into clusters (two free points are linked
    when one is among the other's ``idx`` neighbours, the neighbourhoods of the normals);
    sequential RANSAC proposes planes in each (:func:`_proposals`), whose inliers are then the
    points within 3 sigma of the least-squares plane: the band ``eps`` also admits points of a
    neighbouring surface within the normals' angle tolerance over a spacing, which on a face of
    20 points fail the chi-square test below. The cluster's points then go to their nearest
    proposed plane (:func:`_reassign`), and each proposal, largest first, with n points becomes
    a face when

    * its tilt is determined to :data:`MAX_TILT_SE_DEG` (:func:`tilt_standard_error` at its
      noise sigma along the normal, which all the tests use: the vertical noise pooled over the
      planes found (:func:`pooled_noise`) times its cosine of tilt): the support needed follows
      from the noise, the spacing and the face's extent, not from a fixed count. A face whose
      free fit misses it may pass as the model will carry it: regularised with the planes found
      (:func:`_regular_tilt_se`, touching within three ``spacing``), its azimuth along the
      building's directions and its tilt shared with the other side of its ridge;
    * its points lie on it as the noise predicts: RSS_1 / sigma^2 is not in the upper
      :data:`PLANAR_LEVEL` tail of the chi-square law with n - 3 degrees of freedom (points
      scattered through the slab of half-width ``eps``, a tree crown, give about three times
      the sum of a plane's);
    * it is a surface (:func:`_surface`): most points inside its outline lie on it. A plane
      steeper than :data:`MAX_ROOF_TILT_DEG` is no roof face (the models take it for a wall)
      and has an outline too thin in plan for the test (a few scattered points, a bird or a
      wire, lie on some near-vertical plane);
    * it explains its points better than the planes already there, by the Bayesian information
      criterion for Gaussian residuals of known sigma: (RSS_0 - RSS_1) / sigma^2 > 3 ln n, with
      RSS_1 the squared residuals to the new plane (three parameters) and RSS_0 those to the
      nearest plane among each point's neighbours' planes (all planes where none has one).

    As in sequential RANSAC, a proposal that fails ends the search in its cluster (each test
    more among a cluster's leftovers is one more chance for a chance alignment to pass). Returns
    the labels with the new faces numbered after the existing planes, and (planes,) bool: the
    faces accepted only as regularised (their free tilt error over the rule)."""
    free = np.flatnonzero(labels < 0)
    sigma = pooled_noise(xyz, labels, normals, offsets, vertical=True)
    if len(free) < 4 or not len(normals) or not np.isfinite(sigma) or sigma <= 0:
        return labels, np.zeros(len(normals), bool)
    pos = np.full(len(xyz), -1, np.int64)
    pos[free] = np.arange(len(free))
    a, b = np.repeat(np.arange(len(free)), idx.shape[1] - 1), pos[idx[free, 1:]].ravel()
    comp = small_components(len(free), a[b >= 0], b[b >= 0])
    d_all = np.abs(xyz[free] @ normals.T + offsets)  # (u, p)
    cand = labels[idx[free]]
    near = np.where(cand >= 0, np.take_along_axis(d_all, np.maximum(cand, 0), axis=1), np.inf).min(axis=1)
    rss0 = np.where(np.isfinite(near), near, d_all.min(axis=1)) ** 2
    rng = np.random.default_rng(params.seed)
    out, known_n, known_d, promised = labels.copy(), normals, offsets, []
    order = np.argsort(comp, kind="stable")
    start = np.searchsorted(comp[order], np.arange(comp.max() + 2))
    for c in np.flatnonzero(np.diff(start) >= 4):
        members = order[start[c]:start[c + 1]]
        pts = xyz[free[members]]
        lab, pn, pd = _reassign(pts, *_proposals(pts, eps, sigma, params, rng), 3.0 * sigma)
        for q in np.argsort(-np.bincount(lab[lab >= 0], minlength=len(pn)), kind="stable"):
            on = lab == q
            loose = _accept_face(xyz, out, known_n, known_d, free[members[on]], pn[q], pd[q], rss0[members[on]],
                                 sigma * pn[q, 2], eps, spacing)
            if loose is None:  # the smaller proposals of the cluster are not tested
                break
            out[free[members[on]]] = len(known_n)  # the face's row in known_n
            promised.append(loose)
            known_n, known_d = np.vstack([known_n, pn[q]]), np.r_[known_d, pd[q]]
    return out, np.r_[np.zeros(len(normals), bool), np.array(promised, bool)]


def _accept_face(xyz, labels, normals, offsets, members, nrm, d, rss0, sigma, eps, spacing):
    """The tests of :func:`_residual_faces` for the proposed face of the points ``members`` (m,)
    on the plane (nrm, d) (up) among the planes found (``labels``, ``normals``, ``offsets``),
    ``rss0`` the squared residuals of its points to those planes, ``sigma`` its noise along the
    normal: None when rejected, else whether it passes only as regularised (its free tilt error
    over :data:`MAX_TILT_SE_DEG`)."""
    from scipy.stats import chi2

    pts = xyz[members]
    m = len(pts)
    if m < 4 or nrm[2] < math.cos(math.radians(MAX_ROOF_TILT_DEG)):
        return None
    rss1 = float(np.sum((pts @ nrm + d) ** 2))
    gain = (float(rss0.sum()) - rss1) / sigma ** 2
    if gain <= 3.0 * math.log(m) or chi2.sf(rss1 / sigma ** 2, m - 3) < PLANAR_LEVEL:
        return None
    loose = tilt_standard_error(pts, nrm, sigma) > MAX_TILT_SE_DEG
    reach = 3.0 * spacing
    if loose and _regular_tilt_se(xyz, labels, normals, offsets, members, nrm, d, sigma, reach) > MAX_TILT_SE_DEG:
        return None
    return loose if _surface(xyz, pts, nrm, d, eps) else None


#: Half-width, in noise sigmas, of the band within which a point is consistent with a plane (99.7 %
#: of Gaussian noise), used by :func:`settle_edges` to find the points that fit two planes.
EDGE_BAND_SIGMA = 3.0

#: Half-width, in noise sigmas, of the band around the intersection line of two planes inside
#: which :func:`settle_edges` cannot tell a point's face from the other (the planes are closer
#: than that to each other there): such points are left out of the planes' fits.
AMBIGUOUS_BAND_SIGMA = 2.0


def _two_nearest(xyz, cand, normals, offsets):
    """The two nearest of each point's candidate planes ``cand`` (u, k) (-1: none), distinct:
    (plane a (u,), |residual| to a, plane b (u,), |residual| to b), perpendicular residuals;
    b is -1 with an infinite residual where a point has one candidate only."""
    r = np.take_along_axis(np.abs(xyz @ normals.T + offsets), np.maximum(cand, 0), axis=1)
    r[cand < 0] = np.inf
    u = np.arange(len(xyz))
    k1 = np.argmin(r, axis=1)
    a, ra = cand[u, k1], r[u, k1]
    r[cand == a[:, None]] = np.inf
    k2 = np.argmin(r, axis=1)
    rb = r[u, k2]
    return a, ra, np.where(np.isfinite(rb), cand[u, k2], -1), rb


def _ridges(xyz, labels, normals, offsets) -> np.ndarray:
    """(p, p) bool: whether each pair of planes meets in a ridge (convex; each face the lower of the
    two planes on its side of their intersection line) rather than a valley (concave; the upper
    one), from the points ``xyz`` (u, 3) labelled ``labels`` (u,): with F[a, b] the share of a's
    points under plane b, a ridge when F[a, b] + F[b, a] > 1. Across a ridge each face lies
    wholly under the other plane (F = 1 both ways), across a valley wholly over it (F = 0); a
    large face that the line of a small one crosses (a main roof under a dormer) has a share in
    between, and the small face decides."""
    p = len(normals)
    with np.errstate(divide="ignore", invalid="ignore"):  # heights of every plane (u, p); a wall's are not finite
        z = -(xyz[:, :2] @ normals[:, :2].T + offsets) / normals[:, 2]
        under = z > z[np.arange(len(xyz)), labels][:, None]  # own plane under plane q at the point
    cnt = np.bincount(labels, minlength=p)
    share = np.bincount((labels[:, None] * p + np.arange(p)).ravel(), under.ravel(), minlength=p * p).reshape(p, p)
    share /= np.maximum(cnt, 1)[:, None]
    return share + share.T > 1.0


def _edge_labels(xyz, labels, cand, normals, offsets, sigma, eps, ridge):
    """New labels (u,) of points ``xyz`` (u, 3) labelled ``labels`` (u,) by the segmentation,
    given their candidate planes ``cand`` (u, k) (the planes of their neighbours); -1 for a point
    left out of the fits.

    A point within the segmentation's distance threshold ``eps`` of one candidate plane only
    belongs to that plane: one over :data:`EDGE_BAND_SIGMA` noise sigmas ``sigma`` from its own
    plane (perpendicular residual) and within that band of another moves there. A point within
    ``eps`` of two planes is one the segmentation could have given to either: it is near where
    they meet, and residuals at the noise level do not tell the faces apart, but the
    intersection line does: on a ridge each face is the lower of the two planes on its side of
    the line, in a valley the upper one (``ridge`` (p, p) bool of :func:`_ridges`). A point
    labelled with the plane that does not own its side leaves that plane (-1) rather than
    joining the other: the line runs on beyond the edge where the faces meet (past a dormer's
    ridge, below its cheeks), where its side says nothing of the point's face. Where the two
    planes are closer than
    :data:`AMBIGUOUS_BAND_SIGMA` sigmas to each other (a band around the line; their distance
    apart is the vertical gap times the smaller cosine of tilt) the point could be on either and
    gets -1, as does one whose own plane is neither of the two."""
    a, ra, b, rb = _two_nearest(xyz, cand, normals, offsets)
    band = EDGE_BAND_SIGMA * sigma
    r_own = np.abs(np.einsum("ij,ij->i", normals[labels], xyz) + offsets[labels])
    out = np.where((r_own > band) & (ra < band) & (rb >= eps), a, labels)
    both = np.flatnonzero(rb < eps)
    if not len(both):
        return out
    a2, b2, own = a[both], b[both], labels[both]
    xy = xyz[both, :2]
    with np.errstate(divide="ignore", invalid="ignore"):  # a wall has no height: never clear
        za = -(np.einsum("ij,ij->i", normals[a2, :2], xy) + offsets[a2]) / normals[a2, 2]
        zb = -(np.einsum("ij,ij->i", normals[b2, :2], xy) + offsets[b2]) / normals[b2, 2]
        clear = np.abs(za - zb) * np.minimum(normals[a2, 2], normals[b2, 2]) >= AMBIGUOUS_BAND_SIGMA * sigma
    other = np.where(own == a2, b2, a2)
    mine = (own == a2) | (own == b2)
    lower = np.where(own == a2, za < zb, zb < za)  # the point's own plane is the lower one there
    right_side = mine & (lower == ridge[own, other])
    out[both] = np.where(clear & right_side, own, -1)
    return out


def settle_edges(xyz, labels, normals, offsets, rms, counts, idx, eps, rounds: int = 2):
    """Points near the lines where planes meet (ridges, valleys, a dormer's edges) kept on their
    plane only where they belong to it, and the planes refitted, ``rounds`` times, as the refit
    step of region growing and RANSAC segmentations (Sampath & Shan 2010; Xu et al. 2015): the
    growing and the leftovers' assignment take a point into a plane when within the distance
    threshold ``eps``, which near an edge also holds for the other face's points, and on a face
    of 20-40 points a few such points turn the fitted plane by a degree or more.

    Each round labels again, by :func:`_edge_labels`, the labelled points of ``xyz`` (n, 3) with
    a neighbour (``idx`` (n, k)) on another plane (labels before this step), at the noise pooled
    over the planes (as :func:`pooled_noise`, from the planes' RMS ``rms`` (p,) and point
    ``counts`` (p,)) and with the planes' ridges and valleys of :func:`_ridges`. Each round
    starts from the segmentation's labels with the planes of the round before, so a point left
    out in one round may return in the next. A point that residuals put on another plane moves
    there (its face and its fit). The points near a line that are not clearly their plane's
    (ambiguous, or on the other face's side) are left out of the fit only: they keep their face,
    as the side of a line that runs on past the faces' common edge does not say which face a
    point is on. A plane that would keep under four points keeps its own.

    Returns (labels (n,), fitted (n,) bool, normals, offsets, rms, counts), the planes numbered
    as before: ``labels`` the face of each point, ``fitted`` the points each plane is fitted to,
    and ``rms`` and ``counts`` those of the fitted points."""
    p = len(normals)
    fitted = labels >= 0
    if p >= 2:
        on = np.flatnonzero(fitted)
        seg, cand = labels[on], labels[idx[on]]
        edge = ((cand >= 0) & (cand != seg[:, None])).any(axis=1)
        pts, cand, old = on[edge], cand[edge], labels[on[edge]]
        faces = labels
        xon = xyz[on]
        for _ in range(rounds if len(pts) else 0):
            dof = counts.sum() - 3 * np.count_nonzero(counts)  # pooled_noise from the planes' own rms
            sigma = math.sqrt(float(np.sum(rms * rms * counts)) / dof) if dof > 0 else 0.0
            if sigma <= 0:
                break
            ridge = _ridges(xon, seg, normals, offsets)
            new = _edge_labels(xyz[pts], old, cand, normals, offsets, sigma, eps, ridge)
            fit = labels.copy()
            fit[pts] = new
            few = np.bincount(fit[fit >= 0], minlength=p) < 4
            new = np.where(few[old], old, new)  # a plane left with under four points keeps its own
            fit[pts] = new
            faces = labels.copy()
            faces[pts] = np.where(new >= 0, new, old)
            fitted = fit >= 0
            g = grouped_plane_fit(xyz, fit, p)
            normals, offsets, rms, counts = g.normals, g.offsets, g.rms, g.counts
        labels = faces
    return labels, fitted, normals, offsets, rms, counts


#: Tilt (degrees) below which a roof plane counts as flat (drainage slopes are a few degrees):
#: the models' flat roofs (:mod:`workstation.buildings.models`) and the tilt from which a
#: plane's azimuth is regularised (below it a face has no direction worth a constraint).
FLAT_TILT_DEG = 5.0
REGULAR_MIN_TILT_DEG = FLAT_TILT_DEG

#: Steepest roof plane (degrees; the default of ``models.ModelParams.max_roof_tilt_deg``, steeper
#: planes are walls).
MAX_ROOF_TILT_DEG = 70.0

#: Range (degrees) of a free plane's azimuth modulo a quarter turn, and of a free roof plane's
#: tilt (up to :data:`MAX_ROOF_TILT_DEG`): the widths of the uniform priors of the free
#: parameters in the Bayes factors of :func:`regularise_planes`.
AZIMUTH_RANGE_DEG = 90.0
TILT_RANGE_DEG = MAX_ROOF_TILT_DEG


def plane_moments(xyz: np.ndarray, labels: np.ndarray, normals: np.ndarray):
    """Centroids (p, 3), unit downslope in-plane directions e1 (p, 3), level in-plane directions
    e2 (p, 3), second moments M (p, 2, 2) = sum of [p1 p2]^T [p1 p2] over each plane's points,
    p1 and p2 their centred coordinates along e1 and e2 (a level plane takes e1 along x), and the
    scatter matrices S (p, 3, 3), the sums of the centred coordinates' outer products
    (:func:`workstation.core.pca.group_moments` times the counts): M = E^T S E with E = [e1 e2]."""
    p = len(normals)
    on = labels >= 0
    cnt, cen, cov = group_moments(xyz[on], labels[on], p)
    s = cov * cnt[:, None, None]
    h = np.hypot(normals[:, 0], normals[:, 1])
    d = np.where(h[:, None] > 1e-12, normals[:, :2] / np.maximum(h, 1e-300)[:, None], [1.0, 0.0])
    e1 = np.column_stack([d * normals[:, 2:3], -h])  # (cos t d, -sin t): along the plane, downhill
    e2 = np.cross(normals, e1)
    e = np.stack([e1, e2], axis=2)  # (p, 3, 2)
    return cen, e1, e2, np.einsum("pia,pij,pjb->pab", e, s, e), s


def log_bayes_equal(x: np.ndarray, var: np.ndarray, group: np.ndarray, width: float) -> np.ndarray:
    """Log Bayes factor, per group, of "the values of the group are one value" against "each is
    free": estimates ``x`` (k,) with Gaussian variances ``var``, each free value and the common one
    uniform over a range ``width`` (same units), groups numbered ``group`` (k,) from 0. With the
    weighted mean m, its variance V = 1 / sum(1 / var) and chi^2 = sum((x - m)^2 / var):
    ln B = (k - 1) ln(width) + ln(2 pi V) / 2 - sum(ln(2 pi var)) / 2 - chi^2 / 2 (Jeffreys 1961,
    ch. 5: the nested model wins when B > 1). A value taken as known (variance 0 is not allowed;
    pass its own variance) counts as a member of the group.

    >>> round(float(log_bayes_equal(np.array([0.0, 1.0]), np.array([0.5, 0.5]), np.array([0, 0]), 90.0)[0]), 3)
    3.081
    """
    w = 1.0 / var
    sw = np.bincount(group, w)
    m = np.bincount(group, w * x) / sw
    chi = np.bincount(group, w * (x - m[group]) ** 2)
    k = np.bincount(group)
    return ((k - 1) * math.log(width) + 0.5 * np.log(2 * math.pi / sw) - 0.5 * np.bincount(group, np.log(2 * math.pi * var))
            - 0.5 * chi)


def _along(az: np.ndarray, var: np.ndarray, theta, v0) -> np.ndarray:
    """Whether each azimuth (degrees, variance ``var``) is better explained as the direction
    ``theta`` (variance ``v0``; scalars or one per azimuth) or a quarter turn of it than as free
    over a quarter turn: the Bayes factor of :func:`log_bayes_equal` for the two values."""
    tot = var + v0
    r = (az - theta + 45.0) % 90.0 - 45.0
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.isfinite(tot) & (math.log(AZIMUTH_RANGE_DEG) - 0.5 * np.log(2 * math.pi * tot) - 0.5 * r * r / tot > 0)


def _agreeing(az: np.ndarray, w: np.ndarray, var: np.ndarray, use: np.ndarray, ref: float) -> np.ndarray:
    """The planes whose azimuth agrees (:func:`_along`) with the weighted mean direction of the
    *other* planes of ``use`` (weights ``w`` = 1 / ``var``): for a member i the leave-one-out mean
    ref + (sum(w r) - w_i r_i) / (W - w_i), of variance 1 / (W - w_i), with r the azimuths'
    offsets from ``ref`` within a quarter turn and W = sum(w) over ``use``; for a non-member the
    mean of all of ``use``. A plane thus never agrees with a direction taken from itself alone."""
    r = (az - ref + 45.0) % 90.0 - 45.0
    wu = np.where(use, w, 0.0)
    others = ~np.eye(len(az), dtype=bool)
    sw = others @ wu  # W - w_i for members, W for the rest (exact: no subtraction)
    swr = others @ (wu * r)
    with np.errstate(divide="ignore", invalid="ignore"):
        theta, v = ref + swr / sw, 1.0 / sw
    return (sw > 0) & _along(az, var, theta, v)


def dominant_direction(az: np.ndarray, var: np.ndarray):
    """The building's dominant direction (degrees, 0-90) from plane azimuths ``az`` (degrees) with
    variances ``var`` (degrees^2, inf for none): the inverse-variance weighted mean of the azimuths
    modulo 90 degrees (a rectilinear building's faces look along one direction and its quarter
    turns) over a set of planes each of which agrees with the mean of the others
    (:func:`_agreeing`), so at least two planes. Each plane seeds a set (itself and the planes
    agreeing with it), refined by the leave-one-out test until it is stable; the set of the
    largest total weight wins. Returns (direction, its variance, set (p,) bool), the direction
    the mean of that set; NaN, NaN and an empty set when no two planes agree."""
    ok = np.isfinite(var)
    best, best_w = np.zeros(len(az), bool), 0.0
    w = np.where(ok, 1.0 / np.where(ok, var, 1.0), 0.0)
    seen = np.zeros(len(az), bool)
    for s in np.flatnonzero(ok)[np.argsort(var[ok], kind="stable")]:
        if seen[s]:  # already in a stable set: it would seed the same one
            continue
        use = _along(az, var, az[s], var[s])
        for _ in range(len(az) + 1):
            new = _agreeing(az, w, var, use, float(az[s]))
            if np.array_equal(new, use) or not new.any():
                use = new
                break
            use = new
        seen |= use
        if use.sum() >= 2 and w[use].sum() > best_w:
            best, best_w = use, float(w[use].sum())
    if best.sum() < 2:
        return float("nan"), float("nan"), np.zeros(len(az), bool)
    ref = float(az[best][np.argmax(w[best])])
    r = (az[best] - ref + 45.0) % 90.0 - 45.0
    return float((ref + np.sum(w[best] * r) / best_w) % 90.0), 1.0 / best_w, best


def _line_scatter(s: np.ndarray, down: np.ndarray) -> np.ndarray:
    """(p, 2, 2) scatter of each plane's centred points in (w, z), w the horizontal coordinate
    along its unit horizontal direction ``down`` (p, 2), from the planes' scatter matrices ``s``
    (p, 3, 3) of :func:`plane_moments`: what a plane containing the level direction across
    ``down`` is fitted to."""
    e = np.zeros((len(down), 3, 2))
    e[:, :2, 0], e[:, 2, 1] = down, 1.0
    return np.einsum("pia,pij,pjb->pab", e, s, e)


def _line_fits(scatter, down, groups):
    """Planes through each plane's centroid containing the level direction across ``down``
    (p, 2), one tilt per group (``groups`` (p,), the group's lowest plane): the total
    least-squares line of the group's pooled (w, z) scatters (:func:`_line_scatter`). Returns
    normals (p, 3), tilts (p,) (radians) and the sums of squared downslope coordinates (p,)."""
    pooled = np.zeros_like(scatter)
    np.add.at(pooled, groups, scatter)
    vals, vecs = np.linalg.eigh(pooled[groups])
    v = vecs[:, :, 0] * np.where(vecs[:, 1:2, 0] < 0, -1.0, 1.0)  # smallest: (sin t, cos t), up
    return np.column_stack([v[:, :1] * down, v[:, 1]]), np.arctan2(v[:, 0], v[:, 1]), vals[:, 1]


def _touching(xyz: np.ndarray, labels: np.ndarray, pairs: np.ndarray, reach: float) -> np.ndarray:
    """(pairs,) bool: whether a point of each pair's first plane lies within ``reach`` (m) of a
    point of its second (the planes meet, as the two sides of a ridge do)."""
    from scipy.spatial import cKDTree

    trees = {q: cKDTree(xyz[labels == q]) for q in np.unique(pairs[:, 0])}
    return np.array([bool(np.isfinite(trees[a].query(xyz[labels == b], distance_upper_bound=reach)[0]).any())
                     for a, b in pairs], bool)


def _ridge_pairs_along(xyz, labels, az, var, dominant, sloped, theta, v0, reach) -> np.ndarray:
    """(p,) azimuths (degrees) of the planes of a pair that together agree with the direction
    ``theta`` (variance ``v0``, the mean of the planes ``dominant`` of :func:`dominant_direction`)
    though one of them did not alone; NaN for the other planes. A pair is two ``sloped`` planes,
    at least one of them not ``dominant``, whose points touch (within ``reach``,
    :func:`_touching`) and whose azimuths ``az`` (variances ``var``) are opposite by the Bayes
    factor of :func:`log_bayes_equal` (the other's azimuth free over a full turn otherwise): the
    two sides of a level ridge, whose normals' horizontal parts are opposite (Zhou & Neumann
    2012's symmetric planes). Their common direction, the inverse-variance mean m, is then tested
    by :func:`_along` against the dominant direction without the pair's dominant plane, if any
    (the leave-one-out mean of :func:`_agreeing`), so the points of both decide where one narrow
    face's alone are too few. The first plane of the pair faces m, the second m + 180 degrees
    (of a plane in several pairs, the pair of the largest weight decides); the quarter turn a
    plane snaps to follows from that direction, not from its own azimuth, which may be far off
    (a face of large variance is opposite its partner's within it)."""
    p = len(az)
    out = np.full(p, np.nan)
    i, j = np.triu_indices(p, 1)
    pair = sloped[i] & sloped[j] & ~(dominant[i] & dominant[j])
    i, j = i[pair], j[pair]
    if not len(i):
        return out
    r = (az[j] - az[i]) % 360.0 - 180.0  # j's offset from the opposite of i
    opposite = log_bayes_equal(np.r_[np.zeros(len(i)), r], np.r_[var[i], var[j]], np.tile(np.arange(len(i)), 2),
                               4.0 * AZIMUTH_RANGE_DEG) > 0
    i, j, r = i[opposite], j[opposite], r[opposite]
    if len(i):
        touch = _touching(xyz, labels, np.column_stack([i, j]), reach)
        i, j, r = i[touch], j[touch], r[touch]
    w = 1.0 / var[i] + 1.0 / var[j]
    m = az[i] + r / var[j] / w
    # the dominant mean without the pair's dominant plane d: theta is the weighted mean of the
    # set's offsets from it (their sum is 0), so leaving d out moves it by -w_d r_d / (1/v0 - w_d)
    d = np.where(dominant[i], i, j)
    wd = np.where(dominant[d], 1.0 / var[d], 0.0)
    rd = (az[d] - theta + 45.0) % 90.0 - 45.0
    ok = _along(m, 1.0 / w, theta - wd * rd / (1.0 / v0 - wd), 1.0 / (1.0 / v0 - wd))
    faces, facing, ws = np.r_[i[ok], j[ok]], np.r_[m[ok], m[ok] + 180.0] % 360.0, np.r_[w[ok], w[ok]]
    order = np.lexsort((-ws, faces))
    first = np.unique(faces[order], return_index=True)[1]
    out[faces[order][first]] = facing[order][first]
    return out


def regularise_planes(xyz: np.ndarray, labels: np.ndarray, normals: np.ndarray, offsets: np.ndarray, sigma: float,
                      reach: float, force: np.ndarray | None = None):
    """Roof planes of one building refitted under the regularities of buildings (Zhou & Neumann
    2012, "global regularities"; geoflow's orthogonal rules), each imposed where the Bayes factor
    of the constrained against the free plane (:func:`log_bayes_equal`, free parameters uniform
    over :data:`AZIMUTH_RANGE_DEG` and :data:`TILT_RANGE_DEG`) favours it:

    * azimuth: the fitted normal of a plane of points ``xyz`` (n, 3) turns by a small vector with
      covariance sigma^2 M^-1 (:func:`plane_moments`, noise ``sigma`` (m) along the normal), whose
      level component over sin(tilt) is the azimuth's error. Planes of at least
      :data:`REGULAR_MIN_TILT_DEG` whose azimuth agrees with the building's dominant direction
      (:func:`dominant_direction`) or a quarter turn of it take that azimuth and are refitted with
      it fixed (a line fit in the vertical plane along it); so do the two planes of a level ridge
      (touching, azimuths opposite) whose mean azimuth agrees though one of them alone does not
      (:func:`_ridge_pairs_along`), the quarter turn of such a plane the one its pair's mean
      (or its opposite) gives;
    * tilt: two such planes facing opposite ways whose points touch (within ``reach`` (m): the two
      sides of a gable or a dormer) and whose constrained tilts (variance sigma^2 over the sum of
      squared downslope coordinates) agree share one tilt, fitted to the pooled points of both;
      chains of such pairs are pooled when the Bayes factor of the whole chain favours it.

    Planes marked in ``force`` (p,) bool (small faces accepted because they would be regularised,
    :attr:`RoofPlanes.regular`) take the building's direction and pool their tilt with a touching
    opposite face without the Bayes factors (with the mean of their own azimuths when no two other
    planes agree).

    ``labels`` (n,) index ``normals`` (p, 3, up) and ``offsets`` (p,) (n . x + d = 0). Returns
    (normals, offsets, tilt standard error (p,) in degrees of the constrained planes, NaN for
    planes left free)."""
    p = len(normals)
    se = np.full(p, np.nan)
    sin_t = np.hypot(normals[:, 0], normals[:, 1])
    if not (sin_t >= math.sin(math.radians(REGULAR_MIN_TILT_DEG))).any() or not np.isfinite(sigma) or sigma <= 0:
        return normals, offsets, se
    cen, _, _, m, smat = plane_moments(xyz, labels, normals)
    det = m[:, 0, 0] * m[:, 1, 1] - m[:, 0, 1] ** 2
    sloped = (np.degrees(np.arcsin(np.minimum(sin_t, 1.0))) >= REGULAR_MIN_TILT_DEG)
    sloped &= (np.bincount(labels[labels >= 0], minlength=p) >= 4) & (det > 1e-12 * (m[:, 0, 0] + m[:, 1, 1]) ** 2)
    var_az = np.full(p, np.inf)
    var_az[sloped] = np.degrees(sigma) ** 2 * m[sloped, 0, 0] / det[sloped] / sin_t[sloped] ** 2
    az = azimuth_of(normals)
    theta, v0, snap = dominant_direction(az, var_az)
    if np.isfinite(theta):  # a face refused alone may agree as half of a level ridge
        paired = _ridge_pairs_along(xyz, labels, az, var_az, snap, sloped, theta, v0, reach)
        az = np.where(np.isfinite(paired) & ~snap, paired, az)  # facing its ridge pair's direction
        snap |= np.isfinite(paired)
    force = np.zeros(p, bool) if force is None else np.asarray(force, bool) & sloped
    if not snap.any() and force.any():  # no two other planes agree: the forced planes' own mean
        w, ref = 1.0 / var_az[force], float(az[force][np.argmin(var_az[force])])
        theta = float((ref + np.sum(w * ((az[force] - ref + 45.0) % 90.0 - 45.0)) / np.sum(w)) % 90.0)
    snap |= force & np.isfinite(theta)
    if not snap.any():
        return normals, offsets, se
    k = np.round((az - theta) / 90.0).astype(np.int64) % 4
    a = np.radians(theta + 90.0 * k)
    down = np.column_stack([np.sin(a), np.cos(a)])
    scatter = _line_scatter(smat, down)
    n1, t1, l1 = _line_fits(scatter, down, np.arange(p))
    t1, vt = np.degrees(t1), np.ones(p)  # planes left free are alone in their group: any variance
    vt[snap] = np.degrees(sigma) ** 2 / l1[snap]  # sloped, so l1 > 0
    i, j = np.triu_indices(p, 1)
    pair = snap[i] & snap[j] & ((k[i] - k[j]) % 4 == 2)
    i, j = i[pair], j[pair]
    if len(i):
        b = log_bayes_equal(np.r_[t1[i], t1[j]], np.r_[vt[i], vt[j]], np.tile(np.arange(len(i)), 2), TILT_RANGE_DEG)
        i, j = i[(b > 0) | force[i] | force[j]], j[(b > 0) | force[i] | force[j]]
    if len(i):
        touch = _touching(xyz, labels, np.column_stack([i, j]), reach)
        i, j = i[touch], j[touch]
    comp = small_components(p, i, j)
    good = log_bayes_equal(t1, vt, comp, TILT_RANGE_DEG) >= 0  # a single plane: ln B = 0
    good |= np.bincount(comp, force, minlength=len(good)) > 0
    first = np.full(len(good), p)
    np.minimum.at(first, comp, np.arange(p))
    groups = np.where(good[comp], first[comp], np.arange(p))
    n2, _, l2 = _line_fits(scatter, down, groups)
    normals = np.where(snap[:, None], n2, normals)
    offsets = np.where(snap, -np.einsum("ij,ij->i", normals, cen), offsets)
    se[snap] = np.degrees(sigma / np.sqrt(l2[snap]))
    return normals, offsets, se


def _spans_area(xy: np.ndarray) -> bool:
    """Whether plan points (n, 2) spread over an area: the smaller eigenvalue of their
    covariance above 1e-12 of the larger (false for one spot and for points on a line)."""
    w = np.linalg.eigvalsh(np.cov(xy, rowvar=False))
    return bool(w[0] > 1e-12 * w[1])


def _no_planes(n: int, origin: np.ndarray, noise, spacing, params: PlaneParams) -> RoofPlanes:
    """The result with no plane: every one of the ``n`` points unlabelled and unfitted. An
    unknown (None) noise or spacing is NaN, and then so is the threshold."""
    noise = math.nan if noise is None else float(noise)
    spacing = math.nan if spacing is None else float(spacing)
    return RoofPlanes(np.full(n, -1, np.int64), np.zeros((0, 3)), np.zeros(0), origin, np.zeros(0),
                      np.zeros(0, np.int64), distance_threshold(noise, spacing, params.angle_deg), noise,
                      spacing, params.angle_deg, np.zeros(0, bool), np.zeros(n, bool))


def segment_planes(xyz: np.ndarray, params: PlaneParams = PlaneParams()) -> RoofPlanes:
    """Planes of a cloud of roof points (n, 3) (m) by region growing, RANSAC and merging.

    A cloud of fewer than max(``min_points``, 9) points, one on no area in plan (a spot, a
    line) or one without a planar neighbourhood (clutter) has no plane: every point is
    unlabelled, and the noise (and threshold) not estimated is NaN.

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> xy = rng.uniform(0, 10, (2000, 2))
    >>> z = np.where(xy[:, 1] < 5, 0.5 * xy[:, 1], 5 - 0.5 * (xy[:, 1] - 5)) + rng.normal(0, 0.02, 2000)
    >>> r = segment_planes(np.column_stack([xy, z]))
    >>> len(r.normals), sorted(np.round(r.tilt_deg).astype(int).tolist())
    (2, [27, 27])
    """
    xyz = np.asarray(xyz, float)
    if xyz.ndim != 2 or xyz.shape[1] != 3 or len(xyz) < 3:
        raise InvalidInputError("plane segmentation needs an (n, 3) array of at least 3 points", field="xyz")
    origin = xyz.min(axis=0)
    loc = xyz - origin
    if len(loc) < max(params.min_points, 9) or not _spans_area(loc[:, :2]):
        # scan_frame needs 8 neighbours per point, a plane min_points points, and a roof plane
        # points spread over an area in plan (not one spot or a line): no noise or spacing to
        # estimate, so they are NaN unless given
        return _no_planes(len(loc), origin, params.noise, params.spacing, params)
    frame = scan_frame(loc[:, :2])
    normals, sigma, idx = local_geometry(loc, params.k_neighbors, frame=frame)
    spacing = params.spacing
    if spacing is None:  # the across-line spacing bounds how far neighbours may be
        spacing = frame[2] if frame[2] > frame[1] else float(np.median(np.linalg.norm(loc[idx[:, 1]] - loc, axis=1)))
    finite = np.isfinite(sigma)
    if params.noise is None and not finite.any():
        # no neighbourhood is planar (clutter): no plane can be grown, and the noise, the
        # median planar residual, is undefined (NaN)
        return _no_planes(len(loc), origin, None, spacing, params)
    noise = params.noise if params.noise is not None else float(np.median(sigma[finite]))
    eps = distance_threshold(noise, spacing, params.angle_deg)
    regions = _grow_regions(loc, normals, sigma, idx, eps, spacing, params.angle_deg)
    labels, pn, pd = _ransac_regions(loc, regions, eps, params)
    labels = _merge_coplanar(loc, labels, pn, pd, idx, eps, params.angle_deg)
    labels, pn, pd, _, _ = _refit(loc, labels, params.min_points)
    labels = _assign_leftovers(loc, labels, pn, pd, idx, eps)
    fine = _fine_pass(loc, labels, eps, spacing, frame, params)
    if fine.max(initial=-1) > labels.max(initial=-1):
        # the fine planes' seeds may be smaller; with their neighbours within eps they must reach min_points
        labels, pn, pd, _, _ = _refit(loc, fine, max(3, params.min_points // 2))
        labels = _assign_leftovers(loc, labels, pn, pd, idx, eps)
    labels, pn, pd, _, _ = _refit(loc, labels, params.min_points)
    # pieces of one plane split by a gap of unassigned points touch only now
    labels = _merge_coplanar(loc, labels, pn, pd, idx, eps, params.angle_deg)
    labels, pn, pd, rmse, counts = _refit(loc, labels, params.min_points)
    small, promised = _residual_faces(loc, labels, pn, pd, idx, eps, params, spacing)
    regular = np.zeros(len(pn), bool)
    if small.max(initial=-1) > labels.max(initial=-1):  # faces accepted by test, not by count
        labels, pn, pd, _, _ = _refit(loc, small, 3)
        labels = _assign_leftovers(loc, labels, pn, pd, idx, eps)
        labels = _merge_coplanar(loc, labels, pn, pd, idx, eps, params.angle_deg)
        labels, pn, pd, rmse, counts = _refit(loc, labels, 3)
        # a final plane is such a face when most of its points come from one
        on = (labels >= 0) & (small >= 0)
        votes = np.bincount(labels[on], promised[small[on]], minlength=len(pn))
        regular = votes > 0.5 * np.maximum(counts, 1)
    labels, fitted, pn, pd, rmse, counts = settle_edges(loc, labels, pn, pd, rmse, counts, idx, eps)
    return RoofPlanes(labels, pn, pd, origin, rmse, counts, eps, noise, spacing, params.angle_deg, regular, fitted)
