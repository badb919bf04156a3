"""Delaunay TINs of a shrinking point set: the raised-patch test's passes after the first.

The raised-patch test (:mod:`workstation.ground.patches`) triangulates the lowest ground point
per cell, takes out the raised patches, and triangulates what is left again. The second TIN is
the first one less a few points, so most of it need not be made again: :func:`pass_edges` gives
a pass's TIN edges, re-tiling only where the last full TIN lost points, and falls back to a full
Qhull triangulation wherever that is not sure to give the verdicts a full one gives.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from workstation.core.log import get_logger

from .common import orient2d, walk_tin

log = get_logger(__name__)


def full_edges(xy: np.ndarray, tins=None):
    """(src, dst, tri): the directed edges (each undirected TIN edge both ways, in scipy's
    neighbour order) of the plan Delaunay TIN ``tri`` of ``xy``, made by Qhull; the TIN is left
    in ``tins`` (a :class:`workstation.ground.common.TinHandoff`) when given."""
    from .common import delaunay

    pts = xy - xy.min(axis=0)
    tri = delaunay(pts)
    if tins is not None:
        tins.clear()
        tins.put(pts, tri)
    indptr, indices = tri.vertex_neighbor_vertices
    src = np.repeat(np.arange(len(xy)), np.diff(indptr))
    return src, indices, tri


# -- the passes after the first: the last full TIN, re-tiled where it lost points ----------
#
# Between passes a kept cell keeps its lowest point and a raised cell loses all of its points,
# so a pass's representatives are the last pass's less those of the raised cells. (Points are
# added only where the grid's origin moved, the ground's lowest x or y having gone; such a pass
# is triangulated in full.) A triangle of the last TIN that keeps its three corners is still
# Delaunay: its circumcircle, empty before, stays empty. The triangles that lost a corner form
# the cavity of Bowyer-Watson insertion run backwards (Bowyer 1981; Watson 1981), and the new
# TIN there is made of those triangles of the Delaunay TIN of the cavity's remaining corners
# whose centroid lies in the cavity. The result is checked (triangle count and area, the
# cavity's rim matched edge for edge, every new edge locally Delaunay); a hull vertex removed,
# a cavity of more than _MAX_CAVITY of the TIN, or any failure falls back to Qhull.
#
# Two things could still part the result from a full Qhull run's verdicts, and both are checked:
# - Four points cocircular to within Qhull's rounding (about 1e-14 of the extent, as a distance
#   on its paraboloid) may be merged into one facet and split along either diagonal, by the
#   order in which Qhull met them (merged facets: Barber, Dobkin & Huhdanpaa, *The Quickhull
#   algorithm for convex hulls*, 1996), so a full run on the new set need not keep the last
#   run's choice. Quads within _TIE (some 75 times that) are accepted only where every choice
#   gives the same verdicts (:func:`_ties_harmless`).
# - The edges come out in another order than scipy's neighbour lists, and only the drops'
#   direction sums can see that (floating-point sums depend on their order): where a verdict
#   could, :func:`workstation.ground.patches._order_safe` has the pass triangulated in full.

_MAX_CAVITY = 0.25  # share of the old TIN's triangles beyond which a full triangulation is made
_TIE = 1e-12  # lifted distance, times the coordinates' extent, under which four points count as cocircular
_WALK_STEPS = 2000  # triangles a walk may cross before the pass is triangulated in full


class _Base(NamedTuple):
    """A pass's full (Qhull) TIN, which the next passes' TINs are made from."""

    gid: np.ndarray  # (n,) index into xyz of each vertex
    tri: object  # scipy Delaunay of the vertices' local xy
    cache: dict  # "geometry": its _Geometry, made on first use (:func:`_base_geometry`)


class _Geometry(NamedTuple):
    """What the re-tiling reads of a :class:`_Base`'s TIN (int32 indices, as scipy's)."""

    simp: np.ndarray  # (nt, 3) triangles counter-clockwise
    nbr: np.ndarray  # (nt, 3) neighbour across from each corner, -1 on the hull
    hull: np.ndarray  # (n,) bool: vertex on the hull
    hull_t: np.ndarray  # hull half-edges: the triangle and the corner across from the edge
    hull_j: np.ndarray
    tie_t: np.ndarray  # near-cocircular interior edges: their two triangles
    tie_u: np.ndarray
    tie_quad: np.ndarray  # (k, 4) and their quads, as :func:`_ties_harmless` takes them


class _LazyTin:
    """The scipy ``Delaunay`` of ``pts``, triangulated on first use: left in a ``TinHandoff``
    by a pass that made its edges without one, for a later step that may take it."""

    def __init__(self, pts: np.ndarray):
        self._pts, self._tri = pts, None

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        if self._tri is None:
            from .common import delaunay

            self._tri = delaunay(self._pts)
        return getattr(self._tri, name)


def pass_edges(xyz, gid, pts, base, tins, step: float):
    """(src, dst, base, full): the directed TIN edges of the representatives ``pts`` (points
    ``gid`` of ``xyz``), made from ``base`` where that is sure to give Qhull's verdicts (full
    False; edges not in scipy's order), else by Qhull (full True, ``base`` the new TIN).
    None where Qhull finds no TIN (collinear or too few distinct points)."""
    from scipy.spatial import QhullError

    if base is not None:
        try:
            made = _incremental_edges(xyz, gid, pts, base, step)
        except (QhullError, ValueError, IndexError) as e:  # anything unforeseen: the full triangulation
            log.debug("raised patches: re-tiling failed (%s), triangulating in full", e)
            made = None
        if made is not None:
            if tins is not None:
                local = pts[:, :2] - pts[:, :2].min(axis=0)
                tins.clear()
                tins.put(local, _LazyTin(local))
            return made[0], made[1], base, False
    try:
        src, dst, tri = full_edges(pts[:, :2], tins)
    except (QhullError, ValueError):
        return None
    return src, dst, _Base(gid, tri, {}), True


def _lifted_distance(a, b, c, d, scale: float) -> np.ndarray:
    """Signed distance of d above the plane through a, b, c (counter-clockwise) on the
    paraboloid z = ``scale`` (x² + y²), Qhull's measure of a Delaunay triangle's emptiness:
    < 0 where d lies inside the circumcircle."""
    def lift(p):
        return np.column_stack([p - a, scale * ((p - a) * (p + a)).sum(1)])

    u, v, w = lift(b), lift(c), lift(d)
    nrm = np.cross(u, v)
    return (nrm * w).sum(1) / np.sqrt((nrm * nrm).sum(1))


def _base_geometry(base: _Base) -> _Geometry:
    """``base``'s :class:`_Geometry`, made on first use and kept in its cache. The interior
    edges are tested by the far corner's lifted distance from the triangle's plane (Qhull's own
    equations: a merged facet's triangles share one, distance 0)."""
    if "geometry" in base.cache:
        return base.cache["geometry"]
    tri = base.tri
    pts = tri.points
    simp, nbr = tri.simplices.astype(np.int32), tri.neighbors.astype(np.int32)
    cw = orient2d(pts[simp[:, 0]], pts[simp[:, 1]], pts[simp[:, 2]]) < 0
    simp[cw], nbr[cw] = simp[cw][:, [0, 2, 1]], nbr[cw][:, [0, 2, 1]]
    ht, hj = (a.astype(np.int32) for a in np.nonzero(nbr < 0))
    hull = np.zeros(len(pts), bool)
    hull[simp[ht, (hj + 1) % 3]] = hull[simp[ht, (hj + 2) % 3]] = True
    t, j = np.nonzero(nbr > np.arange(len(simp))[:, None])  # each interior edge once
    u = nbr[t, j]
    d = simp[u].sum(1) - simp[t, (j + 1) % 3] - simp[t, (j + 2) % 3]
    x, y = pts[d, 0], pts[d, 1]
    eq = tri.equations[t]
    lift = (x * x + y * y) * tri.paraboloid_scale + tri.paraboloid_shift
    dist = eq[:, 0] * x + eq[:, 1] * y + eq[:, 2] * lift + eq[:, 3]
    tie = np.abs(dist) < _TIE * _extent(pts)
    t, j, u, d = t[tie].astype(np.int32), j[tie], u[tie], d[tie].astype(np.int32)
    tie_quad = np.column_stack([simp[t, (j + 1) % 3], simp[t, (j + 2) % 3], simp[t, j], d])
    geo = _Geometry(simp, nbr, hull, ht, hj, t, u, tie_quad)
    base.cache["geometry"] = geo
    return geo


def _extent(xy: np.ndarray) -> float:
    """The largest absolute local coordinate (Qhull's scale of its rounding)."""
    return float(max(np.abs(xy).max(), 1.0))


def _match(gid_old: np.ndarray, gid_new: np.ndarray, m: int) -> tuple[np.ndarray, np.ndarray]:
    """(new_of_old, old_of_new): each old vertex's index among the new ones and back, -1 where none."""
    pos = np.full(m, -1, np.int64)
    pos[gid_new] = np.arange(len(gid_new))
    new_of_old = pos[gid_old]
    pos[gid_new] = -1
    pos[gid_old] = np.arange(len(gid_old))
    return new_of_old, pos[gid_new]


def _incremental_edges(xyz, gid, pts, base: _Base, step: float):
    """Directed edges (src, dst) of the Delaunay TIN of the representatives ``pts`` (points
    ``gid`` of ``xyz``) made from ``base``'s TIN (see the notes above), or None where that is
    not sure to give Qhull's verdicts on them."""
    tri = base.tri
    if len(tri.coplanar):
        return None
    geo = _base_geometry(base)
    new_of_old, old_of_new = _match(base.gid, gid, len(xyz))
    removed = new_of_old < 0
    if (old_of_new < 0).any() or removed[geo.hull].any():
        return None  # a point added (the grid moved) or the hull changed
    cavity = removed[geo.simp].any(1)
    if cavity.sum() > _MAX_CAVITY * len(geo.simp):
        return None
    # the new pass's frame, as full_edges makes it: the old TIN's too, its lowest x and y
    # being those of hull vertices, which all stay
    xy = pts[:, :2] - pts[:, :2].min(axis=0)
    if not np.array_equal(xy[new_of_old[geo.hull]], tri.points[geo.hull]):
        return None
    tiles = _retile(xy, geo, tri, cavity, new_of_old, old_of_new)
    if tiles is None:
        return None
    dsimp, dn, sel = tiles
    quads = _new_edge_ties(xy, tri.paraboloid_scale, dsimp, dn, sel, geo.simp, geo.nbr, cavity, new_of_old)
    if quads is None:
        return None
    kept = ~cavity
    tk = kept[geo.tie_t] & kept[geo.tie_u]
    quads = np.concatenate([quads, new_of_old[geo.tie_quad[tk]]])
    if not _ties_harmless(quads, pts[:, 2], step):
        return None
    tris = np.concatenate([new_of_old[geo.simp[kept]], dsimp[sel]])
    ht, hj = geo.hull_t, geo.hull_j
    ha, hb = new_of_old[geo.simp[ht, (hj + 1) % 3]], new_of_old[geo.simp[ht, (hj + 2) % 3]]
    src = np.concatenate([tris[:, 0], tris[:, 1], tris[:, 2], hb])
    return src, np.concatenate([tris[:, 1], tris[:, 2], tris[:, 0], ha])


def _retile(xy, geo: _Geometry, tri, cavity, new_of_old, old_of_new):
    """(dsimp, dn, sel): the Delaunay TIN of the cavity's remaining corners (triangles
    counter-clockwise in new indices, neighbours as scipy's) and which of its triangles tile
    the cavity (centroid inside it, found by walks in the old TIN ``tri``); None where the
    count of triangles or their area is not the cavity's."""
    from .common import delaunay

    simp, nbr, old = geo.simp, geo.nbr, tri.points
    corners = new_of_old[simp[cavity]].ravel()
    s = np.unique(corners[corners >= 0])
    if len(s) < 3:
        return None
    ds = delaunay(xy[s])
    if len(ds.coplanar):
        return None
    dsimp, dn = s[ds.simplices], ds.neighbors.astype(np.int64)
    area = orient2d(xy[dsimp[:, 0]], xy[dsimp[:, 1]], xy[dsimp[:, 2]])
    cw = area < 0
    dsimp[cw], dn[cw], area[cw] = dsimp[cw][:, [0, 2, 1]], dn[cw][:, [0, 2, 1]], -area[cw]
    where = walk_tin(old, simp, nbr, xy[dsimp].mean(axis=1), tri.vertex_to_simplex[old_of_new[dsimp[:, 0]]],
                     _WALK_STEPS)
    if (where == -2).any():  # a walk that did not end
        return None
    sel = (where >= 0) & cavity[np.maximum(where, 0)]
    cav_area = np.abs(orient2d(old[simp[cavity, 0]], old[simp[cavity, 1]], old[simp[cavity, 2]])).sum()
    if sel.sum() != cavity.sum() - 2 * int((new_of_old < 0).sum()):
        return None
    if abs(area[sel].sum() - cav_area) > 1e-9 * cav_area:
        return None
    return dsimp, dn, sel


def _new_edge_ties(xy, scale, dsimp, dn, sel, simp, nbr, cavity, new_of_old):
    """Quads (k, 4: an edge of a new triangle, the triangle's third corner and the far corner
    across the edge) whose four points are near-cocircular; None where the new triangles' rim is not the cavity's, edge
    for edge, or a new edge is not Delaunay."""
    si = np.flatnonzero(sel)
    i, j = np.repeat(si, 3), np.tile(np.arange(3), len(si))
    nb = dn[i, j]
    e1, e2 = dsimp[i, (j + 1) % 3], dsimp[i, (j + 2) % 3]
    inner = (nb >= 0) & sel[np.maximum(nb, 0)]
    far = np.full(len(i), -1, np.int64)
    far[inner] = dsimp[nb[inner]].sum(1) - e1[inner] - e2[inner]
    # the cavity's rim: its half-edges on the hull or beside a kept triangle, with the far corner
    ct, cj = np.nonzero(cavity[:, None] & ((nbr < 0) | ~cavity[np.maximum(nbr, 0)]))
    u = nbr[ct, cj]
    o1, o2 = simp[ct, (cj + 1) % 3], simp[ct, (cj + 2) % 3]
    rfar = np.where(u >= 0, new_of_old[np.where(u >= 0, simp[np.maximum(u, 0)].sum(1) - o1 - o2, 0)], -1)
    n = len(xy)
    rkey, okey = new_of_old[o1] * n + new_of_old[o2], e1[~inner] * n + e2[~inner]
    if len(rkey) != len(okey) or (new_of_old[o1] < 0).any() or (new_of_old[o2] < 0).any():
        return None
    order = np.argsort(rkey)
    rk = rkey[order]
    pos = np.minimum(np.searchsorted(rk, okey), len(rk) - 1)
    if len(rk) and ((rk[pos] != okey).any() or (np.diff(rk) == 0).any() or len(np.unique(pos)) != len(pos)):
        return None
    far[~inner] = rfar[order][pos]
    has = far >= 0
    t, d = dsimp[i[has]], far[has]
    dist = _lifted_distance(xy[t[:, 0]], xy[t[:, 1]], xy[t[:, 2]], xy[d], scale)
    tol = _TIE * _extent(xy)
    if (dist < -tol).any():
        return None
    tie = dist < tol
    return np.column_stack([e1[has][tie], e2[has][tie], dsimp[i[has][tie], j[has][tie]], d[tie]])


def _ties_harmless(quads: np.ndarray, z: np.ndarray, step: float) -> bool:
    """Whether every triangulation of the near-cocircular quads (k, 4: an edge's two ends and
    the far corners of its two triangles) gives the same verdicts. Qhull merges triangles
    across such edges into one facet and triangulates it as it likes; the facets are the
    groups of triangles joined by these edges. Where a group's points lie within ``step`` of
    each other in height, every edge among them joins and breaks none, and its outline joins
    them all: the patches and their breaks are the same whichever edges it gets."""
    if len(quads) == 0:
        return True
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    k = len(quads)
    sides = np.sort(np.vstack([quads[:, [0, 1, 2]], quads[:, [0, 1, 3]]]), axis=1)
    tris, inv = np.unique(sides, axis=0, return_inverse=True)
    inv = inv.ravel()
    graph = coo_matrix((np.ones(k, np.int8), (inv[:k], inv[k:])), shape=(len(tris),) * 2)
    count, lab = connected_components(graph, directed=False)
    hi, lo = np.full(count, -np.inf), np.full(count, np.inf)
    np.maximum.at(hi, lab, z[tris].max(axis=1))
    np.minimum.at(lo, lab, z[tris].min(axis=1))
    return bool(((hi - lo) < step).all())
