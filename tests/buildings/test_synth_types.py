"""The composite analytic buildings of the simulator (cross-gabled L and T, dormer): their truth
(footprint, roof heights, roof planes) is self-consistent, and districts of them can be scored."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from workstation.buildings import synth


def _building(kind, yaw=0.4):
    return synth.SynthBuilding(kind, (1000.0, 2000.0), 16.0, 10.0, yaw, 6.0, 3.5, 100.0)


def _grid(b, step=0.1):
    lo, hi = b.footprint().min(axis=0) - 1.0, b.footprint().max(axis=0) + 1.0
    gx, gy = np.meshgrid(np.arange(lo[0], hi[0], step), np.arange(lo[1], hi[1], step))
    return np.column_stack([gx.ravel(), gy.ravel()]), gx.shape


@pytest.mark.parametrize("kind", synth.COMPLEX_KINDS)
def test_footprint_outline_and_inside_agree(kind):
    b = _building(kind)
    xy, _ = _grid(b)
    poly = shapely.Polygon(b.footprint())
    assert poly.is_valid and shapely.is_ccw(poly.exterior)
    inside = b.inside(xy)
    contains = shapely.contains_xy(poly, xy[:, 0], xy[:, 1])
    d = shapely.distance(poly.exterior, shapely.points(xy[inside != contains]))
    assert np.all(d < 1e-6)  # they differ only on the outline itself
    assert np.isfinite(b.roof_z(xy)).sum() * 0.01 == pytest.approx(poly.area, rel=0.01)


@pytest.mark.parametrize("kind", synth.COMPLEX_KINDS)
def test_every_roof_slope_is_one_of_the_true_planes(kind):
    """Finite differences of the analytic roof, away from its creases, equal one of the
    gradients the truth lists, and every listed plane occurs on the roof."""
    b = _building(kind)
    rng = np.random.default_rng(1)
    xy = rng.uniform(b.footprint().min(axis=0), b.footprint().max(axis=0), (4000, 2))
    h = 1e-3
    z = b.roof_z(xy)
    gx = (b.roof_z(xy + [h, 0]) - b.roof_z(xy - [h, 0])) / (2 * h)
    gy = (b.roof_z(xy + [0, h]) - b.roof_z(xy - [0, h])) / (2 * h)
    ok = np.isfinite(z) & np.isfinite(gx) & np.isfinite(gy)
    g = np.column_stack([gx, gy])[ok]
    truth = b.roof_gradients()
    dist = np.linalg.norm(g[:, None, :] - truth[None], axis=2)
    nearest = dist.min(axis=1)
    assert np.mean(nearest < 1e-6) > 0.98  # the rest straddle a ridge, valley or dormer wall
    assert set(np.argmin(dist[nearest < 1e-6], axis=1)) == set(range(len(truth)))
    assert len(truth) == 4 and np.all(b.true_tilt_azimuth()[:, 0] > 5)


@pytest.mark.parametrize("kind", ["cross_l", "cross_t"])
def test_crossing_wings_meet_in_valleys_without_steps(kind):
    """Neighbouring roof heights never jump (no vertical walls), and some creases are valleys:
    a point lower than the mean of its two neighbours across the crease."""
    b = _building(kind, yaw=0.0)
    xy, shape = _grid(b, 0.05)
    z = b.roof_z(xy).reshape(shape)
    slope = b.rise / (b.width / 2)
    dx = np.abs(np.diff(z, axis=1))
    dy = np.abs(np.diff(z, axis=0))
    assert np.nanmax(dx) <= slope * 0.05 + 1e-9 and np.nanmax(dy) <= slope * 0.05 + 1e-9
    # the second difference along x + y (across a 45-degree valley) is positive somewhere on the roof
    curv = z[:-2, :-2] + z[2:, 2:] - 2 * z[1:-1, 1:-1]
    assert np.nanmax(curv) > slope * 0.05
    ridge = {"cross_l": max(b.width / 4, b.length / 4), "cross_t": 0.3 * b.width}[kind] * slope
    assert np.nanmax(z) - (b.ground + b.eave) == pytest.approx(ridge, rel=1e-3)


def test_dormer_stands_on_the_slope_with_vertical_walls():
    b = _building("dormer", yaw=0.0)
    xy, shape = _grid(b, 0.05)
    z = b.roof_z(xy).reshape(shape)
    main = b.ground + b.eave + b.rise * (1 - np.abs(xy[:, 1] - b.center[1]) / (b.width / 2))
    above = (z.ravel() - main) > 1e-9
    # the dormer is a block of about its width on the v < 0 side, below the main ridge
    u = xy[above, 0] - b.center[0]
    assert above.any() and np.all(xy[above, 1] < b.center[1])
    wd = np.clip(b.length / 4, 2.5, 4.0)
    assert u.max() - u.min() == pytest.approx(wd, abs=0.1)
    assert np.nanmax(z) == pytest.approx(b.ground + b.eave + b.rise)
    front = np.nanmax(np.abs(np.diff(z, axis=0)))  # the gable wall over its front, up to its ridge
    cheek = np.nanmax(np.abs(np.diff(z, axis=1)))  # its side walls, down to the slope at the front
    assert front == pytest.approx(0.6 * b.rise, abs=0.1) and cheek == pytest.approx(0.25 * b.rise, abs=0.1)


def test_district_of_composite_kinds_is_sampled_and_scored():
    from workstation.buildings.pipeline import BuildingsParams, reconstruct_buildings

    xyz, cls, blds = synth.district(3, seed=4, density=10.0, kinds=synth.COMPLEX_KINDS)
    assert [b.kind for b in blds] == list(synth.COMPLEX_KINDS)
    roof = xyz[cls == 6]
    assert np.all(np.isfinite(roof)) and len(roof) > 0.8 * 10.0 * sum(shapely.Polygon(b.footprint()).area for b in blds)
    r = reconstruct_buildings(xyz, cls, BuildingsParams(solar=None))
    rows = synth.evaluate(r.models, blds)
    assert [x["kind"] for x in rows] == list(synth.COMPLEX_KINDS)
    for x in rows:
        assert x["found"] and 0.0 < x["iou"] <= 1.0 and isinstance(x["watertight"], bool)
        assert np.isfinite([x["tilt_err_deg"], x["azimuth_err_deg"], x["roof_rms_m"]]).all()
