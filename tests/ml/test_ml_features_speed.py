"""The feature pass's faster paths give the plain paths' arrays: voxel numbering by packed
column keys, kNN queries within a sampled distance bound, and the tiled kNN scales run
beside the grid features."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from workstation.ml import features as fx
from workstation.ml.features import FeatureParams, _knn, features_and_segments, voxel_ids

from tests.ml.test_ml_tiles import scene


def _unique_ids(xyz: np.ndarray, voxel: float):
    """The reference numbering: np.unique of the (x, y, z) voxel keys."""
    v = np.floor(xyz / voxel).astype(np.int64)
    v -= v.min(axis=0)
    dims = v.max(axis=0) + 1
    key = (v[:, 0] * dims[1] + v[:, 1]) * dims[2] + v[:, 2]
    _, first, inv = np.unique(key, return_index=True, return_inverse=True)
    return first, inv.ravel()


@pytest.mark.parametrize("case", ["ground", "tall", "sparse", "split", "one", "column"])
def test_voxel_ids_are_np_uniques(case):
    rng = np.random.default_rng(3)
    if case == "ground":  # a sloping surface with canopy: columns of a few layers
        xyz = rng.uniform(0, 60, (20000, 3)) * [1, 1, 0.2] + [0, 0, 0]
        xyz[:, 2] += 0.3 * xyz[:, 0]
    elif case == "tall":  # towers over empty columns
        xyz = rng.uniform(0, 30, (5000, 3)) * [1, 1, 8]
    elif case == "sparse":  # a few points over a wide extent: the sorting path
        xyz = rng.uniform(0, 5000, (300, 3))
    elif case == "split":  # two layers 10 km apart in the same columns: the sorting path
        xyz = rng.uniform(0, 20, (2000, 3)) * [1, 1, 0]
        xyz[::2, 2] = 10000
    elif case == "one":
        xyz = np.array([[1.0, 2.0, 3.0]])
    else:  # one column of voxels
        xyz = np.column_stack([np.full(500, 0.2), np.full(500, 0.3), rng.uniform(0, 40, 500)])
    for voxel in (0.75, 1.5):
        first, inv = voxel_ids(xyz, voxel)
        f0, i0 = _unique_ids(xyz, voxel)
        assert np.array_equal(first, f0) and np.array_equal(inv, i0)
        assert first.dtype == np.intp and inv.dtype == np.intp
    fine = voxel_ids(xyz, 0.75)
    for voxel in (1.5, 3.0, 1.2):  # from the fine representatives (1.2: not nested, all the points)
        coarse = fx._coarser_representatives(xyz, fine, 0.75, voxel)
        f0, i0 = _unique_ids(xyz, voxel)
        assert np.array_equal(coarse[0], f0) and np.array_equal(coarse[1], i0)


def test_bounded_queries_are_the_plain_ones(monkeypatch):
    """Far-off points (beyond the sampled bound) are queried again: every row is the plain
    query's, ties of equal distance included (a 1 cm grid, as real files)."""
    rng = np.random.default_rng(5)
    xyz = np.round(np.vstack([rng.uniform(0, 80, (30000, 3)) * [1, 1, 0.1],
                              rng.uniform(0, 80, (40, 3)) + [0, 0, 50]]), 2)
    tree = cKDTree(xyz, balanced_tree=False, compact_nodes=False)
    bound = fx._query_bound(tree, xyz, 11, 1)
    assert np.isfinite(bound)  # the bounded path
    d, j = fx._bounded_query(tree, xyz, 11, 1, bound)
    d0, j0 = tree.query(xyz, k=11)
    assert np.array_equal(d, d0)
    assert np.isfinite(d).all()
    same = (d0[:, 1:] != d0[:, :-1]).all(axis=1)  # rows without ties: the indices too
    assert np.array_equal(j[same], j0[same])
    dk, jk = _knn(tree, xyz, 10, 2)
    monkeypatch.setattr(fx, "_BOUND_SAMPLE", 10 ** 9)  # no bound
    dp, jp = _knn(tree, xyz, 10, 2)
    assert np.array_equal(dk, dp) and np.array_equal(jk, jp)


def test_tiled_features_with_one_worker_are_the_whole_clouds():
    """The tiles run in a worker thread beside the grid features with ``workers=1`` too."""
    c = scene(2)
    p = FeatureParams(workers=1)
    F, seg = features_and_segments(c, p)
    T, tseg = features_and_segments(c, p, tile_side=40.0)
    assert np.array_equal(F, T) and np.array_equal(seg, tseg)


@pytest.mark.parametrize("block", [1, 7, 10 ** 9])
def test_eigen_rows_in_blocks_are_the_whole_arrays(monkeypatch, block):
    """The rows go a block at a time (the last one a single row here): the same features as
    in one block, whose means are numpy's ``mean(axis=1)`` of the (m, k, 3) neighbourhoods."""
    rng = np.random.default_rng(11)
    xyz = np.round(rng.uniform(0, 30, (3000, 3)) * [1, 1, 0.3], 2)
    ref32 = np.ascontiguousarray(xyz.T, dtype=np.float32)
    tree = cKDTree(xyz)
    q = xyz[:50]
    _, j = _knn(tree, q, 10, 1)
    monkeypatch.setattr(fx, "_ROW_BLOCK", block)
    out = np.empty((50, 8), np.float32)
    fx._eigen_rows(q, ref32, j, 10, out)
    monkeypatch.setattr(fx, "_ROW_BLOCK", 10 ** 9)
    whole = np.empty((50, 8), np.float32)
    fx._eigen_rows(q, ref32, j, 10, whole)
    assert np.array_equal(out, whole)
    nb = ref32.T[j]  # (m, k, 3)
    mean_z = nb[:, :, 2].mean(axis=1)
    zc = nb[:, :, 2] - mean_z[:, None]
    assert np.array_equal(out[:, 7], np.minimum(zc.max(axis=1) - (q[:, 2] - mean_z), 30.0).astype(np.float32))


def test_eigen_in_blocks_is_one_block_of_all(monkeypatch):
    """The kNN scales query and compute a block of rows at a time on the cores: the features
    are those of one block of every row, on one thread or two."""
    rng = np.random.default_rng(8)
    xyz = np.round(rng.uniform(0, 120, (40000, 3)) * [1, 1, 0.1], 2)  # 1 cm grid: ties
    q = xyz[::1]
    blocks = [fx._eigen(q, xyz, 10, w, reach=True) for w in (1, 2)]
    monkeypatch.setattr(fx, "_QUERY_BLOCK", 10 ** 9)
    whole = fx._eigen(q, xyz, 10, 1, reach=True)
    assert len(q) > 2 * 16384
    for got in blocks:
        assert all(np.array_equal(a, b) for a, b in zip(got, whole))


def test_non_finite_features_are_replaced(monkeypatch):
    """A NaN or infinite feature value (any column) becomes 0, 60 or -20 before the network."""
    real = fx._density_column

    def broken(F, dh):
        real(F, dh)
        F[:3, 31] = [np.nan, np.inf, -np.inf]

    monkeypatch.setattr(fx, "_density_column", broken)
    F, _ = features_and_segments(scene(3), FeatureParams())
    assert np.isfinite(F).all()
    assert F[:3, 31].tolist() == [0.0, 60.0, -20.0]


def test_in_blocks_on_one_worker_runs_in_the_callers_thread():
    import threading

    from workstation.core.cpu import in_blocks

    seen = []
    in_blocks(lambda s: seen.append((s, threading.get_ident())), 10, 3, 1)
    assert [s for s, _ in seen] == [0, 3, 6, 9] and {t for _, t in seen} == {threading.get_ident()}


def test_a_failed_tile_write_is_raised(monkeypatch):
    def broken(*a):
        raise RuntimeError("tile write")

    monkeypatch.setattr(fx, "_tile_columns", broken)
    with pytest.raises(RuntimeError, match="tile write"):
        features_and_segments(scene(2), FeatureParams(workers=2), tile_side=40.0)
