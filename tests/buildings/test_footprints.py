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
    """The direct serial generator gives contourpy.contour_generator's longest level-0.5 line."""
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
