"""``ws ground --method ml`` (:mod:`workstation.ml.ground`): the member vote."""

from __future__ import annotations

import numpy as np

from workstation.core.cloud import Cloud


def test_member_vote_is_a_strict_majority_of_six(monkeypatch):
    """With the members' flags and the refine chain stubbed: ground where at least 4 of the
    five members and the gate accept, the six votes handed to the refine chain."""
    import workstation.ground.auto as auto
    from workstation.ml.ground import member_vote_ground

    n = 12
    accepted = np.arange(n) % 6  # 0..5 members accept
    flags = np.arange(5)[:, None] < accepted[None, :]  # (5, n)
    gate = np.arange(n) >= 6  # the second half: the gate accepts too
    seen = {}

    def refine(xyz, ground, votes, p, rn, nr):
        seen["votes"] = votes
        return ground

    monkeypatch.setattr(auto, "member_votes", lambda xyz, p: flags)
    monkeypatch.setattr(auto, "refine_vote", refine)
    xyz = np.column_stack([np.arange(n, dtype=float), np.zeros(n), np.zeros(n)])
    got, low = member_vote_ground(Cloud(xyz), gate)
    assert (seen["votes"] == accepted + gate).all()
    assert (got == (accepted + gate >= 4)).all()
    assert low.size == 0


def test_member_vote_keeps_boxes_out_and_terrain_in():
    """The shipped model with the member vote on a sloping terrain with two box buildings: the
    roofs leave the ground, the terrain stays in it, and the history records the switch."""
    from tests.ground.ground_synth import terrain_with_boxes
    from workstation.ml.ground import MLGroundParams, ml_ground

    xyz, truth = terrain_with_boxes(density=4.0)
    out = ml_ground(Cloud(xyz, crs="EPSG:32632"), MLGroundParams(device="cpu", member_vote=True))
    ground = np.asarray(out.attrs["classification"]) == 2
    assert (ground == truth).mean() > 0.97
    assert ground[~truth].mean() < 0.05
    assert out.history[-1].params["member_vote"] is True


def test_member_vote_leaves_low_outliers_out():
    """Points 20-50 m under the terrain (multipath echoes) take no part in the vote, as in
    ``auto``: the low-noise step makes them class 7, none is ground, and the terrain around
    them stays ground (a member's surface is not pulled down to them)."""
    from tests.ground.ground_synth import terrain_with_boxes
    from workstation.ml.ground import MLGroundParams, ml_ground

    xyz, truth = terrain_with_boxes(density=4.0)
    rng = np.random.default_rng(3)
    pick = rng.choice(np.flatnonzero(truth), 6, replace=False)
    low = xyz[pick] - [0, 0, 1] * rng.uniform(20, 50, (6, 1))
    cloud = Cloud(np.vstack([xyz, low]), crs="EPSG:32632")
    out = ml_ground(cloud, MLGroundParams(device="cpu", member_vote=True))
    cls = np.asarray(out.attrs["classification"])
    assert (cls[len(xyz):] == 7).all()
    ground = cls[:len(xyz)] == 2
    assert ground[truth].mean() > 0.95 and ground[~truth].mean() < 0.05
