"""The riser fill (workstation.ground.risers) and its use by ``auto``."""

from __future__ import annotations

import numpy as np

from workstation.core.cloud import Cloud
from workstation.ground.auto import AutoParams, auto_ground
from workstation.ground.methods import ground_filter
from workstation.ground.risers import RiserParams, riser_fill


def terrace(seed=0):
    """A lower and an upper level 3 m apart, joined by a 1 m wide steep face (x in 30..31),
    a house on the lower level (3 m up) and a shrub 1.5 m above the upper level; 4 pts/m².
    Returns xyz, the face, the house, the shrub."""
    rng = np.random.default_rng(seed)
    xy = rng.uniform(0, 60, (60 * 60 * 4, 2))
    x = xy[:, 0]
    z = np.where(x < 30, 100.0, np.where(x < 31, 100.0 + 3.0 * (x - 30), 103.0)) + rng.normal(0, 0.02, len(x))
    face = (x >= 30.2) & (x <= 30.8)
    house = (np.abs(x - 12) < 4) & (np.abs(xy[:, 1] - 30) < 4)
    z[house] += 3.0
    shrub = (np.abs(x - 45) < 1) & (np.abs(xy[:, 1] - 20) < 1)
    z[shrub] += 1.5
    return np.column_stack([xy, z]), face, house, shrub


def test_the_face_of_a_step_goes_back_to_the_ground_and_nothing_else():
    xyz, face, house, shrub = terrace()
    ground = ~face & ~house & ~shrub  # a filter that found both levels but not the face
    votes = np.where(ground, 5, np.where(face, 1, 2))  # one member took the face; two the house and shrub
    out = riser_fill(xyz, ground, votes)
    assert out[ground].all()  # it only adds
    assert out[face].mean() > 0.9
    assert not out[house].any() and not out[shrub].any()  # flat TIN there, and above it
    # the vote guard: a face no member accepted stays out
    assert not riser_fill(xyz, ground, np.where(ground, 5, 0))[face].any()
    # a gentler triangle than the gradient asked for is not a step
    assert not riser_fill(xyz, ground, votes, RiserParams(min_gradient=4.0))[face].any()
    # without the guard every rejected point of a steep triangle is a candidate
    assert riser_fill(xyz, ground, None)[face].mean() > 0.9


def test_degenerate_inputs_give_the_input_back():
    xyz, face, _, _ = terrace(1)
    none = np.zeros(len(xyz), bool)
    assert not riser_fill(xyz, none).any()
    every = np.ones(len(xyz), bool)
    assert riser_fill(xyz, every).all()
    line = np.column_stack([np.arange(10.0), np.zeros(10), np.arange(10.0) * 2])
    g = np.arange(10) % 2 == 0
    assert np.array_equal(riser_fill(line, g), g)  # collinear ground: no TIN


def test_auto_runs_the_riser_fill_and_can_leave_it_out():
    xyz, face, house, _ = terrace(2)
    local = xyz - xyz.min(axis=0)
    on = auto_ground(local, AutoParams())
    off = auto_ground(local, AutoParams(risers=False))
    assert (on >= off).all()  # it only adds ground
    assert not on[house].any()
    out = ground_filter(Cloud(xyz), "auto", risers=False)
    assert ((np.asarray(out.attrs["classification"]) == 2) == off).sum() > 0.99 * len(xyz)


def test_the_riser_fill_takes_the_raised_patch_tests_tin_only_for_the_same_points():
    from workstation.ground import common
    from workstation.ground.patches import raised_patches

    xyz, face, house, shrub = terrace(3)
    local = xyz - xyz.min(axis=0)
    ground = ~face & ~house & ~shrub
    votes = np.where(ground, 5, 1)
    corner = np.flatnonzero(ground)[0]  # the lowest ground point at the corner: both steps'
    local[corner] = (0.0, 0.0, local[corner, 2] - 0.2)  # grids and local origins agree
    tins = common.TinHandoff()
    g = raised_patches(local, ground, tins=tins)
    left = tins._tri
    assert left is not None  # the last pass's TIN, left for a later step
    made = []
    real = common.delaunay
    try:  # count the riser fill's own triangulations
        common.delaunay = lambda *a, **k: made.append(1) or real(*a, **k)
        shared = riser_fill(local, g, votes, tins=tins)
    finally:
        common.delaunay = real
    assert not made and tins._tri is None  # taken, not made again; the slot emptied
    assert np.array_equal(shared, riser_fill(local, g, votes))  # the same ground as its own TIN's
    # other points (or other coordinates of them) are triangulated anew
    pts = np.random.default_rng(0).uniform(0, 9, (20, 2))
    tins.put(pts, left)
    assert tins.take(pts + 0.0) is left and tins.take(pts) is None
    tins.put(pts, left)
    assert tins.take(pts[::-1]) is None and tins.take(pts[:5]) is None


def test_a_chain_keeps_the_patch_tin_only_for_a_riser_fill_right_after():
    from workstation.ground.patches import PatchParams
    from workstation.ground.refine import Refine, run_chain
    from workstation.ground.understorey import UnderstoreyParams

    xyz, face, house, shrub = terrace(4)
    state = Refine(xyz - xyz.min(axis=0), ~face & ~house & ~shrub)
    for chain in ((PatchParams(),), (PatchParams(), UnderstoreyParams(), RiserParams()), (PatchParams(), RiserParams())):
        assert run_chain(state, chain).tins._tri is None  # nothing large held after the chain
