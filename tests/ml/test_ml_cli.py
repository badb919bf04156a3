"""`ws train` on a tiny simulated recipe and `ws classify` with the model it wrote."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from workstation.cli.main import main
from workstation.io import read_cloud, write_cloud

REPO = Path(__file__).resolve().parents[2]


def two_class_scene(seed: int, size: float = 60.0):
    """Flat ground with one box building (classes 2 / 6) in UTM 32N."""
    from workstation.core.cloud import Cloud

    rng = np.random.default_rng(seed)
    n = int(size * size * 3)
    xy = rng.uniform(0, size, (n, 2))
    z = 100 + rng.normal(0, 0.03, n)
    roof = (np.abs(xy[:, 0] - size / 2) < 8) & (np.abs(xy[:, 1] - size / 2) < 6)
    z[roof] += 8
    cls = np.where(roof, 6, 2).astype(np.uint8)
    return Cloud(np.column_stack([xy + [500000, 5000000], z]), {"classification": cls}, crs="EPSG:32632")


@pytest.mark.slow
def test_train_then_classify(tmp_path, capsys):
    model = tmp_path / "tiny.pt"
    rc = main(["train", str(REPO / "datasets_synth" / "ml_tiny.toml"), "-o", str(model), "--json"])
    assert rc == 0
    card = json.loads(capsys.readouterr().out)
    assert model.exists() and Path(card["card_path"]).exists()
    assert card["tiles"] == 2 and card["validation_tiles"] == 1
    assert 1 <= card["epochs"] <= 5
    assert 0.0 <= card["validation"]["accuracy"] <= 1.0
    # deterministic dataset: the same recipe gives the same rows
    from workstation.ml.dataset import build_tileset, load_dataset_recipe

    r = load_dataset_recipe(REPO / "datasets_synth" / "ml_tiny.toml")
    again = build_tileset(r, progress=False)
    assert [t["points"] for t in again.info] == [t["points"] for t in card["tile_draws"]]
    assert int((~again.val[again.tile]).sum()) == card["train_rows"]

    src = tmp_path / "in.laz"
    write_cloud(two_class_scene(3), src)
    out = tmp_path / "out.laz"
    rc = main(["classify", str(src), "-o", str(out), "--model", str(model), "--json"])
    assert rc == 0
    res = json.loads(capsys.readouterr().out)
    assert res["point_count"] == read_cloud(src).n
    c = read_cloud(out)
    assert "confidence" in c.attrs and c.attrs["confidence"].dtype == np.float32
    # refuses to overwrite
    assert main(["classify", str(src), "-o", str(out), "--model", str(model)]) == 1


def test_classify_missing_model_is_a_user_error(tmp_path):
    src = tmp_path / "in.laz"
    write_cloud(two_class_scene(3), src)
    assert main(["classify", str(src), "-o", str(tmp_path / "o.laz"), "--model", str(tmp_path / "nope.pt")]) == 1


def test_ground_method_ml_with_the_shipped_model(tmp_path, capsys):
    src = tmp_path / "in.laz"
    write_cloud(two_class_scene(4), src)
    out = tmp_path / "g.laz"
    assert main(["ground", str(src), "-o", str(out), "--method", "ml", "--reclassify", "--json"]) == 0
    res = json.loads(capsys.readouterr().out)
    ref = np.asarray(read_cloud(src).attrs["classification"])
    cls = np.asarray(read_cloud(out).attrs["classification"])
    assert set(np.unique(cls)) <= {1, 2}
    assert res["ground_count"] == int((cls == 2).sum())
    assert ((cls == 2) == (ref == 2)).mean() > 0.95
    assert res["params"]["raised_patches"] is True  # on by default for ground
    off = tmp_path / "g_off.laz"
    assert main(["ground", str(src), "-o", str(off), "--method", "ml", "--reclassify", "--no-raised-patches",
                 "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["params"]["raised_patches"] is False
    assert ((np.asarray(read_cloud(off).attrs["classification"]) == 2) >= (cls == 2)).all()


def test_ground_method_ml_member_vote_option(tmp_path, capsys):
    """--member-vote reaches MLGroundParams.member_vote (off by default): the classes are
    those of the library call; the other methods refuse it."""
    from workstation.ml.ground import MLGroundParams, ml_ground

    src = tmp_path / "in.laz"
    write_cloud(two_class_scene(5), src)
    out = tmp_path / "mv.laz"
    assert main(["ground", str(src), "-o", str(out), "--method", "ml", "--reclassify", "--member-vote",
                 "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["params"]["member_vote"] is True
    ref = ml_ground(read_cloud(src), MLGroundParams(reclassify=True, member_vote=True))
    np.testing.assert_array_equal(read_cloud(out).attrs["classification"], ref.attrs["classification"])
    assert main(["ground", str(src), "-o", str(tmp_path / "plain.laz"), "--method", "ml", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["params"]["member_vote"] is False
    assert main(["ground", str(src), "-o", str(tmp_path / "x.laz"), "--method", "csf", "--member-vote"]) == 2


def test_ground_method_ml_member_vote_follows_raised_patches(tmp_path, capsys, monkeypatch):
    """--member-vote --no-raised-patches runs the raised-patch test nowhere (neither in the
    classifier's chain nor in auto's); --member-vote alone runs it."""

    calls = _count_raised_patches(monkeypatch)
    src = tmp_path / "in.laz"
    write_cloud(two_class_scene(6), src)
    ran = {}
    for name, extra in (("on", []), ("off", ["--no-raised-patches"])):
        calls.clear()
        assert main(["ground", str(src), "-o", str(tmp_path / f"{name}.laz"), "--method", "ml", "--member-vote",
                     *extra]) == 0
        ran[name] = len(calls)
    assert ran["off"] == 0 and ran["on"] >= 1


def test_ground_method_ml_member_vote_refuses_clouds_over_the_tile_size(tmp_path, capsys):
    """The member vote runs untiled: a cloud over --tile-points is a usage error naming
    --member-vote; --tile-points 0 lifts the limit."""
    src = tmp_path / "in.laz"
    write_cloud(two_class_scene(6), src)  # 10,800 points
    out = tmp_path / "mv.laz"
    assert main(["ground", str(src), "-o", str(out), "--method", "ml", "--member-vote", "--tile-points", "5000"]) == 2
    assert "--member-vote" in capsys.readouterr().err
    assert not out.exists()
    assert main(["ground", str(src), "-o", str(out), "--method", "ml", "--member-vote", "--tile-points", "0"]) == 0
    assert main(["ground", str(src), "-o", str(tmp_path / "plain.laz"), "--method", "ml", "--tile-points",
                 "5000"]) == 0


def test_classify_roof_test_options(tmp_path, capsys):
    """The shipped model with and without the roof planarity test, and a looser tolerance:
    switching the test off or loosening it never gives fewer building points."""
    from tests.ml.test_ml_roofs import gabled_house_and_crown
    from workstation.core.cloud import Cloud

    xyz, _, _ = gabled_house_and_crown(seed=7)
    src = tmp_path / "house.laz"
    write_cloud(Cloud(xyz + [500000, 5000000, 100], crs="EPSG:32632"), src)
    counts = {}
    for name, extra in (("default", []), ("off", ["--no-roof-test"]), ("loose", ["--roof-tolerance", "0.3"])):
        out = tmp_path / f"{name}.laz"
        assert main(["classify", str(src), "-o", str(out), *extra]) == 0
        counts[name] = int((np.asarray(read_cloud(out).attrs["classification"]) == 6).sum())
    assert counts["default"] <= counts["loose"] <= counts["off"]
    assert counts["default"] < counts["off"]  # the network calls part of the crown building


def _count_raised_patches(monkeypatch) -> list:
    """A list that grows by one each time the real raised-patch test runs."""
    import workstation.ground.patches as patches

    calls = []
    real = patches.raised_patches

    def counted(*a, **k):  # the real test, counted
        calls.append(1)
        return real(*a, **k)

    monkeypatch.setattr(patches, "raised_patches", counted)
    return calls


def test_classify_raised_patches_option(tmp_path, capsys, monkeypatch):
    """The raised-patch test runs on the gate's ground by default and not with
    --no-raised-patches, and it only ever takes ground away."""
    from tests.ground.ground_synth import terrain_with_boxes
    from workstation.core.cloud import Cloud

    calls = _count_raised_patches(monkeypatch)
    xyz, truth = terrain_with_boxes(density=4.0)
    src = tmp_path / "boxes.laz"
    write_cloud(Cloud(xyz, crs="EPSG:32632"), src)
    ground, ran = {}, {}
    for name, extra in (("default", []), ("on", ["--raised-patches"]), ("off", ["--no-raised-patches"])):
        out = tmp_path / f"{name}.laz"
        calls.clear()
        assert main(["classify", str(src), "-o", str(out), *extra]) == 0
        ran[name] = len(calls)
        ground[name] = np.asarray(read_cloud(out).attrs["classification"]) == 2
    assert ran == {"default": 1, "on": 1, "off": 0}
    np.testing.assert_array_equal(ground["on"], ground["default"])
    assert (ground["default"] <= ground["off"]).all()
    assert ground["default"][truth].mean() > 0.95


def test_classify_water_option(tmp_path, capsys):
    """A level pond in its basin comes out as water (9) with the shipped model; --no-water
    leaves it to the ground."""
    from tests.ground.test_ground_water import pond_scene
    from workstation.core.cloud import Cloud

    xyz, pond = pond_scene(seed=9, density=3.0)
    ones = np.ones(len(xyz), np.uint8)
    src = tmp_path / "pond.laz"
    write_cloud(Cloud(xyz + [500000, 5000000, 0], {"return_number": ones, "number_of_returns": ones},
                      crs="EPSG:32632"), src)
    cls = {}
    for name, extra in (("default", []), ("off", ["--no-water"])):
        out = tmp_path / f"{name}.laz"
        assert main(["classify", str(src), "-o", str(out), *extra]) == 0
        cls[name] = np.asarray(read_cloud(out).attrs["classification"])
    assert (cls["default"][pond] == 9).mean() > 0.9
    assert (cls["off"][pond] == 9).mean() < 0.05  # the network alone finds next to no water
    assert (cls["off"][pond] == 2).mean() > 0.9
