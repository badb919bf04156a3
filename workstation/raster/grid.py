"""Grid geometry and TIN rasterisation shared by the raster products.

Coordinates inside this module are *cell units*: the centre of cell (row i, col j) is at
(u, v) = (j, i); u grows east, v grows south. :class:`GridSpec` converts between them and
world coordinates.

The TIN machinery is vectorised numpy (no Python loop over points or triangles):

* :func:`lattice_tin` — points reduced to at most one representative per cell (the "lattice")
  are triangulated by splitting every quad of four occupied neighbouring cells along its
  shorter diagonal (the Delaunay choice for a convex quad), and each cell centre is
  interpolated linearly (barycentric) in the triangle of the quads around it that contains it.
  O(cells), no global triangulation.
* :func:`fill_voids_tin` — the cells left without a triangle (voids: buildings, water, sparse
  data) are filled from a scipy/Qhull Delaunay triangulation (Barber et al. 1996) of the
  occupied cells on the rim of the voids only, so the triangulation cost grows with the void
  perimeters, not with the point count. A Delaunay triangle spanning a void has an empty
  circumcircle and its corners lie on the void rim, so it is also a triangle of the rim
  triangulation: the fill equals a full-TIN interpolation there.
* :func:`rasterize_triangles` — barycentric linear interpolation of triangles at the cell
  centres they cover, grouped by bounding-box size so that each group is one array operation;
  triangles whose bounding box holds no cell to fill are skipped (most rim triangles of a
  void fill lie between occupied cells).

Ties: every geometric decision (which diagonal, which Delaunay split of co-circular points,
whether a cell centre on an edge is inside, whether an edge is as long as the limit) treats
values equal within :data:`TIE` as equal and settles them by a fixed rule, so the rounding of
the coordinates — another unit, another origin — does not change the surface
(:func:`canonical_ties`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from workstation.core.errors import InvalidInputError

#: Relative tolerance under which two lengths or angles (cell units, radians) are a tie. World
#: coordinates carry float64 rounding of about 2**-52 * |x| / cell in cell units (1e-9 for
#: 5e6 m northings on 1 m cells, 2e-8 on 5 cm cells), and a change of unit (metres to US
#: feet) moves them by that much; a decision inside this band is made by a fixed rule (the
#: AD diagonal, a fan from the first cell in row-major order) instead of by that rounding, so
#: the same data in another unit gives the same TIN. It is far below any geometry a DEM can
#: resolve (a micrometre on a 1 m cell).
TIE = 1e-6
#: A cell centre whose barycentric coordinates are all ≥ -_EPS is inside the triangle: one on
#: an edge or a corner (a point of a lattice on a cell centre) is inside whatever the rounding
#: of the unit, so the tolerance is the tie band.
_EPS = TIE


@dataclass(frozen=True)
class GridSpec:
    """A north-up grid: west edge ``x0``, north edge ``y1``, square cells of ``res``.

    Attributes
    ----------
    x0, y1 : float
        World coordinates (CRS units) of the upper-left corner.
    res : float
        Cell size in CRS units (metres for projected CRSs).
    rows, cols : int
    """

    x0: float
    y1: float
    res: float
    rows: int
    cols: int

    @classmethod
    def from_bounds(cls, xmin: float, ymin: float, xmax: float, ymax: float, res: float) -> "GridSpec":
        """Smallest grid aligned to multiples of ``res`` that holds every point of the bounds.

        Aligning to multiples of the cell size makes grids of adjacent tiles line up, so
        tiles can be mosaicked cell for cell.
        """
        if not (res > 0 and math.isfinite(res)):
            raise InvalidInputError(f"cell size must be positive, got {res}", field="resolution")
        x0 = math.floor(xmin / res) * res
        y1 = (math.floor(ymax / res) + 1) * res  # a point on a row's top edge belongs to that row
        cols = int(math.floor((xmax - x0) / res)) + 1
        rows = int(math.floor((y1 - ymin) / res)) + 1
        return cls(float(x0), float(y1), float(res), int(rows), int(cols))

    @classmethod
    def from_transform(cls, transform, shape) -> "GridSpec":
        a, b, c, d, e, f = transform
        if b or d or abs(abs(e) - a) > 1e-9 * a or e >= 0:
            raise InvalidInputError("only north-up grids with square cells are supported", field="transform")
        return cls(float(c), float(f), float(a), int(shape[0]), int(shape[1]))

    @property
    def shape(self) -> tuple[int, int]:
        return self.rows, self.cols

    @property
    def transform(self) -> tuple:
        return (self.res, 0.0, self.x0, 0.0, -self.res, self.y1)

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        return self.x0, self.y1 - self.rows * self.res, self.x0 + self.cols * self.res, self.y1

    def to_uv(self, x, y) -> tuple[np.ndarray, np.ndarray]:
        """World (x, y) -> cell units (u, v); cell (i, j) centre is (j, i)."""
        return (np.asarray(x) - self.x0) / self.res - 0.5, (self.y1 - np.asarray(y)) / self.res - 0.5

    def to_xy(self, u, v) -> tuple[np.ndarray, np.ndarray]:
        return self.x0 + (np.asarray(u) + 0.5) * self.res, self.y1 - (np.asarray(v) + 0.5) * self.res

    def cell_index(self, x, y) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(row, col, inside) of points; ``inside`` is False for points off the grid."""
        col = np.floor((np.asarray(x) - self.x0) / self.res).astype(np.int64)
        row = np.floor((self.y1 - np.asarray(y)) / self.res).astype(np.int64)
        inside = (row >= 0) & (row < self.rows) & (col >= 0) & (col < self.cols)
        return row, col, inside


def _bary(p0u, p0v, p1u, p1v, p2u, p2v, qu, qv):
    """Barycentric coordinates of (qu, qv) in triangles (arrays broadcast); den 0 -> nan.

    The reference formula: :func:`lattice_tin` and :func:`rasterize_triangles` evaluate it with
    the query-independent terms hoisted out, operation for operation (bit-identical results).
    """
    den = (p1v - p2v) * (p0u - p2u) + (p2u - p1u) * (p0v - p2v)
    with np.errstate(divide="ignore", invalid="ignore"):
        l0 = ((p1v - p2v) * (qu - p2u) + (p2u - p1u) * (qv - p2v)) / den
        l1 = ((p2v - p0v) * (qu - p2u) + (p0u - p2u) * (qv - p2v)) / den
    return l0, l1, 1.0 - l0 - l1


def _edges_ok(tri_u, tri_v, max_edge):
    """Whether every edge of the triangles (corners ``tri_u[k]``, ``tri_v[k]``, cell units) is
    at most ``max_edge`` long; an edge equal to it within :data:`TIE` (a lattice spacing that
    is a whole number of cells) is kept."""
    if max_edge is None:
        return True
    m2 = max_edge * max_edge * (1.0 + 2.0 * TIE)
    ok = True
    for a, b in ((0, 1), (1, 2), (2, 0)):
        ok = ok & ((tri_u[a] - tri_u[b]) ** 2 + (tri_v[a] - tri_v[b]) ** 2 <= m2)
    return ok


def lattice_tin(du, dv, z, valid, max_edge: float | None = None) -> np.ndarray:
    """Linear TIN interpolation at cell centres from one representative point per cell.

    Parameters
    ----------
    du, dv : (rows, cols) float
        Offset of each cell's representative point from the cell centre, in cells (|d| ≤ 0.5).
    z : (rows, cols) float
        Value at the representative point.
    valid : (rows, cols) bool
        Cells that have a representative.
    max_edge : float, optional
        Triangles with an edge longer than this (in cells) are not used.

    Returns
    -------
    (rows, cols) float64
        Interpolated values; NaN where no lattice triangle covers the cell centre.
    """
    R, C = z.shape
    out = np.full((R, C), np.nan)
    if R < 2 or C < 2:
        out[valid] = z[valid]
        return out
    # quad corners A (r, c), B (r, c+1), C (r+1, c), D (r+1, c+1) in quad-local cell units
    sl = {"A": (slice(0, R - 1), slice(0, C - 1)), "B": (slice(0, R - 1), slice(1, C)),
          "C": (slice(1, R), slice(0, C - 1)), "D": (slice(1, R), slice(1, C))}
    base = {"A": (0.0, 0.0), "B": (1.0, 0.0), "C": (0.0, 1.0), "D": (1.0, 1.0)}
    U = {k: base[k][0] + du[s] for k, s in sl.items()}
    V = {k: base[k][1] + dv[s] for k, s in sl.items()}
    Z = {k: z[s] for k, s in sl.items()}
    qvalid = valid[sl["A"]] & valid[sl["B"]] & valid[sl["C"]] & valid[sl["D"]]
    if not qvalid.any():
        return out
    # the shorter diagonal; AD when the two are equal within TIE (a rectangle, a lattice of points)
    ad2 = (U["D"] - U["A"]) ** 2 + (V["D"] - V["A"]) ** 2
    bc2 = (U["C"] - U["B"]) ** 2 + (V["C"] - V["B"]) ** 2
    ad = ad2 - bc2 <= TIE * (ad2 + bc2)
    # triangle 1: (A, B, D) if AD else (A, B, C); triangle 2: (A, D, C) if AD else (B, D, C)
    def pick(k_ad, k_bc, arr):
        return arr[k_ad] if k_ad == k_bc else np.where(ad, arr[k_ad], arr[k_bc])

    tris = []
    for corners in ((("A", "A"), ("B", "B"), ("D", "C")), (("A", "B"), ("D", "D"), ("C", "C"))):
        tu = [pick(a, b, U) for a, b in corners]
        tv = [pick(a, b, V) for a, b in corners]
        tz = [np.ascontiguousarray(pick(a, b, Z)) for a, b in corners]
        ok = qvalid & _edges_ok(tu, tv, max_edge)
        # the terms of _bary that do not depend on the query point, evaluated as _bary does
        (p0u, p1u, p2u), (p0v, p1v, p2v) = tu, tv
        a0, b0, a1, b1 = p1v - p2v, p2u - p1u, p2v - p0v, p0u - p2u
        den = a0 * b1 + b0 * (p0v - p2v)
        tris.append((a0, b0, a1, b1, den, p2u, p2v, tz, ok))
    for k in ("A", "B", "C", "D"):
        qu, qv = base[k]
        view = out[sl[k]]
        for a0, b0, a1, b1, den, p2u, p2v, tz, ok in tris:
            x, y = qu - p2u, qv - p2v
            with np.errstate(divide="ignore", invalid="ignore"):
                l0 = (a0 * x + b0 * y) / den
                l1 = (a1 * x + b1 * y) / den
                l2 = 1.0 - l0 - l1
            inside = ok & (l0 >= -_EPS) & (l1 >= -_EPS) & (l2 >= -_EPS) & np.isnan(view)
            i = np.flatnonzero(inside)
            if len(i):
                with np.errstate(invalid="ignore"):  # NaN corners lie outside `inside`
                    view[inside] = l0.ravel()[i] * tz[0].ravel()[i] + l1.ravel()[i] * tz[1].ravel()[i] + l2.ravel()[i] * tz[2].ravel()[i]
    return out


# stencil sides of rasterize_triangles: 1, 2, 3, 4, 6, 8, 12, ... (at most 1.5x a box side)
_STENCIL_SIZES = np.unique(np.concatenate([1 << np.arange(32, dtype=np.int64), 3 << np.arange(31, dtype=np.int64)]))


def _box_has_any(mask: np.ndarray, vmin, vmax, umin, umax) -> np.ndarray:
    """Whether each inclusive box ``[vmin, vmax] x [umin, umax]`` of ``mask`` holds a True cell.

    A summed-area table of ``mask``: O(cells) once, then O(1) per box. The boxes must lie
    inside the grid and be non-empty.
    """
    R, C = mask.shape
    sat = np.zeros((R + 1, C + 1), np.int32 if R * C < 2**31 else np.int64)
    sat[1:, 1:] = mask
    np.cumsum(sat, axis=1, out=sat)
    np.cumsum(sat, axis=0, out=sat)
    flat, W = sat.ravel(), C + 1
    lo_v, hi_v = vmin * W, (vmax + 1) * W
    return (flat.take(hi_v + umax + 1) - flat.take(lo_v + umax + 1) - flat.take(hi_v + umin) + flat.take(lo_v + umin)) > 0


def rasterize_triangles(tri_u, tri_v, tri_z, out, target=None, chunk: int = 2_000_000) -> int:
    """Write the linear interpolant of triangles at the cell centres they cover.

    Parameters
    ----------
    tri_u, tri_v : (m, 3) float
        Triangle corners in cell units (centre of cell (i, j) at (j, i)).
    tri_z : (m, 3) float
        Values at the corners.
    out : (rows, cols) float64
        Written in place where a triangle covers a cell centre (and ``target`` is True).
    target : (rows, cols) bool, optional
        Cells that may be written.
    chunk : int
        Bound on the cells evaluated by one array operation (temporary memory).

    Returns
    -------
    int
        Number of (triangle, cell) writes: a cell centre on an edge shared by two triangles
        counts twice.

    Notes
    -----
    Triangles whose bounding box holds no ``target`` cell are dropped up front (a
    summed-area table of ``target``): they would write nothing. The others are evaluated over
    their bounding box rounded up, in each direction separately, to 1, 2, 3, 4, 6, 8, 12, ...
    cells (so a long thin triangle costs about its box, not the square of its longer side). The
    arithmetic per cell is that of :func:`_bary`, term for term. A cell centre covered
    by several triangles (on a shared edge, within ``_EPS``) takes the value of the last of
    them in the order (size class ``ceil(log2(max(w, h)))`` of the box, then input index);
    that order is kept by a per-cell rank of the last write, so the result does not depend
    on how the work is grouped.
    """
    R, C = out.shape
    if len(tri_u) == 0:
        return 0
    umin, umax, vmin, vmax = _cell_boxes(tri_u, tri_v, R, C)
    w = umax - umin + 1
    h = vmax - vmin + 1
    keep = np.flatnonzero((w > 0) & (h > 0))
    if target is not None:
        target = np.ascontiguousarray(target, dtype=bool)
        if len(keep):
            keep = keep[_box_has_any(target, vmin[keep], vmax[keep], umin[keep], umax[keep])]
    if len(keep) == 0:
        return 0
    tris = _triangle_terms(tri_u[keep], tri_v[keep], tri_z[keep], umin[keep], umax[keep], vmin[keep], vmax[keep],
                           w[keep], h[keep])
    return _rasterize_groups(tris, w[keep], h[keep], out, None if target is None else target.ravel(), chunk)


def _cell_boxes(tri_u, tri_v, R: int, C: int):
    """Integer bounding boxes ``(umin, umax, vmin, vmax)`` of the cell centres each triangle may
    cover (``_EPS`` tolerance), clipped to the grid; empty boxes have ``max < min``."""
    # corner-wise min/max: the same values as .min(1)/.max(1), much faster on (m, 3)
    umin = np.ceil(np.minimum(np.minimum(tri_u[:, 0], tri_u[:, 1]), tri_u[:, 2]) - _EPS).astype(np.int64)
    umax = np.floor(np.maximum(np.maximum(tri_u[:, 0], tri_u[:, 1]), tri_u[:, 2]) + _EPS).astype(np.int64)
    vmin = np.ceil(np.minimum(np.minimum(tri_v[:, 0], tri_v[:, 1]), tri_v[:, 2]) - _EPS).astype(np.int64)
    vmax = np.floor(np.maximum(np.maximum(tri_v[:, 0], tri_v[:, 1]), tri_v[:, 2]) + _EPS).astype(np.int64)
    umin = np.maximum(umin, 0)
    vmin = np.maximum(vmin, 0)
    umax = np.minimum(umax, C - 1)
    vmax = np.minimum(vmax, R - 1)
    return umin, umax, vmin, vmax


@dataclass(frozen=True)
class _TriTerms:
    """Per-triangle arrays of :func:`rasterize_triangles` (all of length m): the box corners as
    floats (cell units), the query-independent terms of :func:`_bary` (``a0 .. den``, and the
    third corner ``p2u, p2v``), the corner values ``tz`` (m, 3) and the write ``rank``."""

    umin: np.ndarray
    umax: np.ndarray
    vmin: np.ndarray
    vmax: np.ndarray
    a0: np.ndarray
    b0: np.ndarray
    a1: np.ndarray
    b1: np.ndarray
    den: np.ndarray
    p2u: np.ndarray
    p2v: np.ndarray
    tz: np.ndarray
    rank: np.ndarray


def _triangle_terms(tu, tv, tz, umin, umax, vmin, vmax, w, h) -> _TriTerms:
    """The triangle-only terms of the barycentric formula, evaluated as :func:`_bary` does, and
    the write order of a cell covered by several triangles: the rank of each triangle in the
    order (size class ``ceil(log2(max(w, h)))``, input index)."""
    size_class = np.ceil(np.log2(np.maximum(np.maximum(w, h), 1))).astype(np.int64)
    rdt = np.int32 if len(tu) < 2**31 - 1 else np.int64
    rank = np.empty(len(tu), rdt)
    rank[np.argsort(size_class, kind="stable")] = np.arange(len(tu), dtype=rdt)
    p0u, p1u, p2u = tu[:, 0], tu[:, 1], tu[:, 2]
    p0v, p1v, p2v = tv[:, 0], tv[:, 1], tv[:, 2]
    a0, b0 = p1v - p2v, p2u - p1u
    a1, b1 = p2v - p0v, p0u - p2u
    den = a0 * b1 + b0 * (p0v - p2v)
    return _TriTerms(umin.astype(np.float64), umax.astype(np.float64), vmin.astype(np.float64), vmax.astype(np.float64),
                     a0, b0, a1, b1, den, p2u, p2v, tz, rank)


def _rasterize_groups(tris: _TriTerms, w, h, out, tflat, chunk: int) -> int:
    """Evaluate the triangles in groups of equal stencil (box rounded up to 1, 2, 3, 4, 6, ...
    cells per direction), at most ``chunk`` cells per array operation, and write each covered
    cell once (:func:`_write_last`). Returns the number of (triangle, cell) hits."""
    R, C = out.shape
    last = np.full(R * C, -1, tris.rank.dtype)  # rank of the triangle that wrote each cell
    oflat = out.reshape(-1) if out.flags.c_contiguous else None
    written = 0
    sizes = _STENCIL_SIZES
    kw = np.searchsorted(sizes, w)
    kh = np.searchsorted(sizes, h)
    group = kh * len(sizes) + kw
    order = np.lexsort((tris.rank, group))
    for g in np.split(order, np.flatnonzero(np.diff(group[order])) + 1):
        sw, sh = int(sizes[kw[g[0]]]), int(sizes[kh[g[0]]])
        ov, ou = np.divmod(np.arange(sw * sh, dtype=np.float64), sw)
        step = max(1, chunk // (sw * sh))
        for start in range(0, len(g), step):
            f, val, rk = _covered_cells(tris, g[start : start + step], ou, ov, C, tflat)
            if len(f) == 0:
                continue
            written += len(f)
            _write_last(out, oflat, last, f, val, rk)
    return written


def _covered_cells(tris: _TriTerms, I, ou, ov, C: int, tflat):
    """The cells of the stencil ``(ou, ov)`` placed at the boxes of triangles ``I`` whose centres
    lie inside the triangle (barycentric ≥ −``_EPS``, the arithmetic of :func:`_bary`) and in
    the target. Returns ``(flat cell index, interpolated value, triangle rank)`` per hit."""
    # cell centres as floats (exact integers): the same differences as int - float
    cu = tris.umin[I, None] + ou
    cv = tris.vmin[I, None] + ov
    m = (cu <= tris.umax[I, None]) & (cv <= tris.vmax[I, None])
    qu = cu - tris.p2u[I, None]
    qv = cv - tris.p2v[I, None]
    d = tris.den[I, None]
    with np.errstate(divide="ignore", invalid="ignore"):  # zero-area triangles: nan/inf
        l0 = (tris.a0[I, None] * qu + tris.b0[I, None] * qv) / d
        l1 = (tris.a1[I, None] * qu + tris.b1[I, None] * qv) / d
        l2 = 1.0 - l0 - l1
    m &= (l0 >= -_EPS) & (l1 >= -_EPS) & (l2 >= -_EPS)
    k = np.flatnonzero(m)
    f = (cv.ravel()[k] * C + cu.ravel()[k]).astype(np.int64)
    if tflat is not None:
        hit = tflat.take(f)
        k, f = k[hit], f[hit]
    if len(k) == 0:
        return f, None, None
    t = I[k // len(ou)]
    tz = tris.tz
    with np.errstate(invalid="ignore"):
        val = l0.ravel()[k] * tz[t, 0] + l1.ravel()[k] * tz[t, 1] + l2.ravel()[k] * tz[t, 2]
    return f, val, tris.rank[t]


def _write_last(out, oflat, last, f, val, rk) -> None:
    """Write ``val`` into the cells ``f`` of ``out``, keeping for each cell the value of its
    highest-ranked triangle so far (``last`` holds the rank that wrote each cell), so repeated
    cells get a defined winner whatever the grouping."""
    np.maximum.at(last, f, rk)  # well defined for repeated cells, unlike last[f] = rk
    win = last.take(f) == rk  # one write per cell: its highest-ranked triangle
    f, val = f[win], val[win]
    if oflat is not None:
        oflat[f] = val
    else:
        C = out.shape[1]
        out[f // C, f % C] = val


def _dilate(mask: np.ndarray, iterations: int) -> np.ndarray:
    from scipy.ndimage import binary_dilation

    return binary_dilation(mask, structure=np.ones((3, 3), bool), iterations=iterations)


def _tie_pairs(pu, pv, s, nb) -> tuple[np.ndarray, np.ndarray]:
    """Pairs ``(t, n)`` of neighbouring triangles whose four corners lie on one circle within
    :data:`TIE`: the angles opposite their shared edge sum to π (both Delaunay splits of the
    quad are valid), each angle well away from 0 and π (no sliver)."""
    m = len(s)
    t = np.repeat(np.arange(m), 3)
    k = np.tile(np.arange(3), m)
    n = nb.ravel()
    keep = n > t  # each interior edge once
    t, k, n = t[keep], k[keep], n[keep]
    a, p, q = s[t, k], s[t, (k + 1) % 3], s[t, (k + 2) % 3]
    c = s[n].sum(1) - p - q  # the corner of n off the shared edge pq

    def angle_terms(o):
        e1u, e1v, e2u, e2v = pu[p] - pu[o], pv[p] - pv[o], pu[q] - pu[o], pv[q] - pv[o]
        norm = np.sqrt((e1u * e1u + e1v * e1v) * (e2u * e2u + e2v * e2v))
        return np.abs(e1u * e2v - e1v * e2u), e1u * e2u + e1v * e2v, norm

    sa, ca, na = angle_terms(a)
    sc, cc, nc = angle_terms(c)
    with np.errstate(invalid="ignore"):
        tie = (np.abs(sa * cc + ca * sc) <= TIE * na * nc) & (ca * cc - sa * sc < 0)
        tie &= (sa > TIE * na) & (sc > TIE * nc)
    return t[tie], n[tie]


def canonical_ties(pu, pv, s, nb) -> np.ndarray:
    """Delaunay triangles ``s`` (neighbours ``nb``, as scipy gives them) with every set of
    co-circular corners (within :data:`TIE`) triangulated by a fixed rule.

    Where four or more points lie on one empty circle (a lattice of points, a rectangle of
    cells) every split is a Delaunay triangulation and Qhull's choice follows the rounding of
    the coordinates; so the same points in another unit get another TIN. Here the triangles
    joined by such tied edges (a convex polygon inscribed in the circle) are replaced by the fan
    from their corner of lowest index, the corners taken in angular order; point indices are in
    row-major cell order, so a tied lattice quad is split along AD as in :func:`lattice_tin`.
    A group whose triangles do not make a fan of its corners (not a simple convex polygon) is
    left as Qhull made it.
    """
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    t, n = _tie_pairs(pu, pv, s, nb)
    if len(t) == 0:
        return s
    m = len(s)
    lab = connected_components(coo_matrix((np.ones(len(t)), (t, n)), shape=(m, m)), directed=False)[1]
    size = np.bincount(lab)
    group = np.flatnonzero(size[lab] > 1)  # triangles in a tie group
    glab = lab[group]
    # the corners of each group, once each, in angular order around their mean from the lowest index
    pairs = np.unique(np.column_stack([np.repeat(glab, 3), s[group].ravel()]), axis=0)
    pl, pi = pairs[:, 0], pairs[:, 1]
    cnt = np.bincount(pl, minlength=len(size))
    cu = np.bincount(pl, pu[pi], minlength=len(size)) / np.maximum(cnt, 1)
    cv = np.bincount(pl, pv[pi], minlength=len(size)) / np.maximum(cnt, 1)
    ang = np.arctan2(pv[pi] - cv[pl], pu[pi] - cu[pl])
    first = np.flatnonzero(np.r_[True, pl[1:] != pl[:-1]])  # pairs are sorted by (group, index)
    start = np.repeat(ang[first], cnt[pl[first]])
    order = np.lexsort((np.mod(ang - start, 2 * np.pi), pl))
    pl, pi = pl[order], pi[order]
    pos = np.arange(len(pl)) - np.repeat(first, cnt[pl[first]])
    ok = cnt - 2 == size  # a fan of k corners has k - 2 triangles
    mid = np.flatnonzero((pos >= 1) & (pos < cnt[pl] - 1) & ok[pl])
    fan = np.column_stack([pi[np.repeat(first, cnt[pl[first]])][mid], pi[mid], pi[mid + 1]])
    drop = np.zeros(m, bool)
    drop[group[ok[glab]]] = True
    return np.concatenate([s[~drop], fan.astype(s.dtype)])


def fill_voids_tin(out, du, dv, z, valid, max_edge: float | None = None, rim: int = 1) -> np.ndarray:
    """Fill the NaN cells of ``out`` from a Delaunay TIN of the occupied cells on void rims.

    Parameters
    ----------
    out : (rows, cols) float64
        Values so far; NaN cells are the voids to fill (modified copy returned).
    du, dv, z, valid : (rows, cols)
        Representatives as in :func:`lattice_tin`.
    max_edge : float, optional
        Triangles with an edge longer than this (cells) leave their cells NaN.
    rim : int
        Width in cells of the rim around voids whose points enter the triangulation.

    Returns
    -------
    (rows, cols) float64
        ``out`` with voids inside the convex hull of the points filled.
    """
    from scipy.spatial import Delaunay
    from scipy.spatial import QhullError

    out = out.copy()
    voids = np.isnan(out)
    if not voids.any():
        return out
    sel = valid & _dilate(voids, rim)
    ii, jj = np.nonzero(sel)
    if len(ii) < 3:
        return out
    pu = jj + du[ii, jj]
    pv = ii + dv[ii, jj]
    pz = z[ii, jj]
    try:
        tri = Delaunay(np.column_stack([pu, pv]))
    except (QhullError, ValueError):
        return out  # collinear or too few distinct points: nothing to triangulate
    s = canonical_ties(pu, pv, tri.simplices, tri.neighbors)
    tu, tv, tz = pu[s], pv[s], pz[s]
    if max_edge is not None:
        ok = _edges_ok(tu.T, tv.T, max_edge)
        tu, tv, tz = tu[ok], tv[ok], tz[ok]
    rasterize_triangles(tu, tv, tz, out, target=voids)
    return out


def tin_surface(du, dv, z, valid, max_edge: float | None = None, tile: int = 1024) -> np.ndarray:
    """Full TIN surface at every cell centre: lattice triangles by tiles, then void filling.

    The lattice step is local (a cell needs its 8 neighbours), so tiles of ``tile`` cells with
    a one-cell overlap give exactly the untiled result while bounding temporary memory.
    """
    R, C = z.shape
    out = np.full((R, C), np.nan)
    for r0 in range(0, R, tile):
        for c0 in range(0, C, tile):
            ra, rb = max(r0 - 1, 0), min(r0 + tile + 1, R)
            ca, cb = max(c0 - 1, 0), min(c0 + tile + 1, C)
            part = lattice_tin(du[ra:rb, ca:cb], dv[ra:rb, ca:cb], z[ra:rb, ca:cb], valid[ra:rb, ca:cb], max_edge)
            out[r0 : min(r0 + tile, R), c0 : min(c0 + tile, C)] = part[r0 - ra : r0 - ra + min(tile, R - r0), c0 - ca : c0 - ca + min(tile, C - c0)]
    return fill_voids_tin(out, du, dv, z, valid, max_edge)
