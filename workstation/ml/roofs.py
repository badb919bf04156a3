"""Roof planarity test: a building point must lie on a locally planar surface.

The rule-based building classifiers users know accept a roof only where the points follow a
plane: LAStools ``lasclassify`` takes neighbouring points more than 2 m above the ground over a
search area of about 2 m as a roof when their standard deviation from the plane they share is
below ``-planar 0.1`` m, and as trees when it is above ``-rugged 0.4`` m; TerraScan's
*Buildings* routine fits roof planes with a Z tolerance "related to the noise level of the
points on roof planes". The point classifier ends with the same test on the points its network
calls building: a crown whose laser returns are single echoes (dense foliage, leaf-on) can look
like a roof to the per-point features at their 0.75 m / 1.5 m voxel scales, but not to a plane
fitted through the raw points around it.

For one candidate per ``voxel`` (its first point) the test fits least-squares planes to its
``k`` nearest raised points (more than ``min_height`` above the provisional ground): to the whole
neighbourhood and to each of its four half-discs (the neighbours on one side of the candidate
along x or y), so a point on a ridge, an eave or a roof step, whose disc straddles two planes,
still has a planar half-disc. The residual is the square root of the smallest eigenvalue of
the covariance (the RMS distance to the plane); the candidate fails when the smallest of the
five residuals exceeds ``tolerance``. 0.08 m is a little stricter than lasclassify's 0.1 m
(its search area is 2 m wide, ours about 2.5 m at 5 points per m²); a noisy scan needs a
larger value, as lasclassify's documentation advises for its own ("try -planar 0.2"). A
candidate whose ``k``-th neighbour lies farther than ``max_radius`` (a sparse scan:
lasclassify needs about 2 pulses per m²) is not tested. Every candidate then takes the
majority decision of the ``vote`` tested candidates nearest to it: one 24-neighbour query per
occupied 1 m voxel, and decisions that do not flip from point to point at a crown's edge.
The settings were chosen on a real tile (docs/benchmarks.md gives their sensitivity).

References
----------
M. Isenburg, LAStools: lasclassify README (rapidlasso GmbH).
Terrasolid, TerraScan User Guide: Classify / Buildings.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from workstation.core.cpu import in_blocks


@dataclass(frozen=True)
class RoofParams:
    """Settings of the roof planarity test (lengths in metres).

    Attributes
    ----------
    k : int
        Neighbours of the plane fit (24: a patch about 2.5 m wide at 5 points/m²).
    tolerance : float
        RMS distance (m) to the best local plane above which a candidate fails (lasclassify's
        ``-planar`` is 0.1).
    min_height : float
        Points more than this far above the provisional ground (m) form the neighbourhoods.
    max_radius : float
        Candidates whose ``k``-th neighbour is farther (m) are not tested.
    voxel : float
        One candidate per voxel of this side (m), its first, is tested (0: every candidate).
    vote : int
        Each candidate takes the majority decision of the ``vote`` tested candidates nearest
        to it (itself among them when it was tested): one test per voxel, and decisions that
        do not flip from point to point at the edge of a crown.
    sparse_k, sparse_tolerance : int, float
        Where the ``k`` neighbours span more than ``max_radius`` (scans of about 1 point per
        m²), the test is made again with ``sparse_k`` neighbours and ``sparse_tolerance``
        (m); ``sparse_k`` < 3 leaves such candidates untested.
    """

    k: int = 24
    tolerance: float = 0.08
    min_height: float = 0.5
    max_radius: float = 3.0
    voxel: float = 1.0
    vote: int = 5
    sparse_k: int = 12
    sparse_tolerance: float = 0.12


def plane_residuals(query: np.ndarray, ref: np.ndarray, k: int, workers: int = -1, tree=None) -> tuple[np.ndarray, np.ndarray]:
    """RMS distance (m) of each query point's ``k`` nearest ``ref`` points to the
    least-squares plane of the best of their disc and four half-discs, and the distance to
    the ``k``-th neighbour.

    Parameters
    ----------
    query : (m, 3) float
    ref : (r, 3) float
    k : int
    workers : int
        Threads of the queries and plane fits, a block of candidates each (1: one thread;
        -1: all cores).
    tree : scipy.spatial.cKDTree, optional
        A tree of ``ref`` built beforehand.

    Returns
    -------
    resid, dk : (m,) float64
    """
    from scipy.spatial import cKDTree

    k = int(min(k, len(ref)))
    if k < 3 or len(query) == 0:
        return np.zeros(len(query)), np.full(len(query), np.inf)
    tree = tree if tree is not None else cKDTree(ref, balanced_tree=False, compact_nodes=False)
    best = np.empty(len(query))
    dk = np.empty(len(query))
    order = z_order(query)  # neighbouring queries in turn: the tree's nodes stay in the cache
    query = query[order]
    step = 8192

    def block(s):  # one block of candidates: its query and its moments stay in the cache
        d, i = tree.query(query[s:s + step], k=k, workers=1)
        dk[order[s:s + step]] = d[:, -1]
        best[order[s:s + step]] = _min_plane_variance(np.take(ref, i, axis=0) - query[s:s + step, None, :], k)

    in_blocks(block, len(query), step, workers)
    return np.sqrt(np.maximum(best, 0.0)), dk


def z_order(xyz: np.ndarray, cell: float = 4.0) -> np.ndarray:
    """Indices of the points ``xyz`` (m, >= 2) in the Z-order (Morton 1966) of their
    ``cell``-metre plan cells, stably: a KD-tree queried in that order finds each query's
    nodes where the previous one left them (each query's answer is its own whatever the
    order). The cells are coarsened to at most 256 a side, so the key holds 16 bits and
    numpy sorts it by radix.

    References
    ----------
    G. M. Morton (1966). A computer oriented geodetic data base and a new technique in file
    sequencing. IBM Ltd., Ottawa.
    """
    if len(xyz) == 0:
        return np.zeros(0, np.intp)
    from workstation.ground.common import column_min

    c = np.floor((xyz[:, :2] - column_min(xyz[:, :2])) / cell).astype(np.int64)
    c >>= max(int(c.max()).bit_length() - 8, 0)
    key = np.zeros(len(xyz), np.uint16)
    for b in range(8):  # interleave the bits of x and y
        key |= (((c[:, 0] >> b) & 1) << (2 * b) | ((c[:, 1] >> b) & 1) << (2 * b + 1)).astype(np.uint16)
    return np.argsort(key, kind="stable")


def _min_plane_variance(off: np.ndarray, k: int) -> np.ndarray:
    """Smallest plane variance over the whole disc and its four half-discs of each
    neighbourhood ``off`` (m, k, 3), offsets from the query point."""
    from workstation.core.pca import sym3_eigenvalues

    off = off.astype(np.float32, copy=False)  # offsets of a few metres: float32 moments lose nothing at 1 cm
    x, y, z = off[:, :, 0], off[:, :, 1], off[:, :, 2]
    Q = np.empty(off.shape[:2] + (10,), np.float32)
    Q[..., 0] = 1.0
    Q[..., 1:4] = off
    Q[..., 4], Q[..., 5], Q[..., 6] = x * x, x * y, x * z
    Q[..., 7], Q[..., 8], Q[..., 9] = y * y, y * z, z * z
    # the whole disc and four half-discs (the candidate on their straight edge): a point on a
    # ridge, an eave or a step has a planar half-disc on one side, a crown on none
    masks = np.empty((len(off), 5, off.shape[1]), np.float32)
    masks[:, 0] = 1.0
    masks[:, 1], masks[:, 2], masks[:, 3], masks[:, 4] = x >= 0, x <= 0, y >= 0, y <= 0
    S = np.matmul(masks, Q).astype(np.float64)  # (m, 5, 10) moment sums
    cnt = S[..., 0]
    safe = np.maximum(cnt, 1.0)
    mx, my, mz = S[..., 1] / safe, S[..., 2] / safe, S[..., 3] / safe
    # the six distinct covariance entries (m, 5) each: xx, yy, zz, xy, xz, yz
    cov = (S[..., 4] / safe - mx * mx, S[..., 7] / safe - my * my, S[..., 9] / safe - mz * mz,
           S[..., 5] / safe - mx * my, S[..., 6] / safe - mx * mz, S[..., 8] / safe - my * mz)
    l3 = sym3_eigenvalues(*cov)[2]
    l3 = np.where(cnt >= max(6, k // 3), l3, np.inf)
    return l3.min(axis=1)


class RoofTest:
    """The raised points of a cloud in a KD-tree, ready to test building candidates.

    Building the tree does not need the candidates, so a caller can build it while the
    network runs (:class:`workstation.ml.classifier.PointClassifier` does).

    Parameters
    ----------
    xyz : (n, 3) float64
        Metric coordinates.
    hag : (n,) float
        Height above the provisional ground (m).
    params : RoofParams
    workers : int
        Threads of the plane tests and the vote, a block of candidates each (1: one thread;
        -1: all cores).
    """

    def __init__(self, xyz: np.ndarray, hag: np.ndarray, params: RoofParams = RoofParams(), workers: int = -1):
        from scipy.spatial import cKDTree

        from workstation.ground.common import column_min

        self.xyz = xyz
        self.params = params
        self.workers = workers
        self.origin = column_min(xyz) if len(xyz) else np.zeros(3)
        # centred float32 coordinates: half the memory traffic, 0.1 mm resolution over 1 km
        self.ref = (xyz[np.asarray(hag) > params.min_height] - self.origin).astype(np.float32)
        self.tree = cKDTree(self.ref, balanced_tree=False, compact_nodes=False) if len(self.ref) >= 3 else None

    def nonplanar(self, candidate: np.ndarray) -> np.ndarray:
        """(n,) bool: the candidates whose neighbourhood is not planar within the tolerance."""
        return self.vote(candidate, *self.test(candidate))

    def test(self, candidate: np.ndarray, with_tested=None) -> tuple[np.ndarray, np.ndarray]:
        """Plane test of one candidate per voxel (its first point); ``with_tested``, if given,
        is called with the tested points as soon as they are chosen (work that needs only
        them, such as :meth:`vote_tree`, can run beside the plane fits).

        Returns
        -------
        tested : (t, 3) float32
            The tested candidates, in the tester's local coordinates.
        bad : (t,) bool
            Their neighbourhood is not planar (and is not too sparse to tell).
        """
        p = self.params
        q = np.flatnonzero(candidate)
        if len(q) == 0 or self.tree is None:
            return np.zeros((0, 3), np.float32), np.zeros(0, bool)
        from .features import voxel_ids

        first = voxel_ids(self.xyz[q], p.voxel)[0] if p.voxel > 0 else np.arange(len(q))
        tested = (self.xyz[q[first]] - self.origin).astype(np.float32)
        if with_tested is not None:
            with_tested(tested)
        resid, dk = plane_residuals(tested, self.ref, p.k, self.workers, tree=self.tree)
        bad = (resid > p.tolerance) & (dk <= p.max_radius)
        sparse = np.flatnonzero(dk > p.max_radius)
        if p.sparse_k >= 3 and len(sparse):  # a sparse scan: fewer neighbours, a looser plane
            r2, d2 = plane_residuals(tested[sparse], self.ref, p.sparse_k, self.workers, tree=self.tree)
            bad[sparse] = (r2 > p.sparse_tolerance) & (d2 <= p.max_radius)
        return tested, bad

    def vote(self, candidate: np.ndarray, tested: np.ndarray, bad: np.ndarray, tree=None) -> np.ndarray:
        """(n,) bool: each candidate fails when most of the ``params.vote`` tested points
        nearest to it failed (:meth:`test`; decisions that do not flip from point to point at
        the edge of a crown); ``tree``: :meth:`vote_tree`'s of ``tested``, if built."""
        out = np.zeros(len(self.xyz), bool)
        q = np.flatnonzero(candidate)
        if len(q) == 0 or len(tested) == 0 or not bad.any():
            return out
        if bad.all():  # every vote fails: no neighbours to look up
            out[q] = True
            return out
        vote = int(min(max(self.params.vote, 1), len(tested)))
        tree = tree if tree is not None else self.vote_tree(tested)
        fails = np.empty(len(q), bool)
        step = 32768

        def block(s):
            pts = (self.xyz[q[s:s + step]] - self.origin).astype(np.float32)
            _, j = tree.query(pts, k=vote, workers=1)
            fails[s:s + step] = bad[j.reshape(len(pts), vote)].sum(axis=1) * 2 > vote

        in_blocks(block, len(q), step, self.workers)
        out[q] = fails
        return out

    @staticmethod
    def vote_tree(tested: np.ndarray):
        """The KD-tree :meth:`vote` looks the tested points ``tested`` up in."""
        from scipy.spatial import cKDTree

        return cKDTree(tested)

    def vote_more(self, candidate: np.ndarray, tested: np.ndarray, bad: np.ndarray, tree,
                  more: np.ndarray, more_bad: np.ndarray) -> np.ndarray:
        """:meth:`vote` among ``tested`` then ``more`` (their failures ``bad``, ``more_bad``)
        without a tree of both: ``tree`` is :meth:`vote_tree`'s of ``tested`` (None: one of
        both is built).

        Each candidate's ``vote + 1`` nearest of the two are among the ``vote + 1`` nearest
        of each, merged by distance; the distances are those one tree of both computes, so
        where the ``vote``-th lies nearer than the next the ``vote`` nearest are the ones
        that tree returns, and their majority is its. Where the two lie at one distance (a
        tie the tree breaks its own way) the tree of both decides."""
        from scipy.spatial import cKDTree

        allt, allb = np.concatenate([tested, more]), np.concatenate([bad, more_bad])
        vote = int(min(max(self.params.vote, 1), len(allt)))
        q = np.flatnonzero(candidate)
        if tree is None or len(more) == 0 or len(tested) <= vote or len(q) == 0 or allb.all() or not allb.any():
            return self.vote(candidate, allt, allb)
        pts = (self.xyz[q] - self.origin).astype(np.float32)
        da, ja = tree.query(pts, k=vote + 1, workers=self.workers)
        kb = min(vote + 1, len(more))
        db, jb = cKDTree(more).query(pts, k=list(range(1, kb + 1)), workers=self.workers)
        d, j = np.concatenate([da, db], axis=1), np.concatenate([ja, jb + len(tested)], axis=1)
        o = np.argsort(d, axis=1, kind="stable")[:, :vote + 1]
        d, j = np.take_along_axis(d, o, axis=1), np.take_along_axis(j, o, axis=1)
        out = np.zeros(len(self.xyz), bool)
        out[q] = allb[j[:, :vote]].sum(axis=1) * 2 > vote
        tie = q[d[:, vote - 1] == d[:, vote]]
        if len(tie):
            sel = np.zeros(len(self.xyz), bool)
            sel[tie] = True
            out[tie] = self.vote(sel, allt, allb)[tie]
        return out


def nonplanar_roofs(xyz: np.ndarray, candidate: np.ndarray, hag: np.ndarray,
                    params: RoofParams = RoofParams(), workers: int = -1) -> np.ndarray:
    """Candidates (building points) that fail the planarity test (:class:`RoofTest`).

    Parameters
    ----------
    xyz : (n, 3) float64
        Metric coordinates.
    candidate : (n,) bool
        Points the network calls building.
    hag : (n,) float
        Height above the provisional ground (m); the neighbourhoods are made of the points
        more than ``params.min_height`` above it.
    params : RoofParams

    Returns
    -------
    (n,) bool
        True where a candidate's neighbourhood is not planar within the tolerance.
    """
    if int(np.count_nonzero(candidate)) < 3:
        return np.zeros(len(xyz), bool)
    return RoofTest(xyz, hag, params, workers).nonplanar(candidate)
