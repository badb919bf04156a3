"""LoD1.2 and LoD2.2 building models from footprints and roof planes.

Levels of detail follow Biljecki, Ledoux & Stoter (2016), "An improved LOD specification for 3D
building models" (the LoD x.y refinement used by CityJSON and 3DBAG):

* **LoD1.2**: the footprint extruded from the ground height to a percentile of the roof point
  heights (70th by default, as 3DBAG's ``b3_h_70p``), one closed solid.
* **LoD2.2**: the roof planes intersected into roof faces, vertical walls down to the ground and
  a ground face: one closed, watertight solid per building part.

The roof is built as in geoflow / 3DBAG (Peters et al. 2022, "Automated 3D reconstruction of LoD2
and LoD1 models for all 10 million buildings of the Netherlands") in a reduced form: every roof
plane claims the raster cells where its points dominate; neighbouring planes whose heights
differ at their shared border by more than the step tolerance start a new *part* (a step edge
with a wall), planes meeting continuously stay in one part. The planes are first regularised
(:func:`regular_planes`: azimuths along the building's directions, one tilt for both sides of a
ridge, where the points do not contradict it). Inside a part the roof is the lower
envelope of its planes clipped to the part outline: exact for flat, shed, gabled, hipped and
pyramid roofs and for any convex roof; planes whose envelope face disagrees with their own
points are dropped. Where that drops planes, the arrangement of the planes' intersection lines
labelled by the raster is used instead when it is continuous and agrees better (valleys of
cross-gabled roofs; :mod:`workstation.buildings.roof_faces`). Planes a part's continuous roof
leaves out but that meet its kept planes in a step (a dormer: valleys at its back, a front wall)
become a raised part of their own, a closed solid standing on the ground inside the main part
like the upper level of a multi-level roof; a part around it is cut into pieces without holes.
Faces are welded and T-junctions split so each part is a closed 2-manifold.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .planes import FLAT_TILT_DEG, MAX_ROOF_TILT_DEG
from .roof_faces import lower_envelope, roof_faces

#: Coordinate grid (m) to which part polygons are snapped, so that overlays leave no slivers.
GRID = 1e-5


@dataclass(frozen=True)
class ModelParams:
    """Parameters of :func:`build_models`.

    Attributes
    ----------
    lod1_percentile : float
        Percentile of the roof point heights used as the LoD1.2 block height (%).
    max_roof_tilt_deg : float
        Planes steeper than this are walls and not used for the roof (degrees; default
        :data:`~workstation.buildings.planes.MAX_ROOF_TILT_DEG`). Flat below
        :data:`~workstation.buildings.planes.FLAT_TILT_DEG`.
    min_plane_share : float
        Smallest plane of the main roof, as a share of the building's roof-plane points (0-1).
        Smaller planes are modelled only where they form parts of their own standing on the
        roof behind a step (a dormer, a raised annex; see :func:`build_building`); pieces of
        the main roof below the share are left to their neighbours.
    cell : float or None
        Cell of the plane ownership raster (m); None uses the nominal point spacing.
    """

    lod1_percentile: float = 70.0
    max_roof_tilt_deg: float = MAX_ROOF_TILT_DEG
    min_plane_share: float = 0.05
    cell: float | None = None


@dataclass(frozen=True)
class RoofFace:
    """One roof face of the LoD2.2 model.

    Attributes
    ----------
    polygon : (k, 2) float64
        Exterior ring in plan (m, absolute), counter-clockwise.
    normal : (3,) float64
        Unit upward normal of its plane.
    point : (3,) float64
        A point of its plane (m).
    part : int
        Index of the building part it belongs to.
    """

    polygon: np.ndarray
    normal: np.ndarray
    point: np.ndarray
    part: int

    def z(self, xy: np.ndarray) -> np.ndarray:
        n, p = self.normal, self.point
        return p[2] - (n[0] * (xy[:, 0] - p[0]) + n[1] * (xy[:, 1] - p[1])) / n[2]

    @property
    def tilt_deg(self) -> float:
        return float(np.degrees(np.arccos(min(1.0, abs(self.normal[2])))))

    @property
    def azimuth_deg(self) -> float:
        return float(np.degrees(np.arctan2(self.normal[0], self.normal[1])) % 360.0)

    @property
    def area_m2(self) -> float:
        """Sloped (true) area (m^2)."""
        x, y = self.polygon[:, 0], self.polygon[:, 1]
        plan = 0.5 * abs(np.dot(x, np.concatenate([y[1:], y[:1]])) - np.dot(y, np.concatenate([x[1:], x[:1]])))
        return float(plan / max(abs(self.normal[2]), 1e-9))


@dataclass(frozen=True)
class Solid:
    """A closed polyhedron: vertices (v, 3) (m) and faces as lists of vertex index rings
    (first ring outer, further rings holes), each with a semantic type (``RoofSurface``,
    ``WallSurface``, ``GroundSurface``)."""

    vertices: np.ndarray
    faces: list
    semantics: list


@dataclass(frozen=True)
class BuildingModel:
    """LoD1.2 and LoD2.2 of one building.

    Attributes
    ----------
    id : int
    footprint : (k, 2) float64 (m)
    ground : float
        Ground height (m), the lowest DTM height along the footprint.
    height : float
        LoD1.2 roof height (m, absolute).
    roof_type : str
        ``flat``, ``shed``, ``gabled``, ``hipped``, ``multilevel`` or ``complex``.
    lod1 : Solid
    lod2 : list of Solid
        One solid per part.
    roofs : list of RoofFace
    """

    id: int
    footprint: np.ndarray
    ground: float
    height: float
    roof_type: str
    lod1: Solid
    lod2: list
    roofs: list = field(default_factory=list)


def prism(polygon: np.ndarray, z0: float, z1: float) -> Solid:
    """Closed extruded block of a counter-clockwise polygon (k, 2) from z0 to z1 (m)."""
    k = len(polygon)
    v = np.vstack([np.column_stack([polygon, np.full(k, z0)]), np.column_stack([polygon, np.full(k, z1)])])
    i = np.arange(k)
    faces = [[list(i[::-1])], [list(i + k)]] + [[[j, (j + 1) % k, (j + 1) % k + k, j + k]] for j in range(k)]
    return Solid(v, faces, ["GroundSurface", "RoofSurface"] + ["WallSurface"] * k)


def ownership_raster(polygon, xyz: np.ndarray, labels: np.ndarray, n_planes: int, cell: float):
    """Plane owning each raster cell inside a shapely ``polygon``: the majority label of the
    cell's points, and for cells without labelled points the label of the nearest such cell.

    Returns (label grid (rows, cols) int64, -1 outside; origin (2,); cell centres (rows, cols, 2)).
    """
    import shapely
    from scipy import ndimage

    x0, y0, x1, y1 = polygon.bounds
    origin = np.array([x0, y0])
    cols, rows = max(1, int(math.ceil((x1 - x0) / cell))), max(1, int(math.ceil((y1 - y0) / cell)))
    cx, cy = np.meshgrid(x0 + (np.arange(cols) + 0.5) * cell, y0 + (np.arange(rows) + 0.5) * cell)
    inside = shapely.contains_xy(polygon, cx, cy)
    grid = np.full((rows, cols), -1, np.int64)
    ok = labels >= 0
    ij = np.floor((xyz[ok, :2] - origin) / cell).astype(np.int64)
    good = (ij[:, 0] >= 0) & (ij[:, 0] < cols) & (ij[:, 1] >= 0) & (ij[:, 1] < rows)
    if good.any() and n_planes:
        flat = ij[good, 1] * cols + ij[good, 0]
        votes = np.bincount(flat * n_planes + labels[ok][good], minlength=rows * cols * n_planes).reshape(rows * cols, n_planes)
        has = votes.sum(axis=1) > 0
        grid.ravel()[has] = np.argmax(votes[has], axis=1)
    if (grid >= 0).any():
        _, (ii, jj) = ndimage.distance_transform_edt(grid < 0, return_indices=True)
        grid = grid[ii, jj]
    grid[~inside] = -1
    return grid, origin, np.stack([cx, cy], axis=-1)


def _plane_z(normals, points, idx, xy):
    n, p = normals[idx], points[idx]
    return p[:, 2] - (n[:, 0] * (xy[:, 0] - p[:, 0]) + n[:, 1] * (xy[:, 1] - p[:, 1])) / n[:, 2]


def border_steps(grid, origin, cell, normals, points, eps):
    """Shared raster borders of every pair of planes: (cell borders (p, p), of which steps (p, p)),
    symmetric. A border is a step where the two planes' heights at its midpoint differ by more
    than ``3 eps + (tan a + tan b) cell`` (the plane threshold plus the height change over one
    cell of border uncertainty)."""
    p = len(normals)
    pa, pb, mids = [], [], []
    for a, b, off in ((grid[:, :-1], grid[:, 1:], (1.0, 0.5)), (grid[:-1, :], grid[1:, :], (0.5, 1.0))):
        m = (a >= 0) & (b >= 0) & (a != b)
        r, c = np.nonzero(m)
        pa.append(a[m]), pb.append(b[m])
        mids.append(origin + np.column_stack([c + off[0], r + off[1]]) * cell)
    pa, pb, mids = np.concatenate(pa), np.concatenate(pb), np.concatenate(mids)
    if not len(pa):
        return np.zeros((p, p)), np.zeros((p, p))
    dz = np.abs(_plane_z(normals, points, pa, mids) - _plane_z(normals, points, pb, mids))
    slope = np.hypot(normals[:, 0], normals[:, 1]) / normals[:, 2]
    step = dz > 3 * eps + (slope[pa] + slope[pb]) * cell
    key = np.minimum(pa, pb) * p + np.maximum(pa, pb)
    tot = np.bincount(key, minlength=p * p).reshape(p, p).astype(float)
    stp = np.bincount(key, weights=step, minlength=p * p).reshape(p, p)
    return tot + tot.T, stp + stp.T


def split_parts(grid, origin, cell, normals, points, eps):
    """Part index per plane: planes meeting continuously (a ridge, a valley) share a part;
    planes whose shared border is mostly a step (:func:`border_steps`) are separated."""
    from .planes import small_components

    p = len(normals)
    tot, stp = border_steps(grid, origin, cell, normals, points, eps)
    if not tot.any():
        return np.arange(p) if p else np.zeros(0, int)
    i, j = np.nonzero(np.triu((tot > 0) & (stp < 0.5 * tot), 1))
    return small_components(p, i, j)


def detach_raised(part_of_plane, dropped, steps, min_cells: int = 4, borders=None):
    """Part index per plane after splitting off, from each part, the planes its roof faces left
    out (``dropped`` (p,) bool) where they meet the kept planes of their part in a step of at
    least ``min_cells`` raster cell borders (``steps`` (p, p) from :func:`border_steps`): a dormer
    or a raised annex joined to the main roof by its valleys but standing on it behind a front
    wall, which the part's continuous roof cannot hold. The detached planes that touch form one
    new part each. With ``borders`` (p, p) (the shared cell borders of :func:`border_steps`), a
    left-out plane sharing a border with a detached one of its part goes with it, and so on
    through left-out planes that touch (one shared cell border suffices): the other face of a
    dormer, whose front wall the raster gave to the first face, meets the main roof in a valley
    only and the detached face at the dormer's ridge."""
    from .planes import small_components

    p = len(part_of_plane)
    same = part_of_plane[:, None] == part_of_plane[None, :]
    kept = ~dropped
    raised = dropped & ((steps * (same & kept[None, :])).sum(axis=1) >= min_cells)
    if not raised.any():
        return part_of_plane
    link = same & raised[:, None] & raised[None, :]
    if borders is not None:
        link |= same & dropped[:, None] & dropped[None, :] & (borders > 0)
    i, j = np.nonzero(np.triu(link, 1))
    comp = small_components(p, i, j)
    raised = dropped & np.isin(comp, comp[raised])
    out = part_of_plane.copy()
    out[raised] = part_of_plane.max() + 1 + np.unique(comp[raised], return_inverse=True)[1]
    return out


def step_split(s_own: np.ndarray, s_other: np.ndarray) -> float:
    """Offset along an edge normal that best separates a part's points (``s_own``, expected
    below) from the other parts' points beside it (``s_other``, expected above): the middle of
    the interval where the fewest points fall on the wrong side.

    Along a straight step edge the part's outermost point and the neighbour's innermost one
    are each within about 1 / (density x edge length) of the true edge, so the middle of the
    gap places the edge far closer than the point spacing.

    >>> step_split(np.array([-0.3, -0.1, -0.02]), np.array([0.04, 0.2, 0.5]))
    0.01
    """
    s = np.concatenate([s_own, s_other])
    order = np.argsort(s, kind="stable")
    own = np.r_[np.ones(len(s_own), bool), np.zeros(len(s_other), bool)][order]
    ss = s[order]
    # wrong when the split lies after position i (between ss[i] and ss[i+1]): own above + other below
    wrong = (len(s_own) - np.cumsum(own)) + np.cumsum(~own)
    best = np.flatnonzero(wrong[:-1] == wrong[:-1].min())
    i = best[len(best) // 2]
    return round(float(0.5 * (ss[i] + ss[i + 1])), 12)


def refine_step_edges(ring: np.ndarray, footprint, xy: np.ndarray, point_part: np.ndarray, q: int,
                      cell: float) -> np.ndarray:
    """Part ``q``'s regularised ring (k, 2) with each edge that runs inside the footprint (a
    step edge between parts) refitted to the points within two cells of it: :func:`step_split`
    of ``q``'s own points against those of other parts, in each half of the edge, gives two
    points of the new edge line (its direction from the data, not only from the outline).
    Edges along the footprint, shorter than four cells, or with under three points on either
    side of a half, stay where they are."""
    from .footprints import edge_intersections

    ring = np.asarray(ring, float)
    seg = np.roll(ring, -1, axis=0) - ring
    length = np.linalg.norm(seg, axis=1)
    if len(ring) < 3 or (length <= 0).any():
        return ring
    dirs, pts = seg / length[:, None], ring.copy()
    labelled = point_part >= 0
    for i, (d, p0, L) in enumerate(zip(dirs.copy(), ring, length)):
        if L < 4 * cell or footprint.exterior.distance(_shapely_point(p0 + 0.5 * L * d)) < cell:
            continue
        nrm = np.array([d[1], -d[0]])  # outward normal of a CCW ring
        rel = xy - p0
        along, off = rel @ d, rel @ nrm
        near = labelled & (np.abs(off) < 2 * cell)
        ends = []
        for lo, hi in ((cell, 0.5 * L), (0.5 * L, L - cell)):
            half = near & (along >= lo) & (along < hi)
            own, other = half & (point_part == q), half & (point_part != q)
            if own.sum() < 3 or other.sum() < 3:
                break
            ends.append(p0 + 0.5 * (lo + hi) * d + step_split(off[own], off[other]) * nrm)
        if len(ends) == 2:
            pts[i], dirs[i] = ends[0], (ends[1] - ends[0]) / np.linalg.norm(ends[1] - ends[0])
    return edge_intersections(dirs, pts)


def _longest_edge_direction(ring: np.ndarray) -> float:
    """Direction (radians) of the longest edge of a regularised outline: its parts' edges
    run along it or across it."""
    e = np.diff(ring, axis=0)
    k = int(np.argmax(np.hypot(e[:, 0], e[:, 1])))
    return float(np.arctan2(e[k, 1], e[k, 0]))


def _shapely_point(xy):
    import shapely

    return shapely.Point(float(xy[0]), float(xy[1]))


#: Douglas-Peucker tolerances (raster cells) of the candidate outlines of a building part: the
#: footprints' (``footprints.DP_TOLERANCE``, 2.5) down to one cell.
PART_DP_CELLS = (2.5, 2.0, 1.25, 1.0)


def _part_outlines(traced: np.ndarray, cell: float, direction: float) -> list:
    """Candidate regularised outlines of a part's traced raster outline (k, 2): the
    regularisations (:func:`~workstation.buildings.footprints.regularize`) with the
    simplification tolerances :data:`PART_DP_CELLS`, coarsest first, repeats left out. The
    footprint tolerance suits outlines of tens of metres; on a part a few metres across (a
    dormer) it can cut a corner off, whose edges then lie too far from the points for
    :func:`refine_step_edges` to place them; a finer tolerance keeps the corner."""
    from .footprints import DP_TOLERANCE, regularize

    out = []
    for tol in PART_DP_CELLS:
        ring = regularize(traced, cell * tol / DP_TOLERANCE, direction=direction)
        if len(ring) >= 3 and not any(len(r) == len(ring) and np.allclose(r, ring) for r in out):
            out.append(ring)
    return out or [traced]


def _part_outline(traced: np.ndarray, cell: float, direction: float) -> np.ndarray:
    """Regularised outline of a part's traced raster outline (k, 2) when no points are at hand:
    of :func:`_part_outlines`, the coarsest that stays within one cell of the traced outline
    everywhere (Hausdorff distance; the staircase a raster traces along a straight edge of any
    heading stays within sqrt(2) / 2 cell of it), else the one with the smallest Hausdorff
    distance (a cut corner shows in the largest deviation, hardly in the average one)."""
    import shapely

    rings = _part_outlines(traced, cell, direction)
    ref = shapely.linearrings(traced)
    d = np.array([shapely.hausdorff_distance(shapely.linearrings(r), ref) for r in rings])
    near = np.flatnonzero(d <= cell)
    return rings[int(near[0]) if len(near) else int(np.argmin(d))]


def _misfit(ring: np.ndarray, footprint, xy: np.ndarray, point_part: np.ndarray, q: int, cost: np.ndarray) -> float:
    """Squared height error an outline (k, 2) of part ``q`` makes at the points: the labelled
    points it puts on the wrong side (points of other parts inside it, within the footprint,
    and points of ``q`` outside it), each with its ``cost`` (n,) (m), the vertical distance to
    the nearest plane of the side it is put on."""
    import shapely

    poly = shapely.make_valid(shapely.Polygon(ring)).intersection(footprint)
    inside = shapely.contains_xy(poly, xy[:, 0], xy[:, 1])
    wrong = (point_part >= 0) & (inside != (point_part == q))
    return float(np.sum(cost[wrong] ** 2))


def _fitted_outline(traced, cell, direction, footprint, xy, point_part, q, cost) -> np.ndarray:
    """Outline of part ``q`` from its traced raster outline: each candidate of
    :func:`_part_outlines` with its step edges refitted (:func:`refine_step_edges`), the one
    with the least squared height error at the building's labelled points (n, 2)
    (:func:`_misfit`; the coarsest on a tie)."""
    rings = [refine_step_edges(r, footprint, xy, point_part, q, cell) for r in _part_outlines(traced, cell, direction)]
    if len(rings) == 1:
        return rings[0] if len(rings[0]) >= 3 else traced
    best, best_e = None, np.inf
    for ring in rings:
        if len(ring) < 3:
            continue
        e = _misfit(ring, footprint, xy, point_part, q, cost)
        if e < best_e - 1e-12:
            best, best_e = ring, e
    return best if best is not None else traced


def _side_cost(plane_dz, in_q: np.ndarray, own: np.ndarray) -> np.ndarray:
    """Height error (n,) (m) of putting each point on the other side of part ``q``'s outline:
    for a point of ``q`` (``own``), its vertical distance to the nearest plane of the other
    parts, for any other point to the nearest plane of ``q`` (``in_q`` (planes,) bool); 1 m
    each without ``plane_dz`` (n, planes)."""
    if plane_dz is None or in_q.all() or not in_q.any():
        return np.ones(len(own))
    dz = np.abs(plane_dz)
    return np.where(own, dz[:, ~in_q].min(axis=1), dz[:, in_q].min(axis=1))


#: Smallest distance (m) kept between a cut of :func:`split_holes` and a vertex it passes: the
#: CityJSON export's millimetre grid (:data:`workstation.buildings.export.SCALE`) would merge a
#: vertex closer to the cut with the cut's own vertex into a degenerate ring.
MIN_FEATURE = 1e-3


def part_polygons(footprint, grid, origin, cell, part_of_plane, xy=None, point_plane=None, plane_dz=None):
    """Shapely polygons tiling the footprint, one list per part: each smaller part is its
    traced raster region, regularised (:func:`_part_outline`) and clipped to the footprint; when
    the points ``xy`` (n, 2) and their plane indices ``point_plane`` (n,), -1 for none, are
    given, its step edges are placed between the points of the parts (:func:`refine_step_edges`)
    and of the candidate regularisations the one that misplaces the points least is taken
    (:func:`_fitted_outline`; ``plane_dz`` (n, planes), each point's height above each plane
    (m), weighs a misplaced point by its height error, else every one counts 1 m). The largest
    part is the rest."""
    import shapely

    from .footprints import trace_outline

    parts = np.unique(part_of_plane)
    if len(parts) == 1:
        return {int(parts[0]): [footprint]}
    from scipy import ndimage

    cells = {int(q): int(np.isin(grid, np.flatnonzero(part_of_plane == q)).sum()) for q in parts}
    order = sorted(cells, key=cells.get)
    # parts tile the padded box: every cell (also outside the footprint) takes the nearest label,
    # so neighbouring parts' outlines run through the same cell borders
    full = np.pad(grid, 2, constant_values=-1)
    _, (ii, jj) = ndimage.distance_transform_edt(full < 0, return_indices=True)
    full = part_of_plane[np.maximum(full[ii, jj], 0)]
    o2 = origin - 2 * cell
    direction = _longest_edge_direction(np.asarray(footprint.exterior.coords))
    out, taken = {}, shapely.Polygon()
    near_fp = ndimage.binary_dilation(np.pad(grid >= 0, 2), iterations=2)  # not the box corners
    for q in order[:-1]:
        mask = (full == q) & near_fp
        if cells[q] < 4:
            continue
        traced = trace_outline(mask.astype(float), o2, cell)
        if xy is not None:
            point_part = np.where(point_plane >= 0, part_of_plane[np.maximum(point_plane, 0)], -1)
            ring = _fitted_outline(traced, cell, direction, footprint, xy, point_part, q,
                                   _side_cost(plane_dz, part_of_plane == q, point_part == q))
        else:
            ring = _part_outline(traced, cell, direction)
        if len(ring) < 3:
            continue
        geom = shapely.set_precision(shapely.make_valid(shapely.Polygon(ring)).intersection(footprint).difference(taken), GRID)
        polys = [g for g in getattr(geom, "geoms", [geom]) if g.geom_type == "Polygon" and g.area > 4 * cell * cell]
        if polys:
            out[q] = polys
            taken = taken.union(shapely.MultiPolygon(polys))
    rest = shapely.set_precision(footprint.difference(taken), GRID)
    out[order[-1]] = [g for g in getattr(rest, "geoms", [rest]) if g.geom_type == "Polygon" and g.area > cell * cell]
    return out


def _wall_rings(ring2d: np.ndarray, roof_xy: np.ndarray, roof_z: np.ndarray, ground: float, tol: float):
    """Walls under the closed ring (k, 2) (counter-clockwise for outward normals): each edge
    a -> b becomes [a_ground, b_ground, b_roof, (roof vertices on the edge, from b to a), a_roof]."""
    out = []
    k = len(ring2d)
    for i in range(k):
        a, b = ring2d[i], ring2d[(i + 1) % k]
        d = b - a
        L2 = float(d @ d)
        if L2 < 1e-12:
            continue
        rel = roof_xy - a
        t = rel @ d / L2
        off = np.abs(rel[:, 0] * d[1] - rel[:, 1] * d[0]) / math.sqrt(L2)
        on = (off < tol) & (t > -1e-9) & (t < 1 + 1e-9)
        ts, zs = t[on], roof_z[on]
        za = zb = np.nan
        if len(ts):
            ta, tb = np.abs(ts), np.abs(ts - 1)
            ia, ib = int(np.argmin(ta)), int(np.argmin(tb))
            za = zs[ia] if ta[ia] < 1e-6 else np.nan
            zb = zs[ib] if tb[ib] < 1e-6 else np.nan
        mid = (ts > 1e-9) & (ts < 1 - 1e-9)
        order = np.argsort(-ts[mid])
        between = np.column_stack([a + ts[mid][order][:, None] * d, zs[mid][order]])
        out.append(np.vstack([[a[0], a[1], ground], [b[0], b[1], ground], [b[0], b[1], zb], between, [a[0], a[1], za]]))
    return out


def split_holes(poly) -> list:
    """A shapely polygon cut into polygons without holes (counter-clockwise): each hole is cut
    through by the horizontal line through its centroid (through a vertex instead where one lies
    within :data:`MIN_FEATURE` of that line), and the halves are cut again while they hold
    holes. A part around a raised part (a dormer) so becomes parts whose roof faces have no
    holes (a :class:`RoofFace` stores the outer ring only); the cut is a wall shared by two
    closed solids, as between the parts of a multi-level roof."""
    import shapely

    if not len(poly.interiors):
        return [shapely.orient_polygons(poly)]
    y = shapely.Polygon(poly.interiors[0]).centroid.y
    ys = shapely.get_coordinates(poly)[:, 1]
    close = np.abs(ys - y) < MIN_FEATURE
    if close.any():  # through that vertex, not a hair beside it
        y = float(ys[close][np.argmin(np.abs(ys[close] - y))])
    x0, y0, x1, y1 = poly.bounds
    out = []
    for box in (shapely.box(x0 - 1, y0 - 1, x1 + 1, y), shapely.box(x0 - 1, y, x1 + 1, y1 + 1)):
        half = shapely.set_precision(poly.intersection(box), GRID)
        for g in shapely.get_parts(half):
            if g.geom_type == "Polygon" and g.area > 1e-9:
                out += split_holes(g)
    return out


def part_solid(poly, normals, points, ground, grid, centres, part_index):
    """Closed LoD2.2 solid of one part polygon, its roof faces and the indices of the planes
    (of ``normals``) that hold a face."""
    faces = roof_faces(poly, normals, points, grid, centres) if len(normals) else []
    planes_given = bool(faces)
    if not faces:  # no usable plane over this part: a flat roof at its planes' mean height
        c = poly.representative_point()
        z = float(points[:, 2].mean()) if len(points) else ground + 3.0
        normals, points = np.array([[0.0, 0.0, 1.0]]), np.array([[c.x, c.y, z]])
        faces = lower_envelope(poly, normals, points)
    used = np.array(sorted({int(k) for k, _ in faces}), np.int64) if planes_given else np.zeros(0, np.int64)
    roofs, rings, sem = [], [], []
    for k, face in faces:
        ext = np.asarray(face.exterior.coords)[:-1]
        holes = [np.asarray(h.coords)[:-1] for h in face.interiors]
        z = lambda xy: _plane_z(normals, points, np.full(len(xy), k), xy)
        rings.append([np.column_stack([r, z(r)]) for r in [ext, *holes]])
        sem.append("RoofSurface")
        roofs.append(RoofFace(ext, normals[k], points[k], part_index))
    roof3 = np.vstack([r for f in rings for r in f])
    tol = 10 * GRID
    import shapely

    poly = shapely.orient_polygons(poly)
    for ring in [np.asarray(poly.exterior.coords)[:-1]] + [np.asarray(h.coords)[:-1] for h in poly.interiors]:
        for w in _wall_rings(ring, roof3[:, :2], roof3[:, 2], ground, tol):
            rings.append([w])
            sem.append("WallSurface")
    base = [np.column_stack([r[::-1], np.full(len(r), ground)])
            for r in [np.asarray(poly.exterior.coords)[:-1]] + [np.asarray(h.coords)[:-1] for h in poly.interiors]]
    rings.append(base)
    sem.append("GroundSurface")
    return weld(rings, sem), roofs, used


def weld(faces: list, semantics: list, tol: float = 1e-4) -> Solid:
    """Solid from faces given as lists of (m, 3) rings: vertices closer than ``tol`` (m) are
    merged, repeated vertices dropped, and every vertex lying on another face's edge is
    inserted into that edge (no T-junctions), so shared edges match exactly."""
    allv = np.vstack([r for f in faces for r in f])
    key = np.round(allv / tol).astype(np.int64)
    # the distinct keys in lexicographic order, each from its first occurrence (np.unique over
    # rows, without its structured-array sort)
    order = np.lexsort((key[:, 2], key[:, 1], key[:, 0]))
    sk = key[order]
    new = np.concatenate([[True], (sk[1:] != sk[:-1]).any(axis=1)])
    inv = np.empty(len(key), np.intp)
    inv[order] = np.cumsum(new) - 1
    V = allv[order[new]]
    inv, V = _merge_close(inv, V, tol)
    out, pos = [], 0
    for f in faces:
        rings = []
        for r in f:
            idx = inv[pos:pos + len(r)].ravel()
            pos += len(r)
            idx = idx[np.concatenate([[True], idx[1:] != idx[:-1]])]
            if len(idx) > 1 and idx[0] == idx[-1]:
                idx = idx[:-1]
            rings.append(_split_edges(idx, V, tol))
        out.append(rings)
    return Solid(V, out, list(semantics))


def _merge_close(inv: np.ndarray, V: np.ndarray, tol: float):
    """Vertices of V (v, 3) closer than ``tol`` that rounding put in neighbouring cells merged
    into the first of them: (new index per input index ``inv``, remaining vertices)."""
    from scipy.spatial import cKDTree

    pairs = cKDTree(V).query_pairs(tol, output_type="ndarray")
    if not len(pairs):
        return inv, V
    from .planes import small_components

    comp = small_components(len(V), pairs[:, 0], pairs[:, 1])  # numbered by lowest member
    first = np.unique(comp, return_index=True)[1]
    return comp[inv], V[first]


def _split_edges(idx: np.ndarray, V: np.ndarray, tol: float) -> list:
    """Insert into each edge of the ring ``idx`` the vertices of V lying strictly inside it."""
    a, b = V[idx], V[np.concatenate([idx[1:], idx[:1]])]
    d = b - a
    L2 = np.einsum("ij,ij->i", d, d)
    rel = V[None, :, :] - a[:, None, :]
    t = np.einsum("evj,ej->ev", rel, d) / np.maximum(L2, 1e-18)[:, None]
    perp = rel - t[..., None] * d[:, None, :]
    on = (np.einsum("evj,evj->ev", perp, perp) < tol * tol) & (t > 1e-9) & (t < 1 - 1e-9)
    e, v = np.nonzero(on)
    if not len(e):
        return idx.tolist()
    order = np.lexsort((t[e, v], e))  # by edge, along it
    return np.insert(idx, e[order] + 1, v[order]).tolist()


def triangulate(solid: Solid) -> tuple[np.ndarray, np.ndarray]:
    """Triangles (t, 3) of a solid's faces (constrained Delaunay of each face projected on its
    dominant plane, holes respected) and the face index of each triangle (t,)."""
    import shapely

    tris, owner = [], []
    V = solid.vertices
    for fi, rings in enumerate(solid.faces):
        outer = V[rings[0]]
        nrm = np.sum(np.cross(outer, np.roll(outer, -1, axis=0)), axis=0)  # Newell
        drop = int(np.argmax(np.abs(nrm)))
        ax = [i for i in range(3) if i != drop]
        lookup = {}
        for r in rings:
            for v in r:
                lookup[tuple(np.round(V[v, ax], 7))] = v
        poly = shapely.Polygon(V[rings[0]][:, ax], [V[r][:, ax] for r in rings[1:]])
        if len(rings[0]) == 3:
            t = [list(rings[0])]
        else:
            t = []
            try:
                geoms = shapely.constrained_delaunay_triangles(poly).geoms
            except shapely.errors.GEOSException:  # degenerate (collinear) ring: a fan
                geoms = []
                t = [[rings[0][0], rings[0][i], rings[0][i + 1]] for i in range(1, len(rings[0]) - 1)]
            for g in geoms:
                c = np.asarray(g.exterior.coords)[:3]
                try:
                    t.append([lookup[tuple(np.round(p, 7))] for p in c])
                except KeyError:
                    continue
        t = np.array(t, np.int64).reshape(-1, 3)
        if len(t):  # orient every triangle like the face (Newell normal)
            tn = np.cross(V[t[:, 1]] - V[t[:, 0]], V[t[:, 2]] - V[t[:, 0]])
            flip = tn @ nrm < 0
            t[flip] = t[flip][:, ::-1]
        tris.append(t)
        owner.append(np.full(len(t), fi))
    return np.vstack(tris), np.concatenate(owner)


def is_watertight(solid: Solid) -> bool:
    """Whether the triangulated solid is a closed, consistently oriented 2-manifold with a
    positive volume (trimesh's checks)."""
    import trimesh

    tris, _ = triangulate(solid)
    m = trimesh.Trimesh(solid.vertices, tris, process=False)
    return bool(m.is_watertight and m.is_winding_consistent and m.volume > 0)


def roof_type(faces: list) -> str:
    """``flat``, ``shed``, ``gabled``, ``hipped``, ``multilevel`` (several flat parts) or
    ``complex`` (several parts, flat and sloped faces mixed, or valleys), from the faces that
    hold at least 5 % of the roof area; the parts are counted over all faces, so that a small
    part of its own (a dormer, a raised annex) makes the roof ``complex`` (``multilevel`` on a
    flat roof) whatever its area."""
    area = np.array([f.area_m2 for f in faces])
    n_parts = len({f.part for f in faces})
    faces = [f for f, a in zip(faces, area) if a >= 0.05 * area.sum()]
    tilt = np.array([f.tilt_deg for f in faces])
    sloped = tilt >= FLAT_TILT_DEG
    if not sloped.any():
        return "flat" if n_parts == 1 else "multilevel"
    if n_parts > 1 or (~sloped).any() or _has_valley(faces):
        return "complex"
    az = np.array([f.azimuth_deg for f in faces])
    planes = np.unique(np.round(np.column_stack([tilt, az]), 1), axis=0)
    if len(planes) == 1:
        return "shed"
    if len(planes) == 2 and abs(((planes[0, 1] - planes[1, 1]) % 360) - 180) < 10:
        return "gabled"
    if len(planes) >= 3:
        return "hipped"
    return "complex"


def _has_valley(faces: list, tol: float = 0.01) -> bool:
    """Whether some face stands above another face's plane at its own centre (m): the roof is
    not the lower envelope of its planes, so two faces meet in a valley (a convex roof, gabled
    or hipped, is the lower envelope)."""
    centres = np.array([f.polygon.mean(axis=0) for f in faces])
    own = np.array([f.z(c[None])[0] for f, c in zip(faces, centres)])
    lowest = np.min([f.z(centres) for f in faces], axis=0)
    return bool((own > lowest + tol).any())


def _claim_unlabelled(xyz, local, normals, points, eps, cell):
    """Give points on no plane (edges, a second flight strip offset in height) the plane
    vertically nearest to them when that is within the step tolerance of :func:`split_parts`
    (3 eps + tan(tilt) cell): closer than a step, it is the same roof surface."""
    free = np.flatnonzero(local < 0)
    if not len(free) or not len(normals):
        return local
    xy = xyz[free, :2]
    dz = np.abs(np.stack([_plane_z(normals, points, np.full(len(free), q), xy) for q in range(len(normals))], 1)
                - xyz[free, 2:3])
    best = np.argmin(dz, axis=1)
    slope = np.hypot(normals[:, 0], normals[:, 1]) / normals[:, 2]
    ok = dz[np.arange(len(free)), best] < 3 * eps + slope[best] * cell
    out = local.copy()
    out[free[ok]] = best[ok]
    return out


def merge_building_planes(xyz, local, normals, eps, angle_deg, fit):
    """Merge the planes of one building that are the same plane (normals within ``angle_deg``,
    each centroid within ``eps`` of the other plane) even where they do not touch (pieces of one
    roof side cut by a chimney or a tree crown), then refit each: (labels, normals, points).
    Centroids and fits use the points of ``fit`` (n,) bool only (the mask of :func:`fit_mask`);
    the labels returned are every point's."""
    from .planes import fit_plane, small_components

    p = len(normals)
    cen = np.array([xyz[fit & (local == q)].mean(axis=0) for q in range(p)])
    i, j = np.triu_indices(p, 1)
    same = np.einsum("ij,ij->i", normals[i], normals[j]) > math.cos(math.radians(angle_deg))
    same &= np.abs(np.einsum("ij,ij->i", normals[i], cen[j] - cen[i])) < eps
    same &= np.abs(np.einsum("ij,ij->i", normals[j], cen[i] - cen[j])) < eps
    comp = small_components(p, i[same], j[same])
    local = np.where(local >= 0, comp[np.maximum(local, 0)], -1)
    out_n, out_p = [], []
    for q in range(comp.max() + 1):
        pts = xyz[fit & (local == q)]
        n, d = fit_plane(pts)
        c = pts.mean(axis=0)
        out_n.append(n)
        out_p.append(c - (n @ c + d) * n)
    return local, np.array(out_n), np.array(out_p)


def fit_mask(local, fit=None, least: int = 3):
    """(n,) bool: the points of labels ``local`` (n,) that the planes are fitted to: those of
    ``fit`` (n,) bool (:attr:`~workstation.buildings.planes.RoofPlanes.fitted`), or every
    labelled point where ``fit`` is None or leaves a plane under ``least`` points."""
    on = local >= 0
    if fit is None:
        return on
    use = on & np.asarray(fit, bool)
    if not on.any():  # no plane: nothing to fit
        return use
    few = np.bincount(local[use], minlength=int(local.max()) + 1) < least
    return use | (on & few[np.maximum(local, 0)])


def regular_planes(xyz, local, normals, points, spacing, force=None):
    """The building's planes (``normals`` (p, 3), ``points`` (p, 3)) of its points ``xyz`` labelled
    ``local``, refitted by :func:`~workstation.buildings.planes.regularise_planes` (azimuths along
    the building's directions, one tilt for the two sides of a ridge, each where the points do not
    reject it) at the noise pooled over the planes, with touching meaning within three point
    spacings (the neighbour reach of region growing). Planes marked in ``force`` (p,) bool (small
    faces that segmentation accepted as regularised, :attr:`~workstation.buildings.planes.RoofPlanes.regular`)
    are regularised whatever the Bayes factors at this noise say. Only labelled points count
    (pass the labels of the points the planes are fitted to, -1 elsewhere). Returns (normals,
    points)."""
    from .planes import pooled_noise, regularise_planes

    o = xyz.min(axis=0)
    loc = xyz - o
    d = -np.einsum("ij,ij->i", normals, points - o)
    n, d, _ = regularise_planes(loc, local, normals, d, pooled_noise(loc, local, normals, d), 3.0 * spacing, force)
    q = points - o
    return n, q - (np.einsum("ij,ij->i", n, q) + d)[:, None] * n + o


def build_building(bid: int, footprint: np.ndarray, xyz: np.ndarray, labels: np.ndarray, planes, ground: float,
                   params: ModelParams = ModelParams(), cell: float = 0.5, fitted=None) -> BuildingModel:
    """LoD1.2 and LoD2.2 of one building from its footprint (k, 2), its points (m, 3), their
    plane labels (m,) into ``planes`` (a :class:`~workstation.buildings.planes.RoofPlanes`) and
    the ground height (m). ``fitted`` (m,) bool marks the points the planes are fitted to
    (None: ``planes.fitted``; pass ``labels >= 0`` for every labelled point): the model counts
    and refits its planes on them, and the labelled points outside them take the plane of
    :func:`_claim_unlabelled`.

    The LoD2.2 is first built from all roof planes; it is kept when every plane under the
    ``min_plane_share`` ended in a raised part of small planes only (:func:`_lod2`), else the
    model is rebuilt from the main planes alone."""
    import shapely

    from .footprints import ccw

    if fitted is None:
        fitted = getattr(planes, "fitted", None)
    fp_xy = ccw(np.asarray(footprint, float))
    fp = shapely.Polygon(fp_xy)
    height = float(np.percentile(xyz[:, 2], params.lod1_percentile)) if len(xyz) else ground
    lod1 = prism(fp_xy, ground, max(height, ground + 0.1))
    ids, counts = np.unique(labels[fit_mask(labels, fitted)], return_counts=True)  # the planes' counts
    small = ids[:0]
    if len(ids):
        roof = planes.tilt_deg[ids] <= params.max_roof_tilt_deg
        least = max(3, params.min_plane_share * counts[roof].sum())
        keep, small = ids[roof & (counts >= least)], ids[roof & (counts < least) & (counts >= 3)]
    else:
        keep = ids
    raised = None
    if len(keep) and len(small):  # the smaller planes too, where they stand raised on the roof
        raised = _lod2(fp, xyz, labels, np.union1d(keep, small), planes, ground, height, cell, least, fitted)
    solids, roofs, _ = raised if raised is not None and raised[2] else _lod2(fp, xyz, labels, keep, planes, ground,
                                                                             height, cell, None, fitted)
    return BuildingModel(bid, fp_xy, ground, height, roof_type(roofs), lod1, solids, roofs)


def _lod2(fp, xyz, labels, keep, planes, ground, height, cell, least=None, fitted=None):
    """LoD2.2 solids and roof faces of a building from its planes ``keep`` (indices into
    ``planes``), and whether planes a part's roof left out were detached as raised parts.

    Each part's roof is built from its planes (:func:`split_parts`, :func:`part_solid`); planes
    a part's continuous roof left out but that meet its kept planes in a step are split off
    (:func:`detach_raised`) when that keeps every solid watertight. With ``least`` (points), the
    model is for the planes under ``least`` points: it only counts (third value True) when each
    such plane ended in a part of small planes only (a dormer, a raised annex, split off by a
    step that :func:`split_parts` or :func:`detach_raised` found; the latter also splits off
    small planes that a part's roof kept but that meet its other planes in a step, unless one of
    the larger planes has their direction within the angle tolerance: a piece of a main face
    offset by a step is no raised part), so small planes never reshape the main roof. The
    planes are refitted to the ``fitted`` points (:func:`fit_mask`), which own their raster
    cells by their labels; the points left out of the fits near the planes' edges
    are claimed again by :func:`_claim_unlabelled`, against the refitted planes: their labels
    were given within the segmentation's threshold of either face, and the plane vertically
    nearest to them once refitted decides their face better."""
    if len(keep):
        local = np.full(len(xyz), -1, np.int64)
        m = np.isin(labels, keep)
        local[m] = np.searchsorted(keep, labels[m])
        before, use = local, fit_mask(local, fitted)
        local, normals, points = merge_building_planes(xyz, local, planes.normals[keep], planes.threshold,
                                                       planes.angle_deg, use)
        force = None
        if planes.regular is not None and planes.regular[keep].any():  # a merged plane all of such faces
            on = before >= 0
            mixed = np.bincount(local[on], ~planes.regular[keep][before[on]], minlength=len(normals))
            force = mixed == 0
        fit_local = np.where(use, local, -1)  # the labels of the points the planes are fitted to
        normals, points = regular_planes(xyz, fit_local, normals, points, planes.spacing, force)
    else:  # no plane: a flat roof at the median height
        c = fp.centroid
        normals = np.array([[0.0, 0.0, 1.0]])
        points = np.array([[c.x, c.y, float(np.median(xyz[:, 2])) if len(xyz) else height]])
        fit_local = np.zeros(len(xyz), np.int64)
    is_small = np.bincount(fit_local[fit_local >= 0], minlength=len(normals)) < (least or 0)
    # points out of the fits (near an edge) are owned by the refitted plane nearest to them
    local = _claim_unlabelled(xyz, fit_local, normals, points, planes.threshold, cell)
    grid, origin, centres = ownership_raster(fp, xyz, local, len(normals), cell)
    part_of_plane = split_parts(grid, origin, cell, normals, points, planes.threshold)
    solids, roofs, used = _part_solids(fp, grid, origin, centres, cell, part_of_plane, xyz, local, normals, points,
                                       ground)
    detached = False
    dropped = ~used
    if least is not None:  # small planes turned from every larger one: in raised parts of their own
        cos = math.cos(math.radians(planes.angle_deg))
        dropped |= is_small & ~((np.abs(normals @ normals[~is_small].T) > cos).any(axis=1))
    if len(normals) > 2 and dropped.any():  # planes a part's roof left out: raised on a step?
        borders, steps = border_steps(grid, origin, cell, normals, points, planes.threshold)
        again = detach_raised(part_of_plane, dropped, steps, borders=borders)
        if not np.array_equal(again, part_of_plane):
            alt = _part_solids(fp, grid, origin, centres, cell, again, xyz, local, normals, points, ground)
            if all(is_watertight(s) for s in alt[0]):  # else keep the roof without the raised planes
                solids, roofs, used, part_of_plane, detached = *alt, again, True
    if least is None:
        return solids, roofs, detached
    mixed = np.bincount(part_of_plane, weights=~is_small, minlength=part_of_plane.max() + 1) > 0
    ok = is_small.any() and not mixed[part_of_plane[is_small]].any() and used[is_small].all()
    return solids, roofs, bool(ok)


def _part_solids(fp, grid, origin, centres, cell, part_of_plane, xyz, local, normals, points, ground):
    """LoD2.2 solids and roof faces of every part polygon, and which planes (p,) bool hold a face."""
    solids, roofs = [], []
    used = np.zeros(len(normals), bool)
    dz = None  # each point's height above each plane, for placing the outlines of several parts
    if len(np.unique(part_of_plane)) > 1:
        dz = xyz[:, 2:3] - np.stack([_plane_z(normals, points, np.full(len(xyz), k), xyz[:, :2])
                                     for k in range(len(normals))], axis=1)
    for q, polys in part_polygons(fp, grid, origin, cell, part_of_plane, xyz[:, :2], local, dz).items():
        sel = np.flatnonzero(part_of_plane == q)
        lut = np.full(len(normals), -2, np.int64)
        lut[sel] = np.arange(len(sel))
        sub = np.where(grid >= 0, lut[np.maximum(grid, 0)], -1)
        for poly in [piece for poly in polys for piece in split_holes(poly)]:
            solid, faces, k = part_solid(poly, normals[sel], points[sel], ground, sub, centres, len(solids))
            used[sel[k]] = True
            solids.append(solid)
            roofs += faces
    return solids, roofs, used
