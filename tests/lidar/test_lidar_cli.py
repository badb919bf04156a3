"""`ws plan-flight` and `ws simulate` through the CLI boundary, and the demo step."""

from __future__ import annotations

import json

import numpy as np
import pytest

from workstation.cli.main import main


def test_plan_flight_json_keys(capsys):
    rc = main(["plan-flight", "--altitude", "800", "--speed", "50", "--prf", "200000", "--fov", "30", "--json"])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    for k in ("swath_width", "spacing_along", "spacing_across", "density", "nps", "flight_lines", "total_time_s"):
        assert k in d
    assert d["swath_width"] == pytest.approx(1600 * np.tan(np.radians(15)))
    assert d["density"] == pytest.approx(200000 / (d["swath_width"] * 50))


def test_plan_flight_inverse_and_text(capsys):
    assert main(["plan-flight", "--target-density", "8", "--solve-for", "altitude", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["density"] == pytest.approx(8.0) and d["solved_for"] == "altitude"
    assert main(["plan-flight"]) == 0
    assert "swath width" in capsys.readouterr().out
    assert main(["plan-flight", "--overlap", "1.5"]) == 2  # out of its range: a usage error


def test_simulate_tls_cli_writes_las_and_trajectory(tmp_path, capsys):
    out = tmp_path / "tls.laz"
    rc = main(["simulate", "tls", "-o", str(out), "--scene", "demo_small", "--h-step", "2", "--v-step", "2",
               "--station", "0,0", "--station", "20,10", "--json"])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    assert d["flight_lines_or_stations"] == 2 and d["point_count"] > 1000
    from workstation.io import read_cloud

    c = read_cloud(out)
    assert c.meta["las"]["point_format"] == 7
    assert set(np.unique(c.attrs["point_source_id"])) == {1, 2}
    assert np.array_equal(c.attrs["user_data"], (c.attrs["object_id"] % 256).astype(np.uint8))

    assert c.crs and "32632" in c.crs
    traj = (tmp_path / "tls.trajectory.csv").read_text().splitlines()
    assert traj[0].startswith("gps_time,easting,northing,height,roll_deg,pitch_deg,heading_deg")
    # refuses to overwrite
    assert main(["simulate", "tls", "-o", str(out), "--scene", "demo_small", "--h-step", "5", "--v-step", "5"]) == 1
    # same seed -> identical file; the LAS header's creation day is the only field allowed to
    # differ (bytes 90-93), so a run across midnight still passes
    again = tmp_path / "tls_again.laz"
    assert main(["simulate", "tls", "-o", str(again), "--scene", "demo_small", "--h-step", "2", "--v-step", "2",
                 "--station", "0,0", "--station", "20,10"]) == 0
    a, b = bytearray(again.read_bytes()), bytearray(out.read_bytes())
    a[90:94] = b[90:94]
    assert a == b


def test_simulate_als_cli_config_file(tmp_path, capsys):
    cfg = tmp_path / "survey.toml"
    cfg.write_text(
        '[survey]\nscene = "demo_small"\nseed = 4\n'
        '[flight]\naltitude = 150.0\nspeed = 70.0\nn_lines = 1\n'
        '[scanner]\nprf = 20000.0\nscan_frequency = 20.0\n'
        '[sensor]\nsubrays = 2\n'
        '[errors]\nrange_noise_m = 0.0\n'
    )
    out = tmp_path / "als.las"
    rc = main(["simulate", "als", "-o", str(out), "--config", str(cfg), "--point-format", "8", "--json"])
    assert rc == 0
    d = json.loads(capsys.readouterr().out)
    assert d["seed"] == 4 and d["flight_lines_or_stations"] == 1
    from workstation.io import read_cloud

    c = read_cloud(out)
    assert c.meta["las"]["point_format"] == 8 and "nir" in c.attrs
    from workstation.lidar.scene import PART_ID

    roof = c.attrs["part"] == PART_ID["roof"]
    assert roof.sum() > 50 and np.all(c.attrs["classification"][roof] == 6)
    bad = tmp_path / "bad.toml"
    bad.write_text("[flight]\naltitud = 3\n")
    assert main(["simulate", "als", "-o", str(tmp_path / "x.laz"), "--config", str(bad)]) == 1


@pytest.mark.slow
def test_demo_step_products(tmp_path):
    from workstation.pipeline.demo import DemoContext
    from workstation.pipeline.demo_steps.simulate import step
    from workstation.io import read_cloud
    from workstation.lidar.scene import load_scene

    ctx = DemoContext(tmp_path)
    made = step(ctx)
    assert {"als_laz", "tls_laz", "scene_mesh"} <= set(made)
    als = read_cloud(made["als_laz"])
    assert set(np.unique(als.attrs["point_source_id"])) == {1, 2}
    assert (als.attrs["number_of_returns"] > 1).any()
    assert len(np.unique(read_cloud(made["tls_laz"]).attrs["point_source_id"])) == 3
    assert load_scene(made["scene_mesh"]).n_faces > 10_000
