"""Raised patches: a patch of ground that stands above the ground all around it is an object.

A ground filter's result can hold whole roofs, decks, platforms and wagons: a roof wider than
SMRF's or PMF's window survives the opening, a cloth lies on a flat roof, a TIN densifies onto a
deck. Such a patch gives itself away by its rim. Walk over the ground points' TIN: where two
neighbours differ by less than ``step`` the surface is continuous, and the continuous pieces are
the patches. Terrain patches meet their neighbours uphill and downhill; a roof accepted as ground
is cut off from the terrain by its walls, and every rim edge leaves it *downwards* by more than
``step``. So (Sithole & Vosselman's segment-based filtering, in its simplest form):

1. Delaunay TIN in plan of the lowest ground point per ``cell`` (``scipy.spatial.Delaunay``;
   its CSR neighbour lists are the edges);
2. edges with ``|dz| < step`` join points into patches (``scipy.sparse.csgraph``);
3. a patch, other than the largest, is not ground when at least ``rim_share`` of the breaks
   that leave its points (edges with ``|dz| >= step``; a break inside a patch counts from both
   ends, a drop and a rise, so a rough patch stays terrain-like) drop from it, *and* the drops
   surround it: the mean of their unit directions is shorter than ``max_resultant``. Drops on
   one side only are a terrace, or the upper edge of a slope that the data's edge or a gap in
   the ground cuts off; without this, a hillside cut into strips by gaps would be peeled away
   strip by strip from the top;
4. repeat until no patch goes (a roof on a deck is found once the deck is gone), at most
   ``max_passes`` times.

The TIN is made of the lowest ground point per ``cell`` (1 m), and each ground point takes its
cell's verdict (scipy's Delaunay costs about 10 µs a point, and a dense scan's every point is
not needed to see a roof's rim), except beside a raised cell, where a cell may hold a roof's
edge over the ground below the wall: there a point takes the verdict of the representative
nearest to it in 3-D.

Everything is vectorised over edges (``bincount`` per patch); the cost is one Delaunay
triangulation of the cells' representatives (0.1-0.4 s on the real tiles, 2 s on 276 k
representatives of 1.36 M ground points). A later pass, whose representatives are the last
pass's less those of the raised cells, re-tiles only the triangles that lost a corner (0.2 s
there; see the notes before :class:`_Base`), and triangulates in full wherever that is not
sure to give Qhull's verdicts. It takes out raised platforms, wagons and roofs the vote let in;
steep slopes and dikes, which drop on one side only, are kept.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class PatchParams:
    """Parameters of the raised-patch test. Lengths in metres.

    Attributes
    ----------
    step : float
        Height difference (m) between TIN neighbours that breaks the surface (1.0).
    rim_share : float
        Share of the breaks leaving a patch's points that must drop by ``step`` or more (0.9).
    max_resultant : float
        The drops' directions must spread around the patch: the length of the mean of their
        unit vectors at most this (0.7; 1 = off; one-sided drops give about 1, drops on all
        sides about 0, on two sides of a corner 0.7).
    cell : float
        The test runs on the lowest ground point of each ``cell`` × ``cell`` m cell, and every
        ground point takes its cell's verdict (1.0: a TIN of a million points a km², not of
        every point; roofs and decks are metres across). Larger cells cut peaks and ridges
        out of steep terrain: a crest whose neighbours lie lower by more than ``step`` on all
        sides looks like a roof; with 1 m cells that takes a slope of about 2 (63°), with
        2 m cells a slope of 1.
    max_passes : int
        Passes at most (3; 0 = off).
    """

    step: float = 1.0
    rim_share: float = 0.9
    max_resultant: float = 0.7
    cell: float = 1.0
    max_passes: int = 3


def raised_patches(xyz: np.ndarray, ground: np.ndarray, p: PatchParams = PatchParams(), tins=None) -> np.ndarray:
    """Ground flags (m,) bool with the raised patches taken out.

    Parameters
    ----------
    xyz : (m, 3) float64
        Local metric coordinates.
    ground : (m,) bool
        A ground filter's result.
    tins : TinHandoff, optional
        Where the last pass's TIN is left for a later step
        (:class:`workstation.ground.common.TinHandoff`).
    """
    from scipy import ndimage
    from scipy.spatial import cKDTree

    from .common import auto_cell, grid_index, grid_min
    from .retile import pass_edges

    g = np.asarray(ground, dtype=bool).copy()
    base = None  # the last full TIN, which the next pass's edges are made from (see :func:`workstation.ground.retile.pass_edges`)
    for _ in range(p.max_passes):
        idx = np.flatnonzero(g)
        if len(idx) < 4:
            break
        r, c, shape, _ = grid_index(xyz[idx, :2], auto_cell(xyz[idx, :2], p.cell))
        _, low = grid_min(xyz[idx, 2], r, c, shape)
        cell_rep = low.ravel()  # per cell: the index (into idx) of its lowest ground point
        rep = cell_rep[cell_rep >= 0]
        pts = xyz[idx[rep]]
        raised = None
        for prior in (base, None):  # from the last TIN if it can be; if a sum is too close: Qhull's
            made = pass_edges(xyz, idx[rep], pts, prior, tins, p.step)
            if made is None:  # collinear or too few distinct points: no TIN, nothing to test
                break
            src, dst, base, full = made
            raised, patch, safe = _raised(pts, src, dst, p, exact=full)
            if safe:
                break
        if raised is None or not raised.any():
            break
        verdict = raised[patch]
        cell_raised = np.zeros(len(cell_rep), bool)
        cell_raised[cell_rep >= 0] = verdict
        flat = r * shape[1] + c
        out = cell_raised[flat]
        # a cell beside a raised one may hold both (a roof's edge over the ground below the
        # wall): its points take the verdict of the representative nearest to them in 3-D
        edge = ndimage.binary_dilation(cell_raised.reshape(shape), np.ones((3, 3), bool)).ravel() & ~cell_raised
        near = np.flatnonzero(edge[flat])
        if len(near):
            _, j = cKDTree(pts).query(xyz[idx[near]])
            out[near] = verdict[j]
        g[idx[out]] = False
    return g


def _raised(pts: np.ndarray, src: np.ndarray, dst: np.ndarray, p: PatchParams, exact: bool):
    """(raised, patch, safe): per patch of the TIN edges ``src -> dst`` whether it is raised,
    and each representative's patch (None, None when there is a single patch). With ``exact``
    False (edges not in scipy's order) ``safe`` is False, and nothing else returned, when a
    drops' resultant lies too close to its bound for the sum's rounding, which depends on the
    edges' order, to rule it out (:func:`_order_safe`)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    dz = pts[src, 2] - pts[dst, 2]
    joined = np.abs(dz) < p.step
    n = len(pts)
    graph = coo_matrix((np.ones(int(joined.sum()), np.int8), (src[joined], dst[joined])), shape=(n, n))
    count, patch = connected_components(graph, directed=False)
    if count < 2:
        return None, None, True
    # every break that leaves a patch's points, its rim and any inside it (an inside break
    # is seen from both ends, one drop and one rise: a rough patch is terrain-like)
    brk = ~joined
    breaks = np.bincount(patch[src[brk]], minlength=count)
    drop = brk & (dz >= p.step)
    drops = np.bincount(patch[src[drop]], minlength=count)
    raised = (breaks > 0) & (drops >= p.rim_share * breaks)
    # the drops must surround the patch: one-sided drops are a terrace or the upper edge of
    # a slope cut by the data's edge. Resultant length of the drops' unit directions.
    d = pts[dst[drop], :2] - pts[src[drop], :2]
    d /= np.maximum(np.hypot(d[:, 0], d[:, 1]), 1e-12)[:, None]
    sx = np.bincount(patch[src[drop]], weights=d[:, 0], minlength=count)
    sy = np.bincount(patch[src[drop]], weights=d[:, 1], minlength=count)
    largest = np.bincount(patch, minlength=count).argmax()
    bound = p.max_resultant * np.maximum(drops, 1)
    if not exact and not _order_safe(np.hypot(sx, sy), bound, drops, raised, largest):
        return None, None, False
    raised &= np.hypot(sx, sy) <= bound
    raised[largest] = False
    return raised, patch, True


def _order_safe(resultant: np.ndarray, bound: np.ndarray, drops: np.ndarray, raised: np.ndarray, largest) -> bool:
    """Whether ``resultant <= bound`` comes out the same for every order of the sums of the
    drops' unit vectors, for the patches it decides (``raised`` so far, not the ``largest``).

    A sequential sum of k terms of magnitude at most 1 is within (k - 1) k u of the exact sum
    (u = 2^-53, Higham, *Accuracy and Stability of Numerical Algorithms*, 2002, eq. 4.4), so
    two orders' sums differ by at most 2 k^2 u per component; with a margin for hypot's
    rounding, a resultant farther than that from its bound is on the same side in any order."""
    k = drops.astype(np.float64)
    slack = 4.0 * (k * k + 1.0) * np.finfo(np.float64).eps + 4.0 * np.finfo(np.float64).eps * bound
    close = raised & (np.abs(resultant - bound) <= slack)
    close[largest] = False
    return not close.any()
