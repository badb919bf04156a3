"""Neighbourhood and object-level features: float32 kNN moments and raised-object areas."""

from __future__ import annotations

import numpy as np

from workstation.core.cloud import Cloud
from workstation.ml.features import (
    FEATURE_NAMES,
    FeatureParams,
    _eigen,
    compute_features,
    opening_steps,
)


def test_knn_eigen_features_match_numpy_covariance():
    rng = np.random.default_rng(4)
    pts = rng.uniform(0, 20, (3000, 3)) * [1, 1, 0.3] + [700.0, 300.0, 50.0]
    out, _ = _eigen(pts[:200], pts, 12, 1)
    from scipy.spatial import cKDTree

    _, j = cKDTree(pts).query(pts[:200], k=12)
    for q in range(0, 200, 23):
        w, v = np.linalg.eigh(np.cov(pts[j[q]].T, bias=True))
        l3, l2, l1 = w
        assert abs(out[q, 1] - (l2 - l3) / l1) < 1e-3  # planarity
        assert abs(out[q, 4] - abs(v[2, 0])) < 1e-3  # |n_z| of the smallest eigenvector


def test_knn_eigen_features_split_over_two_threads_are_the_same_values():
    # above 50,000 query rows the moments are done in two halves on two threads
    rng = np.random.default_rng(5)
    pts = rng.uniform(0, 300, (60_001, 3)) * [1, 1, 0.0002]
    one, d1 = _eigen(pts, pts, 10, 1)
    two, d2 = _eigen(pts, pts, 10, 2)
    assert np.array_equal(one, two) and np.array_equal(d1, d2)
    assert np.isfinite(two).all() and (two[:, 4] > 0.9).mean() > 0.9  # a near-flat cloud


def test_one_opening_sequence_serves_both_provisional_grounds():
    # the steepest-step grids of the shared sequence flag, for any tolerance and any window up
    # to the largest, the cells the per-test progressive opening flags
    from scipy import ndimage

    rng = np.random.default_rng(9)
    z0 = np.cumsum(rng.normal(0, 0.4, (50, 80)), axis=0) + rng.exponential(0.4, (50, 80))
    z0[10:22, 30:45] += 5.0
    steps = opening_steps(z0, 1.0, (12.0, 12.0 * 0.4))
    for window, grid in zip((12, 5), steps):
        for tol in (0.15, 0.3, rng.uniform(0.1, 1.0, z0.shape)):
            last, flagged = z0, np.zeros(z0.shape, bool)
            for w in range(1, window + 1):
                op = ndimage.grey_opening(last, size=(2 * w + 1, 2 * w + 1), mode="nearest")
                flagged |= (last - op) > tol * w
                last = op
            assert flagged.any() and np.array_equal(grid > tol, flagged)


def _roof_and_car_scene(seed=0):
    """Flat ground, a 12 x 12 m flat roof 4 m up and a 2 x 4.5 m car 1.5 m up, 8 pts/m²."""
    rng = np.random.default_rng(seed)
    xy = rng.uniform(0, 60, (int(60 * 60 * 8), 2))
    z = 100.0 + rng.normal(0, 0.02, len(xy))
    roof = (np.abs(xy[:, 0] - 20) < 6) & (np.abs(xy[:, 1] - 30) < 6)
    car = (np.abs(xy[:, 0] - 45) < 1.0) & (np.abs(xy[:, 1] - 30) < 2.25)
    z[roof] += 4.0
    z[car] += 1.5
    return Cloud(np.column_stack([xy, z])), roof, car


def test_object_areas_tell_a_house_from_a_car():
    c, roof, car = _roof_and_car_scene()
    F = compute_features(c, FeatureParams(ground_window=20.0))
    area = np.expm1(F[:, FEATURE_NAMES.index("planar_area")])
    raised = np.expm1(F[:, FEATURE_NAMES.index("elev_area")])
    ground = ~roof & ~car
    # the roof's footprint is 144 m² (cells at its border add a little), the car's 9 m²
    assert 110 < np.median(area[roof]) < 200
    assert np.median(raised[car]) < 25
    assert np.median(area[car]) < 25
    assert (raised[ground] == 0).mean() > 0.95


def test_planar_segments_group_a_roof_and_the_context_step_follows_them():
    from workstation.ml.classifier import _segment_mean
    from workstation.ml.features import features_and_segments

    c, roof, car = _roof_and_car_scene(1)
    fp = FeatureParams(ground_window=20.0)
    lab = features_and_segments(c, fp)[1]
    roof_labels, counts = np.unique(lab[roof], return_counts=True)
    main = roof_labels[counts.argmax()]
    assert main > 0 and counts.max() > 0.9 * roof.sum()  # one object holds the roof
    assert not np.isin(lab[car], [main]).any()  # the car is not part of it
    assert (lab[~roof & ~car] == 0).mean() > 0.95
    # a roof point the network calls vegetation follows its roof
    P = np.zeros((c.n, 3), np.float32)
    P[:, 0] = 1.0
    P[roof] = [0.0, 1.0, 0.0]
    odd = np.flatnonzero(roof & (lab == main))[0]
    P[odd] = [0.0, 0.0, 1.0]
    Q = _segment_mean(P, lab, 0.8)
    assert Q[odd].argmax() == 1
    np.testing.assert_allclose(Q.sum(axis=1), 1.0, atol=1e-6)
    assert np.array_equal(Q[lab == 0], P[lab == 0])


def test_relief_and_fine_extreme_columns_follow_their_definitions():
    # columns 0-6 and 16-17 are made in reused float64 buffers: the same values as the plain
    # expressions (height above each radius's minimum grid, relief, depth; kNN extremes)
    from scipy import ndimage

    from workstation.ml.features import (_density_column, _eigen_columns, _grid, _relief_features, _voxel_eigen,
                                         fill_nearest, grid_reduce)

    rng = np.random.default_rng(11)
    xyz = rng.uniform(0, 80, (20_000, 3)) * [1, 1, 0.1]
    z = xyz[:, 2]
    p = FeatureParams()
    r, c, shape = _grid(xyz[:, :2], 1.0)
    zmin = grid_reduce(z, r, c, shape, np.minimum, np.inf)
    zmax = grid_reduce(z, r, c, shape, np.maximum, -np.inf)
    zmin_f = fill_nearest(zmin, ~np.isfinite(zmin))
    flat = r * shape[1] + c
    F = np.zeros((len(z), len(FEATURE_NAMES)), np.float32, order="F")
    _relief_features(F, z, zmin_f, zmax, flat, 1.0, p)
    at = lambda g: g.ravel()[flat]  # noqa: E731
    for t, rad in enumerate(p.min_radii):
        m = ndimage.minimum_filter(zmin_f, size=2 * int(round(rad / 1.0)) + 1, mode="nearest")
        assert np.array_equal(F[:, t], np.minimum(z - at(m), 60.0).astype(np.float32))
    mx = at(ndimage.maximum_filter(zmax, size=5, mode="nearest"))
    m0 = at(ndimage.minimum_filter(zmin_f, size=5, mode="nearest"))
    assert np.array_equal(F[:, 5], np.minimum(mx - m0, 60.0).astype(np.float32))
    assert np.array_equal(F[:, 6], np.minimum(mx - z, 60.0).astype(np.float32))
    fine = _voxel_eigen(xyz, p.fine_voxel, p.k_fine, 1)
    coarse = _voxel_eigen(xyz, p.coarse_voxel, p.k_coarse, 1)
    _density_column(F, _eigen_columns(F, z, fine, coarse))
    ef, zr, _, finv = fine
    zf = zr[finv]
    assert np.array_equal(F[:, 16], np.clip(z - (zf - ef[finv, 6]), 0, 30).astype(np.float32))
    assert np.array_equal(F[:, 17], np.clip((zf + ef[finv, 7]) - z, 0, 30).astype(np.float32))
    assert np.array_equal(F[:, 10], ef[finv, 0]) and np.array_equal(F[:, 23], coarse[0][coarse[3], 5])
