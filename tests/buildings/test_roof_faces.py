"""Roof faces of non-convex (cross-gabled) parts: the plane arrangement against the analytic
roofs of synth.py, watertight solids, and convex roofs left to the lower envelope."""

from __future__ import annotations

import numpy as np
import pytest
import shapely

from workstation.buildings import models, synth
from workstation.buildings.roof_faces import (_jumps, _meets, _plane_coefficients, _shared_segments, arrangement_faces,
                                              envelope_faces, roof_faces)

CELL = 0.3


def _truth_planes(b: synth.SynthBuilding):
    """Upward normals (p, 3) and points (p, 3) of the true roof planes of a wing roof."""
    normals, points = [], []
    base = b.ground + b.eave
    for w in b.wings():
        for sign in (1.0, -1.0):  # the slope rising towards the ridge from below / above it
            across = w.ridge - sign * w.half_width / 2
            uv = np.array([[(w.u0 + w.u1) / 2, across]]) if w.along_u else np.array([[across, (w.v0 + w.v1) / 2]])
            gl = np.array([0.0, sign * w.slope]) if w.along_u else np.array([sign * w.slope, 0.0])
            c, s = np.cos(b.yaw), np.sin(b.yaw)
            gx, gy = gl[0] * c - gl[1] * s, gl[0] * s + gl[1] * c
            n = np.array([-gx, -gy, 1.0])
            normals.append(n / np.linalg.norm(n))
            points.append(np.r_[b.to_world(uv)[0], base + w.z(uv[:, 0], uv[:, 1])[0]])
    return np.array(normals), np.array(points)


def _truth_raster(b: synth.SynthBuilding, poly, normals, points):
    """Ownership raster (as models.ownership_raster makes it) from the truth: each cell inside
    the footprint is owned by the plane that is the roof at its centre."""
    x0, y0, x1, y1 = poly.bounds
    cx, cy = np.meshgrid(x0 + (np.arange(int(np.ceil((x1 - x0) / CELL))) + 0.5) * CELL,
                         y0 + (np.arange(int(np.ceil((y1 - y0) / CELL))) + 0.5) * CELL)
    centres = np.stack([cx, cy], axis=-1)
    xy = centres.reshape(-1, 2)
    p = len(normals)
    z = np.stack([models._plane_z(normals, points, np.full(len(xy), k), xy) for k in range(p)], axis=1)
    grid = np.argmin(np.abs(z - b.roof_z(xy)[:, None]), axis=1)
    grid[~shapely.contains_xy(poly, xy[:, 0], xy[:, 1])] = -1
    return grid.reshape(cx.shape), centres


def _part(kind: str, yaw: float = 0.5):
    b = synth.SynthBuilding(kind, (500100.0, 5300200.0), 15.0, 9.5, yaw, 6.0, 3.5, 100.0)
    poly = shapely.orient_polygons(shapely.Polygon(b.footprint()))
    normals, points = _truth_planes(b)
    grid, centres = _truth_raster(b, poly, normals, points)
    return b, poly, normals, points, grid, centres


def _face_z(faces, normals, points, xy):
    z = np.full(len(xy), np.nan)
    for k, f in faces:
        inside = shapely.contains_xy(f, xy[:, 0], xy[:, 1])
        z[inside] = models._plane_z(normals, points, np.full(inside.sum(), k), xy[inside])
    return z


def _samples(b, poly, step=0.1):
    x0, y0, x1, y1 = poly.bounds
    g = np.stack(np.meshgrid(np.arange(x0, x1, step) + step / 3, np.arange(y0, y1, step) + step / 7), -1).reshape(-1, 2)
    return g[shapely.contains_xy(poly, g[:, 0], g[:, 1])]


@pytest.mark.parametrize("kind", ["cross_l", "cross_t"])
@pytest.mark.parametrize("yaw", [0.5, 2.0])
def test_cross_gabled_faces_follow_the_true_roof(kind, yaw):
    b, poly, normals, points, grid, centres = _part(kind, yaw)
    envelope = envelope_faces(poly, normals, points, grid, centres)
    faces = roof_faces(poly, normals, points, grid, centres)
    xy = _samples(b, poly)
    dz_env = _face_z(envelope, normals, points, xy) - b.roof_z(xy)
    dz = _face_z(faces, normals, points, xy) - b.roof_z(xy)
    assert np.nanmax(np.abs(dz_env)) > 1.0  # the lower envelope cannot model the valleys
    assert np.isfinite(dz).all()  # the faces cover the part
    assert np.max(np.abs(dz)) < 0.01
    assert sum(f.area for _, f in faces) == pytest.approx(poly.area, rel=1e-9)
    assert {k for k, _ in faces} == set(range(len(normals)))


@pytest.mark.parametrize("kind", ["cross_l", "cross_t"])
def test_cross_gabled_solid_is_watertight(kind):
    b, poly, normals, points, grid, centres = _part(kind)
    solid, roofs, _ = models.part_solid(poly, normals, points, b.ground, grid, centres, 0)
    assert models.is_watertight(solid)
    assert len(roofs) >= len(normals)


def test_estimated_planes_still_meet_continuously():
    """Planes off the truth by fractions of a degree and a few cm (as fitted from noisy points)
    no longer meet in common points; the arrangement still gives a continuous roof near the
    true one."""
    rng = np.random.default_rng(3)
    b, poly, normals, points, grid, centres = _part("cross_l", 1.1)
    normals = normals + rng.normal(0, 0.002, normals.shape)
    normals /= np.linalg.norm(normals, axis=1, keepdims=True)
    points = points + np.c_[np.zeros((len(points), 2)), rng.normal(0, 0.02, len(points))]
    faces = arrangement_faces(poly, normals, points, grid, centres)
    assert faces is not None
    cells = np.array([f for _, f in faces], object)
    g, h = _plane_coefficients(normals, points)
    seg = _shared_segments(cells)
    assert len(seg[0]) >= 3  # the faces do share edges: ridges and valleys
    assert not _jumps(np.array([k for k, _ in faces]), seg, _meets(seg, g, h)).any()
    xy = _samples(b, poly, 0.2)
    dz = _face_z(faces, normals, points, xy) - b.roof_z(xy)
    assert np.sqrt(np.mean(dz ** 2)) < 0.05
    assert models.is_watertight(models.part_solid(poly, normals, points, b.ground, grid, centres, 0)[0])


@pytest.mark.parametrize("kind", ["gabled", "hipped"])
def test_convex_roofs_keep_the_lower_envelope(kind):
    b = synth.SynthBuilding(kind, (500100.0, 5300200.0), 15.0, 9.5, 0.5, 6.0, 3.5, 100.0)
    poly = shapely.orient_polygons(shapely.Polygon(b.footprint()))
    g = b.roof_gradients()
    normals = np.c_[-g, np.ones(len(g))] / np.linalg.norm(np.c_[-g, np.ones(len(g))], axis=1, keepdims=True)
    c = np.asarray(b.center)
    ridge = b.ground + b.eave + b.rise
    points = np.tile(np.r_[c, ridge], (len(g), 1))  # every plane passes through the ridge's middle
    if kind == "hipped":  # the hip planes reach the ridge height a - b from the centre along u
        u = np.array([[np.cos(b.yaw), np.sin(b.yaw)]]) * (b.length / 2 - b.width / 2)
        points[2:, :2] = c + np.array([1.0, -1.0])[:, None] * u
    grid, centres = _truth_raster(b, poly, normals, points)
    env = envelope_faces(poly, normals, points, grid, centres)
    faces = roof_faces(poly, normals, points, grid, centres)
    assert len(faces) == len(env) == len(normals)
    for (k, f), (ke, fe) in zip(faces, env):
        assert k == ke and f.equals_exact(fe, 0.0)


def test_one_plane_has_no_arrangement():
    b, poly, normals, points, grid, centres = _part("cross_l")
    only = np.where(grid >= 0, 0, grid)
    assert arrangement_faces(poly, normals, points, only, centres) is None


def test_fill_specks_fills_only_holes_of_sliver_size():
    """A hole of about 1e-18 m^2 (the noding's cell where several planes' lines nearly meet in a
    point) is filled; a hole of 1e-4 m^2 is kept."""
    import shapely

    from workstation.buildings.roof_faces import _fill_specks

    outer = [(0, 0), (4, 0), (4, 4), (0, 4)]
    speck = [(2, 2), (2 + 1e-9, 2), (2 + 1e-9, 2 + 1e-9), (2, 2 + 1e-9)]
    hole = [(1, 1), (1.01, 1), (1.01, 1.01), (1, 1.01)]
    filled = _fill_specks(shapely.Polygon(outer, [speck, hole]))
    assert len(filled.interiors) == 1 and shapely.Polygon(filled.interiors[0]).area == pytest.approx(1e-4)
    kept = shapely.Polygon(outer, [hole])
    assert _fill_specks(kept) is kept
