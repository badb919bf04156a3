"""Roof plane segmentation: the RANSAC iteration bound, analytic planes with noise and
outliers, the distance threshold and coplanar merging."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workstation.buildings import synth
from workstation.buildings.planes import (PlaneParams, distance_threshold, ransac_iterations, ransac_plane,
                                          segment_planes)


@pytest.mark.parametrize("p,w,m", [(0.99, 0.5, 3), (0.999, 0.3, 3), (0.95, 0.8, 2), (0.99, 0.1, 3)])
def test_ransac_iterations_is_the_textbook_bound(p, w, m):
    k = ransac_iterations(p, w, m)
    assert k == math.ceil(math.log(1 - p) / math.log(1 - w ** m))
    # k draws reach the confidence, k - 1 do not
    assert 1 - (1 - w ** m) ** k >= p
    assert 1 - (1 - w ** m) ** (k - 1) < p


def test_ransac_iterations_rejects_bad_input():
    with pytest.raises(ValueError):
        ransac_iterations(1.0, 0.5)
    with pytest.raises(ValueError):
        ransac_iterations(0.99, 0.0)


def test_ransac_plane_finds_the_plane_among_outliers():
    rng = np.random.default_rng(3)
    xy = rng.uniform(0, 10, (600, 2))
    z = 2.0 + 0.3 * xy[:, 0] - 0.1 * xy[:, 1] + rng.normal(0, 0.02, 600)
    out = rng.uniform([0, 0, 0], [10, 10, 8], (400, 3))  # 40 % outliers
    pts = np.vstack([np.column_stack([xy, z]), out])
    n, d, inl = ransac_plane(pts, 0.06, PlaneParams(), rng)
    true = np.array([-0.3, 0.1, 1.0]) / np.linalg.norm([-0.3, 0.1, 1.0])
    assert np.degrees(np.arccos(abs(n @ true))) < 0.5
    assert inl[:600].mean() > 0.97
    assert inl[600:].mean() < 0.1  # only outliers that happen to lie in the slab


def test_distance_threshold_grows_with_noise_and_spacing():
    assert distance_threshold(0.0, 0.5, 10.0) == pytest.approx(0.5 * math.tan(math.radians(10)))
    assert distance_threshold(0.05, 0.0, 10.0) == pytest.approx(0.15)
    assert distance_threshold(0.05, 0.5, 10.0) > distance_threshold(0.02, 0.5, 10.0)


@pytest.mark.parametrize("kind,planes", [("gabled", 2), ("hipped", 4), ("shed", 1), ("flat", 1)])
def test_roof_planes_match_the_analytic_roof(kind, planes):
    rng = np.random.default_rng(7)
    b = synth.SynthBuilding(kind, (1000.0, 2000.0), 15.0, 9.0, 0.7, 6.0, 3.5, 100.0)
    pts = synth.sample_building(b, 10.0, 0.03, rng)
    outliers = np.column_stack([rng.uniform(990, 1010, 60), rng.uniform(1990, 2010, 60), rng.uniform(100, 115, 60)])
    r = segment_planes(np.vstack([pts, outliers]))
    assert len(r.normals) == planes
    truth = b.true_tilt_azimuth()
    for tilt, az in truth:
        k = int(np.argmin(np.abs(r.tilt_deg - tilt) + np.where(tilt > 0, np.abs((r.azimuth_deg - az + 180) % 360 - 180), 0)))
        assert abs(r.tilt_deg[k] - tilt) < 1.0
        if tilt > 0:
            assert abs((r.azimuth_deg[k] - az + 180) % 360 - 180) < 2.0
    assert (r.labels[:len(pts)] >= 0).mean() > 0.95  # roof points on planes
    assert (r.labels[len(pts):] >= 0).mean() < 0.2  # outliers mostly not
    assert r.noise == pytest.approx(0.03, rel=0.35)  # estimated from the local PCA residuals


def test_coplanar_pieces_are_merged():
    """A plane cut by a seam (a 5 cm crease line) grows into two regions that are merged back
    into one plane; a parallel patch 1 m higher stays apart."""
    from workstation.buildings import planes as P

    rng = np.random.default_rng(1)
    a = rng.uniform([0, 0], [12, 6], (2000, 2))
    seam = np.abs(a[:, 0] - 6.0) < 0.15
    za = 0.2 * a[:, 0] + rng.normal(0, 0.01, len(a)) + 0.05 * seam
    c = rng.uniform([16, 0], [22, 6], (1000, 2))
    zc = 1.0 + 0.2 * c[:, 0] + rng.normal(0, 0.01, len(c))
    pts = np.vstack([np.column_stack([a, za]), np.column_stack([c, zc])])
    loc = pts - pts.min(axis=0)
    normals, sigma, idx = P.local_geometry(loc, 12)
    spacing = float(np.median(np.linalg.norm(loc[idx[:, 1]] - loc, axis=1)))
    eps = P.distance_threshold(float(np.median(sigma)), spacing, 10.0)
    regions = P._grow_regions(loc, normals, sigma, idx, eps, spacing, 10.0)
    big = np.unique(regions[:len(a)][regions[:len(a)] >= 0], return_counts=True)[1]
    assert (big > 100).sum() >= 2  # growing alone leaves two pieces
    r = segment_planes(pts, PlaneParams(seed=2))
    assert len(r.normals) == 2
    first = r.labels[:len(a)][~seam]
    assert len(set(first[first >= 0])) == 1


def test_scan_lines_far_apart_still_give_the_roof_planes():
    """Airborne scan lines 0.9 m apart with points every 0.1 m along them (the simulator's
    pattern): neighbours found along one line have no normal; the scan frame stretches the
    search across lines and the two sides of a gable come out whole."""
    from workstation.buildings.planes import scan_frame

    rng = np.random.default_rng(5)
    x = np.arange(-7.0, 7.0, 0.9)
    y = np.arange(-4.5, 4.5, 0.1)
    xy = np.stack(np.meshgrid(x, y), -1).reshape(-1, 2) + rng.normal(0, 0.01, (len(x) * len(y), 2))
    yaw = np.radians(25)
    R = np.array([[np.cos(yaw), -np.sin(yaw)], [np.sin(yaw), np.cos(yaw)]])
    b = synth.SynthBuilding("gabled", (0.0, 0.0), 14.0, 9.0, yaw, 6.0, 3.0, 100.0)
    xy = xy @ R.T
    pts = np.column_stack([xy, b.roof_z(xy) + rng.normal(0, 0.02, len(xy))])
    pts = pts[np.isfinite(pts[:, 2])]
    u, a, across, _ = scan_frame(pts[:, :2] - pts[:, :2].min(axis=0))
    assert abs(abs(u @ R[:, 1]) - 1) < 0.01  # the lines run along the rotated y axis
    assert a == pytest.approx(0.1, rel=0.2)
    assert 0.9 <= across < 1.3  # density over 2 m cells: the partly covered edge cells lower it
    r = segment_planes(pts)
    big = r.counts > 0.2 * len(pts)
    assert big.sum() == 2 and r.counts[big].sum() > 0.9 * len(pts)
    assert np.allclose(r.tilt_deg[big], np.degrees(np.arctan(3.0 / 4.5)), atol=1.0)


def test_scan_frame_of_points_mostly_on_one_spot_is_the_cell_density_spacing():
    """More than half the points repeated on one spot (their k-th neighbour at distance 0): the
    median neighbour spacing is 0, so the frame is isotropic with the spacing of the density over
    the occupied 2 m cells; segmentation of such a cloud runs through without an error or a
    warning."""
    import warnings

    from workstation.buildings.planes import scan_frame

    rng = np.random.default_rng(0)
    xy = rng.uniform(0, 10, (400, 2))
    plane = np.column_stack([xy, 0.3 * xy[:, 1] + rng.normal(0, 0.02, 400)])
    pts = np.vstack([plane, np.tile([5.0, 5.0, 1.5], (600, 1))])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        u, a, b, density = scan_frame(pts[:, :2])
        r = segment_planes(pts)
    assert np.array_equal(u, [1.0, 0.0]) and density == pytest.approx(1000 / 100.0)  # 25 cells of 4 m2
    assert a == b == pytest.approx(1 / math.sqrt(density))
    assert r.labels.shape == (1000,)


@pytest.mark.parametrize("p", [1, 7, 40, 64, 65, 600])
def test_small_components_numbers_components_like_scipy(p):
    """Same labels, in the same order, as scipy's connected components: isolated nodes, self
    loops, repeated edges, chains (several propagation rounds) and the sparse fallback."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    from workstation.buildings.planes import small_components

    rng = np.random.default_rng(p)
    for e in (0, p // 2, 2 * p):
        i, j = rng.integers(0, p, e), rng.integers(0, p, e)
        chain = np.arange(p - 1)[::-1][: p // 3]  # a path walked from its high end
        i, j = np.r_[i, chain], np.r_[j, chain + 1]
        want = connected_components(coo_matrix((np.ones(len(i)), (i, j)), shape=(p, p)), directed=False)[1]
        got = small_components(p, i, j)
        assert got.dtype == want.dtype and got.tolist() == want.tolist()


def test_fine_pass_finds_the_two_planes_of_a_dormer():
    """A dormer's faces (about 3 m^2, 30-40 points each at 10 points/m^2) are too narrow for the
    24-neighbour normals; the fine pass on the leftover points finds both, and the main roof's
    two planes stay as they were."""
    rng = np.random.default_rng(6)
    b = synth.SynthBuilding("dormer", (500.0, 800.0), 15.0, 9.5, 0.5, 6.0, 3.5, 100.0)
    pts = synth.sample_building(b, 10.0, 0.03, rng)
    r = segment_planes(pts)
    found = np.column_stack([r.tilt_deg, r.azimuth_deg])
    for k, (tilt, az) in enumerate(b.true_tilt_azimuth()):
        d = np.hypot(found[:, 0] - tilt, (found[:, 1] - az + 180) % 360 - 180)
        assert d.min() < (0.5 if k < 2 else 3.0), (k, tilt, az, found)
    uv = b.to_local(pts[:, :2])
    main, dormer = b.wings()
    on = dormer.z(uv[:, 0], uv[:, 1]) > main.z(uv[:, 0], uv[:, 1]) + 0.1
    assert np.mean(r.labels[on] >= 0) > 0.8
