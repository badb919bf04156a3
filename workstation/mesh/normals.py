"""Normal estimation and orientation for point clouds (MeshLab ``compute_normal_for_point_clouds``).

Normals are fitted by PCA of the k nearest neighbours (Hoppe et al., "Surface reconstruction
from unorganized points", SIGGRAPH 1992). Their sign is then chosen, in order of preference:
toward the scanner or camera that saw each point when those positions are known (the only
choice that is right on thin and multi-sided objects), straight up for terrain, or by
MeshLab's propagation over the neighbour graph (Hoppe's minimum-spanning-tree orientation).

Scan lines (airborne, terrestrial and mobile strips: points close along each line, lines far
apart) give neighbourhoods of k points that all lie on one line; their plane is undetermined
about the line. Those points (and only those) get their normals from neighbourhoods widened
until they span more than one line (:func:`widen_collinear`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, StageError
from workstation.core.log import get_logger
from workstation.core.products import Reconstruction

from .steps import StepRecord, Timer, import_pymeshlab

log = get_logger(__name__)

ORIENTATIONS = ("auto", "viewpoint", "up", "propagate", "keep")

#: A neighbourhood is one line of points when its spread across (the second principal
#: standard deviation) is below this many steps along it, the step being that of its k points
#: spread evenly over its length (from λ1, see :func:`widen_collinear`). Noise across a line
#: spreads it by the noise's standard deviation, so lines are found while that is under half
#: their step. A neighbourhood split between two parallel rows a gap g apart, a fraction p of
#: its points on one, spreads across by g·sqrt(p(1 − p)): g/2 for an even split,
#: g·sqrt(k − 1)/k with one of its k points on the second row. So with k = 10 one point on a
#: row 1.5 to 2 steps away (by where along it lies) already ends the line, and so do two rows
#: evenly split 0.55 of their own step apart; a patch of surface spreads across about as far
#: as along and is never one.
LINE_WIDTH_IN_STEPS = 0.5


@dataclass(frozen=True)
class NormalParams:
    """Parameters of normal estimation.

    Attributes
    ----------
    k : int
        Neighbours used for each PCA plane fit (count).
    smooth_iterations : int
        Passes of MeshLab's neighbour averaging of the normals after the fit (count; 0 =
        none). The normals that :func:`widen_collinear` refits replace smoothed ones and are
        not smoothed themselves: their neighbourhoods are already 2 to 16 times as wide.
    orient : {"auto", "viewpoint", "up", "propagate", "keep"}
        How signs are chosen: ``viewpoint`` toward the given scanner/camera positions, ``up``
        with a positive Z component (terrain, aerial scans), ``propagate`` consistently over
        the neighbour graph, ``keep`` leave the fitted sign. ``auto`` = ``viewpoint`` when
        positions are given, else ``propagate``.
    recompute : bool
        Re-estimate even when the cloud already carries ``normal``.
    """

    k: int = 10
    smooth_iterations: int = 0
    orient: str = "auto"
    recompute: bool = False

    def __post_init__(self):
        if self.k < 3:
            raise InvalidInputError(f"k={self.k}: a plane fit needs at least 3 neighbours", field="k")
        if self.orient not in ORIENTATIONS:
            raise InvalidInputError(f"unknown orientation '{self.orient}'", "use one of " + ", ".join(ORIENTATIONS),
                                    field="orient")


def viewpoints_from_reconstruction(cloud: Cloud, rec: Reconstruction) -> np.ndarray:
    """Per-point viewpoint (n, 3): the centre of the nearest camera of ``rec``.

    A point seen by a camera lies in front of it, so the nearest camera centre is on the
    visible side of the surface for all but grazing views.
    """
    from scipy.spatial import cKDTree

    centres = np.array([np.asarray(im.pose.center, dtype=np.float64) for im in rec.images.values()])
    if centres.size == 0:
        raise InvalidInputError("the reconstruction has no oriented images", field="images")
    _, idx = cKDTree(centres).query(cloud.xyz)
    return centres[idx]


def orient_toward(xyz: np.ndarray, normals: np.ndarray, viewpoints: np.ndarray) -> np.ndarray:
    """Flip normals (n, 3) so each points toward its viewpoint ((3,) or (n, 3)), vectorised."""
    vp = np.broadcast_to(np.asarray(viewpoints, dtype=np.float64), xyz.shape)
    s = np.einsum("ij,ij->i", normals, vp - xyz)
    return np.where((s < 0)[:, None], -normals, normals)


def estimate_normals(cloud: Cloud, params: NormalParams = NormalParams(), viewpoints=None) -> tuple[Cloud, StepRecord]:
    """Estimate (or reuse) and orient per-point normals.

    Parameters
    ----------
    cloud : Cloud
    params : NormalParams
    viewpoints : (3,) or (n, 3) float, or Reconstruction, optional
        Scanner position(s) or cameras, in the cloud's coordinates. One position for a single
        scan, one per point for merged scans (e.g. looked up from ``point_source_id``).

    Returns
    -------
    (Cloud, StepRecord)
        A new cloud with ``normal`` (n, 3) float32 unit vectors; the input is unchanged. The
        record's summary counts ``points_widened`` (normals refitted on widened
        neighbourhoods) and ``points_unresolved`` (still on one line at the widest, so MeshLab's
        normal is kept; see :func:`widen_collinear`).
    """
    if cloud.n < params.k + 1:
        raise InvalidInputError(f"{cloud.n} points: too few for normals with k={params.k}")
    if isinstance(viewpoints, Reconstruction):
        viewpoints = viewpoints_from_reconstruction(cloud, viewpoints)
    if viewpoints is not None:
        viewpoints = np.asarray(viewpoints, dtype=np.float64)
        if viewpoints.shape not in ((3,), (cloud.n, 3)):
            raise InvalidInputError(f"viewpoints must be (3,) or ({cloud.n}, 3), got {viewpoints.shape}",
                                    field="viewpoints")
    orient = params.orient
    if orient == "auto":
        orient = "viewpoint" if viewpoints is not None else "propagate"
    if orient == "viewpoint" and viewpoints is None:
        raise InvalidInputError("orientation 'viewpoint' needs scanner or camera positions",
                                "pass viewpoints, or use orient='propagate' or 'up'", field="orient")
    with Timer() as t:
        reused = "normal" in cloud.attrs and not params.recompute
        if reused:
            n = np.asarray(cloud.attrs["normal"], dtype=np.float64)
        else:
            pml = import_pymeshlab()
            from workstation.interop.pymeshlab import cloud_to_pymeshlab, meshset_with

            m, origin = cloud_to_pymeshlab(cloud.without_attrs(*[a for a in ("normal", "rgb") if a in cloud.attrs]))
            ms = meshset_with(m)
            # MeshLab orients by propagation over the kNN graph unless a view position is given.
            ms.compute_normal_for_point_clouds(k=int(params.k), smoothiter=int(params.smooth_iterations),
                                               flipflag=False, viewpos=np.zeros(3))
            n = np.asarray(ms.current_mesh().vertex_normal_matrix(), dtype=np.float64)
            del pml
        norm = np.linalg.norm(n, axis=1)
        if n.shape != (cloud.n, 3) or not np.all(np.isfinite(n)) or np.any(norm < 1e-12):
            raise StageError("normals", "normal estimation failed for some points",
                             "remove duplicate points or raise k")
        n = n / norm[:, None]
        widened = unresolved = 0
        if not reused:
            n, widened, unresolved = _fix_collinear(cloud.xyz, n, params.k,
                                                    propagate=orient in ("propagate", "keep"))
        if orient == "viewpoint":
            n = orient_toward(cloud.xyz, n, viewpoints)
        elif orient == "up":
            n = np.where((n[:, 2] < 0)[:, None], -n, n)
        elif reused and orient == "propagate":
            orient = "keep"  # given normals are taken as oriented
    rec = StepRecord("normals", {"k": params.k, "smooth_iterations": params.smooth_iterations, "orient": orient,
                                 "reused_existing": bool(reused)}, t.seconds,
                     {"points_widened": int(widened), "points_unresolved": int(unresolved)})
    out = cloud.with_attrs(normal=n.astype(np.float32)).with_history("mesh.normals", rec.params, t.seconds)
    return out, rec


def _fix_collinear(xyz: np.ndarray, n: np.ndarray, k: int, propagate: bool) -> tuple[np.ndarray, int, int]:
    """Replace the normals (n, 3) of the points whose k neighbours lie on one line by
    :func:`widen_collinear`'s; with ``propagate``, orient those and the unresolved ones (whose
    MeshLab normal is kept) over their widened neighbour graph from the others
    (:func:`orient_from_anchors`). Returns the normals and the counts widened and unresolved;
    the input comes back unchanged (the same array) when there are neither."""
    idx, fit, rows, cols, unresolved = widen_collinear(xyz, k)
    if idx.size == 0 and unresolved.size == 0:
        return n, 0, 0
    out = n.copy()
    out[idx] = fit
    if propagate:
        anchored = np.ones(len(out), dtype=bool)
        anchored[idx], anchored[unresolved] = False, False
        out = orient_from_anchors(out, anchored, rows, cols)
    return out, int(idx.size), int(unresolved.size)


def _pca_block(tree, pts: np.ndarray, q: np.ndarray, kk: int, k: int = 0,
               chunk: int = 1 << 20) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """PCA of the kk nearest points of ``pts`` (``tree``) to each query point of ``q`` (m, 3):
    eigenvalues (m, 3) ascending, then, if ``k``, the unit normal (m, 3) (smallest-eigenvalue
    axis) and k of the neighbours (m, k), every (kk // k)-th by distance so that they reach
    across the whole neighbourhood (else two empty arrays); indices are int32 (int64 past 2³¹
    points). Queries run in blocks of about ``chunk`` neighbours."""
    m = len(q) if k else 0
    itype = np.int32 if len(pts) < 2 ** 31 else np.int64
    lam, nrm, nbr = np.empty((len(q), 3)), np.empty((m, 3)), np.empty((m, k), dtype=itype)
    step = max(1, chunk // kk)
    for s in range(0, len(q), step):
        _, ii = tree.query(q[s:s + step], kk)
        nb = pts[ii]
        nb -= nb.mean(axis=1, keepdims=True)
        cov = np.matmul(nb.transpose(0, 2, 1), nb) / kk
        if k:
            lam[s:s + step], v = np.linalg.eigh(cov)
            nrm[s:s + step], nbr[s:s + step] = v[:, :, 0], ii[:, ::kk // k][:, :k]
        else:
            lam[s:s + step] = np.linalg.eigvalsh(cov)
    return lam, nrm, nbr


def _on_a_line(lam: np.ndarray, kk: int) -> np.ndarray:
    """Whether each neighbourhood of kk points with eigenvalues ``lam`` (m, 3) ascending is one
    line: spread across under :data:`LINE_WIDTH_IN_STEPS` steps along (see
    :func:`widen_collinear`)."""
    return lam[:, 1] * (kk * kk - 1) < LINE_WIDTH_IN_STEPS ** 2 * 12.0 * lam[:, 2]


def widen_collinear(xyz: np.ndarray, k: int, k_max: int | None = None, sample: int = 20000, seed: int = 0):
    """Normals of the points whose ``k`` nearest points (themselves included) lie on one line,
    from neighbourhoods doubled until they do not.

    A neighbourhood is a line when its spread across is under :data:`LINE_WIDTH_IN_STEPS`
    point steps along it: with eigenvalues λ1 ≥ λ2 of its covariance, k points evenly
    spaced by d along a line have λ1 = d² (k² − 1) / 12, so the test is
    λ2 < (w² · 12 / (k² − 1)) · λ1 with w = 0.5. The points so found are searched again with
    2k, 4k, ... neighbours (vectorised per doubling) up to ``k_max`` (default 16 k, capped by
    the cloud's size); those still on one line there are returned as unresolved.

    The test runs first on a seeded random sample of ``sample`` points (all of them in a
    smaller cloud) and on the whole cloud only if some sampled point is on a line. A cloud
    where a fraction f of the points is on lines goes unnoticed with probability (1 − f)^sample:
    under 2·10⁻⁹ for f ≥ 1/1000 with 20 000 samples. Scan-line clouds (nearly all points on
    lines) are always found; a few isolated line-shaped neighbourhoods in an otherwise
    surface-like cloud may be skipped, and keep their fitted normals.

    Returns
    -------
    idx : (m,) int
        The points whose neighbourhood was widened to more than one line.
    normals : (m, 3) float
        Their unit normals, unoriented.
    rows, cols : (e,) int32
        Edges from each widened or unresolved point to k of the neighbours of its final
        search, every (k_i / k)-th by distance so that they reach as far as it (self-loops
        removed).
    unresolved : (u,) int
        The points whose neighbourhood of ``k_max`` is still one line.
    """
    from scipy.spatial import cKDTree

    pts = np.asarray(xyz, dtype=np.float64)
    pts = pts - pts.mean(axis=0)
    k_max = min(16 * k if k_max is None else k_max, len(pts))
    tree, kk = cKDTree(pts), min(k, len(pts))
    todo = np.arange(len(pts))
    if len(pts) > sample:
        probe = np.random.default_rng(seed).choice(len(pts), sample, replace=False)
        if not _on_a_line(_pca_block(tree, pts, pts[probe], kk)[0], kk).any():
            todo = todo[:0]
    todo = todo[_on_a_line(_pca_block(tree, pts, pts[todo], kk)[0], kk)]
    idx, fits, rows, cols, unresolved = [], [], [], [], []
    while todo.size and kk < k_max:
        kk = min(2 * kk, k_max)
        lam, nrm, nbr = _pca_block(tree, pts, pts[todo], kk, k)
        line = _on_a_line(lam, kk)
        done = ~line | (kk >= k_max)
        idx.append(todo[~line]), fits.append(nrm[~line])
        unresolved.append(todo[line & done])
        r = np.repeat(todo[done].astype(nbr.dtype), k)
        c = nbr[done].ravel()
        rows.append(r[r != c]), cols.append(c[r != c])
        todo = todo[~done]
    unresolved.append(todo)  # only when k_max <= k: never searched wider
    e, e32 = np.empty(0, dtype=np.int64), np.empty(0, dtype=np.int32)
    return (np.concatenate(idx + [e]), np.concatenate(fits + [np.empty((0, 3))]), np.concatenate(rows + [e32]),
            np.concatenate(cols + [e32]), np.concatenate(unresolved + [e]))


def orient_from_anchors(n: np.ndarray, anchored: np.ndarray, rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """Flip the non-anchored normals of ``n`` (n, 3) consistently with the anchored ones
    (whose signs are kept), over the graph of edges ``rows`` → ``cols``.

    Hoppe's orientation: a minimum spanning tree with edge cost 2 − |n_i · n_j| (nearly
    parallel normals first) plus a virtual root tied to every anchored point (cheaper than any
    edge) and, for a part of the graph without one, to its first point (dearer than any edge,
    keeping that point's sign). Signs then multiply down the tree from the root (pointer
    jumping, vectorised).
    """
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import breadth_first_order, connected_components, minimum_spanning_tree

    m = len(n)
    g = coo_matrix((np.ones(len(rows)), (rows, cols)), shape=(m, m)).tocsr()
    _, lab = connected_components(g, directed=False)
    has_anchor = np.bincount(lab, weights=anchored, minlength=lab.max() + 1) > 0
    first = np.unique(lab, return_index=True)[1]
    free = first[~has_anchor[lab[first]]]
    tied = np.flatnonzero(anchored)
    cost = 2.0 - np.abs(np.einsum("ij,ij->i", n[rows], n[cols]))
    r = np.concatenate([rows, np.full(tied.size + free.size, m)])
    c = np.concatenate([cols, tied, free])
    w = np.concatenate([cost, np.full(tied.size, 0.5), np.full(free.size, 3.0)])
    tree = minimum_spanning_tree(coo_matrix((w, (r, c)), shape=(m + 1, m + 1)).tocsr())
    _, pred = breadth_first_order(tree, m, directed=False, return_predecessors=True)
    par = np.where(pred[:m] < 0, m, pred[:m])
    par = np.append(par, m)
    nn = np.vstack([n, np.zeros(3)])
    sign = np.where((par[:m] == m) | (np.einsum("ij,ij->i", nn[par[:m]], n) >= 0), 1.0, -1.0)
    sign = np.append(sign, 1.0)
    while np.any(par != m):
        sign, par = sign * sign[par], par[par]
    return n * sign[:m, None]
