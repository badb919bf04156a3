"""The photogrammetry demo step: fast, writes its products, numbers consistent with the truth."""

from __future__ import annotations

import json

from workstation.io.camera import read_camera
from workstation.pipeline.demo import DemoContext
from workstation.pipeline.demo_steps.photogrammetry import step


def test_demo_step(tmp_path):
    ctx = DemoContext(tmp_path, seed=3)
    made = step(ctx)
    assert set(made) == {"camera_dlt", "gcp_report"}
    rep = json.loads(made["gcp_report"].read_text())
    cam = read_camera(made["camera_dlt"])
    assert abs(cam.fx / rep["dlt"]["true"]["fx"] - 1) < 0.005
    assert rep["dlt"]["centre_error_pct_of_distance"] < 0.1
    geo = rep["georeference"]["metrics"]
    exp = rep["expected_check_rmse_from_image_noise"]
    assert geo["check_n"] == 12 and geo["check_rmse_h"] < 3 * exp["rmse_h"] and geo["check_rmse_z"] < 3 * exp["rmse_z"]
    assert rep["resection"]["converged"] and rep["resection"]["sigma0_px"] < 1.0
    bent = rep["bent_block"]["georeference"]
    assert bent["adjustment"] == "bundle"
    assert bent["metrics"]["check_rmse_z"] < 0.5 * bent["metrics"]["similarity_check_rmse_z"]
    assert bent["metrics"]["check_rmse_z"] < 2 * rep["bent_block"]["expected_check_rmse_from_image_noise"]["rmse_z"]
