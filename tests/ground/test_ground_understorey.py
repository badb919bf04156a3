"""The under-canopy refinement (workstation.ground.understorey) and its use by ``auto``."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.ground.understorey import (UnderstoreyParams, canopy_share, envelope_height, plane_residual,
                                            refine_understorey)


def _forest_floor(seed=0, size=60.0, density=10.0, slope=0.3, under_frac=0.25):
    """Ground of a slope with 3 cm noise at ``density`` pts/m², plus understorey points 0.3-0.6 m
    above it; returns xyz, the truth (True = terrain) and the understorey mask."""
    rng = np.random.default_rng(seed)
    n = int(size * size * density)
    xy = rng.uniform(0, size, (n, 2))
    z = slope * xy[:, 0] + 0.5 * np.sin(xy[:, 1] / 7.0) + rng.normal(0, 0.03, n)
    under = rng.uniform(size=n) < under_frac
    z[under] += rng.uniform(0.3, 0.6, under.sum())
    return np.column_stack([xy, z]), ~under, under


def test_canopy_share_counts_multi_echo_pulses_per_cell():
    xy = np.array([[0.5, 0.5], [0.6, 0.6], [0.7, 0.7], [0.8, 0.8], [5.5, 0.5], [5.6, 0.6]])
    rn = np.array([1, 2, 1, 1, 1, 1])
    nr = np.array([2, 2, 1, 1, 1, 1])
    # cell 1: three pulses (the first return of the two-echo pulse is not counted), one multi-echo
    share = canopy_share(xy, rn, nr, 5.0)
    assert share[:4] == pytest.approx([1 / 3] * 4)
    assert (share[4:] == 0).all()
    # no valid return numbers: no canopy anywhere
    assert (canopy_share(xy, np.zeros(6), np.zeros(6), 5.0) == 0).all()


def test_plane_residual_of_a_tilted_plane_is_zero_except_the_spike():
    rng = np.random.default_rng(1)
    xy = rng.uniform(0, 20, (2000, 2))
    z = 0.4 * xy[:, 0] - 0.2 * xy[:, 1] + 100.0
    z[7] += 1.0
    xyz = np.column_stack([xy, z])
    res, slope = plane_residual(xyz, 1.0)
    assert res[7] == pytest.approx(1.0, abs=1e-6)
    far = np.abs(xy - xy[7]).max(axis=1) > 2.0  # outside the spike's 3 x 3 cells
    assert np.abs(res[far]).max() < 1e-6
    assert np.median(slope) == pytest.approx(np.hypot(0.4, 0.2), abs=1e-9)
    # the spike lifts its neighbours' planes, so they look low
    near = ~far & (np.arange(2000) != 7)
    assert (res[near] <= 1e-6).all() and res[near].min() < -0.01
    # only the queried points
    r2, s2 = plane_residual(xyz, 1.0, query=np.array([7, 8]))
    assert r2 == pytest.approx(res[[7, 8]]) and s2 == pytest.approx(slope[[7, 8]])
    # too few others in the 3 x 3 cells: no plane, residual 0
    assert plane_residual(xyz[:3], 1.0)[0].tolist() == [0.0, 0.0, 0.0]


def test_envelope_height_of_a_plane_is_bounded_by_the_slope_term():
    rng = np.random.default_rng(2)
    xy = rng.uniform(0, 30, (20000, 2))
    xyz = np.column_stack([xy, 0.5 * xy[:, 0]])
    h, slope = envelope_height(xyz, 3.0)
    assert h.min() >= -0.01  # edge cells extrapolate
    assert (h <= 0.7 * 3.0 * slope + 1e-6).mean() > 0.95  # all but the clamped edge cells


def test_refine_takes_understorey_out_under_canopy_and_keeps_terrain():
    xyz, terrain, under = _forest_floor()
    ground = np.ones(len(xyz), bool)  # a filter that accepted everything
    out = refine_understorey(xyz, ground, np.full(len(xyz), 0.5))
    assert out[terrain].mean() >= 0.97
    assert out[under].mean() <= 0.1
    # open terrain (no multi-echo pulses): unchanged
    assert (refine_understorey(xyz, ground, np.zeros(len(xyz))) == ground).all()


def test_refine_keeps_a_bare_steep_slope_under_canopy():
    xyz, terrain, _ = _forest_floor(seed=3, slope=1.0, under_frac=0.0)
    out = refine_understorey(xyz, np.ones(len(xyz), bool), np.full(len(xyz), 0.5))
    assert out.mean() >= 0.97


def test_refine_switches_off():
    xyz, _, _ = _forest_floor(seed=4, size=30.0)
    g = np.ones(len(xyz), bool)
    p = UnderstoreyParams(spike_passes=0, envelope_spacing=0.0)
    assert (refine_understorey(xyz, g, np.ones(len(xyz)), p) == g).all()


def test_auto_uses_the_echoes():
    """``auto`` on a forest floor under canopy: the understorey is not ground with the step,
    is ground without it; without return numbers the step does nothing."""
    from workstation.ground.auto import auto

    xyz, terrain, under = _forest_floor(seed=5, size=40.0, density=6.0, slope=0.1)
    n = len(xyz)
    rng = np.random.default_rng(5)
    multi = rng.uniform(size=n) < 0.5  # last returns of two-echo pulses
    rn = np.where(multi, 2, 1).astype(np.uint8)
    nr = rn.copy()
    cloud = Cloud(xyz + [500000.0, 4e6, 100.0], attrs={"return_number": rn, "number_of_returns": nr})
    on = np.asarray(auto(cloud).attrs["classification"]) == 2
    off = np.asarray(auto(cloud, understorey=False).attrs["classification"]) == 2
    assert on[under].mean() < 0.2 < off[under].mean()
    assert on[terrain].mean() > 0.95
    bare = Cloud(cloud.xyz)
    assert (np.asarray(auto(bare).attrs["classification"]) == 2).sum() == off.sum()
