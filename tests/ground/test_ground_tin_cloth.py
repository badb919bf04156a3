"""PTD's facet test, mirroring and TIN updates, and CSF's own cloth simulation, on hand-made cases."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.ground.csf import CSFParams, simulate
from scipy.spatial import Delaunay

from workstation.ground.ptd import PTDParams, _Tin, densify, facet_test


def _tri(k):
    a = np.tile([[0.0, 0.0, 0.0]], (k, 1))
    b = np.tile([[10.0, 0.0, 0.0]], (k, 1))
    c = np.tile([[0.0, 10.0, 0.0]], (k, 1))
    return a, b, c


def test_facet_test_distance_and_angle():
    a, b, c = _tri(3)
    # 1 m above the flat facet, 4 m from the nearest vertex: angle asin(1/sqrt(17)) = 14.0 deg
    # 1 m above, 1 m from a vertex: 45 deg; 0.5 m below at 3 m: 9.5 deg
    q = np.array([[4.0, 0.0, 1.0], [1.0, 0.0, 1.0], [3.0, 3.0, -0.5]])
    ok, d, dist_ok = facet_test(q, a, b, c, np.tan(np.radians(15.0)), 1.5)
    assert np.allclose(d, [1.0, 1.0, -0.5])
    assert ok.tolist() == [True, False, True]
    assert dist_ok.all()
    ok, _, _ = facet_test(q, a, b, c, np.tan(np.radians(13.0)), 1.5)
    assert ok.tolist() == [False, False, True]


def _ridge(mirror: bool):
    """A 60 m wide roof-shaped ridge (slopes of 0.6) sampled at 1 m."""
    g = np.arange(0.0, 60.0, 1.0)
    x, y = np.meshgrid(g, g)
    z = 0.6 * (30.0 - np.abs(x - 30.0))
    cand = np.column_stack([x.ravel(), y.ravel(), z.ravel()])
    return densify(cand, PTDParams(mirror=mirror))


def test_mirroring_adds_ground_at_a_breakline():
    without, with_ = _ridge(False), _ridge(True)
    # every point is terrain; mirroring accepts more of the slopes (2410 against 2324 of
    # 3600); the crest stays out of reach of seeds 20 m apart (6 m above their TIN)
    assert with_.sum() > without.sum() + 50
    assert 0.5 < with_.mean() < 0.9


def test_cloth_bridges_a_pit_and_rests_on_the_ground():
    # inverted surface: flat ground at 0 with a 10 x 10 particle pit 8 m deep (a roof, inverted)
    ihv = np.zeros((60, 60))
    ihv[25:35, 25:35] = -8.0
    cloth, steps = simulate(ihv, CSFParams(rigidness=3, slope_smooth=False))
    assert steps < 500
    assert np.allclose(cloth[:10, :10], 0.0, atol=0.05)
    # the cloth stays far above the roof: the roof is 8 m from the cloth, not ground
    assert cloth[25:35, 25:35].min() > -4.0


def _triangles(simp):
    return set(map(tuple, np.sort(simp, axis=1).tolist()))


@pytest.mark.parametrize("where", ["inside", "hull"])
def test_tin_update_is_the_delaunay_triangulation_of_all_points(where):
    """40 points join anywhere, or those in triangles on the hull join (their cavities reach it)."""
    rng = np.random.default_rng(3)
    xy = rng.uniform(0.0, 100.0, (3000, 2))
    ground = np.zeros(3000, dtype=bool)
    ground[:2000] = True
    ground[[2000, 2001, 2002, 2003]] = False
    tin = _Tin(xy, np.flatnonzero(ground))
    rest = np.flatnonzero(~ground)
    s_rest = tin.tri.find_simplex(xy[rest])
    inside = s_rest >= 0
    pick = np.flatnonzero(inside)[:40]  # 40 points join (2 % of the TIN: the cavity is small)
    if where == "hull":
        pick = np.flatnonzero(inside & (tin.nbr[np.maximum(s_rest, 0)] < 0).any(axis=1))
        assert len(pick) >= 5
    new = rest[pick]
    s = tin.insert(new, s_rest[pick], rest, s_rest)
    assert s is not None and tin.tri is None
    ground[new] = True
    full = Delaunay(xy[ground])
    assert _triangles(tin.simp) == _triangles(np.flatnonzero(ground)[full.simplices])
    # every remaining candidate is in the triangle the full triangulation puts it in
    left = ~np.isin(rest, new)
    want = full.find_simplex(xy[rest[left]])
    got = s[left]
    assert ((got >= 0) == (want >= 0)).all()
    g = np.flatnonzero(ground)
    assert (np.sort(tin.simp[got[got >= 0]], axis=1) == np.sort(g[full.simplices[want[want >= 0]]], axis=1)).all()
    # the neighbours are scipy's: the triangle across from each vertex, -1 on the hull
    rank = {tri: i for i, tri in enumerate(map(tuple, np.sort(g[full.simplices], axis=1).tolist()))}
    same = np.array([rank[tri] for tri in map(tuple, np.sort(tin.simp, axis=1).tolist())])
    ours = np.column_stack([np.repeat(same, 3), tin.simp.ravel(), np.where(tin.nbr >= 0, same[tin.nbr], -1).ravel()])
    theirs = np.column_stack([np.repeat(np.arange(full.nsimplex), 3), g[full.simplices].ravel(), full.neighbors.ravel()])
    assert (ours[np.lexsort(ours.T[::-1])] == theirs[np.lexsort(theirs.T[::-1])]).all()
    # the walk finds what scipy finds
    q = rng.uniform(-10.0, 110.0, (500, 2))
    w = tin.walk(q, np.zeros(500, dtype=np.int64))
    f = full.find_simplex(q)
    assert ((w >= 0) == (f >= 0)).all()
    assert (np.sort(tin.simp[w[w >= 0]], axis=1) == np.sort(g[full.simplices[f[f >= 0]]], axis=1)).all()


def test_tin_update_falls_back_on_a_large_cavity():
    rng = np.random.default_rng(4)
    xy = rng.uniform(0.0, 100.0, (400, 2))
    tin = _Tin(xy, np.arange(100))
    rest = np.arange(100, 400)
    s_rest = tin.tri.find_simplex(xy[rest])
    inside = s_rest >= 0
    assert tin.insert(rest[inside], s_rest[inside], rest, s_rest) is None  # 3x the TIN: rebuild


def test_densify_with_tin_updates_equals_full_triangulations(monkeypatch):
    # rolling terrain with low objects: many iterations, the late ones add few points
    rng = np.random.default_rng(5)
    n = 6000
    xy = rng.uniform(0.0, 100.0, (n, 2))
    z = 3.0 * np.sin(xy[:, 0] / 20.0) + 2.0 * np.cos(xy[:, 1] / 15.0) + rng.normal(0.0, 0.05, n)
    obj = rng.random(n) < 0.3
    z[obj] += rng.uniform(0.5, 8.0, obj.sum())
    cand = np.column_stack([xy, z])[np.lexsort((xy[:, 0], np.floor(xy[:, 1])))]
    updates = []
    insert = _Tin.insert

    def counted(self, *args):
        s = insert(self, *args)
        updates.append(s is not None)
        return s

    monkeypatch.setattr(_Tin, "insert", counted)
    updated = densify(cand, PTDParams())
    assert sum(updates) >= 3  # the late iterations updated the TIN around the new points
    monkeypatch.setattr(_Tin, "MAX_CAVITY", 0.0)  # every iteration triangulates in full
    full = densify(cand, PTDParams())
    assert 0.5 < updated.mean() < 0.8
    assert (updated == full).all()
