"""The crest fill (workstation.ground.crests): terrain a ground filter cut off goes back, objects
never do; and the classifier's use of it on the gallery's ridge (samp61's failure mode)."""

from __future__ import annotations

import numpy as np
import pytest

from gallery_scenes import ridges
from workstation.core.cloud import Cloud
from workstation.ground.crests import CrestParams, crest_fill, crest_test
from workstation.ground.refine import Refine, declare, run_chain


def dyke_scene(seed=0, pulses=1.0, side=1.0, tree_on_crest=False):
    """A 120 x 100 m plain with a dyke along y = 50 (crest 6 m wide, 6 m high, faces of ``side``
    run per unit rise), two houses (3 m and 8 m high, flat roofs), three cars (1.6 m), a tree
    beside the dyke (crown 4-12 m over the ground, half its pulses reach the ground) and, with
    ``tree_on_crest``, one on the crest. Returns xyz, the terrain's points, the crest's points,
    the objects' points and what a morphological filter left as ground (the terrain but the
    dyke's points more than 0.5 m up)."""
    rng = np.random.default_rng(seed)
    xy = rng.uniform(0, [120.0, 100.0], (int(120 * 100 * pulses), 2))
    x, y = xy[:, 0], xy[:, 1]
    dyke = np.clip(6.0 - (np.abs(y - 50.0) - 3.0) / side, 0.0, 6.0)
    z = 0.01 * x + dyke + rng.normal(0, 0.03, len(x))
    terrain = z.copy()
    objects = np.zeros(len(x), bool)
    for (x0, x1, y0, y1), h in (((10, 30, 10, 25), 3.0), ((70, 95, 72, 90), 8.0), ((40, 44.5, 20, 21.8), 1.6),
                                ((60, 64.5, 80, 81.8), 1.6), ((100, 104.5, 15, 16.8), 1.6)):
        on = (x >= x0) & (x <= x1) & (y >= y0) & (y <= y1)
        z[on] += h
        objects |= on
    centres = [(20.0, 70.0)] + ([(80.0, 50.0)] if tree_on_crest else [])
    for cx, cy in centres:
        crown = (np.hypot(x - cx, y - cy) < 4.0) & (rng.uniform(size=len(x)) < 0.5)
        z[crown] += rng.uniform(4.0, 12.0, crown.sum())
        objects |= crown
    on_terrain = ~objects
    crest = on_terrain & (np.abs(y - 50.0) <= 3.0)
    ground = on_terrain & (dyke <= 0.5)
    return np.column_stack([xy, z]), on_terrain, crest, objects, ground


@pytest.mark.parametrize("pulses", [1.0, 0.16])
def test_the_crest_comes_back_and_no_object_joins(pulses):
    xyz, on_terrain, crest, objects, ground = dyke_scene(pulses=pulses)
    out = crest_fill(xyz, ground)
    assert out[ground].all()  # it only adds
    assert out[crest].mean() > 0.9
    assert not out[objects].any()  # roofs and crowns stand over the ground beyond them; cars are low
    assert not out[~on_terrain].any()


def test_a_crest_steeper_than_terrain_or_too_low_stays_out():
    for side in (0.4, 0.7):  # 68° and 55° faces: steeper than terrain
        xyz, _, crest, _, ground = dyke_scene(seed=1, side=side)
        assert not crest_fill(xyz, ground)[crest].any()
    xyz, _, crest, _, ground = dyke_scene(seed=1)
    assert not crest_fill(xyz, ground, CrestParams(min_rise=7.0))[crest].any()  # the dyke is 6 m high
    assert crest_fill(xyz, ground, CrestParams(max_slope=1.2))[crest].mean() > 0.9


def test_a_point_steeper_than_terrain_keeps_its_whole_feature_out_unless_it_cannot_be_terrain():
    xyz, _, crest, _, ground = dyke_scene(seed=2)
    pit = (np.abs(xyz[:, 0] - 60.0) < 1.5) & (np.abs(xyz[:, 1] - 45.0) < 1.5)  # 5 m deep, on the face
    xyz[pit, 2] -= 5.0
    assert pit.sum() >= 5 and not crest_fill(xyz, ground)[crest].any()
    out = crest_fill(xyz, ground, surface=~pit)  # the pit left out, as noise would be
    assert out[crest].mean() > 0.9 and not out[pit].any()
    # so does a lone multipath echo, far under the terrain 30 m away, unless left out as noise
    xyz, _, crest, _, ground = dyke_scene(seed=2)
    xyz2 = np.vstack([xyz, [[60.0, 20.0, xyz[:, 2].min() - 40.0]]])
    ground2 = np.append(ground, False)
    assert not crest_fill(xyz2, ground2)[:-1][crest].any()
    out = crest_fill(xyz2, ground2, surface=np.arange(len(xyz2)) < len(xyz))
    assert out[:-1][crest].mean() > 0.9 and not out[-1]


def test_a_roof_whose_walls_and_nearby_ground_were_not_sampled_stays_out():
    """A 20 m tower wider than the steep surface's openings (as a large building is wider than
    30 m ones), no point within 8 m of its walls (beyond the slope test's radius): the lower
    points farther away still show it is no terrain."""
    xyz, _, crest, _, ground = dyke_scene(seed=6)
    ring = (np.abs(xyz[:, :2] - [60.0, 85.0]).max(axis=1) < 18.0)
    tower = np.abs(xyz[:, :2] - [60.0, 85.0]).max(axis=1) < 10.0
    keep = ~ring | tower
    xyz, crest, ground, tower = xyz[keep], crest[keep], ground[keep], tower[keep]
    xyz[tower, 2] += 20.0
    ground &= ~tower
    p = CrestParams(window=5.0)
    test = crest_test(xyz, ground, p)
    roof = np.isin(test.candidates, np.flatnonzero(tower))
    assert roof.any() and test.tall[test.feature[roof]].all()
    assert not (test.slope[roof] > test.max_slope).any()  # nothing lower within the radius
    assert test.beyond[roof].any()
    out = crest_fill(xyz, ground, p)
    assert not out[tower].any() and out[crest].mean() > 0.9


def test_a_roof_a_few_metres_from_the_nearest_lower_point_stays_out():
    """A 4.5 m platform with no point within 3.5 m of its edge: too steep over the ground
    beyond the gap by the exact test within ``radius``, not by the grid's coarser far test."""
    xyz, _, crest, _, ground = dyke_scene(seed=7, pulses=2.0)
    d = np.abs(xyz[:, :2] - [40.0, 85.0]).max(axis=1)
    keep = (d < 8.0) | (d > 11.5)
    xyz, crest, ground, d = xyz[keep], crest[keep], ground[keep], d[keep]
    roof = d < 8.0
    xyz[roof, 2] += 4.5
    ground &= ~roof
    p = CrestParams(window=5.0)  # the roof wider than the openings, as a large one is
    assert not crest_fill(xyz, ground, p)[roof].any()
    assert crest_fill(xyz, ground, CrestParams(window=5.0, radius=2.0))[roof].mean() > 0.9  # the gap hides it


def test_a_tree_on_the_crest_stays_out_and_the_crest_comes_back():
    xyz, _, crest, objects, ground = dyke_scene(seed=3, tree_on_crest=True)
    out = crest_fill(xyz, ground)
    assert not out[objects].any()
    assert out[crest].mean() > 0.9


def test_degenerate_inputs_give_the_input_back():
    xyz, _, _, _, ground = dyke_scene(seed=4, pulses=0.2)
    for g in (np.zeros(len(xyz), bool), np.ones(len(xyz), bool), np.arange(len(xyz)) < 2):
        assert np.array_equal(crest_fill(xyz, g), g)
    flat = np.column_stack([np.arange(10.0), np.zeros(10), np.zeros(10)])
    assert crest_fill(flat, np.arange(10) % 2 == 0).sum() == 5  # one row of cells, nothing raised
    assert np.array_equal(crest_fill(xyz, ground, surface=np.zeros(len(xyz), bool)), ground)


def test_the_refine_chain_runs_it_by_name():
    xyz, _, crest, _, ground = dyke_scene(seed=5, pulses=0.5)
    out = run_chain(Refine(xyz, ground), declare(("crests",)))
    assert out.ground[crest].mean() > 0.9
    assert np.array_equal(run_chain(Refine(xyz, ground), declare(("crests",), on={"crests": False})).ground, ground)


def test_classify_keeps_the_ridge_of_sparse_old_als():
    """The gallery's ridge (0.16 points/m², 1:1 faces, 9 m high): the gate refuses its top, the
    crest step, when asked for, gives it back (0-4 % of the top kept without it,
    ``bench_ground.py ridges``)."""
    from workstation.ml.classifier import PointClassifier, StepSwitches

    clf = PointClassifier.load(device="cpu")
    assert not clf.crests and "crests" in clf.steps  # declared, off unless asked for
    cloud, terrain, top, _ = ridges(seed=1)
    on_terrain = np.abs(cloud.xyz[:, 2] - terrain(cloud.xyz[:, :2])) < 0.3
    ground = clf.predict_codes(cloud, StepSwitches(crests=True)).codes == 2
    assert ground[top].mean() > 0.9 and not ground[~on_terrain].any()
    assert (clf.predict_codes(cloud).codes[top] == 2).mean() < 0.1
    # a multipath echo 40 m under the terrain near the ridge: noise to the network, no veto
    echo = Cloud(np.vstack([cloud.xyz, cloud.xyz[top][:1] + [0.0, 30.0, -50.0]]))
    codes = clf.predict_codes(echo, StepSwitches(crests=True)).codes
    assert codes[-1] == 7 and (codes[:-1][top] == 2).mean() > 0.9


def test_ws_classify_crests_option(tmp_path):
    """``ws classify --crests`` gives the gallery ridge's top back; the default (the shipped
    model's setting) leaves it out; a model saved with it on runs it unless ``--no-crests``."""
    from workstation.cli.main import main
    from workstation.io import read_cloud, write_cloud

    cloud, _, top, _ = ridges(seed=0)
    src = tmp_path / "ridge.laz"
    write_cloud(cloud, src)
    from workstation.ml.classifier import PointClassifier

    on = PointClassifier.load(device="cpu")
    on.crests = True
    model = on.save(tmp_path / "with_crests.pt")  # a model saved with the step on keeps it on
    kept = {}
    for name, extra in (("default", []), ("crests", ["--crests"]), ("model", ["--model", str(model)]),
                        ("model_off", ["--model", str(model), "--no-crests"])):
        out = tmp_path / f"{name}.laz"
        assert main(["classify", str(src), "-o", str(out), *extra]) == 0
        kept[name] = float(np.mean(np.asarray(read_cloud(out).attrs["classification"])[top] == 2))
    assert kept["default"] < 0.1 and kept["model_off"] < 0.1
    assert kept["crests"] > 0.9 and kept["model"] > 0.9
