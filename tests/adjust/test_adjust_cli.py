"""`ws strip-adjust` end to end on small LAS files, and the simulator's injected range offset
read back through the trajectory CSV it writes."""

from __future__ import annotations

import hashlib
import json

import numpy as np
import pytest
from workstation.cli.main import main
from workstation.core.cloud import Cloud
from workstation.io import read_cloud, write_cloud

from .synth import calibration_lines, fly, plates

ORIGIN_X = 500000.0


def _write_tiles(tmp_path, xyz, attrs):
    """Two adjacent 'tiles' split at x = 0 (local), each holding part of every strip."""
    west = xyz[:, 0] < ORIGIN_X
    paths = []
    for name, m in (("west.las", west), ("east.las", ~west)):
        p = tmp_path / name
        write_cloud(Cloud(xyz[m], {k: v[m] for k, v in attrs.items()}, crs="EPSG:32632"), p)
        paths.append(p)
    return paths


def _digest(p):
    return hashlib.sha256(p.read_bytes()).hexdigest()


def _run(capsys, *args):
    """(exit code, stdout, stderr) of ``ws args``."""
    capsys.readouterr()
    rc = main([str(a) for a in args])
    out = capsys.readouterr()
    return rc, out.out, out.err


@pytest.fixture(scope="module")
def scene():
    return plates(np.random.default_rng(1), n=40)


def test_strip_adjust_cli_writes_adjusted_tiles_and_report(tmp_path, scene, capsys):
    xyz, attrs, _ = fly(calibration_lines(120.0), scene, line_shift={2: (0.1, -0.05, 0.08)})
    inputs = _write_tiles(tmp_path, xyz, attrs)
    digests = [_digest(p) for p in inputs]
    out = tmp_path / "adjusted"
    rc, stdout, err = _run(capsys, "strip-adjust", *inputs, "-o", out, "--fixed-strip", 1, "--json")
    assert rc == 0, err
    rep = json.loads(stdout)
    for key in ("model", "boresight_deg", "boresight_sigma_deg", "range_offset_m", "strips", "rmsdz_before_m",
                "rmsdz_after_m", "pairs", "parameters", "correlation", "not_determined"):
        assert key in rep
    assert rep["model"] == "strip"
    s2 = {s["id"]: s for s in rep["strips"]}[2]
    assert s2["shift_m"][2] == pytest.approx(-0.08, abs=0.003)
    assert rep["rmsdz_after_m"] < 0.5 * rep["rmsdz_before_m"]
    # pairs without strip 2 were aligned already: they stay within a millimetre
    assert all(p["rmsdz_after_m"] <= p["rmsdz_before_m"] + 0.001 for p in rep["pairs"])
    assert all(p["rmsdz_after_m"] < 0.5 * p["rmsdz_before_m"] for p in rep["pairs"] if 2 in (p["a"], p["b"]))
    assert [_digest(p) for p in inputs] == digests  # inputs untouched
    assert json.loads((out / "strip_adjust.json").read_text())["strips"] == rep["strips"]
    assert (out / "dz_before" / "dz.tif").exists() and (out / "dz_after" / "dz_values.tif").exists()
    for p in inputs:
        a, b = read_cloud(p), read_cloud(out / p.name)
        assert b.n == a.n
        for k in ("intensity", "gps_time", "point_source_id"):
            np.testing.assert_array_equal(b.attrs[k], a.attrs[k])
        moved = b.xyz - a.xyz
        two = a.attrs["point_source_id"] == 2
        assert np.median(moved[two, 2]) == pytest.approx(-0.08, abs=0.004)
        assert np.abs(moved[~two]).max() < 0.01
    rc, _, err = _run(capsys, "strip-adjust", *inputs, "-o", out)
    assert rc == 1 and "exists" in err


def test_strip_adjust_cli_rigorous_with_trajectory_csv(tmp_path, scene, capsys):
    xyz, attrs, nav = fly(calibration_lines(), scene, boresight_err_deg=(0.05, -0.03, 0.08), range_offset=0.05)
    inputs = _write_tiles(tmp_path, xyz, attrs)
    traj = tmp_path / "traj.csv"
    cols = np.column_stack([nav.time, nav.position, np.degrees(nav.rpy[:, :2]), np.mod(np.degrees(nav.rpy[:, 2]), 360)])
    np.savetxt(traj, cols, delimiter=",", fmt="%.6f", comments="",
               header="gps_time,easting,northing,height,roll_deg,pitch_deg,heading_deg")
    rc, stdout, err = _run(capsys, "strip-adjust", *inputs, "-o", tmp_path / "out", "--trajectory", traj,
                           "--lever-arm", "0.1,0,0.25", "--json")
    assert rc == 0, err
    rep = json.loads(stdout)
    assert rep["model"] == "rigorous" and rep["fixed_strip"] is None
    np.testing.assert_allclose(rep["boresight_deg"], [0.05, -0.03, 0.08], atol=0.005)
    assert rep["range_offset_m"] == pytest.approx(0.05, abs=0.01)
    assert rep["rmsdz_after_m"] <= 0.03 < rep["rmsdz_before_m"]


def test_strip_adjust_cli_refuses_bad_estimate_and_missing_trajectory(tmp_path, capsys):
    xyz, attrs, _ = fly(calibration_lines(40.0)[:2], None)
    inputs = _write_tiles(tmp_path, xyz, attrs)
    rc, _, err = _run(capsys, "strip-adjust", *inputs, "-o", tmp_path / "o", "--estimate", "boresight,zoom")
    assert rc == 2 and "zoom" in err
    rc, _, err = _run(capsys, "strip-adjust", *inputs, "-o", tmp_path / "o", "--estimate", "boresight")
    assert rc == 1 and "--trajectory" in err
    assert not (tmp_path / "o").exists()


def test_simulator_range_offset_moves_points_along_the_beam():
    from workstation.lidar.platforms import FlightSpec, Oscillation, flight_lines
    from workstation.lidar.scanners import ScanPattern
    from workstation.lidar.scene import plane_scene
    from workstation.lidar.simulate import ErrorModel, Sensor, simulate

    h, z0, off = 300.0, 100.0, 0.05
    spec = FlightSpec(altitude=h, speed=50.0, swath=2 * h * np.tan(np.radians(20)), n_lines=1, run_in=0.0,
                      heading_deg=90.0, oscillation=Oscillation.none())
    traj = flight_lines((-30, 30, -30, 30), z0, spec, np.random.default_rng(0))
    res = simulate(plane_scene(300, z0), traj, ScanPattern("zigzag", prf=20_000, scan_frequency=40, fov_deg=40),
                   Sensor(subrays=1), ErrorModel.none(range_offset_m=off), seed=1, with_truth=True)
    a = res.cloud.attrs
    d = res.cloud.xyz - np.column_stack([a["true_x"], a["true_y"], a["true_z"]])
    theta = np.radians(a["scan_angle"].astype(float))
    np.testing.assert_allclose(np.linalg.norm(d, axis=1), off, atol=1e-3)
    np.testing.assert_allclose(d[:, 2], -off * np.cos(theta), atol=1e-3)  # farther along a down-looking beam
