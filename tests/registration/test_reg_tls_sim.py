"""Simulated TLS stations (workstation.lidar) registered from random relative poses."""

from dataclasses import replace

import numpy as np
import pytest

from workstation.registration.merge import transform_cloud
from workstation.registration.register import RegisterParams, register
from workstation.registration.transforms import invert, make_transform, transform_error


@pytest.fixture(scope="module")
def stations():
    from workstation.lidar.scene import build_scene
    from workstation.lidar.survey import default_stations, default_survey, run_survey

    scene = build_scene("demo_small", 0)
    cfg = default_survey("tls")
    cfg = replace(cfg, scanner=replace(cfg.scanner, h_step_deg=0.6, v_step_deg=0.6),
                  stations=default_stations(scene, 3))
    c = run_survey(scene, cfg, seed=0).cloud
    ids = np.unique(c.attrs["point_source_id"])
    return [c[c.attrs["point_source_id"] == i] for i in ids]


@pytest.mark.slow
@pytest.mark.parametrize("pair,seed", [((0, 1), 1), ((1, 2), 2)])
def test_simulated_tls_pair_from_a_random_pose(stations, pair, seed):
    rng = np.random.default_rng(seed)
    a = np.radians(rng.uniform(90, 180)) * rng.choice([-1, 1])
    R = np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])
    G = make_transform(R, np.append(rng.uniform(-10, 10, 2), 0.4))
    i, j = pair
    src = transform_cloud(stations[i], G)
    res = register(src, stations[j], RegisterParams())
    rot, tr = transform_error(res.transform, invert(G), center=src.xyz.mean(axis=0))
    assert rot <= 0.2 and tr <= 0.02, (rot, tr)
    assert res.converged
