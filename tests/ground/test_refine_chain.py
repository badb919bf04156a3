"""The declared refine chains (workstation.ground.refine): what auto and the point classifier
declare, that every step of a chain counts and its order matters, and that both owners run
exactly their declared chain."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.ground.auto import AutoParams, refine_vote
from workstation.ground.bridges import BridgeParams
from workstation.ground.crests import CrestParams
from workstation.ground.patches import PatchParams, raised_patches
from workstation.ground.refine import Refine, declare, run_chain
from workstation.ground.risers import RiserParams, riser_fill
from workstation.ground.understorey import UnderstoreyParams, canopy_share, refine_understorey
from workstation.ground.water import WaterParams
from workstation.ml.classifier import SHIPPED_MODEL, PointClassifier, StepSwitches
from workstation.ml.features import metric_xyz

ORIGIN = np.array([500000.0, 5000000.0, 100.0])


def scene(seed: int = 0):
    """A 90 x 40 m scene where each of auto's steps has work, in local metres.

    A 12 m roof 6 m up that the vote called ground (the raised-patch step takes it out), its
    walls rejected but accepted by one member (the riser step puts them back if it runs
    while the roof is still ground), a 2 m terrain step at x = 45 whose face was rejected (the
    riser step puts it back), and a forest (x > 60) of three-echo pulses whose understorey,
    0.4 m up, the vote let in (the understorey step takes it out).

    Returns xyz (m, 3), ground, votes, return_number, number_of_returns and a label per point:
    0 terrain, 1 roof, 2 step face, 3 understorey, 4 canopy, 5 wall.
    """
    rng = np.random.default_rng(seed)
    xy = rng.uniform([0, 0], [90, 40], (7200, 2))
    x = xy[:, 0]
    face = (x > 44.6) & (x < 45.4)
    zt = np.where(face, (x - 44.6) / 0.8 * 2.0, np.where(x < 45, 0.0, 2.0)) + 0.02 * xy[:, 1]
    roof = (np.abs(xy - [20, 20]) < 6).all(axis=1)
    forest = x > 60
    under = forest & (rng.uniform(size=len(x)) < 0.3)
    z = np.where(roof, 6.0, zt) + rng.normal(0, 0.02, len(x)) + np.where(under, 0.4, 0.0)
    t, side = rng.uniform(-6, 6, 400), rng.integers(0, 4, 400)
    wall = np.column_stack([np.where(side == 0, 14.0, np.where(side == 1, 26.0, 20 + t)),
                            np.where(side == 2, 14.0, np.where(side == 3, 26.0, 20 + t)), rng.uniform(0.3, 5.7, 400)])
    k = int(forest.sum())
    cxy = rng.uniform([60, 0], [90, 40], (k, 2))
    crowns = np.column_stack([cxy, 2.0 + 0.02 * cxy[:, 1] + rng.uniform(8, 15, k)])
    xyz = np.vstack([np.column_stack([xy, z]), wall, crowns])
    ground = np.concatenate([~face, np.zeros(400 + k, bool)])
    votes = np.concatenate([np.where(face, 1, 3), np.ones(400, int), np.zeros(k, int)])
    nr = np.concatenate([np.where(forest, 3, 1), np.ones(400, int), np.full(k, 3)]).astype(np.uint8)
    rn = np.concatenate([np.where(forest, 3, 1), np.ones(400 + k, int)]).astype(np.uint8)
    label = np.concatenate([np.select([roof, face, under], [1, 2, 3], 0), np.full(400, 5), np.full(k, 4)])
    return xyz, ground, votes, rn, nr, label


@pytest.fixture(scope="module")
def state():
    xyz, ground, votes, rn, nr, label = scene()
    return Refine(xyz, ground, votes, rn, nr), label


def test_the_declared_chains():
    """auto: raised patches, risers, understorey; the classifier: understorey, raised patches,
    crests (off unless asked for), water, bridges; a switch drops its step and keeps the order."""
    assert AutoParams().steps == ("raised_patches", "risers", "understorey")
    assert [type(p) for p in AutoParams().chain()] == [PatchParams, RiserParams, UnderstoreyParams]
    assert [type(p) for p in AutoParams(risers=False).chain()] == [PatchParams, UnderstoreyParams]
    p = AutoParams(riser_params=RiserParams(min_votes=2), steps=("risers", "raised_patches"))
    assert p.chain() == (RiserParams(min_votes=2), PatchParams())
    clf = PointClassifier()
    assert clf.steps == ("understorey", "raised_patches", "crests", "water", "bridges")
    assert [type(p) for p in clf.chain()] == [UnderstoreyParams, PatchParams, WaterParams, BridgeParams]
    assert [type(p) for p in clf.chain(StepSwitches(raised_patches=True, water=False))] == [UnderstoreyParams, PatchParams, BridgeParams]
    assert [type(p) for p in clf.chain(StepSwitches(crests=True))] == [UnderstoreyParams, PatchParams, CrestParams,
                                                                        WaterParams, BridgeParams]
    assert clf.config()["steps"] == list(clf.steps)


@pytest.mark.skipif(not SHIPPED_MODEL.exists(), reason="no shipped model")
def test_the_shipped_model_loads_with_the_default_chain(tmp_path):
    """The shipped model's config predates ``steps``: it loads with the default chain, and a
    model saved with another chain loads with it."""
    clf = PointClassifier.load(device="cpu")
    assert clf.steps == ("understorey", "raised_patches", "crests", "water", "bridges")
    assert (clf.understorey, clf.raised_patches, clf.water, clf.bridges, clf.roof_test) == (True, True, True, True, True)
    assert not clf.crests
    clf.steps = ("raised_patches", "understorey", "bridges")
    assert PointClassifier.load(clf.save(tmp_path / "m.pt"), device="cpu").steps == clf.steps


def test_bad_steps_are_refused_naming_the_field():
    for bad in [("nope",), ("risers", "risers"), ("bridges",), "risers"]:
        with pytest.raises(InvalidInputError) as e:
            AutoParams(steps=bad)
        assert e.value.field == "steps"
    with pytest.raises(InvalidInputError, match="last"):
        PointClassifier(steps=("bridges", "water"))
    with pytest.raises(InvalidInputError):
        PointClassifier(steps=("risers",))
    with pytest.raises(InvalidInputError):
        run_chain(Refine(np.zeros((3, 3)), np.ones(3, bool)), (object(),))
    with pytest.raises(TypeError):
        StepSwitches(gate=False)


def test_every_step_counts_and_the_order_matters(state):
    """Dropping any step of auto's chain changes the ground where that step has work; running
    the risers before the raised patches puts the walls back and keeps them."""
    st, label = state
    full = run_chain(st, AutoParams().chain()).ground
    assert full[label == 0].all() and not full[(label == 1) | (label == 4) | (label == 5)].any()
    assert full[label == 2].mean() > 0.8 and full[label == 3].mean() < 0.05
    works = {PatchParams: 1, RiserParams: 2, UnderstoreyParams: 3}
    for i, p in enumerate(AutoParams().chain()):
        rest = AutoParams().chain()[:i] + AutoParams().chain()[i + 1:]
        without = run_chain(st, rest).ground
        assert (without != full)[label == works[type(p)]].mean() > 0.5, type(p).__name__
    swapped = run_chain(st, (RiserParams(), PatchParams(), UnderstoreyParams())).ground
    assert swapped[label == 5].mean() > 0.3


def test_auto_refines_its_vote_with_the_module_functions_in_order(state):
    """refine_vote is raised_patches, riser_fill, refine_understorey in turn, with the
    parameters of AutoParams; its switches drop single steps."""
    st, _ = state
    p = AutoParams(patch_params=PatchParams(step=1.5), understorey_params=UnderstoreyParams(threshold=0.25))
    g = raised_patches(st.xyz, st.ground, p.patch_params)
    g = riser_fill(st.xyz, g, st.votes, p.riser_params)
    share = canopy_share(st.xyz[:, :2], st.return_number, st.number_of_returns, p.understorey_params.canopy_cell)
    g = refine_understorey(st.xyz, g, share, p.understorey_params)
    np.testing.assert_array_equal(refine_vote(st.xyz, st.ground, st.votes, p, st.return_number, st.number_of_returns), g)
    no_echoes = refine_vote(st.xyz, st.ground, st.votes, p)  # the understorey step needs return numbers
    np.testing.assert_array_equal(no_echoes, run_chain(st, p.chain()[:2]).ground)
    np.testing.assert_array_equal(refine_vote(st.xyz, st.ground, st.votes, AutoParams(understorey=False), st.return_number,
                                              st.number_of_returns), no_echoes)


@pytest.mark.parametrize("steps", [("understorey", "raised_patches", "water"), ("raised_patches", "understorey")])
def test_the_classifier_runs_its_declared_chain_on_the_gate(state, steps):
    """The classifier's ground is its gate's ground after its declared steps, in its order
    (network probabilities made up: ground where the vote said so)."""
    st, label = state
    cloud = Cloud(st.xyz + ORIGIN, {"return_number": st.return_number, "number_of_returns": st.number_of_returns},
                  crs="EPSG:32632")
    n = cloud.n
    P = np.zeros((n, 6), np.float32)
    P[:, 0] = np.where(st.ground, 0.9, 0.001)
    P[:, 2], P[:, 1] = 0.6 * (1 - P[:, 0]), 0.4 * (1 - P[:, 0])
    hs = np.zeros((n, 2), np.float32)  # everything in the gate's band: P decides
    clf = PointClassifier(steps=steps, raised_patches=True, roof_test=False)
    codes, _ = clf.codes_from_proba(P, hs, cloud)
    expect = run_chain(Refine(metric_xyz(cloud)[0], st.ground, None, st.return_number, st.number_of_returns),
                       declare(steps))
    np.testing.assert_array_equal(codes == 2, expect.ground)
    assert not (codes == 2)[label == 1].any() and (codes == 2)[label == 0].all()
    off = PointClassifier(steps=steps, raised_patches=False, understorey=False, roof_test=False)
    np.testing.assert_array_equal(off.codes_from_proba(P, hs, cloud)[0] == 2,
                                  run_chain(Refine(metric_xyz(cloud)[0], st.ground), declare(steps, {
                                      "raised_patches": False, "understorey": False})).ground)
