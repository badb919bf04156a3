"""Building footprints from building-class points.

The raster method of the laser scanning notes (Vosselman & Maas 2010, ch. 4; Rottensteiner &
Briese 2002), with the occupancy raster replaced by a smoothed density so edges are placed
without the bias of occupied cells:

1. Rasterise the points (cell ``s / 2``), smooth the counts with a Gaussian (sigma
   ``CORNER_RADIUS * s``) and divide by the typical roof density (measured in the cores of the
   roofs, away from their margins): the level 0.5 of that field lies on a straight roof edge
   without bias (a symmetric kernel over a half-plane integrates to one half at its edge), and
   gaps between scan lines vanish.
2. Threshold at 0.5, fill holes, label the connected components (scipy.ndimage).
3. Trace each outline (contourpy, marching squares with sub-cell interpolation).
4. Orthogonal buildings (Sampath & Shan 2007: most buildings are orthogonal): rotate the points
   into the frame of their minimum-area rectangle, rasterise them again, open and close the mask
   with a square of the Douglas-Peucker tolerance, trace it, keep axis-parallel edges, merge
   parallel runs, and move every edge to its maximum-likelihood place among the points
   (:func:`_rectilinear`). When the points do not fit that outline (:func:`_outline`: too
   few of them for its area, or an empty region in it that chance would not leave, :func:`_vacancy`),
   it is fitted again with the finer ``FINE_RADIUS`` (which keeps short wings and stems: the
   corner regions the tracing breaks into slanted pieces are rebuilt as axis-parallel steps, a
   rectilinear Douglas-Peucker, and steps the points do not support by the Bayesian information
   criterion are taken out again), and when neither fits, with ``FINEST_RADIUS`` (a wing a few
   metres wide is only a few spacings wide at a low density); the outline under which the points
   are likeliest is kept (:func:`_cost`).
5. Other buildings: Douglas-Peucker (Douglas & Peucker 1973) and snapping of the edges within
   their angular uncertainty of the dominant direction (:func:`regularize`); when no rectilinear
   outline agrees with the traced one, the likeliest of them and that one is kept.

All lengths derive from the nominal point spacing ``s = 1 / sqrt(density)`` (estimated from the
nearest-neighbour distances when not given): cell ``s / 2``, smoothing ``2.5 s`` (and ``1.5 s``, ``s``),
Douglas-Peucker tolerance ``2.5 s`` (about 3.5 times the lateral noise of the half-density
outline of randomly sampled points, 0.7 s), snapping tolerance ``atan(2 s / L)`` for an edge of
length L, clamped to 5-30 degrees, edge ends ``s`` left out when points place an edge, points
outside every region joined to the nearest within ``2.93 s`` (``ASSIGN_REACH``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from statistics import NormalDist

import numpy as np


@dataclass(frozen=True)
class FootprintParams:
    """Parameters of :func:`extract_footprints`.

    Attributes
    ----------
    spacing : float or None
        Nominal point spacing 1/sqrt(density) (m); None estimates it as twice the median 2-D
        nearest-neighbour distance (the Poisson relation for random sampling).
    min_area : float
        Smallest footprint kept (m^2).
    min_snap_deg : float
        Smallest snapping tolerance (degrees) for long edges.
    max_snap_deg : float
        Largest snapping tolerance (degrees) for short edges.
    """

    spacing: float | None = None
    min_area: float = 10.0
    min_snap_deg: float = 5.0
    max_snap_deg: float = 30.0


@dataclass(frozen=True)
class Footprint:
    """One building outline.

    Attributes
    ----------
    polygon : (k, 2) float64
        Counter-clockwise outer ring without the repeated first vertex (m, absolute).
    source : str
        ``"points"`` (traced) or ``"given"``.
    """

    polygon: np.ndarray
    source: str = "points"

    @property
    def area(self) -> float:
        x, y = self.polygon[:, 0], self.polygon[:, 1]
        return float(0.5 * (np.dot(x, _nxt(y)) - np.dot(y, _nxt(x))))


def _nxt(a: np.ndarray) -> np.ndarray:
    """``a`` shifted by one along its first axis, the first row last (``np.roll(a, -1, 0)``
    without its general-axis overhead: rings are short and walked many times)."""
    return np.concatenate([a[1:], a[:1]])


def _prv(a: np.ndarray) -> np.ndarray:
    """``a`` shifted the other way, the last row first (``np.roll(a, 1, 0)``)."""
    return np.concatenate([a[-1:], a[:-1]])


def _norm(v: np.ndarray) -> np.ndarray:
    """Row lengths of (m, d) vectors, summed and rooted as ``np.linalg.norm(v, axis=1)`` does."""
    return np.sqrt(np.add.reduce(v * v, axis=1))


def nominal_spacing(xy: np.ndarray, threads: int = 1) -> float:
    """1/sqrt(density) (m) from the median 2-D nearest-neighbour distance (Poisson: d = 0.5 s),
    the neighbours looked up on ``threads`` threads. Where more than half the points repeat
    another (the median is 0), that of the distinct points; NaN for fewer than two of them."""
    from scipy.spatial import cKDTree

    if len(xy) < 2:
        return float("nan")
    d, _ = cKDTree(xy).query(xy, k=2, workers=threads)
    s = float(2.0 * np.median(d[:, 1]))
    if s > 0:
        return s
    distinct = np.unique(xy, axis=0)
    return nominal_spacing(distinct, threads) if len(distinct) < len(xy) else float("nan")


def douglas_peucker(ring: np.ndarray, tol: float) -> np.ndarray:
    """Indices of the vertices of a closed ring (k, 2) kept by Douglas-Peucker at ``tol`` (m).

    The ring is split at its two mutually farthest vertices (from vertex 0) so both halves are
    open polylines.

    >>> sq = np.array([[0, 0], [1, 0.01], [2, 0], [2, 1], [2, 2], [0, 2], [0, 1]], float)
    >>> douglas_peucker(sq, 0.1).tolist()
    [0, 2, 4, 5]
    """
    far = int(np.argmax(np.linalg.norm(ring - ring[0], axis=1)))
    keep = np.zeros(len(ring), bool)
    keep[[0, far]] = True
    closed = np.vstack([ring, ring[:1]])
    stack = [(0, far), (far, len(ring))]
    while stack:
        a, b = stack.pop()
        if b - a < 2:
            continue
        p, q = closed[a], closed[b]
        seg = closed[a + 1:b] - p
        d = q - p
        ln = math.hypot(*d)
        dist = np.abs(seg[:, 0] * d[1] - seg[:, 1] * d[0]) / ln if ln > 0 else np.linalg.norm(seg, axis=1)
        i = int(np.argmax(dist))
        if dist[i] > tol:
            m = a + 1 + i
            keep[m] = True
            stack += [(a, m), (m, b)]
    return np.flatnonzero(keep)


#: Radius (in point spacings) of the Gaussian that smooths the density (sigma); the level-0.5
#: outline rounds a right-angled corner over about this distance.
CORNER_RADIUS = 2.5

#: Douglas-Peucker tolerance (in point spacings): about 3.5 times the lateral noise of the
#: half-density outline of randomly sampled points (0.7 s, see :func:`regularize`).
DP_TOLERANCE = 2.5

#: Smoothing (in point spacings) of the second rectilinear candidate: it keeps wings and stems
#: a few metres long that the wider smoothing rounds away (see :func:`_outline`).
FINE_RADIUS = 1.5

#: Smoothing (in point spacings) of the third candidate, fitted when neither of the others
#: explains the points (:func:`_outline`): at a low density a wing a few metres wide is only a
#: few spacings wide, and one spacing (two cells) still resolves it.
FINEST_RADIUS = 1.0

#: log(roof density / density of stray points outside a roof): what leaving a point outside an
#: outline costs against the empty area inside it (strays at 5 % of the roof density).
STRAY_WEIGHT = 3.0

#: Significance level of the empty-space test of the first outline (:func:`_vacancy`): the
#: expected number of empty regions as large as its largest, under which the finer pass is tried.
VACANCY_LEVEL = 0.05

#: Length (in point spacings) left out at both ends of an edge when its points place it: the
#: corner's own uncertainty, so points of a wing that meets the edge are not taken for its own.
EDGE_MARGIN = 1.0

#: Reach (in point spacings) within which a point outside every region joins the nearest one
#: (:func:`district_components`). The level-0.5 line of the smoothed density passes a convex right
#: angle at ``sqrt(2) t`` smoothing radii from its corner, Phi(t)^2 = 1/2 (t = 0.545): 1.93
#: spacings, where the corner's own points lie. Along an edge the line wanders by the smoothed
#: count's Poisson noise over its slope there: standard deviation ``s / (sigma sqrt(8 pi))`` over
#: ``phi(0) / sigma``, half a spacing whatever the smoothing. The reach is the corner's distance
#: plus two such deviations (2.93 spacings), so the corner points that place the edges are kept.
ASSIGN_REACH = math.sqrt(2) * NormalDist().inv_cdf(math.sqrt(0.5)) * CORNER_RADIUS + 2 * 0.5


def _dominant_direction_rect(p: np.ndarray) -> float:
    """Direction of the minimum-area rectangle of a ring (radians), refined by the
    length-weighted mean of the edges within 15 degrees of it (modulo 90 degrees)."""
    import shapely

    rect = np.asarray(shapely.minimum_rotated_rectangle(shapely.Polygon(p)).exterior.coords)
    e = rect[1] - rect[0]
    t0 = math.atan2(e[1], e[0])
    d = _nxt(p) - p
    ln = np.hypot(d[:, 0], d[:, 1])
    dev = (np.arctan2(d[:, 1], d[:, 0]) - t0 + np.pi / 4) % (np.pi / 2) - np.pi / 4
    near = np.abs(dev) < math.radians(15)
    if near.any():
        t0 += float((ln[near] * dev[near]).sum() / ln[near].sum())
    return t0


def _points_direction(pts: np.ndarray) -> float:
    """Direction (radians) of the minimum-area rectangle of a building's points: its sides rest
    on the outermost points, whose distance to the true edge shrinks as 1 / (density x length),
    unlike a smoothed outline's wander (square-root rate). The points go to GEOS as one line
    string (its rectangle is that of the vertices' convex hull, as for a multipoint, without
    making a point object per vertex)."""
    import shapely

    if len(pts) < 2:
        return 0.0
    # points on a line have a line for rectangle, one spot a point: its direction, or 0
    rect = shapely.get_coordinates(shapely.minimum_rotated_rectangle(shapely.linestrings(pts)))
    e = rect[1] - rect[0] if len(rect) > 1 else np.array([1.0, 0.0])
    return math.atan2(e[1], e[0])


def _edges(ring, keep):
    """Traced points (list of (m, 2)) and chord vectors (e, 2) of the ring between kept vertices."""
    nxt = _nxt(np.arange(len(keep)))
    segs = [ring[keep[i]:keep[nxt[i]] + 1] if keep[nxt[i]] > keep[i] else np.vstack([ring[keep[i]:], ring[:keep[nxt[i]] + 1]])
            for i in range(len(keep))]
    return segs, ring[keep[nxt]] - ring[keep]


def _classify(chords, theta0, spacing, params):
    """Class of each edge: 0 along theta0, 1 perpendicular, -1 free (outside the snapping
    tolerance atan(2 s / L), clamped to [min_snap_deg, max_snap_deg])."""
    L = np.hypot(chords[:, 0], chords[:, 1])
    tol = np.clip(np.degrees(np.arctan(2 * spacing / np.maximum(L, 1e-9))), params.min_snap_deg, params.max_snap_deg)
    th = np.arctan2(chords[:, 1], chords[:, 0])
    dev = (th - theta0 + np.pi / 4) % (np.pi / 2) - np.pi / 4
    c = np.round((th - dev - theta0) / (np.pi / 2)).astype(int) % 2
    return np.where(np.abs(np.degrees(dev)) < tol, c, -1), L


def _joint_direction(segs, cls, trim):
    """Common orientation (radians) of all snapped edges, class 1 perpendicular to class 0:
    the normal n minimising sum over class-0 edges of n' C n plus class-1 edges of n_perp' C
    n_perp (C the scatter of each edge's traced points, ``trim`` metres cut at both ends to
    skip the rounded corners)."""
    M = np.zeros((2, 2))
    R = np.array([[0.0, -1.0], [1.0, 0.0]])
    for sg, c in zip(segs, cls):
        if c < 0 or len(sg) < 3:
            continue
        sel = _trimmed(sg, trim)
        d = sel - sel.mean(axis=0)
        C = d.T @ d
        M += C if c == 0 else R.T @ C @ R
    w, v = np.linalg.eigh(M)
    n = v[:, 0]
    return math.atan2(n[1], n[0]) - math.pi / 2  # the class-0 direction is perpendicular to n


def _trimmed(sg: np.ndarray, trim: float) -> np.ndarray:
    """Traced points of an edge without ``trim`` metres at each end (all if too short)."""
    t = np.concatenate([[0.0], np.cumsum(_norm(sg[1:] - sg[:-1]))])
    sel = sg[(t > trim) & (t < t[-1] - trim)]
    return sel if len(sel) >= 2 else sg


def _lines(segs, chords, cls, theta0, trim):
    """Unit direction and mean point of each edge (snapped edges use theta0 or theta0 + 90),
    from its traced points without the rounded corners (``trim`` metres at each end)."""
    dirs, pts = [], []
    segs = [_trimmed(sg, trim) for sg in segs]
    for sg, d, c in zip(segs, chords, cls):
        if c >= 0:
            t = theta0 + c * math.pi / 2
        elif len(sg) > 2:
            _, _, vt = np.linalg.svd(sg - sg.mean(0), full_matrices=False)
            t = math.atan2(vt[0, 1], vt[0, 0])
        else:
            t = math.atan2(d[1], d[0])
        u = np.array([math.cos(t), math.sin(t)])
        dirs.append(u if np.dot(u, d) >= 0 else -u)
        pts.append(sg.mean(axis=0))
    return np.array(dirs), np.array(pts)


def _merge_runs(dirs, pts, cls, weights, tol):
    """Merge consecutive snapped edges of one class whose lines lie within ``tol`` (m) (a
    length-weighted mean line); join those further apart by a perpendicular step."""
    change = cls != _prv(cls)
    start = int(np.flatnonzero(change)[0]) if change.any() else 0
    order = np.concatenate([np.arange(start, len(cls)), np.arange(start)])
    out = []  # [dir, point, class, weight]
    for i in order:
        d, p, c, w = dirs[i], pts[i], cls[i], weights[i]
        if out and c >= 0 and out[-1][2] == c:
            d0, p0, _, w0 = out[-1]
            nrm = np.array([-d0[1], d0[0]])
            gap = float(np.dot(p - p0, nrm))
            if abs(gap) < tol:
                out[-1] = [d0, p0 + nrm * gap * w / (w0 + w) + d0 * np.dot(p - p0, d0) * w / (w0 + w), c, w0 + w]
                continue
            out.append([nrm if np.dot(nrm, p - p0) > 0 else -nrm, 0.5 * (p0 + p), 1 - c, 0.0])
        out.append([d, p, c, w])
    if len(out) > 1 and out[0][2] >= 0 and out[0][2] == out[-1][2]:  # first and last may be one line
        d0, p0, c, w0 = out[-1]
        d1, p1, _, w1 = out[0]
        nrm = np.array([-d0[1], d0[0]])
        gap = float(np.dot(p1 - p0, nrm))
        if abs(gap) < tol:
            out[0] = [d1, p0 + nrm * gap * w1 / (w0 + w1), c, w0 + w1]
            out.pop()
    return np.array([o[0] for o in out]), np.array([o[1] for o in out]), np.array([o[2] for o in out])


def edge_intersections(dirs, pts):
    """Corner k = intersection of edge line k-1 and edge line k."""
    prev = _prv(np.arange(len(dirs)))
    u, v = dirs[prev], dirs
    p, q = pts[prev], pts
    cross = u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
    w = q - p
    t = (w[:, 0] * v[:, 1] - w[:, 1] * v[:, 0]) / np.where(np.abs(cross) < 1e-12, np.nan, cross)
    out = p + t[:, None] * u
    bad = ~np.isfinite(out).all(axis=1)
    out[bad] = 0.5 * (p[bad] + q[bad])
    return out


def regularize(ring: np.ndarray, spacing: float, params: FootprintParams = FootprintParams(),
               direction: float | None = None) -> np.ndarray:
    """Douglas-Peucker then orthogonal regularisation of a traced closed ring (k, 2) (m).

    Douglas-Peucker at ``DP_TOLERANCE`` spacings; short free edges at corners (chamfers of the smoothed outline,
    under 3 smoothing radii) are dropped; snapped edges share one orientation fitted to all of
    them (or ``direction``, radians, when given: a building part takes its footprint's);
    consecutive parallel lines closer than the Douglas-Peucker tolerance are merged.
    Returns the counter-clockwise polygon (m, 2); when regularisation fails, the simplified ring,
    or where that crosses itself the outer ring of its largest part (:func:`_simple_ring`).
    """
    import shapely

    ring = ccw(ring)
    tol = DP_TOLERANCE * spacing
    keep = douglas_peucker(ring, tol)
    if len(keep) < 3:
        return ring
    simple = ring[keep]
    segs, chords = _edges(ring, keep)
    theta0 = _dominant_direction_rect(simple) if direction is None else float(direction)
    cls, L = _classify(chords, theta0, spacing, params)
    if (cls >= 0).any() and direction is None:
        theta0 = _joint_direction(segs, cls, 2 * CORNER_RADIUS * spacing)
        cls, L = _classify(chords, theta0, spacing, params)
    chamfer = (cls < 0) & (L < 3.0 * CORNER_RADIUS * spacing)
    if (~chamfer).sum() >= 3:
        segs = [sg for sg, c in zip(segs, chamfer) if not c]
        chords, cls, L = chords[~chamfer], cls[~chamfer], L[~chamfer]
    dirs, pts = _lines(segs, chords, cls, theta0, 2 * CORNER_RADIUS * spacing)
    dirs, pts, cls = _merge_runs(dirs, pts, cls, L, tol)
    if len(dirs) < 3:
        return _simple_ring(simple, ring)
    poly = _drop_short(edge_intersections(dirs, pts), spacing / 4)
    if len(poly) < 3 or not shapely.is_valid(shapely.Polygon(poly)):
        return _simple_ring(simple, ring)
    reg, ref = shapely.Polygon(poly), shapely.Polygon(simple)
    if not shapely.is_valid(ref):  # a simplified ring may cross itself: the area it encloses
        ref = shapely.make_valid(ref, method="structure", keep_collapsed=False)
    if reg.symmetric_difference(ref).area > 0.25 * ref.area:  # regularisation went astray
        return _simple_ring(simple, ring)
    return ccw(poly)


def _simple_ring(ring: np.ndarray, fallback: np.ndarray) -> np.ndarray:
    """``ring`` (k, 2) when it bounds a valid polygon; else (a simplified ring may cross itself)
    the counter-clockwise outer ring of the largest polygon of its repair by
    ``shapely.make_valid(method="structure")``, which keeps the area the ring encloses (a
    bow-tie's two triangles) where the shoelace sum of a crossing ring cancels part of it; or
    ``fallback`` when that repair leaves no area."""
    import shapely

    poly = shapely.Polygon(ring)
    if shapely.is_valid(poly):
        return ring
    parts = shapely.get_parts(shapely.make_valid(poly, method="structure", keep_collapsed=False))
    parts = parts[(shapely.get_type_id(parts) == 3) & (shapely.area(parts) > 0)]  # polygons
    if not len(parts):
        return fallback
    return ccw(shapely.get_coordinates(shapely.get_exterior_ring(parts[np.argmax(shapely.area(parts))]))[:-1])


def _drop_short(poly: np.ndarray, tol: float) -> np.ndarray:
    """Remove vertices closer than ``tol`` (m) to the previous one and collinear vertices."""
    if len(poly) < 4:
        return poly
    d = _norm(poly - _prv(poly))
    poly = poly[d > tol] if (d > tol).sum() >= 3 else poly
    a, b = _prv(poly) - poly, _nxt(poly) - poly
    cross = np.abs(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]) / np.maximum(_norm(a) * _norm(b), 1e-12)
    keep = cross > 1e-6
    return poly[keep] if keep.sum() >= 3 else poly


def ccw(ring: np.ndarray) -> np.ndarray:
    x, y = ring[:, 0], ring[:, 1]
    area = 0.5 * (np.dot(x, _nxt(y)) - np.dot(y, _nxt(x)))
    return ring if area > 0 else ring[::-1].copy()


def density_field(xy: np.ndarray, spacing: float, ref: float | None = None, radius: float = CORNER_RADIUS,
                  threads: int = 1):
    """Smoothed point density on a raster of cell ``spacing / 2`` (Gaussian, sigma ``radius``
    spacings), normalised so the interior of a roof is 1 (by ``ref``, the smoothed count per
    cell of a roof, estimated by :func:`_roof_density` when None): the level 0.5 then lies on a
    straight roof edge without bias (a symmetric kernel over a half-plane integrates to one half
    at its edge). The smoothing and the roof cores are computed on ``threads`` threads
    (:func:`_by_bands`).

    Returns (field (rows, cols), origin (2,), cell, ref); rows follow y.
    """
    cell = spacing / 2
    sig = radius * spacing / cell
    pad = int(math.ceil(3 * sig)) + 2
    origin = xy.min(axis=0) - pad * cell
    ij = np.floor((xy - origin) / cell).astype(np.int64)
    shape = (int(ij[:, 1].max()) + pad + 1, int(ij[:, 0].max()) + pad + 1)
    counts = np.bincount(ij[:, 1] * shape[1] + ij[:, 0], minlength=shape[0] * shape[1]).reshape(shape).astype(float)
    field = _smooth(counts, sig, threads)
    if ref is None:
        ref = _roof_density(counts, field, sig, threads)
    return field / ref, origin, cell, ref


def _by_bands(fn, a: np.ndarray, reach: int, threads: int) -> np.ndarray:
    """``fn(a)`` for a filter ``fn`` whose every output row depends on the input rows within
    ``reach`` of it only, computed by bands of rows on ``threads`` threads (ndimage lets go of
    the GIL). Each band is filtered with ``reach`` rows of context on either side (the raster's
    own edge where it ends), so every value comes from the same inputs in the same order as over
    the whole raster: the same bits."""
    from concurrent.futures import ThreadPoolExecutor

    rows = a.shape[0]
    if threads <= 1 or rows < 64 * threads:
        return fn(a)
    cuts = np.linspace(0, rows, 2 * threads + 1).astype(int)
    out = None

    def band(lo_row, hi_row):
        lo, hi = max(lo_row - reach, 0), min(hi_row + reach, rows)
        return lo_row, hi_row, fn(a[lo:hi])[lo_row - lo:hi_row - lo]

    with ThreadPoolExecutor(threads) as ex:
        for lo_row, hi_row, part in ex.map(band, cuts[:-1], cuts[1:]):
            if out is None:
                out = np.empty(a.shape, part.dtype)
            out[lo_row:hi_row] = part
    return out


def _smooth(counts: np.ndarray, sig: float, threads: int) -> np.ndarray:
    """``scipy.ndimage.gaussian_filter(counts, sig, mode="constant", truncate=3.0)`` by bands of
    rows on ``threads`` threads (:func:`_by_bands`, with the kernel's reach)."""
    from scipy import ndimage

    reach = int(3.0 * sig + 0.5) + 1  # the kernel's radius in scipy, plus one
    return _by_bands(lambda a: ndimage.gaussian_filter(a, sig, mode="constant", truncate=3.0), counts, reach, threads)


#: Smallest sigma (cells, half a point spacing) at which :func:`_roof_density` looks for roof
#: cores; a Gaussian kernel of sigma s cells weighs as many cells as 4 pi s^2 equal ones, at the
#: nominal spacing a quarter point each, so at 1 cell it still averages about three (pi) points.
MIN_SIGMA = 1.0


def _roof_density(counts: np.ndarray, field: np.ndarray, sig: float, threads: int = 1) -> float:
    """Typical smoothed roof density of ``field``, the point ``counts`` per cell smoothed with
    sigma ``sig`` (cells): the median over the cells at least two sigmas inside the half-density
    mask, where the kernel lies wholly on the roof (a straight edge at two sigmas still lowers the
    field by 2.3 %); the margins, where the field falls off to half and below, would bias it low
    and move every outline out (:func:`_core_median`).

    Where no core as large as the erosion square remains (a building processed alone that is
    narrower than about four sigmas plus the mask's margin), the counts are smoothed again with
    half the sigma, down to :data:`MIN_SIGMA`, until cores remain: a normalised kernel keeps the
    mean count of a roof's interior at every scale, so only the spread of the estimate grows (a
    kernel of half the sigma averages a quarter of the points) while the erosion shrinks by half.
    Without a core at any scale, the first level of :func:`_core_median` at the finest one (tiny
    buildings only).
    """
    ref, first = _core_median(field, sig, threads)
    while ref is None and sig / 2 >= MIN_SIGMA:
        sig /= 2
        ref, first = _core_median(_smooth(counts, sig, threads), sig, threads)
    return first if ref is None else ref


def _core_median(field: np.ndarray, sig: float, threads: int = 1):
    """(median of ``field`` over its cores or None, first level) for a field smoothed with sigma
    ``sig`` (cells); None when no core as large as the erosion square remains.

    The first level is the median over covered cells, twice (the second without the thin
    margins); the cores are the cells at least two sigmas inside the mask above half of it. Dense
    facade lines of a few cells do not move either median, unlike the maximum. The cores'
    minimum filter runs by bands of rows on ``threads`` threads (:func:`_by_bands`, the same result).
    """
    from scipy import ndimage

    covered = field[field > 1e-3 * field.max()]
    first = float(np.median(covered[covered > 0.5 * np.median(covered)]))
    size = 2 * int(math.ceil(2 * sig)) + 1
    core = _by_bands(lambda a: ndimage.minimum_filter(a, size=size), (field > 0.5 * first).view(np.uint8),
                     size // 2 + 1, threads)
    inner = field[core.view(bool)]
    return (float(np.median(inner)) if inner.size >= size * size else None), first


def fill_holes(mask: np.ndarray) -> np.ndarray:
    """``mask`` with every background region not touching the border set (4-connected
    background labelling, faster than iterative dilation)."""
    from scipy import ndimage

    lab, n = ndimage.label(~mask)
    outside = np.zeros(n + 1, bool)
    for edge in (lab[0], lab[-1], lab[:, 0], lab[:, -1]):
        outside[edge] = True
    return mask | ~outside[lab]


def building_mask(field: np.ndarray):
    """Half-density mask with holes filled, labelled into connected components."""
    from scipy import ndimage

    labels, _ = ndimage.label(fill_holes(field > 0.5))
    return labels


def trace_outline(field: np.ndarray, origin: np.ndarray, cell: float) -> np.ndarray:
    """Longest closed level-0.5 outline (k, 2) (m) of a density field (rows = y), marching
    squares with linear interpolation between cell centres."""
    import contourpy

    m = np.pad(np.asarray(field, np.float64), 1)
    gen = contourpy.contour_generator(z=m, name="serial", line_type=contourpy.LineType.Separate)
    ring = max(gen.lines(0.5), key=len)
    if np.all(np.abs(ring[0] - ring[-1]) <= 1e-8 + 1e-5 * np.abs(ring[-1])):  # np.allclose
        ring = ring[:-1]
    return origin + (ring - 1 + 0.5) * cell


def _rot(p: np.ndarray, theta: float) -> np.ndarray:
    c, s = math.cos(theta), math.sin(theta)
    return np.column_stack([p[:, 0] * c - p[:, 1] * s, p[:, 0] * s + p[:, 1] * c])


def _rectilinear(pts, ring, spacing, ref, radius):
    """Rectilinear outline of one building's points ``pts`` (m, 2) in its dominant frame (None
    when no valid one is found) and whether it agrees with the traced outline ``ring``.

    The points are rotated so the sides of their minimum-area rectangle
    (:func:`_points_direction`) are the axes and rasterised again there, smoothed with sigma
    ``radius`` spacings; the half-density mask is opened and closed with a square of the
    Douglas-Peucker tolerance (removing teeth and notches smaller than that), traced, and reduced
    to axis-parallel edges; each edge line is then moved to its maximum-likelihood place among
    the points (:func:`_fit_offsets`). It agrees when its symmetric difference with the
    traced outline ``ring`` is within 1.5 spacings times the perimeter (about 2.7 times what the
    outline's own lateral noise gives).
    """
    import shapely

    theta0 = _points_direction(pts)
    centre = ring.mean(axis=0)
    poly = _orthogonal_pass(_rot(pts - centre, -theta0), spacing, ref, radius)
    if poly is None:
        return None, False
    P, R = shapely.Polygon(poly), shapely.Polygon(_rot(ring - centre, -theta0))
    if not P.is_valid:
        return None, False
    return ccw(_rot(poly, theta0) + centre), P.symmetric_difference(R).area <= 1.5 * spacing * R.length


def _orthogonal_pass(rp, spacing, ref, radius):
    """One rectilinear fit of rotated points ``rp`` (m, 2), its edges along the axes: the
    polygon (k, 2) or None.

    When the smoothing ``radius`` (spacings) is narrower than the Douglas-Peucker tolerance, a
    feature of the tolerance's size (a wing, a stem, a notch) survives the smoothing and the
    opening, so the corner regions the tracing leaves as slanted pieces are rebuilt from
    axis-parallel steps (:func:`_axis_lines`) and the features the points do not support are
    taken out again (:func:`_supported`); the wider smoothing rounds such features away, and its
    corner regions are left to the lines on either side, as any corner."""
    from scipy import ndimage

    field, origin, cell, _ = density_field(rp, spacing, ref, radius)
    lab, n = ndimage.label(fill_holes(field > 0.5))
    if n == 0:
        return None
    mask = lab == 1 + int(np.argmax(np.bincount(lab.ravel())[1:]))
    k = max(1, int(round(DP_TOLERANCE * spacing / cell)))
    m8 = mask.view(np.uint8)
    m8 = ndimage.maximum_filter(ndimage.minimum_filter(m8, size=k), size=k)  # opening by a k x k square
    m8 = ndimage.minimum_filter(ndimage.maximum_filter(m8, size=k), size=k)  # closing
    mask = fill_holes(m8 > 0)
    if not mask.any():
        return None
    stair = ccw(trace_outline(mask.astype(float), origin, cell))
    keep = douglas_peucker(stair, cell)
    segs, chords = _edges(stair, keep)
    cls, L = _classify(chords, 0.0, spacing, FootprintParams(min_snap_deg=10.0, max_snap_deg=10.0))
    sel = cls >= 0
    if sel.sum() < 4:
        return None
    tol = DP_TOLERANCE * spacing
    resolved = radius < DP_TOLERANCE
    dirs, mids, c, w = _axis_lines(segs, chords, cls, L, tol if resolved else math.inf, cell)
    dirs, mids, c = _merge_runs(dirs, mids, c, w, tol)
    fit = _AxisFit(rp, tol, spacing, cell, ref / (cell * cell))
    poly = fit.polygon(dirs, mids)
    return _supported(fit, dirs, mids, c, poly) if resolved and poly is not None else poly


def _supported(fit, dirs, mids, cls, poly):
    """``poly`` without the notches, bumps and wings the points do not support.

    A feature is a pair of lines between two perpendicular ones (a notch or wing at a corner:
    without it the two meet) or the four lines after one up to a parallel one within the
    tolerance (a notch or bump in a side: without it the side runs straight on). The least
    supported feature is removed, the others refitted, while removing one raises the negative
    log-likelihood of the points (:func:`_cost`) by less than the Bayesian information
    criterion's price of its k lines, ``k log(n)`` for n points: half a log(n) (Schwarz 1978)
    for each line's offset and half for the place where it cuts its neighbours, a change point
    searched along the outline (Yao 1988). A notch stays when it is emptier than the density
    explains, given the points."""
    price = math.log(len(fit.rp))
    cost = fit.cost(poly)
    while len(dirs) > 4:
        best = None
        for drop in _features(cls, mids, fit.tol):
            keep = np.ones(len(dirs), bool)
            keep[drop] = False
            less = fit.polygon(dirs[keep], mids[keep])
            if less is None:
                continue
            rise = fit.cost(less) - cost - price * len(drop)
            if rise < 0 and (best is None or rise < best[0]):
                best = (rise, keep, less)
        if best is None:
            break
        _, keep, poly = best
        dirs, mids, cls, cost = dirs[keep], mids[keep], cls[keep], fit.cost(best[2])
    return poly


def _features(cls, mids, tol):
    """Index arrays of the removable features of alternating axis-parallel lines (class 0 along
    x, 1 along y; ``mids`` points on them), at least four lines left: two lines between
    perpendicular neighbours, or the four after a line up to a parallel one within ``tol`` (m)
    of it."""
    n = len(cls)
    out = []
    for i in range(n):
        j = (i + np.arange(1, 5)) % n
        if n - 2 >= 4 and cls[i] != cls[j[2]]:
            out.append(j[:2])
        if n - 4 >= 4 and cls[i] == cls[j[3]] and abs(mids[i, 1 - cls[i]] - mids[j[3], 1 - cls[i]]) < tol:
            out.append(j)
    return out


@dataclass(frozen=True)
class _AxisFit:
    """Polygons from alternating axis-parallel lines fitted to rotated points ``rp`` (m, 2), and
    their cost: each edge moved to its maximum-likelihood place (:func:`_fit_offsets`, ``tol``
    (m) either side, roof ``density`` per m^2)."""

    rp: np.ndarray
    tol: float
    spacing: float
    cell: float
    density: float

    def polygon(self, dirs, mids):
        """The polygon (k, 2) of the lines (unit directions, points on them), or None when it is
        not a valid one."""
        import shapely

        if len(dirs) < 4:
            return None
        corners = edge_intersections(dirs, mids)
        nxt = _nxt(corners)
        mids = _fit_offsets(dirs, 0.5 * (corners + nxt), _norm(nxt - corners), self.rp, self.tol,
                            EDGE_MARGIN * self.spacing, self.spacing, self.density, STRAY_WEIGHT)
        poly = _drop_short(edge_intersections(dirs, mids), self.cell / 2)
        if len(poly) < 4 or not shapely.is_valid(shapely.Polygon(poly)):
            return None
        return poly

    def cost(self, poly):
        """Negative log-likelihood of the points under ``poly`` (:func:`_cost`)."""
        return _cost(poly, self.rp, self.density, STRAY_WEIGHT)


def _axis_lines(segs, chords, cls, L, tol, cell):
    """Axis-parallel lines of a traced outline in its own frame: (dirs, points, classes, weights).

    Each snapped edge (class 0 along x, 1 along y) gives its line through its traced points. A
    run of free edges between two snapped ones (a corner region the tracing broke into short
    slanted pieces) is replaced by the axis-parallel steps that bring the outline within ``tol``
    of its traced points (:func:`_steps`): none at a plain corner, the two lines of a notch or a
    wing's end otherwise (never at an infinite ``tol``, where the steps are not looked for). Added
    lines weigh ``cell`` (m) against the snapped edges' lengths when parallel lines are merged."""
    snap = np.flatnonzero(cls >= 0)
    dirs, pts = _lines([segs[i] for i in snap], chords[snap], cls[snap], 0.0, 0.0)
    lines = [(int(cls[i]), float(p[1 - cls[i]]), d) for i, d, p in zip(snap, dirs, pts)]
    out = []
    for j, i in enumerate(snap):
        nxt = snap[(j + 1) % len(snap)]
        run = np.arange(i + 1, nxt if nxt > i else nxt + len(cls)) % len(cls)
        out.append((lines[j], pts[j], L[i]))
        if len(run) and tol < math.inf:  # at an infinite tolerance every corner stays plain
            chain = np.vstack([segs[r] for r in run])
            out += [(ln, _on_line(ln, chain), cell) for ln in _steps(chain, lines[j], lines[(j + 1) % len(snap)], tol)]
    return (np.array([o[0][2] for o in out]), np.array([o[1] for o in out]), np.array([o[0][0] for o in out]),
            np.array([o[2] for o in out], float))


def _on_line(line, chain):
    """A point of an axis-parallel ``line`` (class, value, direction) near the middle of ``chain``."""
    p = chain[len(chain) // 2].copy()
    p[1 - line[0]] = line[1]
    return p


def _segment_distance(q: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance (m) of points ``q`` (m, 2) to the segments from ``a`` to ``b`` ((2,) or (c, 2)
    each): (m,) or (c, m)."""
    d = b - a
    rel = q - a[..., None, :]
    t = np.clip(np.einsum("...mk,...k->...m", rel, d) / np.maximum(np.einsum("...k,...k->...", d, d), 1e-12)[..., None],
                0.0, 1.0)
    return np.sqrt(np.add.reduce((rel - t[..., None] * d[..., None, :]) ** 2, axis=-1))


def _path_deviation(q: np.ndarray, verts: np.ndarray) -> np.ndarray:
    """Distance (m) of points ``q`` (m, 2) to each of c polylines ``verts`` (c, k, 2): (c, m)."""
    return np.min([_segment_distance(q, verts[:, j], verts[:, j + 1]) for j in range(verts.shape[1] - 1)], axis=0)


def _heading(a: np.ndarray, b: np.ndarray, default: np.ndarray) -> np.ndarray:
    """Unit vector from ``a`` to ``b`` along the axis they share a line on; ``default`` when they coincide."""
    d = b - a
    n = math.hypot(*d)
    return d / n if n > 1e-9 else default


def _steps(chain: np.ndarray, a: tuple, b: tuple, tol: float, depth: int = 0) -> list:
    """Axis-parallel lines (class, value, direction) to put between lines ``a`` and ``b`` so
    the outline passes within ``tol`` (m) of the traced points ``chain`` (m, 2) that join them:
    a rectilinear Douglas-Peucker. Perpendicular ``a`` and ``b`` may get a step
    (:func:`_corner_step`), parallel ones a crossing line or a bump (:func:`_side_step`). Both
    halves of the chain, split at the new lines' chain point, are treated the same way. The
    class of a line is 0 along x (its value y), 1 along y (its value x); directions follow the
    ring."""
    inner = chain[1:-1]
    if len(inner) < 1 or depth > 8:
        return []
    i, add = (_corner_step if a[0] != b[0] else _side_step)(chain, inner, a, b, tol)
    if not add:
        return []
    k = i + 1
    return _steps(chain[:k + 1], a, add[0], tol, depth + 1) + add + _steps(chain[k:], add[-1], b, tol, depth + 1)


def _corner_step(chain, inner, a, b, tol):
    """For perpendicular lines ``a`` and ``b`` (:func:`_steps`): nothing (``(0, [])``) when the
    chain stays within ``tol`` of their corner, else a step, two lines through a chain point q:
    the q whose outline (s, c1, q, c2, e, c1 on line a, c2 on line b) strays least from the
    chain, which is the inner corner of a notch and the outer corner of a wing's end. Returns
    (the index of q in ``inner``, the lines)."""
    (ca, va, da), (cb, vb, db) = a, b
    corner = np.empty(2)
    corner[1 - ca], corner[1 - cb] = va, vb
    s, e = chain[0].copy(), chain[-1].copy()
    s[1 - ca], e[1 - cb] = va, vb
    if _path_deviation(inner, np.array([[s, corner, e]])).max() <= tol:
        return 0, []
    verts = np.repeat(np.array([[s, s, s, e, e]]), len(inner), axis=0)
    verts[:, 1, 1 - cb] = verts[:, 2, 1 - cb] = inner[:, 1 - cb]
    verts[:, 2, 1 - ca] = verts[:, 3, 1 - ca] = inner[:, 1 - ca]
    i = int(np.argmin(_path_deviation(inner, verts).max(axis=1)))
    p = inner[i]
    return i, [(cb, float(p[1 - cb]), _heading(verts[i, 1], p, db)),
               (ca, float(p[1 - ca]), _heading(p, verts[i, 3], da))]


def _side_step(chain, inner, a, b, tol):
    """For parallel lines ``a`` and ``b`` (:func:`_steps`), with each inner chain point's
    deviation the smaller of its offsets from the two: when they are ``tol`` or more apart, the
    perpendicular line through the middle of the crossing, the median (along the lines) of the
    points whose deviation is at least half the largest (every one when the chain has none); when
    closer, a parallel line through the farthest point if it is beyond ``tol`` (a bump or notch
    in a side), else nothing (``(0, [])``). Returns (the index in ``inner`` of the point the new
    line passes, the lines)."""
    (ca, va, da), (cb, vb, db) = a, b
    off = inner[:, 1 - ca]
    dev = np.minimum(np.abs(off - va), np.abs(off - vb))
    i = int(np.argmax(dev))
    if abs(va - vb) >= tol:
        mid = np.flatnonzero(dev >= 0.5 * dev[i])  # holds i
        at = float(np.median(inner[mid, ca]))
        d = np.zeros(2)
        d[1 - ca] = math.copysign(1.0, vb - va)
        return int(mid[np.argmin(np.abs(inner[mid, ca] - at))]), [(1 - ca, at, d)]
    if dev[i] > tol:
        return i, [(ca, float(inner[i, 1 - ca]), da)]
    return 0, []


def _fit_offsets(dirs, mids, lengths, pts, tol, margin, min_band, density, weight):
    """Move each edge line of a counter-clockwise polygon to its maximum-likelihood place among
    the points ``pts`` within ``tol`` of it and inside its extent less ``margin`` at both ends
    (the band), when that band is at least ``min_band`` (m) long.

    With roof density ``density`` inside and stray points at density ``density * exp(-weight)``
    outside, the negative log-likelihood of an edge at offset t (outward) is ``weight`` per point
    beyond t plus ``density`` times the band area inside t; it is least at one of the points
    (the outermost, unless the outermost few are sparse enough to be strays), to which the mean
    gap of a Poisson process's last point, 1 / (density x band length), is added (one spacing for
    a band one spacing long; shorter bands keep the mask's place). Edges with a band under three
    points keep their place too.
    """
    out = mids.copy()
    for i, (d, m, L) in enumerate(zip(dirs, mids, lengths)):
        band = L - 2 * margin
        if band < min_band:
            continue
        nrm = np.array([d[1], -d[0]])  # outward (right-hand) normal of a counter-clockwise ring
        rel = pts - m
        off = rel @ nrm
        o = -np.sort(-off[(np.abs(off) < tol) & (np.abs(rel @ d) < band / 2)])
        if len(o) < 3:
            continue
        j = int(np.argmin(weight * np.arange(len(o)) + density * band * o))
        out[i] = m + nrm * (o[j] + 1.0 / (density * band))
    return out


def _cost(poly: np.ndarray, pts: np.ndarray, density: float, weight: float) -> float:
    """Negative Poisson log-likelihood (up to constants) of a building's points ``pts`` (m, 2)
    under the outline ``poly``: ``weight`` per point left outside plus ``density`` times the area
    (the expected count of an empty area). ``weight`` is log(roof density / density of stray points)."""
    import shapely

    P = shapely.Polygon(poly)
    n_out = len(pts) - int(np.count_nonzero(shapely.contains_xy(P, pts[:, 0], pts[:, 1])))
    return weight * n_out + density * P.area


def _vacancy(poly: np.ndarray, pts: np.ndarray, density: float, cell: float, level: float) -> float:
    """Expected number of empty regions as large as the largest one inside ``poly`` that
    points ``pts`` (m, 2) of a Poisson process of ``density`` per m^2 over ``poly`` would leave
    (a scan statistic of the empty space: small when the outline takes in an area the points
    avoid, a filled notch, which a count over the whole outline dilutes); ``inf`` when it is
    surely not under ``level``.

    On a raster of ``cell`` (m) over the outline, each cell's empty disc reaches its nearest
    point; its area a is that of the disc's cells inside the outline (a disc at an edge is
    clipped, as the points are), and the largest k = density x a is kept. Discs of one area a
    around Poisson points of density d leave about ``d |A| k exp(-k)`` uncovered regions in an
    area |A| (Janson 1986, Random coverings in several dimensions, Acta Math. 156), which is the
    value returned. That is under ``level`` only for k above the root k* of ``d |A| k exp(-k) =
    level`` (a fixed point of ``k = log(d |A| k / level)``), so only cells farther than
    ``r* = sqrt(k* / (pi d))`` from every point are measured, among those whose box of cells
    wholly within r* of their centre holds no point (a maximum filter)."""
    import shapely
    from scipy import ndimage
    from scipy.spatial import cKDTree

    if density <= 0 or not len(pts):
        return math.inf
    P = shapely.Polygon(poly)
    n = density * P.area
    k_min = math.log(max(n / level, math.e))
    for _ in range(4):
        k_min = math.log(max(n * k_min / level, math.e))
    r_min = math.sqrt(k_min / (math.pi * density))
    x0, y0, x1, y1 = P.bounds
    shape = (int(math.ceil((y1 - y0) / cell)), int(math.ceil((x1 - x0) / cell)))
    ij = np.floor((pts - [x0, y0]) / cell).astype(np.int64)
    ij = ij[(ij >= 0).all(axis=1) & (ij[:, 0] < shape[1]) & (ij[:, 1] < shape[0])]
    occ = np.zeros(shape, np.uint8)
    occ[ij[:, 1], ij[:, 0]] = 1
    half = int(r_min / (cell * math.sqrt(2)) - 0.5)  # the box of cells within r* of a cell's centre
    rows, cols = np.nonzero(ndimage.maximum_filter(occ, size=2 * max(half, 0) + 1, mode="constant") == 0)
    cand = np.column_stack([x0 + (cols + 0.5) * cell, y0 + (rows + 0.5) * cell])
    cand = cand[shapely.contains_xy(P, cand[:, 0], cand[:, 1])]
    r, _ = cKDTree(pts).query(cand) if len(cand) else (np.zeros(0), None)
    cand, r = cand[r >= r_min], r[r >= r_min]
    if not len(cand):
        return math.inf
    reach = float(r.max())  # the cells any disc can hold: the candidates' window widened by it
    j0, i0 = np.maximum(np.floor((cand.min(axis=0) - reach - [x0, y0]) / cell).astype(np.int64) - 1, 0)
    j1, i1 = np.minimum(np.ceil((cand.max(axis=0) + reach - [x0, y0]) / cell).astype(np.int64) + 1, shape[::-1])
    gx, gy = np.meshgrid(x0 + (np.arange(j0, j1) + 0.5) * cell, y0 + (np.arange(i0, i1) + 0.5) * cell)
    c = np.column_stack([gx.ravel(), gy.ravel()])
    c = c[shapely.contains_xy(P, c[:, 0], c[:, 1])]
    k = density * cell * cell * float(cKDTree(c).query_ball_point(cand, r, return_length=True).max())
    return n * k * math.exp(-k)


def _outline(pts: np.ndarray, ring: np.ndarray, spacing: float, ref: float, cell: float,
             params: FootprintParams) -> np.ndarray:
    """Footprint polygon of one building from its points and traced outline.

    The rectilinear outlines at ``CORNER_RADIUS``, ``FINE_RADIUS`` and ``FINEST_RADIUS``
    (:func:`_rectilinear`) are fitted in turn until the likeliest so far (:func:`_cost`)
    explains the points as well as the true outline would on average: its cost exceeds the
    number of points, the cost's expectation under the true outline, by less than that count's
    Poisson standard deviation, and it holds no empty region larger than a Poisson process of the
    roof density leaves by chance (:func:`_vacancy` at least ``VACANCY_LEVEL``: the global count
    dilutes a local deficit, and a few per cent of error in the density hide a filled notch in
    it). A stem rounded away leaves points out, a filled notch adds empty area; the finer
    smoothings keep them. The likeliest outline is kept when none explains the points so.

    When no rectilinear outline agrees with the traced ring (the building is not orthogonal, or,
    at a low density, the ring is rounded far from it), the likeliest of those outlines and the
    regularised ring (:func:`regularize`) is kept."""
    density = ref / (cell * cell)
    scored, disagreeing = [], []  # (cost, outline) of the outlines found
    for radius in (CORNER_RADIUS, FINE_RADIUS, FINEST_RADIUS):
        poly, agrees = _rectilinear(pts, ring, spacing, ref, radius)
        if poly is not None:
            (scored if agrees else disagreeing).append((_cost(poly, pts, density, STRAY_WEIGHT), poly))
        if not scored or radius == FINEST_RADIUS:
            continue
        cost, best = scored[int(np.argmin([c for c, _ in scored]))]
        if cost - len(pts) < math.sqrt(len(pts)) and _vacancy(best, pts, density, cell, VACANCY_LEVEL) >= VACANCY_LEVEL:
            return best
    if not scored:
        reg = regularize(ring, spacing, params)
        scored = disagreeing + [(_cost(reg, pts, density, STRAY_WEIGHT), reg)]
    return scored[int(np.argmin([c for c, _ in scored]))][1]


@dataclass(frozen=True)
class Component:
    """One connected region of the half-density mask, cut out of the district raster.

    Attributes
    ----------
    label : int
        Its label in the district mask (1-based, in :func:`scipy.ndimage.label` order).
    cut : (r, c) float64
        The normalised density over the region's bounding box widened by two cells.
    region : (r, c) bool
        The region's cells in ``cut``.
    origin : (2,) float64
        Lower-left corner of the cut (m).
    """

    label: int
    cut: np.ndarray
    region: np.ndarray
    origin: np.ndarray

    def outline_field(self) -> np.ndarray:
        """``cut`` raised to just above 0.5 inside the region (its holes filled) and zero beyond
        one cell outside it, so its level-0.5 line is the region's edge. Made where the building
        is traced (a worker, with several), not in the district pass."""
        from scipy import ndimage

        rim = np.where(ndimage.binary_dilation(self.region), self.cut, 0.0)
        return np.where(fill_holes(self.region), np.maximum(self.cut, 0.5 + 1e-9), rim)


@dataclass(frozen=True)
class District:
    """The district-wide pass of :func:`district_components`.

    Attributes
    ----------
    spacing, cell, ref : float
        Nominal point spacing (m), raster cell (m) and the roof's smoothed count per cell.
    components : list of Component
        The regions of at least ``min_area``, in label order.
    point_label : (n,) int64
        Label of the region of every point (0 for none).
    n_labels : int
        Number of regions, small ones included.
    """

    spacing: float
    cell: float
    ref: float
    components: list
    point_label: np.ndarray
    n_labels: int

    def point_component(self) -> np.ndarray:
        """(n,) int64: index into ``components`` of every point's region, -1 for none (no region
        or one under ``min_area``)."""
        remap = np.full(self.n_labels + 1, -1, np.int64)
        remap[[c.label for c in self.components]] = np.arange(len(self.components))
        return remap[self.point_label]


def _nearest_label(labels: np.ndarray, rows: np.ndarray, cols: np.ndarray, reach: float,
                   threads: int = 1) -> np.ndarray:
    """Label of the nearest labelled cell (centre to centre) within ``reach`` cells of each cell
    (``rows``, ``cols``), 0 when none is that close; a labelled cell gives its own label.

    The nearest labelled cell to an unlabelled one lies on the region's edge (a step from it
    towards the query would otherwise be closer and labelled), so only edge cells (with an
    unlabelled 4-neighbour) enter the k-d tree; of equidistant cells of two regions one is taken.
    The edge cells and the look-up run on ``threads`` threads.
    """
    from scipy import ndimage
    from scipy.spatial import cKDTree

    out = labels[rows, cols].astype(np.int64)
    free = np.flatnonzero(out == 0)
    fg = labels > 0
    edge = np.argwhere(fg & ~_by_bands(ndimage.binary_erosion, fg, 2, threads))
    if not len(free) or not len(edge):
        return out
    d, i = cKDTree(edge).query(np.column_stack([rows[free], cols[free]]), distance_upper_bound=reach * (1 + 1e-9),
                               workers=threads)
    near = np.isfinite(d) & (d <= reach)
    out[free[near]] = labels[edge[i[near], 0], edge[i[near], 1]]
    return out


def district_components(xy: np.ndarray, params: FootprintParams = FootprintParams(), threads: int = 1) -> District:
    """The district-wide step of :func:`extract_footprints` on building points ``xy`` (n, 2) (m):
    density field, half-density mask and its regions, and the region of every point (points just
    outside the outline, the edge itself, join the nearest region within ``ASSIGN_REACH`` spacings).
    Regions under ``min_area`` are left out of ``components`` but keep their points. The spacing,
    the smoothing, the roof cores and the nearest regions are computed on ``threads`` threads
    (the same result); each component's outline field is made only when it is traced. Under two
    distinct points (no spacing, :func:`nominal_spacing`) there is no region."""
    from scipy import ndimage

    xy = np.asarray(xy, float)
    spacing = params.spacing or nominal_spacing(xy, threads)
    if not (math.isfinite(spacing) and spacing > 0):  # under two distinct points: no region
        return District(spacing, math.nan, math.nan, [], np.zeros(len(xy), np.int64), 0)
    field, origin, cell, ref = density_field(xy, spacing, threads=threads)
    labels = building_mask(field)
    ij = np.floor((xy - origin) / cell).astype(np.int64)
    point_label = _nearest_label(labels, ij[:, 1], ij[:, 0], ASSIGN_REACH * spacing / cell, threads)
    comps, slices = [], ndimage.find_objects(labels)
    for k, sl in enumerate(slices):
        sl = tuple(slice(max(a.start - 2, 0), a.stop + 2) for a in sl)
        sub = labels[sl] == k + 1
        if np.count_nonzero(sub) * cell * cell < params.min_area:
            continue
        comps.append(Component(k + 1, field[sl].copy(), sub, origin + np.array([sl[1].start, sl[0].start]) * cell))
    return District(spacing, cell, ref, comps, point_label, len(slices))


def component_footprint(comp: Component, pts: np.ndarray, spacing: float, ref: float, cell: float,
                        params: FootprintParams = FootprintParams()) -> Footprint:
    """Footprint of one region of :func:`district_components` from its points ``pts`` (m, 2)."""
    ring = trace_outline(comp.outline_field(), comp.origin, cell)
    return Footprint(_outline(pts, ring, spacing, ref, cell, params))


def points_by_label(point_label: np.ndarray, n_labels: int):
    """(order, starts): ``order[starts[k]:starts[k + 1]]`` are the indices of the points of
    label k, in their input order."""
    order = np.argsort(point_label, kind="stable")
    return order, np.searchsorted(point_label[order], np.arange(n_labels + 2))


def no_footprint_error(params: FootprintParams, n: int):
    """The error of a district without any footprint."""
    from workstation.core.errors import StageError

    return StageError("footprints", f"no building larger than {params.min_area:g} m² in {n} points",
                      "check that building points are classified (class 6) or pass --footprints")


def extract_footprints(xy: np.ndarray, params: FootprintParams = FootprintParams()):
    """Footprints of building points ``xy`` (n, 2) (m).

    Returns ``(footprints list, point_building (n,) int64)``: the regularised outlines and the
    footprint index of every point (-1 for points of discarded components).
    """
    xy = np.asarray(xy, float)
    d = district_components(xy, params)
    order, starts = points_by_label(d.point_label, d.n_labels)
    out = [component_footprint(c, xy[order[starts[c.label]:starts[c.label + 1]]], d.spacing, d.ref, d.cell, params)
           for c in d.components]
    if not out:
        raise no_footprint_error(params, len(xy))
    return out, d.point_component()
