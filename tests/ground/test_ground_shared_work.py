"""Work the ground filters share gives the answers of the plain runs: SMRF surfaces shared by
several runs (``smrf.SharedSurfaces``), also inside ``auto``'s vote (``auto.member_votes``)."""

from __future__ import annotations

import numpy as np

from ground_synth import terrain_with_boxes
from workstation.ground.auto import MEMBERS, AutoParams, member_votes
from workstation.ground.csf import csf_ground, surface_params
from workstation.ground.pmf import pmf_ground
from workstation.ground.ptd import ptd_ground
from workstation.ground.smrf import SharedSurfaces, SMRFParams, smrf_ground, smrf_surface


def _local(seed=0):
    xyz, _ = terrain_with_boxes(seed=seed, size=50.0, density=2.0)
    return xyz - xyz.min(axis=0)


def test_shared_surfaces_give_the_runs_alone():
    xyz = _local()
    auto = AutoParams()
    runs = [auto.smrf_wide, auto.smrf_tight, surface_params(xyz, auto.csf), SMRFParams(window=12.0)]
    shared = SharedSurfaces(xyz, runs)
    alone = [smrf_surface(xyz, p) for p in runs]
    for _ in range(2):  # the second round reads what the first made
        for p, a in zip(runs, alone):
            assert all(np.array_equal(x, y) for x, y in zip(a, smrf_surface(xyz, p, shared)))
    assert np.array_equal(smrf_ground(xyz, auto.smrf_wide), smrf_ground(xyz, auto.smrf_wide, shared))
    assert np.array_equal(csf_ground(xyz, auto.csf), csf_ground(xyz, auto.csf, shared))
    # a run it was not made for (another window, another cloud) computes on its own
    other = SMRFParams(window=7.0)
    assert not shared.serves(xyz, other) and not shared.serves(xyz.copy(), auto.smrf_wide)
    assert np.array_equal(smrf_ground(xyz, other, shared), smrf_ground(xyz, other))


def test_member_votes_with_shared_surfaces_equal_the_members_one_by_one():
    xyz = _local(seed=3)
    p = AutoParams()
    alone = {"smrf_wide": smrf_ground(xyz, p.smrf_wide), "smrf_tight": smrf_ground(xyz, p.smrf_tight),
             "pmf": pmf_ground(xyz, p.pmf), "csf": csf_ground(xyz, p.csf), "ptd": ptd_ground(xyz, p.ptd)}
    assert np.array_equal(member_votes(xyz, p), np.stack([alone[m] for m in MEMBERS]))


def test_one_provisional_dem_per_distinct_set_of_left_out_cells():
    from workstation.ground.smrf import _provisional

    xyz = _local(seed=5)
    shared = SharedSurfaces(xyz, [SMRFParams(window=18.0), SMRFParams(window=30.0)])
    g = shared.grid(1.0)
    bad = np.isnan(g.zmin) | (shared.steps(1.0, 18.0) > 0.15)
    first = shared.provisional(1.0, bad)
    assert np.array_equal(first, _provisional(g.zmin, bad, g.zfill, g.off))
    assert shared.provisional(1.0, bad.copy()) is first  # the same cells: the same surface
    other = bad.copy()
    other[np.unravel_index(np.flatnonzero(~bad)[0], bad.shape)] = True
    second = shared.provisional(1.0, other)
    assert second is not first and np.array_equal(second, _provisional(g.zmin, other, g.zfill, g.off))
