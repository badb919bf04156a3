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


def _corner_scene():
    """terrace(3) in local coordinates, its ground (the face, house and shrub left out) and
    votes, with the lowest ground point moved to the corner (0, 0): the raised-patch test's and
    the riser fill's grids and local origins agree, so the riser fill can take the patch TIN."""
    xyz, face, house, shrub = terrace(3)
    local = xyz - xyz.min(axis=0)
    ground = ~face & ~house & ~shrub
    corner = np.flatnonzero(ground)[0]
    local[corner] = (0.0, 0.0, local[corner, 2] - 0.2)
    return local, ground, np.where(ground, 5, 1)


def _count_riser_triangulations(monkeypatch) -> list:
    """A list that gets one entry per Delaunay triangulation the riser fill makes (those of
    other steps are not counted)."""
    from workstation.ground import common, risers

    made, inside = [], []
    real_tin, real_fill = common.delaunay, risers.riser_fill

    def tin(*a, **k):
        if inside:
            made.append(1)
        return real_tin(*a, **k)

    def fill(*a, **k):
        inside.append(1)
        try:
            return real_fill(*a, **k)
        finally:
            inside.pop()

    monkeypatch.setattr(common, "delaunay", tin)
    monkeypatch.setattr(risers, "riser_fill", fill)
    return made


def test_the_riser_fill_takes_the_raised_patch_tests_tin_only_for_the_same_points(monkeypatch):
    from workstation.ground import common, risers
    from workstation.ground.patches import raised_patches

    local, ground, votes = _corner_scene()
    tins = common.TinHandoff()
    g = raised_patches(local, ground, tins=tins)
    assert tins._slot is not None  # the last pass's TIN, left for a later step
    left = tins._slot[1]
    made = _count_riser_triangulations(monkeypatch)
    shared = risers.riser_fill(local, g, votes, tins=tins)
    assert not made and tins._slot is None  # taken, not made again; the slot emptied
    own = risers.riser_fill(local, g, votes)
    assert len(made) == 1 and np.array_equal(shared, own)  # the same ground as its own TIN's
    # other points (or other coordinates of them) are triangulated anew
    pts = np.random.default_rng(0).uniform(0, 9, (20, 2))
    tins.put(pts, left)
    assert tins.take(pts + 0.0) is left and tins.take(pts) is None
    tins.put(pts, left)
    assert tins.take(pts[::-1]) is None and tins.take(pts[:5]) is None
    tins.put(pts, left)
    assert tins.take(pts.astype(np.float32)) is None  # another dtype
    tins.put(pts, left)
    assert tins.take(np.asfortranarray(pts)) is left  # the same values in another layout
    tins.put(pts.astype(np.float32), left)
    assert tins.take(pts.astype(np.float32)) is left  # other dtypes compare byte for byte
    tins.put(np.zeros(3), left)
    assert tins.take(-np.zeros(3)) is None  # bit for bit: -0.0 is not 0.0


def test_a_chain_hands_the_patch_tin_only_to_a_riser_fill_right_after(monkeypatch):
    from workstation.ground import common
    from workstation.ground.patches import PatchParams
    from workstation.ground.refine import Refine, run_chain
    from workstation.ground.understorey import UnderstoreyParams

    local, ground, votes = _corner_scene()
    made = _count_riser_triangulations(monkeypatch)
    mine = common.TinHandoff()
    marker = (np.zeros((3, 2)), object())
    mine.put(*marker)
    state = Refine(local, ground, votes=votes, tins=mine)
    outs = {}
    for chain in ((PatchParams(), RiserParams()), (PatchParams(), UnderstoreyParams(), RiserParams()), (PatchParams(),)):
        made.clear()
        out = run_chain(state, chain)
        outs[len(chain)] = (len(made), out.ground)
        assert out.tins._slot is None  # nothing large held after the chain
        assert mine._slot is not None and mine._slot[1] is marker[1]  # the caller's handoff untouched
    assert outs[2][0] == 0  # the riser fill took the patch test's TIN
    assert outs[3][0] == 1  # not across another step: triangulated anew
    assert outs[2][1].sum() > outs[1][1].sum()  # the fill ran and added ground
    assert np.array_equal(outs[2][1], outs[3][1])  # the same ground either way (no return numbers)
