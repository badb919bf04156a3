"""The shipped model on real scans: the levels it measurably reaches (models/MODEL_CARD.md).

Thresholds are the measured figures rounded up a little (not the issue's goals, which the
model does not all reach; see the card). Small files only; the full set is in
scripts/bench_classify.py.
"""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.classes import ASPRSClass as C

pytestmark = [pytest.mark.realdata, pytest.mark.slow]


@pytest.fixture(scope="module")
def shipped():
    from workstation.ml.classifier import PointClassifier

    return PointClassifier.load(None, device="cpu")


def test_isprs_mean_total_error(shipped, shared_data):
    from workstation.ml.realdata import isprs_scores

    s = isprs_scores(lambda c: shipped.predict(c) == C.GROUND, shared_data / "isprs")
    assert len(s) == 7
    # measured 3.24 % (3.49 % without the raised-patch step, 3.68 % before the slope-adaptive
    # provisional surface), and samp42 1.54 % (2.90 % without the raised-patch step, so the
    # bound catches the step switched off); the margins cover floating-point differences
    # between CPUs, not the model
    assert s["mean_total"] <= 3.3, s["mean_total"]
    assert s["samp31"]["total"] <= 2.5 and s["samp21"]["total"] <= 2.0 and s["samp42"]["total"] <= 1.8, s


@pytest.mark.parametrize("name", ["MixedConifer.laz", "Topography.laz", "bcts_1.laz", "bcts_2.laz", "autzen_trim.las"])
def test_dtm_under_predicted_ground(shipped, shared_data, name):
    from workstation.ml.realdata import tile_scores

    r = tile_scores(shipped.predict, shared_data / "lidar" / name)
    # the goal (issue 5); measured 0.089, 0.229, 0.213, 0.234 and 0.168 m with the
    # understorey and water steps (Topography 0.242 m without the water step; 0.089, 0.328,
    # 0.289, 0.370, 0.189 m without the understorey step)
    assert r["dtm_rmse_m"] <= 0.25, r


def test_building_roof_of_sample_c(shipped, shared_data):
    from workstation.ml.realdata import tile_scores

    r = tile_scores(shipped.predict, shared_data / "lidar" / "sample_c.las")
    # measured 0.985 (0.982 before the roof planarity test): a roof 26 m up that fills the
    # crop (the goal is 0.85)
    assert r["building_f1"] >= 0.9, r


def test_lidarhd_vegetation_and_house(shipped, shared_data):
    from workstation.ml.realdata import tile_scores

    r = tile_scores(shipped.predict, shared_data / "lidar" / "lidarhd_extra_bytes.laz")
    # measured vegetation 0.909 (goal 0.85), building 0.863 (goal 0.85; 0.703 without the
    # roof planarity test: a crown of single returns over a shed), ground 0.997
    assert r["vegetation_f1"] >= 0.85, r
    assert r["building_f1"] >= 0.85, r
    assert r["ground_f1"] >= 0.99, r


def test_water_of_topography(shipped, shared_data):
    from workstation.ml.realdata import tile_scores

    r = tile_scores(shipped.predict, shared_data / "lidar" / "Topography.laz")
    # measured: water F1 0.909 (0.0 without the water step: the network alone calls the lake
    # ground, and its own 132 water points are elsewhere), and with the lake out of the ground
    # the DTM 0.229 m (0.242 with it)
    assert r["water_f1"] >= 0.88, r
    assert r["dtm_rmse_m"] <= 0.235, r


def test_vegetation_of_warsaw_small(shipped, shared_data):
    from workstation.ml.realdata import tile_scores

    r = tile_scores(shipped.predict, shared_data / "lidar" / "warsaw_small.las")
    # measured 0.813 (the goal, 0.85, is missed: 240 of its 257 low-vegetation points lie
    # 0.0-0.2 m above the ground, where the model calls them ground)
    assert r["vegetation_f1"] >= 0.80, r
    assert r["ground_f1"] >= 0.9, r


def test_ml_ground_function_marks_ground_only(shipped, shared_data):
    from workstation.io import read_cloud
    from workstation.ml.ground import ml_ground

    c = read_cloud(shared_data / "lidar" / "MixedConifer.laz")
    out = ml_ground(c.without_attrs("classification"))
    cls = np.asarray(out.attrs["classification"])
    assert set(np.unique(cls)) <= {int(C.GROUND), int(C.UNCLASSIFIED)}
    ref = np.asarray(c.attrs["classification"]) == C.GROUND
    # vendor ground is a strict subset; most of it must be found
    assert (cls[ref] == C.GROUND).mean() > 0.85


def test_ml_ground_on_isprs_runs_the_raised_patch_test(shared_data):
    from workstation.ml.ground import ml_ground
    from workstation.ml.realdata import isprs_scores

    s = isprs_scores(lambda c: np.asarray(ml_ground(c).attrs["classification"]) == C.GROUND, shared_data / "isprs")
    # measured 3.24 % (3.49 % without the raised-patch test): samp42's roof at the sample's corner, on which the provisional surface sits,
    # leaves the ground (2.90 -> 1.54 %)
    assert s["mean_total"] <= 3.3, s["mean_total"]
    assert s["samp42"]["total"] <= 1.8, s


def test_ml_ground_member_vote_on_isprs(shared_data):
    from workstation.ml.ground import MLGroundParams, ml_ground
    from workstation.ml.realdata import isprs_scores

    p = MLGroundParams(device="cpu", member_vote=True)
    s = isprs_scores(lambda c: np.asarray(ml_ground(c, p).attrs["classification"]) == C.GROUND, shared_data / "isprs")
    # measured 2.84 % (7.87, 1.31, 2.11, 1.50, 2.27, 2.00; auto 2.91 %: 7.92, 1.47, 2.56, 1.46,
    # 2.46, 1.55): samp61's embankment crests, which the network's provisional surface cuts,
    # come back with the members (2.60 -> 2.00 %); samp42 is 3.48 % without the raised patches
    assert s["mean_total"] <= 2.9, s["mean_total"]
    assert s["samp61"]["total"] <= 2.1 and s["samp42"]["total"] <= 1.6 and s["samp11"]["total"] <= 8.0, s
