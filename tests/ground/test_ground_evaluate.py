"""Evaluation metrics on hand-computed cases."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.ground.evaluate import (
    confusion_matrix,
    evaluate_clouds,
    evaluate_labels,
    ground_errors,
    match_points,
    plot_confusion,
    plot_errors,
    read_reference,
)


def test_ground_errors_hand_computed():
    # a=40 ground kept, b=10 ground lost, c=5 object kept as ground, d=45 object rejected
    ref = np.array([1] * 50 + [0] * 50, bool)
    pred = np.array([1] * 40 + [0] * 10 + [1] * 5 + [0] * 45, bool)
    e = ground_errors(ref, pred)
    assert (e.a, e.b, e.c, e.d) == (40, 10, 5, 45)
    assert e.type1 == pytest.approx(10 / 50)
    assert e.type2 == pytest.approx(5 / 50)
    assert e.total_error == pytest.approx(15 / 100)
    po = 85 / 100
    pe = (50 * 45 + 50 * 55) / 100 ** 2
    assert e.kappa == pytest.approx((po - pe) / (1 - pe))
    assert e.kappa == pytest.approx(0.7)


def test_kappa_perfect_and_chance():
    ref = np.array([1, 1, 0, 0], bool)
    assert ground_errors(ref, ref).kappa == pytest.approx(1.0)
    assert ground_errors(ref, ref).total_error == 0.0
    # all predicted ground: kappa 0, Type II 100 %
    e = ground_errors(ref, np.ones(4, bool))
    assert e.kappa == pytest.approx(0.0)
    assert e.type2 == 1.0 and e.type1 == 0.0


def test_type1_undefined_without_ground():
    e = ground_errors(np.zeros(3, bool), np.array([0, 1, 0], bool))
    assert math.isnan(e.type1)
    assert e.type2 == pytest.approx(1 / 3)


def test_confusion_and_per_class_scores():
    ref = [2, 2, 2, 6, 6, 5]
    pred = [2, 2, 6, 6, 2, 5]
    cls, m = confusion_matrix(ref, pred)
    assert cls.tolist() == [2, 5, 6]
    assert m.tolist() == [[2, 0, 1], [0, 1, 0], [1, 0, 1]]
    ev = evaluate_labels(ref, pred)
    s = {c.code: c for c in ev.per_class}
    assert s[2].precision == pytest.approx(2 / 3) and s[2].recall == pytest.approx(2 / 3)
    assert s[6].precision == pytest.approx(1 / 2) and s[6].recall == pytest.approx(1 / 2)
    assert s[5].f1 == pytest.approx(1.0)
    assert ev.overall_accuracy == pytest.approx(4 / 6)
    # ground view: class 2 vs the rest
    assert (ev.ground.a, ev.ground.b, ev.ground.c, ev.ground.d) == (2, 1, 1, 2)
    d = ev.to_dict()
    for k in ("type1", "type2", "total_error", "kappa", "confusion", "classes"):
        assert k in d


def test_confusion_with_given_classes_ignores_others():
    cls, m = confusion_matrix([1, 2, 9], [1, 2, 2], classes=[2, 1])
    assert cls.tolist() == [2, 1]
    assert m.tolist() == [[1, 0], [0, 1]]


def test_match_by_order_and_by_coordinates(rng):
    xyz = rng.uniform(0, 100, (200, 3))
    pi, ri, how = match_points(xyz, xyz)
    assert how == "order" and np.array_equal(pi, ri)
    perm = rng.permutation(200)
    pi, ri, how = match_points(xyz[perm], xyz)
    assert how == "coordinates"
    assert np.array_equal(perm[pi], ri)
    # a prediction with fewer points and one far point
    sub = np.vstack([xyz[perm[:50]], [[1e4, 1e4, 0]]])
    pi, ri, _ = match_points(sub, xyz)
    assert pi.size == 50 and 50 not in pi


def test_evaluate_clouds_with_shuffled_prediction(rng):
    xyz = rng.uniform(0, 50, (100, 3)) + [500000, 4e6, 0]
    ref_cls = np.where(rng.random(100) < 0.6, 2, 1)
    ref = Cloud(xyz, {"classification": ref_cls})
    pred_cls = ref_cls.copy()
    pred_cls[:10] = 1  # 10 ground points (or objects already 1) rejected
    perm = rng.permutation(100)
    pred = Cloud(xyz[perm], {"classification": pred_cls[perm]})
    ev, _, _ = evaluate_clouds(pred, ref)
    assert ev.matched_by == "coordinates"
    lost = int(np.count_nonzero(ref_cls[:10] == 2))
    assert ev.ground.b == lost
    assert ev.ground.c == 0


def test_read_isprs_reference_and_plots(tmp_path, rng):
    xyz = rng.uniform(0, 20, (30, 3))
    lab = (rng.random(30) < 0.3).astype(int)
    f = tmp_path / "samp.txt"
    np.savetxt(f, np.column_stack([xyz, lab]), fmt="%.3f\t%.3f\t%.3f\t%d")
    ref = read_reference(f)
    assert np.array_equal(np.asarray(ref.attrs["classification"]), np.where(lab == 0, 2, 1))
    pred = Cloud(ref.xyz, {"classification": np.full(30, 2)})
    ev, pi, ri = evaluate_clouds(pred, ref)
    assert ev.type2 == 1.0 and ev.type1 == 0.0
    p1 = plot_errors(ref.xyz, lab == 0, np.ones(30, bool), tmp_path / "e.png")
    p2 = plot_confusion(ev, tmp_path / "c.png")
    for p in (p1, p2):
        assert p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
