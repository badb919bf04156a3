"""PTD's TIN reuse: the densified TIN is the Delaunay TIN of the ground candidates, and the
final test on it flags what a fresh triangulation of the ground points flags."""

import numpy as np
import pytest
from scipy.spatial import Delaunay, cKDTree

from workstation.ground import common
from workstation.ground.ptd import PTDParams, _delaunay, _densify, densify, ptd_ground


def _terrain(n: int, seed: int) -> np.ndarray:
    """Rolling terrain with low objects on it (metres), random x, y: no point on a TIN edge."""
    rng = np.random.default_rng(seed)
    xy = rng.uniform(0.0, 100.0, (n, 2))
    z = 3.0 * np.sin(xy[:, 0] / 20.0) + 2.0 * np.cos(xy[:, 1] / 15.0) + rng.normal(0.0, 0.05, n)
    obj = rng.random(n) < 0.3
    z[obj] += rng.uniform(0.5, 8.0, obj.sum())
    return np.column_stack([xy, z])


def _triangles(simp: np.ndarray) -> set:
    return set(map(tuple, np.sort(simp, axis=1)))


def test_densified_tin_is_the_delaunay_tin_of_the_ground_candidates():
    xyz = _terrain(6000, 5)
    cand = xyz[np.lexsort((xyz[:, 0], np.floor(xyz[:, 1])))]
    ground, tin, near = _densify(cand, PTDParams(), None)
    gi = np.flatnonzero(ground)
    assert _triangles(tin.simp) == _triangles(gi[Delaunay(cand[gi, :2]).simplices])
    # near: a triangle of each ground candidate, the triangle holding each other one
    assert (tin.simp[near[gi]] == gi[:, None]).any(axis=1).all()
    ref = Delaunay(cand[gi, :2])
    s = ref.find_simplex(cand[~ground, :2])
    held = near[~ground]
    assert ((held >= 0) == (s >= 0)).all()
    assert (_triangles(tin.simp[held[held >= 0]]) == _triangles(gi[ref.simplices[s[s >= 0]]]))


def _final_by_fresh_tin(xyz: np.ndarray, gidx: np.ndarray, threshold: float, scalar: float) -> np.ndarray:
    """The final test on a fresh Delaunay TIN of the ground points (scipy's point location)."""
    out = np.zeros(xyz.shape[0], dtype=bool)
    out[gidx] = True
    tri = Delaunay(xyz[gidx, :2])
    s = tri.find_simplex(xyz[:, :2])
    ii = np.flatnonzero(s >= 0)
    v = gidx[tri.simplices[s[ii]]]
    a = xyz[v[:, 0]]
    n = np.cross(xyz[v[:, 1]] - a, xyz[v[:, 2]] - a)
    zt = a[:, 2] - ((xyz[ii, 0] - a[:, 0]) * n[:, 0] + (xyz[ii, 1] - a[:, 1]) * n[:, 1]) / n[:, 2]
    tol = threshold + scalar * np.hypot(n[:, 0], n[:, 1]) / np.abs(n[:, 2])
    out[ii[np.abs(xyz[ii, 2] - zt) < tol]] = True
    oo = np.flatnonzero(s < 0)
    _, j = cKDTree(xyz[gidx, :2]).query(xyz[oo, :2])
    out[oo[np.abs(xyz[oo, 2] - xyz[gidx[j], 2]) < threshold]] = True
    return out


@pytest.mark.parametrize("chunk, ratio", [(1 << 18, 20), (1000, 20), (1 << 18, 0)])
def test_final_test_on_the_densified_tin_equals_a_fresh_triangulation(monkeypatch, chunk, ratio):
    # the walk on the updated TIN in one chunk or many, and the fresh TIN of a dense cloud
    import workstation.ground.ptd as ptd

    monkeypatch.setattr(ptd, "_WALK_CHUNK", chunk)
    monkeypatch.setattr(ptd, "_FRESH_RATIO", ratio)
    xyz = _terrain(20000, 7)
    p = PTDParams(final_scalar=1.0)
    seen = {}
    final = ptd.final_ground

    def spy(xyz_, gidx, *args):
        seen["gidx"] = gidx
        return final(xyz_, gidx, *args)

    monkeypatch.setattr(ptd, "final_ground", spy)
    got = ptd_ground(xyz, p)
    assert 0.4 < got.mean() < 0.9
    want = _final_by_fresh_tin(xyz, seen["gidx"], p.final_threshold, p.final_scalar)
    assert (got == want).all()


def test_every_candidate_a_seed_still_gets_a_tin():
    # 3 x 3 points on a 30 m grid, jittered: each its own seed cell, nothing left to densify
    rng = np.random.default_rng(1)
    g = np.stack(np.meshgrid(np.arange(3.0), np.arange(3.0)), axis=-1).reshape(-1, 2) * 30.0
    cand = np.column_stack([g + rng.uniform(-1, 1, g.shape), rng.normal(0, 0.1, 9)])
    ground, tin, near = _densify(cand, PTDParams(), None)
    assert ground.all() and tin is not None and (near >= 0).all()
    # in the 1 m cell of the middle point: 1 m above it is ground by the final test, 5 m not
    q = cand[4] + np.array([[0.01, 0.01, 1.0], [0.02, 0.0, 5.0]])
    flags = ptd_ground(np.concatenate([cand, q]), PTDParams(seed_cell=5.0, final_threshold=1.5, final_scalar=0.0))
    assert flags[:9].all() and flags[9] and not flags[10]


def test_bulk_transforms_locate_as_scipy_does():
    rng = np.random.default_rng(3)
    xy = rng.uniform(0.0, 50.0, (3000, 2))
    q = rng.uniform(-5.0, 55.0, (20000, 2))
    q = q[np.lexsort((q[:, 0], np.floor(q[:, 1])))]
    assert np.array_equal(common.locate(_delaunay(xy), q), Delaunay(xy).find_simplex(q))


def test_densify_skips_the_final_tin_update():
    xyz = _terrain(6000, 5)
    cand = xyz[np.lexsort((xyz[:, 0], np.floor(xyz[:, 1])))]
    ground, tin, near = _densify(cand, PTDParams(), None)
    bare = _densify(cand, PTDParams(), None, with_tin=False)
    assert bare[1] is None and bare[2] is None
    assert np.array_equal(bare[0], ground) and np.array_equal(densify(cand, PTDParams()), ground)


def test_bulk_transforms_fill_only_an_empty_cache():
    xy = np.random.default_rng(4).uniform(0.0, 10.0, (50, 2))
    tri = Delaunay(xy)
    assert common.with_bulk_transforms(tri) is tri
    assert np.array_equal(tri.transform, common.barycentric_transforms(xy, tri.simplices), equal_nan=True)
    own = Delaunay(xy)
    own.transform  # scipy's own, cached on first use
    kept = own._transform
    assert common.with_bulk_transforms(own)._transform is kept


def test_delaunay_q5_is_scipys_triangulation_bit_for_bit():
    # Q5 only skips Qhull's final outer-plane check: the triangulation every ground step reads
    # (simplices, neighbours, equations, coplanar points, paraboloid) is scipy's default one,
    # here on gridded points with ties and duplicates as ground grids have
    from scipy.spatial import Delaunay

    from workstation.ground.common import delaunay

    rng = np.random.default_rng(5)
    pts = np.round(rng.uniform(0, 60, (20_000, 2)), 1)
    pts = np.vstack([pts, pts[:50]])  # duplicates become coplanar points
    ours, plain = delaunay(pts), Delaunay(pts)
    for name in ("simplices", "neighbors", "equations", "coplanar"):
        assert np.array_equal(getattr(ours, name), getattr(plain, name)), name
    assert (ours.paraboloid_scale, ours.paraboloid_shift) == (plain.paraboloid_scale, plain.paraboloid_shift)
