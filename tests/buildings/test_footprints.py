"""Footprints: Douglas-Peucker, orthogonal regularisation of noisy outlines, IoU on analytic
buildings, rasterisation of several buildings."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.buildings import synth
from workstation.buildings.footprints import FootprintParams, douglas_peucker, extract_footprints, regularize


def _iou(a, b):
    import shapely

    pa, pb = shapely.Polygon(a), shapely.Polygon(b)
    return pa.intersection(pb).area / pa.union(pb).area


def _angles(poly):
    d = np.roll(poly, -1, axis=0) - poly
    e = np.roll(d, 1, axis=0)
    cos = np.einsum("ij,ij->i", d, e) / (np.linalg.norm(d, axis=1) * np.linalg.norm(e, axis=1))
    return np.degrees(np.arccos(np.clip(cos, -1, 1)))


def test_douglas_peucker_keeps_the_corners_of_a_noisy_square():
    rng = np.random.default_rng(0)
    t = np.linspace(0, 4, 400, endpoint=False)
    side, f = np.divmod(t, 1.0)
    corners = np.array([[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]], float)
    ring = corners[side.astype(int)] + f[:, None] * (corners[side.astype(int) + 1] - corners[side.astype(int)])
    ring += rng.normal(0, 0.05, ring.shape)
    keep = douglas_peucker(ring, 0.3)
    assert len(keep) == 4
    assert np.abs(ring[keep] - corners[:4]).max() < 0.3


def test_regularize_a_noisy_l_shape():
    """A traced L with jagged edges (0.1 m noise) and a 10 degree yaw becomes six right angles."""
    rng = np.random.default_rng(4)
    L = np.array([[0, 0], [12, 0], [12, 5], [5, 5], [5, 10], [0, 10]], float)
    pts = []
    for a, b in zip(L, np.roll(L, -1, axis=0)):
        t = np.linspace(0, 1, int(np.linalg.norm(b - a) / 0.1), endpoint=False)
        pts.append(a + t[:, None] * (b - a))
    ring = np.vstack(pts) + rng.normal(0, 0.1, (sum(map(len, pts)), 2))
    yaw = np.radians(10)
    R = np.array([[np.cos(yaw), -np.sin(yaw)], [np.sin(yaw), np.cos(yaw)]])
    out = regularize(ring @ R.T, 0.3)
    assert len(out) == 6
    assert np.allclose(_angles(out), 90.0, atol=0.5)
    assert _iou(out, L @ R.T) > 0.97


@pytest.mark.parametrize("kind", ["flat", "gabled", "lshape", "multilevel"])
def test_footprint_iou_on_analytic_buildings(kind):
    rng = np.random.default_rng(11)
    b = synth.SynthBuilding(kind, (0.0, 0.0), 16.0, 10.0, 0.3, 6.0, 3.0, 100.0)
    pts = synth.sample_building(b, 10.0, 0.03, rng)
    fps, owner = extract_footprints(pts[:, :2])
    assert len(fps) == 1
    assert (owner == 0).mean() > 0.99
    poly = fps[0].polygon
    assert _iou(poly, b.footprint()) >= 0.9
    assert len(poly) == len(b.footprint())  # four corners, six for the L
    assert np.allclose(_angles(poly), 90.0, atol=1.0)


def test_buildings_are_separated_and_small_blobs_dropped():
    rng = np.random.default_rng(2)
    xyz, cls, blds = synth.district(4, seed=3, density=8.0)
    roof = xyz[cls == 6]
    blob = np.column_stack([rng.uniform(500100, 500101.5, 20), rng.uniform(5300100, 5300101.5, 20), np.full(20, 105.0)])
    fps, owner = extract_footprints(np.vstack([roof, blob])[:, :2], FootprintParams(min_area=10.0))
    assert len(fps) == 4
    assert (owner[len(roof):] == -1).all()
    for b in blds:
        assert max(_iou(f.polygon, b.footprint()) for f in fps) > 0.9


def test_trace_outline_is_contourpys_level_half_line():
    """trace_outline gives contourpy.contour_generator's longest level-0.5 line, in metres."""
    import contourpy

    from workstation.buildings.footprints import trace_outline

    rng = np.random.default_rng(4)
    yy, xx = np.mgrid[0:40, 0:50]
    field = np.exp(-((xx - 22) ** 2 / 120 + (yy - 18) ** 2 / 60)) + 0.05 * rng.random((40, 50))
    gen = contourpy.contour_generator(z=np.pad(field, 1), line_type=contourpy.LineType.Separate)
    ring = max(gen.lines(0.5), key=len)
    got = trace_outline(field, np.array([10.0, 20.0]), 0.25)
    assert len(ring) > 20 and np.allclose(ring[0], ring[-1])
    assert np.array_equal(got, np.array([10.0, 20.0]) + (ring[:-1] - 1 + 0.5) * 0.25)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_small_cross_t_keeps_its_stem(seed):
    """A small T (10.4 x 7.1 m: a stem 3.8 m wide and 2.8 m long) is traced with its eight
    corners at right angles and IoU >= 0.9, whatever its yaw."""
    rng = np.random.default_rng(seed)
    b = synth.SynthBuilding("cross_t", (0.0, 0.0), 10.4, 7.1, rng.uniform(0, np.pi), 6.0, 3.0, 100.0)
    pts = synth.sample_building(b, 10.0, 0.03, rng)
    fps, _ = extract_footprints(pts[:, :2])
    assert len(fps) == 1
    poly = fps[0].polygon
    assert len(poly) == 8
    assert np.allclose(_angles(poly), 90.0, atol=1.0)
    assert _iou(poly, b.footprint()) >= 0.9


def test_roof_density_is_measured_in_the_roof_cores():
    """On small roofs (most cells near a margin) the reference density is the roofs' own, so the
    level-0.5 outline of a 7 x 6 m rectangle crosses the middle of its sides within 0.15 m."""
    from workstation.buildings.footprints import density_field, trace_outline

    rng = np.random.default_rng(3)
    rho, s = 10.0, 10.0 ** -0.5
    boxes = [(x0, 0.0, x0 + 7.0, 6.0) for x0 in np.arange(0.0, 200.0, 20.0)]
    xy = np.vstack([_uniform(rng, rho, box) for box in boxes])
    field, origin, cell, ref = density_field(xy, s)
    actual = len(xy) / sum((c - a) * (d - b) for a, b, c, d in boxes) * cell * cell
    assert ref == pytest.approx(actual, rel=0.04)  # the median over all covered cells: 37 % low
    first = np.where(np.arange(field.shape[1]) * cell + origin[0] < 10.0, field, 0.0)  # the first roof alone
    ring = trace_outline(first, origin, cell)
    across = ring[np.abs(ring[:, 1] - 3.0) < 0.5, 0]  # the outline across the middle of each side
    along = ring[np.abs(ring[:, 0] - 3.5) < 0.5, 1]
    assert np.abs([across.min(), across.max() - 7.0, along.min(), along.max() - 6.0]).max() < 0.15


def test_roof_density_of_a_lone_narrow_roof_comes_from_a_finer_smoothing():
    """A 12 x 7 m roof alone at 2 points/m2 has no core two sigmas inside its mask (sigma 1.8 m):
    over six draws, the reference density, taken from the cores of the counts smoothed with a
    smaller sigma, is within 25 % of the roof's true count per cell, and the footprint found
    overlaps the roof with an IoU of at least 0.95."""
    from workstation.buildings.footprints import density_field, nominal_spacing

    rect = np.array([[0, 0], [12, 0], [12, 7], [0, 7]], float)
    for seed in range(6):
        rng = np.random.default_rng(seed)
        xy = _uniform(rng, 2.0, (0.0, 0.0, 12.0, 7.0))
        _, _, cell, ref = density_field(xy, nominal_spacing(xy))
        assert ref == pytest.approx(len(xy) / 84.0 * cell * cell, rel=0.25)
        fps, _ = extract_footprints(xy)
        assert len(fps) == 1 and _iou(fps[0].polygon, rect) >= 0.95


def _uniform(rng, rho, box):
    a, b, c, d = box
    n = rng.poisson(rho * (c - a) * (d - b))
    return np.column_stack([rng.uniform(a, c, n), rng.uniform(b, d, n)])


def test_edges_move_to_their_maximum_likelihood_place():
    """Edge lines started 0.3 m off move to within 5 cm of a uniformly sampled rectangle's sides;
    two stray points 0.5 m outside one side do not pull it."""
    from workstation.buildings.footprints import _fit_offsets, edge_intersections

    rng = np.random.default_rng(5)
    pts = np.vstack([_uniform(rng, 10.0, (0.0, 0.0, 12.0, 8.0)), [[6.0, 8.5], [7.0, 8.5]]])
    dirs = np.array([[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]])
    mids = np.array([[6.0, 0.3], [11.7, 4.0], [6.0, 7.7], [0.3, 4.0]])
    lengths = np.array([12.0, 8.0, 12.0, 8.0])
    got = _fit_offsets(dirs, mids, lengths, pts, 0.8, 0.3, 0.6, 10.0, 3.0)
    corners = edge_intersections(dirs, got)
    assert np.abs(corners - np.array([[0, 0], [12, 0], [12, 8], [0, 8]])).max() < 0.05


def test_points_direction_of_a_rectangle():
    """The minimum-area rectangle of uniformly sampled points gives a building's yaw within 0.3 degrees."""
    from workstation.buildings.footprints import _points_direction

    rng = np.random.default_rng(6)
    for yaw in np.radians([3.0, 27.0, 61.0]):
        b = synth.SynthBuilding("flat", (0.0, 0.0), 12.0, 8.0, yaw, 6.0, 3.0, 0.0)
        pts = synth.sample_building(b, 10.0, 0.03, rng)
        err = (_points_direction(pts[:, :2]) - yaw + np.pi / 4) % (np.pi / 2) - np.pi / 4
        assert abs(np.degrees(err)) < 0.3


@pytest.mark.parametrize("seed", [0, 1, 2, 3])
def test_t_keeps_its_stem_at_four_points_per_m2(seed):
    """At 4 points/m2 (national-programme density) the stems of a district's Ts (2.8-4.8 m long:
    six to ten spacings) are kept: every T has its eight corners and IoU >= 0.9."""
    xyz, cls, blds = synth.district(9, seed=seed, density=4.0, kinds=("cross_t",))
    fps, _ = extract_footprints(xyz[cls == 6, :2])
    for b in blds:
        poly = max((f.polygon for f in fps), key=lambda p: _iou(p, b.footprint()))
        assert _iou(poly, b.footprint()) >= 0.9
        assert len(poly) == 8


def _polyline(corners, step=0.1):
    pts = [a + t[:, None] * (b - a) for a, b in zip(corners[:-1], corners[1:])
           for t in [np.linspace(0, 1, max(int(np.linalg.norm(b - a) / step), 1), endpoint=False)]]
    return np.vstack(pts + [corners[-1:]])


@pytest.mark.parametrize("corners, a, b, expected", [
    # a notch: down the end of a bar, along its underside, down the side of the stem, along its foot
    ([[0, 1], [0, 0], [3, 0], [3, -4], [4, -4]], (1, 0.0, (0, -1)), (0, -4.0, (1, 0)), [(0, 0.0, (1, 0)), (1, 3.0, (0, -1))]),
    # a wing's end: up the side of a stem, along the underside of the bar, up its end, back along its top
    ([[0, -1], [0, 0], [4, 0], [4, 5], [3, 5]], (1, 0.0, (0, 1)), (0, 5.0, (-1, 0)), [(0, 0.0, (1, 0)), (1, 4.0, (0, 1))]),
    # a plain corner, rounded by less than the tolerance
    ([[0, 1], [0, 0.3], [0.3, 0], [1, 0]], (1, 0.0, (0, -1)), (0, 0.0, (1, 0)), []),
    # the end of a bar between its two long sides
    ([[0, 0], [5, 0], [5, 3], [4, 3]], (0, 0.0, (1, 0)), (0, 3.0, (-1, 0)), [(1, 5.0, (0, 1))]),
])
def test_steps_rebuild_notches_and_wing_ends(corners, a, b, expected):
    """The rectilinear Douglas-Peucker puts the lines of a notch through its inner corner and
    those of a wing's end through its outer corner, headed along the ring; a corner within the
    tolerance gets none."""
    from workstation.buildings.footprints import _steps

    chain = _polyline(np.array(corners, float))
    chain = chain + np.random.default_rng(0).normal(0, 0.03, chain.shape)
    got = _steps(chain, (a[0], a[1], np.array(a[2], float)), (b[0], b[1], np.array(b[2], float)), 0.8)
    assert [g[0] for g in got] == [e[0] for e in expected]
    assert np.allclose([g[1] for g in got], [e[1] for e in expected], atol=0.15)
    assert all(np.allclose(g[2], e[2]) for g, e in zip(got, expected))


@pytest.mark.parametrize("density", [4.0, 2.0])
def test_vacancy_finds_an_empty_corner_that_chance_does_not_leave(density):
    """Points of a 12 x 10 m rectangle leave no empty region improbable at the 5 % level inside
    it; without a 3 x 3 m corner (9 m^2, about a twentieth of the points: within two standard
    deviations of the whole count at 2 points/m^2) the rectangle holds one."""
    from workstation.buildings.footprints import VACANCY_LEVEL, _vacancy

    rect = np.array([[0, 0], [12, 0], [12, 10], [0, 10]], float)
    cell = 0.5 / np.sqrt(density)
    for seed in range(10):
        rng = np.random.default_rng(seed)
        pts = rng.uniform([0, 0], [12, 10], (rng.poisson(density * 120), 2))
        assert _vacancy(rect, pts, density, cell, VACANCY_LEVEL) >= VACANCY_LEVEL
        notch = pts[~((pts[:, 0] > 9) & (pts[:, 1] > 7))]
        assert _vacancy(rect, notch, density, cell, VACANCY_LEVEL) < 1e-3


@pytest.mark.parametrize("chain, value", [([[0, 0], [1, 0], [1, 1], [2, 1]], 1.0),
                                          ([[0, 0], [1, 0], [2, 0], [2, 1], [3, 1]], 2.0)])
def test_steps_between_parallel_lines_with_inner_points_on_them(chain, value):
    """Parallel lines 1 m apart (y = 0 and y = 1) joined by a traced chain whose inner points all
    lie exactly on one or the other (no deviation anywhere): the crossing goes through the middle
    of the chain's points, the line x = 1 or x = 2 heading up (the selection of the points at
    least half the largest deviation holds them all, none being more)."""
    from workstation.buildings.footprints import _steps

    got = _steps(np.array(chain, float), (0, 0.0, np.array([1.0, 0])), (0, 1.0, np.array([1.0, 0])), 0.8)
    assert len(got) == 1 and got[0][0] == 1
    assert got[0][1] == value and np.allclose(got[0][2], [0.0, 1.0])


@pytest.mark.parametrize("n, density", [(0, 4.0), (50, 0.0), (50, -1.0)])
def test_vacancy_without_points_or_density_is_infinite(n, density):
    """No points, or no positive density, give no scan statistic: ``inf`` (never under a level)."""
    from workstation.buildings.footprints import _vacancy

    rect = np.array([[0, 0], [12, 0], [12, 10], [0, 10]], float)
    pts = np.random.default_rng(0).uniform([0, 0], [12, 10], (n, 2))
    assert _vacancy(rect, pts, density, 0.25, 0.05) == np.inf


def test_sparse_t_keeps_its_stem_at_the_finest_smoothing():
    """At 2 points/m2 the stem (5.5 x 4.1 m) of building 34 of this district is rounded away at
    2.5 and 1.5 spacings (the likelier outline a rectangle, IoU 0.71); neither explains the
    points, and the one-spacing smoothing keeps the stem."""
    xyz, cls, blds = synth.district(40, seed=7, density=2.0, kinds=synth.COMPLEX_KINDS)
    fps, _ = extract_footprints(xyz[cls == 6, :2])
    b = blds[34]
    poly = max((f.polygon for f in fps), key=lambda p: _iou(p, b.footprint()))
    assert len(poly) == 8
    assert _iou(poly, b.footprint()) >= 0.85


def test_the_coarse_pass_looks_for_no_steps(monkeypatch):
    """At the wide smoothing every corner region is left to the lines on either side: the
    rectilinear Douglas-Peucker (:func:`_steps`) is never called."""
    from workstation.buildings import footprints as F

    def fail(*args, **kwargs):
        raise AssertionError("steps looked for in the coarse pass")

    rng = np.random.default_rng(3)
    b = synth.SynthBuilding("cross_t", (0.0, 0.0), 14.0, 9.0, 0.0, 6.0, 3.0, 100.0)
    pts = synth.sample_building(b, 4.0, 0.03, rng)[:, :2]
    monkeypatch.setattr(F, "_steps", fail)
    assert F._orthogonal_pass(pts, 0.5, 0.25, F.CORNER_RADIUS) is not None
    with pytest.raises(AssertionError, match="coarse"):
        F._orthogonal_pass(pts, 0.5, 0.25, F.FINE_RADIUS)


def test_outlines_that_disagree_with_the_ring_compete_with_its_regularisation(monkeypatch):
    """When no rectilinear outline agrees with the traced ring, the likeliest of them and the
    regularised ring is kept: a right outline beats a ring regularised astray, and a wrong one
    (a third of the building) loses to the right ring."""
    from workstation.buildings import footprints as F

    rng = np.random.default_rng(5)
    rect = np.array([[0, 0], [14, 0], [14, 9], [0, 9]], float)
    pts = rng.uniform([0, 0], [14, 9], (rng.poisson(2.0 * 126), 2))
    field, origin, cell, ref = F.density_field(pts, 2 ** -0.5)
    ring = F.trace_outline(field, origin, cell)
    astray = np.array([[3, 2], [11, 2], [11, 7], [3, 7]], float)
    monkeypatch.setattr(F, "regularize", lambda *a, **k: astray)
    monkeypatch.setattr(F, "_rectilinear", lambda *a: (rect, False))
    assert np.array_equal(F._outline(pts, ring, 2 ** -0.5, ref, cell, FootprintParams()), rect)
    monkeypatch.setattr(F, "regularize", lambda *a, **k: rect)
    monkeypatch.setattr(F, "_rectilinear", lambda *a: (astray, False))
    assert np.array_equal(F._outline(pts, ring, 2 ** -0.5, ref, cell, FootprintParams()), rect)


@pytest.mark.parametrize("xy", [np.zeros((0, 2)), np.array([[1.0, 2.0]]), np.array([[0.0, 0.0], [0.3, 0.0]]),
                                np.tile([[5.0, 5.0]], (50, 1))], ids=["none", "one", "two", "one spot"])
def test_too_few_distinct_points_give_no_footprint(xy):
    """Fewer than two distinct points have no spacing and no region: the error of a district
    without footprints (as for points too few to make one), not a numerical failure."""
    from workstation.buildings.footprints import district_components
    from workstation.core.errors import StageError

    d = district_components(xy)
    assert d.components == [] and d.point_component().tolist() == [-1] * len(xy)
    with pytest.raises(StageError, match="no building"):
        extract_footprints(xy)


def test_collinear_and_repeated_points_are_measured_on_their_distinct_points():
    """Points on a line have a line for minimum rectangle (its direction is theirs) and make a
    footprint without failing; a roof whose every point is repeated has the spacing, and so the
    footprint, of its distinct points."""
    from workstation.buildings.footprints import _points_direction, nominal_spacing

    assert _points_direction(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]])) == pytest.approx(np.pi / 4)
    assert _points_direction(np.tile([[1.0, 1.0]], (3, 1))) == 0.0
    fps, _ = extract_footprints(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]))
    assert len(fps) == 1
    rng = np.random.default_rng(0)
    xy = _uniform(rng, 10.0, (0.0, 0.0, 12.0, 8.0))
    assert nominal_spacing(np.repeat(xy, 3, axis=0)) == nominal_spacing(xy)
    a, _ = extract_footprints(xy)
    b, _ = extract_footprints(np.repeat(xy, 3, axis=0))
    assert _iou(a[0].polygon, b[0].polygon) > 0.97


def test_regularize_returns_a_simple_ring_where_the_simplified_one_crosses_itself():
    """A traced ring that crosses itself (a bow tie, whose Douglas-Peucker ring crosses too) is
    not regularised: the ring returned is the outer ring of the larger triangle of its repair,
    counter-clockwise and valid, not the crossing ring, whose shoelace area (the difference of
    the triangles', 10 m2) understates what it encloses."""
    import shapely

    from workstation.buildings.footprints import _simple_ring

    t = np.linspace(0.0, 1.0, 40, endpoint=False)[:, None]
    corners = np.array([[0.0, 0.0], [10.0, 6.0], [10.0, 0.0], [0.0, 8.0]])
    ring = np.vstack([a + t * (b - a) for a, b in zip(corners, np.roll(corners, -1, axis=0))])
    out = regularize(ring, 0.3)
    poly = shapely.Polygon(out)
    assert poly.is_valid and poly.exterior.is_ccw and poly.area == pytest.approx(0.5 * 8.0 * 40.0 / 7.0, rel=1e-6)
    square = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
    assert _simple_ring(square, None) is square  # a valid ring is kept as it is
    assert _simple_ring(np.array([[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]), square) is square  # no area: the fallback
