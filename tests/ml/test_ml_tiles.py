"""The classifier's tiling: a cloud's features, probabilities and codes do not depend on
whether (or how) its kNN scales are cut into tiles."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.ml.classifier import PointClassifier
from workstation.ml.features import FeatureParams, _knn, features_and_segments


def scene(seed: int = 0, size: float = 160.0, density: float = 2.0) -> Cloud:
    """Sloping ground with boxes, canopy blobs and a few lone points high above (noise whose
    neighbours lie far away, beyond any tile's first buffer), on a 1 cm grid (ties of equal
    neighbour distance, as in real files); buildings cross the tile borders."""
    rng = np.random.default_rng(seed)
    n = int(size * size * density)
    xy = rng.uniform(0, size, (n, 2))
    z = 50 + 0.05 * xy[:, 0] + 2 * np.sin(xy[:, 1] / 25) + rng.normal(0, 0.03, n)
    for _ in range(8):
        c, h = rng.uniform(10, size - 10, 2), rng.uniform(3, 25, 2)
        inside = (np.abs(xy - c) < h).all(axis=1)
        z[inside] += rng.uniform(4, 12)
    for _ in range(6):
        c = rng.uniform(0, size, 2)
        near = np.hypot(*(xy - c).T) < rng.uniform(3, 8)
        z[near] += rng.uniform(2, 15, int(near.sum()))
    lone = rng.uniform(0, size, (5, 3)) + [0, 0, 120]
    xyz = np.round(np.vstack([np.column_stack([xy, z]), lone]), 2)
    nr = rng.integers(1, 3, len(xyz)).astype(np.uint8)
    return Cloud(xyz + [400000, 6000000, 0], {"return_number": np.minimum(nr, rng.integers(1, 3, len(xyz))).astype(np.uint8),
                                             "number_of_returns": nr,
                                             "intensity": rng.integers(0, 3000, len(xyz)).astype(np.uint16)},
                 crs="EPSG:32633")


@pytest.mark.parametrize("side", [33.0, 50.0, 120.0])
def test_tiled_features_are_the_whole_clouds_bit_for_bit(side):
    c = scene()
    p = FeatureParams()
    F, seg = features_and_segments(c, p)
    T, tseg = features_and_segments(c, p, tile_side=side)
    assert np.array_equal(F, T)
    assert np.array_equal(seg, tseg)


def test_neighbours_do_not_depend_on_the_tree():
    """Ties of equal distance come in reference order: a subset of the references holding a
    query's neighbours (same relative order) gives the same neighbours in the same order."""
    from scipy.spatial import cKDTree

    g = np.stack(np.meshgrid(np.arange(12.0), np.arange(12.0), [0.0]), -1).reshape(-1, 3)  # every distance tied
    q = g[[40, 77]]
    d, j = _knn(cKDTree(g), q, 9, 1)
    keep = np.flatnonzero((g[:, 0] > 1) & (g[:, 0] < 9))  # still holds both neighbourhoods
    d2, j2 = _knn(cKDTree(g[keep], leafsize=3), q, 9, 1)
    assert np.array_equal(d, d2)
    assert np.array_equal(j, keep[j2])
    assert (np.diff(d, axis=1) >= 0).all()
    tie = np.diff(d, axis=1) == 0
    assert (np.diff(j, axis=1)[tie] > 0).all()


def test_classifier_codes_do_not_depend_on_tile_points():
    c = scene(1)
    clf = PointClassifier.load(device="cpu")
    whole = clf.predict_codes(c)
    clf.tile_points = c.n // 5
    assert clf._tile_side(c) is not None and sum(1 for _ in clf._tiles(c)) > 4
    tiled = clf.predict_codes(c)
    assert np.array_equal(whole.codes, tiled.codes)
    assert np.array_equal(whole.proba, tiled.proba)
    assert np.array_equal(whole.confidence, tiled.confidence)


def test_eigen_features_of_one_query_are_its_row_of_many():
    """A neighbourhood's mean adds the neighbours in order whatever the number of queries
    (numpy's reduce of a single column would sum pairwise): the tiled pass queries a few
    representatives again on their own."""
    from workstation.ml.features import _eigen

    rng = np.random.default_rng(3)
    pts = np.round(rng.uniform(0, 20, (3000, 3)), 2)
    many, d = _eigen(pts[:100], pts, 16, 1)
    for i in (0, 7, 99):
        one, d1 = _eigen(pts[i:i + 1], pts, 16, 1)
        assert np.array_equal(one[0], many[i]) and d1[0] == d[i]


def test_tiled_features_on_one_thread_are_the_same():
    """``workers=1`` writes each tile's columns in turn, more threads while the next tile's
    neighbours are found: the same features either way."""
    c = scene(seed=2)
    one = features_and_segments(c, FeatureParams(workers=1), tile_side=40.0)[0]
    two = features_and_segments(c, FeatureParams(workers=2), tile_side=40.0)[0]
    assert np.array_equal(one, two)
