"""PTD's facet test and mirroring, and CSF's own cloth simulation, on hand-made cases."""

from __future__ import annotations

import numpy as np

from workstation.ground.csf import CSFParams, simulate
from workstation.ground.ptd import PTDParams, densify, facet_test


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
