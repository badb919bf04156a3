"""The dense demo step: writes a fused cloud close to the true box-and-wall surface."""

from __future__ import annotations

import json

from workstation.io import read_cloud
from workstation.pipeline.demo import DemoContext
from workstation.pipeline.demo_steps.dense import step


def test_dense_demo_step(tmp_path):
    made = step(DemoContext(tmp_path, seed=0))
    assert set(made) == {"dense_ply", "dense_summary"}
    cloud = read_cloud(made["dense_ply"])
    rep = json.loads(made["dense_summary"].read_text())
    assert cloud.n == rep["points"] > 1000
    assert rep["device"] == "cpu" and rep["accuracy_median_m"] < 0.05  # ~0.6 px at 12 m, 160 x 120 px
