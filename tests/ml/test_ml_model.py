"""Point classifier: features, model shapes/devices, learning, persistence, attributes."""

from __future__ import annotations

import time

import numpy as np
import pytest

from workstation.core.classes import ASPRSClass as C
from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError, NotFittedError
from workstation.ml.classifier import PointClassifier
from workstation.ml.dataset import MODEL_CLASSES
from workstation.ml.features import FEATURE_NAMES, compute_features, sym3_eigen


def two_class_scene(seed: int, size: float = 80.0, density: float = 3.0) -> Cloud:
    """Gently sloping ground with noise plus flat-roofed boxes (buildings), labelled 2 / 6."""
    rng = np.random.default_rng(seed)
    n = int(size * size * density)
    xy = rng.uniform(0, size, (n, 2))
    z = 100 + 0.03 * xy[:, 0] + rng.normal(0, 0.03, n)
    cls = np.full(n, C.GROUND, np.uint8)
    for _ in range(4):
        cx, cy = rng.uniform(12, size - 12, 2)
        hx, hy = rng.uniform(4, 9, 2)
        h = rng.uniform(4, 12)
        inside = (np.abs(xy[:, 0] - cx) < hx) & (np.abs(xy[:, 1] - cy) < hy)
        z[inside] = 100 + 0.03 * cx + h + rng.normal(0, 0.03, inside.sum())
        cls[inside] = C.BUILDING
    return Cloud(np.column_stack([xy + [500000, 5000000], z]), {"classification": cls,
                 "intensity": rng.integers(100, 4000, n).astype(np.uint16)}, crs="EPSG:32632")


@pytest.fixture(scope="module")
def tiny_model():
    t0 = time.perf_counter()
    clf = PointClassifier(hidden=(32, 32), epochs=15, patience=15, seed=0, device="cpu")
    clf.fit([two_class_scene(1), two_class_scene(2)], samples_per_cloud=8000)
    clf.fit_seconds_ = time.perf_counter() - t0
    return clf


def test_features_shape_and_finite_on_random_points():
    rng = np.random.default_rng(0)
    c = Cloud(rng.uniform(0, 50, (2000, 3)))
    F = compute_features(c)
    assert F.shape == (2000, len(FEATURE_NAMES))
    assert F.dtype == np.float32
    assert np.isfinite(F).all()
    # no echo or intensity information: the flags say so
    assert (F[:, FEATURE_NAMES.index("has_returns")] == 0).all()
    assert (F[:, FEATURE_NAMES.index("has_intensity")] == 0).all()


def test_features_are_in_metres_whatever_the_crs_unit():
    c = two_class_scene(3)
    ft = 1200 / 3937  # US survey foot
    c_ft = Cloud(np.asarray(c.xyz) / ft, dict(c.attrs), crs="EPSG:2992")  # Oregon Lambert, ftUS
    F, G = compute_features(c), compute_features(c_ft)
    i = FEATURE_NAMES.index("hag_prov")
    assert np.percentile(np.abs(F[:, i] - G[:, i]), 95) < 0.05


def test_closed_form_eigenvalues_match_numpy():
    rng = np.random.default_rng(1)
    a = rng.normal(size=(500, 3, 3))
    a = a @ a.transpose(0, 2, 1)
    l1, l2, l3 = sym3_eigen(a)
    w = np.linalg.eigvalsh(a)
    np.testing.assert_allclose(np.column_stack([l3, l2, l1]), w, atol=1e-9)


def test_tiny_model_learns_two_class_scene_quickly(tiny_model):
    test = two_class_scene(7)
    pred = tiny_model.predict(test)
    acc = (pred == np.asarray(test.attrs["classification"])).mean()
    assert acc >= 0.95, acc
    assert tiny_model.fit_seconds_ < 60  # a few seconds uncontended


def test_predict_proba_shape_and_rows_sum_to_one(tiny_model):
    c = two_class_scene(8)
    P = tiny_model.predict_proba(c)
    assert P.shape == (c.n, len(MODEL_CLASSES)) and P.dtype == np.float32
    np.testing.assert_allclose(P.sum(1), 1, atol=1e-5)


def test_cpu_and_cuda_devices_agree(tiny_model):
    torch = pytest.importorskip("torch")
    c = two_class_scene(9)
    p_cpu = tiny_model.predict_proba(c)
    if not torch.cuda.is_available():
        assert next(tiny_model.net_.parameters()).device.type == "cpu"
        return
    tiny_model.device = "cuda"
    try:
        p_gpu = tiny_model.predict_proba(c)
    finally:
        tiny_model.device = "cpu"
    np.testing.assert_allclose(p_cpu, p_gpu, atol=1e-4)


def test_save_load_round_trip_gives_identical_predictions(tiny_model, tmp_path):
    import torch

    p = tiny_model.save(tmp_path / "m.pt")
    payload = torch.load(p, weights_only=True)  # safe loading works
    assert payload["format"].startswith("workstation-point-classifier")
    back = PointClassifier.load(p, device="cpu")
    c = two_class_scene(10)
    np.testing.assert_array_equal(back.predict_proba(c), tiny_model.predict_proba(c))
    np.testing.assert_array_equal(back.predict(c), tiny_model.predict(c))
    with pytest.raises(FileExistsError):
        tiny_model.save(p)


def test_classify_keeps_every_other_attribute(tiny_model):
    c = two_class_scene(11)
    rng = np.random.default_rng(0)
    c = c.with_attrs(gps_time=rng.uniform(0, 10, c.n), user_data=rng.integers(0, 255, c.n).astype(np.uint8))
    out = tiny_model.classify(c)
    assert out.n == c.n
    np.testing.assert_array_equal(out.xyz, c.xyz)
    for k in c.attrs:
        if k != "classification":
            np.testing.assert_array_equal(out.attrs[k], c.attrs[k])
    assert out.attrs["confidence"].dtype == np.float32
    assert ((out.attrs["confidence"] > 0) & (out.attrs["confidence"] <= 1)).all()
    assert set(np.unique(out.attrs["classification"])) <= {int(x) for x in C}
    # the input is untouched
    assert "confidence" not in c.attrs


def test_not_fitted_error_before_fit():
    clf = PointClassifier()
    with pytest.raises(NotFittedError):
        clf.predict(two_class_scene(1))
    with pytest.raises(NotFittedError):
        clf.save("never.pt")


def test_tiled_prediction_matches_untiled_in_the_tile_cores(tiny_model):
    c = two_class_scene(12, size=200.0, density=1.0)
    whole = tiny_model.predict(c)
    tiny_model.tile_points = 15_000
    try:
        tiled = tiny_model.predict(c)
    finally:
        tiny_model.tile_points = 3_000_000
    assert (whole == tiled).mean() > 0.98


def test_random_forest_baseline_same_harness():
    rf = PointClassifier(model="rf", n_estimators=20, seed=0)
    rf.fit([two_class_scene(1)], samples_per_cloud=5000)
    test = two_class_scene(7)
    assert (rf.predict(test) == np.asarray(test.attrs["classification"])).mean() > 0.95
    with pytest.raises(InvalidInputError):
        PointClassifier(model="svm")


def test_understorey_step_under_canopy_only(tiny_model, tmp_path):
    """With return numbers that show a canopy, ground points well above the ground's lower
    envelope leave the ground class; without them (or switched off) nothing changes."""
    c = two_class_scene(12)
    rng = np.random.default_rng(3)
    z = c.xyz[:, 2].copy()
    ground = np.asarray(c.attrs["classification"]) == C.GROUND
    lift = ground & (rng.uniform(size=c.n) < 0.2)
    z[lift] += 0.35  # understorey in the gate's 0.5 m band
    lifted = Cloud(np.column_stack([c.xyz[:, :2], z]), dict(c.attrs), crs=c.crs)
    plain = tiny_model.predict(lifted)
    n = c.n
    echoes = lifted.with_attrs(return_number=np.full(n, 2, np.uint8), number_of_returns=np.full(n, 2, np.uint8))
    with_step = tiny_model.predict(echoes)
    assert (plain[lift] == C.GROUND).mean() > 0.8  # the band lets them in
    assert (with_step[lift] == C.GROUND).mean() < 0.2
    assert (with_step[ground & ~lift] == C.GROUND).mean() > 0.9 * (plain[ground & ~lift] == C.GROUND).mean()
    single = echoes.with_attrs(number_of_returns=np.ones(n, np.uint8), return_number=np.ones(n, np.uint8))
    np.testing.assert_array_equal(tiny_model.predict(single), plain)
    off = PointClassifier.load(tiny_model.save(tmp_path / "u.pt"), device="cpu")
    assert off.understorey is True and off.config()["understorey"] is True
    off.understorey = False
    np.testing.assert_array_equal(off.predict(echoes), plain)


def test_roof_test_sends_rough_building_points_to_their_next_class(tiny_model, tmp_path):
    """Points the network calls building whose neighbourhood is not planar (a crown) take the
    best other object class; a gabled roof keeps its class; the setting is saved."""
    from tests.ml.test_ml_roofs import gabled_house_and_crown

    xyz, label, hag = gabled_house_and_crown(seed=5)
    cloud = Cloud(xyz + [500000, 5000000, 100], {}, crs="EPSG:32632")
    n = len(xyz)
    P = np.zeros((n, len(MODEL_CLASSES)), np.float32)
    raised = label != 2
    P[~raised, 0] = 1.0
    P[raised, 2], P[raised, 1], P[raised, 4] = 0.7, 0.2, 0.1  # building, then vegetation, other
    hs = np.column_stack([hag, np.zeros(n)]).astype(np.float32)
    codes, conf = tiny_model.codes_from_proba(P, hs, cloud)
    assert (codes[label == 6] == C.BUILDING).mean() > 0.97
    crown = label == 5
    assert (codes[crown] == C.HIGH_VEGETATION).mean() > 0.8
    moved = crown & (codes == C.HIGH_VEGETATION)
    np.testing.assert_allclose(conf[moved], 0.2 / 0.3, rtol=1e-5)
    tiny_model.roof_test = False
    try:
        assert (tiny_model.codes_from_proba(P, hs, cloud)[0][crown] == C.BUILDING).all()
    finally:
        tiny_model.roof_test = True
    loaded = PointClassifier.load(tiny_model.save(tmp_path / "r.pt"), device="cpu")
    assert loaded.roof_test is True and loaded.config()["roof_test"] is True


def test_raised_patches_send_a_roof_called_ground_to_its_next_class(tiny_model, tmp_path):
    """A flat roof that the network and the gate both call ground (here: probabilities and
    heights made up so) is a raised patch: it takes the network's best non-ground class;
    the terrain stays ground. The step is on by default and a model saved with it off loads
    with it on (a rule of inference, not of the model)."""
    import json

    import torch

    from workstation.ml.classifier import StepSwitches

    cloud = two_class_scene(7)
    cls = np.asarray(cloud.attrs["classification"])
    roof = cls == C.BUILDING
    n = cloud.n
    P = np.zeros((n, len(MODEL_CLASSES)), np.float32)
    P[:, 0], P[:, 2], P[:, 1] = 0.6, 0.3, 0.1  # ground first, then building, vegetation
    hs = np.zeros((n, 2), np.float32)  # every point inside the gate's band
    assert tiny_model.raised_patches is True  # on by default (ws classify and ws ground --method ml)
    tiny_model.roof_test = False  # this test is about the ground
    try:
        codes, _ = tiny_model.codes_from_proba(P, hs, cloud)
        assert (codes[roof] == C.BUILDING).mean() > 0.99
        assert (codes[~roof] == C.GROUND).all()
        off = StepSwitches(raised_patches=False)
        assert (tiny_model.codes_from_proba(P, hs, cloud, off)[0] == C.GROUND).all()
        tiny_model.raised_patches = False
        assert (tiny_model.codes_from_proba(P, hs, cloud)[0] == C.GROUND).all()
        path = tiny_model.save(tmp_path / "p.pt")
        saved = json.loads(torch.load(path, map_location="cpu", weights_only=True)["config"])
        assert saved["raised_patches"] is False
        assert PointClassifier.load(path, device="cpu").raised_patches is True
    finally:
        tiny_model.roof_test, tiny_model.raised_patches = True, True


def test_prediction_gate_is_the_ground_before_the_refine_chain(tiny_model):
    """``Prediction.gate`` is the gate's ground: the ground with every refine step off, and
    a superset of the ground the chain leaves (its ground steps only take ground away)."""
    from workstation.ml.classifier import StepSwitches

    cloud = two_class_scene(8)
    steps_off = StepSwitches(understorey=False, raised_patches=False, water=False, roof_test=False, bridges=False)
    bare = tiny_model.predict_codes(cloud, steps_off)
    np.testing.assert_array_equal(bare.gate, bare.codes == C.GROUND)
    full = tiny_model.predict_codes(cloud, StepSwitches(roof_test=False))
    np.testing.assert_array_equal(full.gate, bare.gate)
    assert not ((full.codes == C.GROUND) & ~full.gate).any()


def test_water_step_makes_still_water_class_9(tiny_model, tmp_path):
    """Ground on a level pond whose banks rise from it becomes water (9) with a confidence
    that falls off with the height above the level; the banks stay ground; without the step
    (or saved and loaded with it off) everything is ground."""
    from tests.ground.test_ground_water import pond_scene

    xyz, pond = pond_scene(seed=8)
    cloud = Cloud(xyz + [500000, 5000000, 0], {"number_of_returns": np.ones(len(xyz), np.uint8),
                                               "return_number": np.ones(len(xyz), np.uint8)}, crs="EPSG:32632")
    n = cloud.n
    P = np.zeros((n, len(MODEL_CLASSES)), np.float32)
    P[:, 0], P[:, 1] = 0.9, 0.1  # the network and the gate call everything ground
    hs = np.zeros((n, 2), np.float32)
    assert tiny_model.water is True
    codes, conf = tiny_model.codes_from_proba(P, hs, cloud)
    assert (codes[pond] == C.WATER).mean() > 0.95
    assert (codes[~pond] == C.GROUND).mean() > 0.99
    w = codes == C.WATER
    assert (conf[w] >= 0.5).all() and (conf[w] <= 1.0).all() and conf[w].mean() > 0.85
    tiny_model.water = False
    try:
        assert (tiny_model.codes_from_proba(P, hs, cloud)[0] == C.GROUND).all()
        loaded = PointClassifier.load(tiny_model.save(tmp_path / "w.pt"), device="cpu")
        assert loaded.water is False and loaded.config()["water"] is False
    finally:
        tiny_model.water = True


def test_roof_failures_of_multi_echo_pulses_take_vegetation(tiny_model):
    """A crown the network calls building, with "other" as its second class: the roof test
    sends its single-echo points to "other" and its points of multi-echo pulses to
    vegetation; without return numbers nothing but the network's order decides."""
    from tests.ml.test_ml_roofs import gabled_house_and_crown

    xyz, label, hag = gabled_house_and_crown(seed=5)
    n = len(xyz)
    crown = label == 5
    multi = crown & (np.arange(n) % 2 == 0)
    nr = np.where(multi, 2, 1).astype(np.uint8)
    cloud = Cloud(xyz + [500000, 5000000, 100], {"return_number": np.ones(n, np.uint8), "number_of_returns": nr},
                  crs="EPSG:32632")
    P = np.zeros((n, len(MODEL_CLASSES)), np.float32)
    P[label == 2, 0] = 1.0
    P[label != 2, 2], P[label != 2, 4], P[label != 2, 1] = 0.7, 0.2, 0.1  # building, then other, vegetation
    hs = np.column_stack([hag, np.zeros(n)]).astype(np.float32)
    codes, conf = tiny_model.codes_from_proba(P, hs, cloud)
    moved = crown & (codes != C.BUILDING)
    assert moved.mean() / crown.mean() > 0.8
    assert (codes[moved & multi] == C.HIGH_VEGETATION).all()
    assert (codes[moved & ~multi] == C.UNCLASSIFIED).all()
    np.testing.assert_allclose(conf[moved & multi], 0.1 / 0.3, rtol=1e-5)
    assert (codes[label == 6] == C.BUILDING).mean() > 0.97
    plain = tiny_model.codes_from_proba(P, hs, cloud.without_attrs("return_number", "number_of_returns"))[0]
    assert (plain[moved] == C.UNCLASSIFIED).all()


def test_cpu_inference_equals_the_plain_forward(tiny_model):
    # predict_logits on the CPU standardises by numpy into C-ordered batches run with torch on
    # one intra-op thread: the same values as the module's own forward on the whole matrix,
    # torch's thread setting restored afterwards
    torch = pytest.importorskip("torch")
    from workstation.ml import model as m

    rng = np.random.default_rng(3)
    X = np.asfortranarray(rng.normal(0, 3, (m.CPU_BATCH * 2 + 777, len(FEATURE_NAMES))).astype(np.float32))
    net = tiny_model.net_.cpu().eval()
    with torch.inference_mode():
        ref = torch.softmax(net(torch.from_numpy(np.ascontiguousarray(X))), dim=1).numpy()
    before = torch.get_num_threads()  # (fitting on the CPU left one thread)
    torch.set_num_threads(2)
    try:
        P = m.predict_logits(net, X, "cpu")
        assert P.dtype == np.float32 and np.array_equal(P, ref)
        assert torch.get_num_threads() == 2
    finally:
        torch.set_num_threads(before)


def test_roof_vote_without_mixed_decisions_needs_no_lookup():
    # all tested candidates pass (or all fail): every candidate takes that decision, as the
    # majority of its nearest tested candidates would give
    from workstation.ml.roofs import RoofTest

    rng = np.random.default_rng(2)
    xyz = rng.uniform(0, 30, (3000, 3))
    t = RoofTest(xyz, xyz[:, 2])
    cand = xyz[:, 2] > 10
    tested, bad = t.test(cand)
    assert len(tested) > 5
    for value in (False, True):
        mask = np.full(len(tested), value)
        assert np.array_equal(t.vote(cand, tested, mask), cand & value)
    mixed = np.arange(len(tested)) % 2 == 0  # the lookup path still votes among neighbours
    v = t.vote(cand, tested, mixed)
    assert v[cand].any() and not v[cand].all() and not v[~cand].any()


def test_started_chain_is_used_only_for_its_own_gate_and_steps():
    """The refine chain _infer starts early is taken only for the gate and steps it ran on;
    otherwise it is cancelled (if not yet begun) and _codes runs the chain itself."""
    from concurrent.futures import Future

    from workstation.ml.classifier import _Started

    gate = np.array([True, False, True])
    fut = Future()
    started = _Started(chain=fut, ground=gate, steps=("a",))
    assert started.chain_for(gate.copy(), ("a",)) is fut
    assert started.chain_for(~gate, ("a",)) is None and fut.cancelled()
    assert _Started(chain=Future(), ground=gate, steps=("a",)).chain_for(gate, ("b",)) is None
    assert _Started().chain_for(gate, ("a",)) is None


def test_cpu_prediction_is_the_same_on_one_or_several_threads():
    """The network's CPU batches shared among threads give the values one thread gives."""
    import torch

    from workstation.ml.model import CPU_BATCH, _predict_cpu

    net = torch.nn.Sequential(torch.nn.Linear(5, 8), torch.nn.ReLU(), torch.nn.Linear(8, 3))
    model = type("M", (), {})()
    model.net, model.mean, model.std = net, torch.zeros(5), torch.ones(5)
    X = np.random.default_rng(0).normal(size=(3 * CPU_BATCH + 17, 5)).astype(np.float32)
    one = _predict_cpu(model, X, threads=1)
    assert np.array_equal(one, _predict_cpu(model, X, threads=3))
