"""Simulator geometry with known answers: flat plane, smile, boresight, TLS room, returns, water."""

from __future__ import annotations

import numpy as np
import pytest

from workstation.core.classes import ASPRSClass
from workstation.core.errors import StageError
from workstation.lidar.platforms import FlightSpec, Oscillation, Station, flight_lines, station_trajectory
from workstation.lidar.scanners import ScanPattern
from workstation.lidar.scene import SceneRecipe, TerrainSpec, box_room_scene, build_scene, merge_scenes, plane_scene
from workstation.lidar.simulate import ErrorModel, Sensor, simulate, subray_pattern

H = 300.0  # flying height above the test plane (m)
PLANE_Z = 100.0


def _one_line(area=(-40, 40, -40, 40), altitude=H, heading=90.0, speed=50.0):
    spec = FlightSpec(altitude=altitude, speed=speed, swath=2 * altitude * np.tan(np.radians(20)), n_lines=1,
                      run_in=0.0, heading_deg=heading, oscillation=Oscillation.none())
    return flight_lines(area, PLANE_Z, spec, np.random.default_rng(0))


SCAN = ScanPattern("zigzag", prf=50_000, scan_frequency=40, fov_deg=40)


def test_flat_plane_points_lie_on_it_within_range_noise():
    sigma = 0.05
    res = simulate(plane_scene(400, PLANE_Z), _one_line(), SCAN, Sensor(subrays=1), ErrorModel.none(range_noise_m=sigma), seed=3)
    z = res.cloud.xyz[:, 2]
    assert res.cloud.n > 50_000
    assert abs(z.mean() - PLANE_Z) < 0.002
    # the noise is along the beam: vertical spread sigma * cos(scan angle)
    expected = sigma * np.sqrt(np.mean(np.cos(np.radians(res.cloud.attrs["scan_angle"])) ** 2))
    assert z.std() == pytest.approx(expected, rel=0.03)
    assert np.all(res.cloud.attrs["classification"] == ASPRSClass.GROUND)
    assert res.cloud.crs == "EPSG:32632"
    assert 499_700 < res.cloud.xyz[:, 0].min() and res.cloud.xyz[:, 1].max() < 5_000_300


def test_perfect_measurements_give_exact_points():
    res = simulate(plane_scene(400, PLANE_Z), _one_line(), SCAN, Sensor(subrays=1), ErrorModel.none(), seed=3, with_truth=True)
    a = res.cloud.attrs
    err = res.cloud.xyz - np.column_stack([a["true_x"], a["true_y"], a["true_z"]])
    assert np.abs(err).max() < 1e-3
    assert np.abs(res.cloud.xyz[:, 2] - PLANE_Z).max() < 1e-3


def test_scan_angle_scale_error_bends_plane_into_a_smile():
    k = -0.003
    res = simulate(plane_scene(400, PLANE_Z), _one_line(), SCAN, Sensor(subrays=1),
                   ErrorModel.none(scan_angle_scale=k), seed=3)
    theta = np.radians(res.cloud.attrs["scan_angle"].astype(float))  # encoder angle (no roll here)
    dz = res.cloud.xyz[:, 2] - PLANE_Z
    # processed z = z_platform - r cos(theta_enc), with r = H / cos(theta_true)
    expected = H * (1 - np.cos(theta) / np.cos(theta * (1 + k)))
    np.testing.assert_allclose(dz, expected, atol=2e-3)
    # a smile: edges up, nadir on the plane; curvature d2z/dtheta2 = -2 H k near nadir
    c2 = np.polyfit(theta, dz, 2)[0]
    assert c2 == pytest.approx(-H * k, rel=0.1)
    assert dz[np.abs(theta) > np.radians(18)].mean() > 0.05 > abs(dz[np.abs(theta) < np.radians(1)].mean())


def test_boresight_pitch_error_shifts_points_by_h_tan_delta():
    delta = 0.1  # degrees of pitch
    res = simulate(plane_scene(400, PLANE_Z), _one_line(heading=90.0), SCAN, Sensor(subrays=1),
                   ErrorModel.none(boresight_error_deg=(0.0, delta, 0.0)), seed=3, with_truth=True)
    a = res.cloud.attrs
    d = res.cloud.xyz - np.column_stack([a["true_x"], a["true_y"], a["true_z"]])
    # flying east: along track is +x; the beam really looks forward by delta, the processing
    # puts the point under the nominal beam, H tan(delta) behind the true hit, H(sec-1) low
    np.testing.assert_allclose(d[:, 0], -H * np.tan(np.radians(delta)), atol=2e-3)
    np.testing.assert_allclose(d[:, 1], 0.0, atol=2e-3)
    np.testing.assert_allclose(d[:, 2], -H * (1 / np.cos(np.radians(delta)) - 1), atol=2e-3)


def test_lever_arm_error_and_gnss_bias_shift_points_rigidly():
    res = simulate(plane_scene(400, PLANE_Z), _one_line(heading=0.0), SCAN, Sensor(subrays=1),
                   ErrorModel.none(gnss_bias_m=(0.3, -0.2, 0.1), lever_arm_error_m=(0.5, 0.0, 0.0)), seed=3, with_truth=True)
    a = res.cloud.attrs
    d = res.cloud.xyz - np.column_stack([a["true_x"], a["true_y"], a["true_z"]])
    # flying north, a 0.5 m forward lever-arm error puts the true beam 0.5 m north: points 0.5 m south
    np.testing.assert_allclose(d.mean(axis=0), [0.3, -0.2 - 0.5, 0.1], atol=2e-3)
    assert d.std(axis=0).max() < 2e-3


def test_time_bias_shifts_points_along_track_by_speed_times_bias():
    dt, v = 0.01, 50.0
    res = simulate(plane_scene(400, PLANE_Z), _one_line(heading=0.0, speed=v), SCAN, Sensor(subrays=1),
                   ErrorModel.none(time_bias_s=dt), seed=3, with_truth=True)
    a = res.cloud.attrs
    d = res.cloud.xyz - np.column_stack([a["true_x"], a["true_y"], a["true_z"]])
    # georeferenced with the pose dt later: the platform is v * dt further north
    np.testing.assert_allclose(d[:, 1], v * dt, atol=2e-3)
    np.testing.assert_allclose(d[:, [0, 2]], 0.0, atol=2e-3)


def test_gnss_and_imu_noise_have_their_size():
    res = simulate(plane_scene(400, PLANE_Z), _one_line(heading=0.0), SCAN, Sensor(subrays=1),
                   ErrorModel.none(gnss_noise_m=(0.0, 0.0, 0.05), gnss_correlation_s=0.005), seed=3, with_truth=True)
    dz = res.cloud.xyz[:, 2] - res.cloud.attrs["true_z"]
    assert dz.std() == pytest.approx(0.05 * np.sqrt(2 / 3), rel=0.15)  # linear interpolation of white knots
    res = simulate(plane_scene(400, PLANE_Z), _one_line(heading=0.0), SCAN, Sensor(subrays=1),
                   ErrorModel.none(imu_noise_deg=(0.01, 0.0, 0.0)), seed=3, with_truth=True)
    dx = res.cloud.xyz[:, 0] - res.cloud.attrs["true_x"]
    # a roll error moves nadir points across track by about H * roll
    assert dx.std() == pytest.approx(H * np.radians(0.01) * np.sqrt(2 / 3), rel=0.3)


def test_range_walk_ranges_dark_targets_long():
    dark = plane_scene(100, PLANE_Z, material="asphalt", origin=(499950.0, 5000000.0))
    bright = plane_scene(100, PLANE_Z, material="plaster", origin=(500050.0, 5000000.0))
    scene = merge_scenes(dark, bright)
    sensor = Sensor(subrays=1)
    res = simulate(scene, _one_line(area=(-100, 100, -40, 40)), SCAN, sensor, ErrorModel.none(range_walk_m=0.1), seed=2)
    x = res.cloud.xyz[:, 0] - 500_000
    z = res.cloud.xyz[:, 2] - PLANE_Z
    near = np.abs(res.cloud.attrs["scan_angle"]) < 25
    assert z[(x < -5) & near].mean() < z[(x > 5) & near].mean() - 0.01  # dark ranged longer -> lower
    assert np.all(z < 1e-4) and z.min() > -0.1  # walk only lengthens ranges, at most 0.1 m


def test_tls_scan_of_box_room_recovers_its_dimensions():
    lx, ly, lz = 12.0, 8.0, 3.5
    room = box_room_scene(lx, ly, lz)
    scan = ScanPattern("spherical", prf=1_000_000, h_step_deg=1.0, v_step_deg=1.0, v_min_deg=-89, v_max_deg=89)
    st = [Station(1.5, -1.0, 1.4, 30.0)]
    traj = station_trajectory(st, lambda xy: np.zeros(len(np.atleast_2d(xy))), [scan.tls_duration()])
    res = simulate(room, traj, scan, Sensor(wavelength_nm=1550, peak_power_w=50, aperture_m=0.04, subrays=1,
                                            min_range_m=0.5, max_range_m=100), ErrorModel.none(range_noise_m=0.002),
                   seed=1, roll_in_scan_angle=False)
    xyz = res.cloud.xyz - room.origin
    assert res.cloud.n == scan.pulses_in(0)  # every beam hits a wall, floor or ceiling
    size = np.percentile(xyz, 99.9, axis=0) - np.percentile(xyz, 0.1, axis=0)
    np.testing.assert_allclose(size, [lx, ly, lz], atol=0.02)
    floor = xyz[res.cloud.attrs["classification"] == ASPRSClass.GROUND]
    assert abs(np.median(floor[:, 2])) < 0.005


def _tree_scene(seed=3):
    flat = TerrainSpec(resolution=2.0, slope_percent=0, relief=0, roughness=0, ridge_height=0,
                       breakline_slope_percent=0, ditch_depth=0, embankment_height=0)
    r = SceneRecipe(extent=(80.0, 80.0), terrain=flat, buildings=0, courtyards=0, heritage=False, trees=12,
                    forest_fraction=0, bushes=0, grass_patches=0, road=False, cars=0, stream=False, pond=False,
                    powerline=False)
    return build_scene(r, seed)


def test_multiple_returns_under_trees_and_none_on_bare_ground():
    scene = _tree_scene()
    res = simulate(scene, _one_line(), SCAN, Sensor(subrays=5), ErrorModel.none(), seed=1)
    a = res.cloud.attrs
    veg = a["classification"] == ASPRSClass.HIGH_VEGETATION
    # pulses that met a crown mostly split into several returns
    veg_pulses = np.isin(a["gps_time"], np.unique(a["gps_time"][veg]))
    first = a["return_number"] == 1
    assert np.mean(a["number_of_returns"][veg_pulses & first] > 1) > 0.5
    # on bare ground every pulse has one return: ground points whose slanted beam passed no
    # crown (farther from every leaf than the beam drifts over 25 m of height, plus 1 m)
    tree_xy = (scene.vertices[scene.faces[scene.classification == ASPRSClass.HIGH_VEGETATION]].mean(1)[:, :2])
    from scipy.spatial import cKDTree

    xy = res.cloud.xyz[:, :2] - scene.origin[:2]
    drift = 25.0 * np.tan(np.radians(np.abs(a["scan_angle"]))) + 1.0
    far = cKDTree(tree_xy).query(xy, k=1)[0] > drift
    bare = far & (a["classification"] == ASPRSClass.GROUND)
    assert bare.sum() > 10_000
    assert np.all(a["number_of_returns"][bare] == 1)
    # return numbers are consistent: 1..n, last returns on the ground under the crowns
    assert np.all(a["return_number"] <= a["number_of_returns"])
    last = a["return_number"] == a["number_of_returns"]
    assert np.mean(a["classification"][last & veg_pulses & (a["number_of_returns"] > 1)] == ASPRSClass.GROUND) > 0.5
    # a single thin ray per pulse never splits
    one = simulate(scene, _one_line(), SCAN, Sensor(subrays=1), ErrorModel.none(), seed=1)
    assert np.all(one.cloud.attrs["number_of_returns"] == 1)


def test_beam_divergence_changes_the_hits():
    scene = _tree_scene()

    def share(div):
        a = simulate(scene, _one_line(), SCAN, Sensor(subrays=5, divergence_mrad=div), ErrorModel.none(), seed=1).cloud.attrs
        veg = np.isin(a["gps_time"], np.unique(a["gps_time"][a["classification"] == ASPRSClass.HIGH_VEGETATION]))
        return np.mean(a["number_of_returns"][veg & (a["return_number"] == 1)] > 1)

    # a 6 mm footprint (0.02 mrad at 300 m) is smaller than a leaf gap cell: few splits;
    # a 30 cm footprint straddles many cells and leaf triangles
    narrow, wide = share(0.02), share(1.0)
    assert wide > 0.5 and narrow < 0.5 * wide


def test_water_returns_are_sparse():
    ground = plane_scene(100, PLANE_Z, origin=(499950.0, 5000000.0))
    water = plane_scene(100, PLANE_Z, material="water", origin=(500050.0, 5000000.0), cls=ASPRSClass.WATER)
    scene = merge_scenes(ground, water)
    res = simulate(scene, _one_line(area=(-100, 100, -40, 40)), SCAN, Sensor(subrays=1), ErrorModel.none(), seed=2)
    cls = res.cloud.attrs["classification"]
    n_ground, n_water = np.sum(cls == ASPRSClass.GROUND), np.sum(cls == ASPRSClass.WATER)
    assert n_ground > 10_000
    assert 0 < n_water < 0.25 * n_ground
    # the few water returns come from near-specular (near-nadir) beams
    assert np.abs(res.cloud.attrs["scan_angle"][cls == ASPRSClass.WATER]).max() < 12.0


def test_intensity_follows_range_equation():
    sc = plane_scene(600, PLANE_Z)
    sensor = Sensor(subrays=1, saturation_power_w=1e-3)
    lo = simulate(sc, _one_line(altitude=200), SCAN, sensor, ErrorModel.none(), seed=0)
    hi = simulate(sc, _one_line(altitude=400), SCAN, sensor, ErrorModel.none(), seed=0)
    near = lambda r: r.cloud.attrs["intensity"][np.abs(r.cloud.attrs["scan_angle"]) < 1].mean()  # noqa: E731
    ratio = near(lo) / near(hi)
    atm = np.exp(-2 * sensor.extinction_per_m * (200 - 400))
    assert ratio == pytest.approx(4.0 * atm, rel=0.02)


def test_targets_beyond_maximum_range_give_no_returns():
    sensor = Sensor(subrays=1, peak_power_w=1.0)
    assert sensor.max_range(0.35) < H
    with pytest.raises(StageError):
        simulate(plane_scene(400, PLANE_Z), _one_line(), SCAN, sensor, ErrorModel.none(), seed=0)


def test_subray_pattern_weights():
    offs, w = subray_pattern(7)
    assert offs.shape == (7, 2) and w.sum() == pytest.approx(1.0)
    assert np.all(np.hypot(*offs.T) <= 1.0) and w[0] == w.max()


def test_same_seed_same_cloud_different_seed_different_scene():
    r = SceneRecipe(extent=(60.0, 60.0), buildings=2, courtyards=0, heritage=False, trees=4, bushes=2,
                    grass_patches=2, cars=2, powerline=False, pond=False)
    s1, s1b, s2 = build_scene(r, 1), build_scene(r, 1), build_scene(r, 2)
    assert np.array_equal(s1.vertices, s1b.vertices) and np.array_equal(s1.faces, s1b.faces)
    assert s1.vertices.shape != s2.vertices.shape or not np.array_equal(s1.vertices, s2.vertices)
    traj = _one_line(area=(-30, 30, -30, 30))
    a = simulate(s1, traj, SCAN, Sensor(subrays=3), ErrorModel(), seed=5).cloud
    b = simulate(s1b, traj, SCAN, Sensor(subrays=3), ErrorModel(), seed=5).cloud
    c = simulate(s1, traj, SCAN, Sensor(subrays=3), ErrorModel(), seed=6).cloud
    assert np.array_equal(a.xyz, b.xyz)
    assert all(np.array_equal(a.attrs[k], b.attrs[k]) for k in a.attrs)
    assert a.n != c.n or not np.array_equal(a.xyz, c.xyz)


def test_mls_drive_sees_road_and_both_sides():
    from dataclasses import replace

    from workstation.lidar.survey import default_survey, run_survey

    scene = build_scene("demo_small", 0)
    road = scene.meta["road"]
    p, d = np.array(road["p"]), np.array(road["d"])
    cfg = default_survey("mls")
    cfg = replace(cfg, waypoints=(tuple(p - 15 * d), tuple(p + 15 * d)), scanner=replace(cfg.scanner, prf=40_000.0))
    res = run_survey(scene, cfg, seed=0)
    a = res.cloud.attrs
    assert ASPRSClass.ROAD_SURFACE in set(np.unique(a["classification"]).tolist())
    assert np.all(a["point_source_id"] == 1) and np.abs(a["scan_angle"]).max() <= 180
    # points on both sides of the road axis
    xy = res.cloud.xyz[:, :2] - scene.origin[:2] - p
    side = xy[:, 0] * -d[1] + xy[:, 1] * d[0]
    assert (side > 5).sum() > 100 and (side < -5).sum() > 100
    # the vehicle's own height above the road is the IMU height plus the lever arm (scanner 0.6 m higher)
    assert res.true_trajectory.position[:, 2].min() > float(scene.vertices[:, 2].min())


def _three_lines(area=(-60, 60, -60, 60), altitude=150.0):
    spec = FlightSpec(altitude=altitude, speed=50.0, swath=2 * altitude * np.tan(np.radians(20)), n_lines=3,
                      overlap=0.5, run_in=0.0, heading_deg=0.0, oscillation=Oscillation.none())
    return flight_lines(area, PLANE_Z, spec, np.random.default_rng(0))


def test_line_bias_shifts_only_that_line_by_its_offset():
    traj = _three_lines()
    scan = ScanPattern("zigzag", prf=20_000, scan_frequency=40, fov_deg=40)
    bias = (2, 0.02, -0.03, 0.10)
    base = simulate(plane_scene(400, PLANE_Z), traj, scan, Sensor(subrays=1), ErrorModel.none(), seed=5)
    moved = simulate(plane_scene(400, PLANE_Z), traj, scan, Sensor(subrays=1), ErrorModel.none(line_bias_m=(bias,)),
                     seed=5)
    sid = moved.cloud.attrs["point_source_id"]
    assert [s.source_id for s in traj.segments] == [1, 2, 3] and set(np.unique(sid)) == {1, 2, 3}
    np.testing.assert_array_equal(sid, base.cloud.attrs["point_source_id"])
    d = moved.cloud.xyz - base.cloud.xyz
    two = sid == 2
    # a flat plane, perfect measurements: line 2 is 0.10 m higher (and 2 cm east, 3 cm south), the others unchanged
    np.testing.assert_allclose(d[two], np.broadcast_to([0.02, -0.03, 0.10], d[two].shape), atol=1e-6)
    np.testing.assert_allclose(d[~two], 0.0, atol=1e-6)
    np.testing.assert_allclose(moved.cloud.xyz[two, 2], PLANE_Z + 0.10, atol=1e-3)
    # the navigation solution written out carries the bias during line 2 only
    seg = traj.segments[1]
    t = moved.trajectory.time
    inside, outside = (t > seg.t0) & (t < seg.t1), (t < traj.segments[0].t1)
    np.testing.assert_allclose(moved.trajectory.position[inside] - traj.position[inside],
                               np.broadcast_to([0.02, -0.03, 0.10], (int(inside.sum()), 3)), atol=1e-9)
    np.testing.assert_allclose(moved.trajectory.position[outside], traj.position[outside], atol=1e-9)


def test_line_bias_is_checked():
    from workstation.core.errors import InvalidInputError

    import tomllib

    from workstation.lidar.survey import apply_overrides, default_survey

    toml = tomllib.loads("[errors]\nline_bias_m = [[2, 0.0, 0.0, 0.1], [3, 0.05, 0, 0]]\n")  # a survey config
    assert apply_overrides(default_survey("als"), toml).errors.line_bias_m == ((2, 0.0, 0.0, 0.1), (3, 0.05, 0.0, 0.0))
    for bad in ([(0, 0, 0, 0.1)], [(2, 0, 0)], [(2.5, 0, 0, 0)], [(2, 0, 0, float("nan"))], [(2, 0, 0, 1), (2, 0, 0, 2)]):
        with pytest.raises(InvalidInputError):
            ErrorModel(line_bias_m=bad)
    with pytest.raises(InvalidInputError, match="line 7"):
        simulate(plane_scene(400, PLANE_Z), _one_line(), SCAN, Sensor(subrays=1),
                 ErrorModel.none(line_bias_m=((7, 0, 0, 0.1),)), seed=3)


def test_line_bias_cli_option(tmp_path, capsys):
    import json

    from workstation.cli.main import main
    from workstation.io import read_cloud

    base = ["simulate", "als", "--scene", "demo_small", "--no-errors", "--altitude", "150", "--lines", "2",
            "--prf", "10000", "--scan-frequency", "20", "--subrays", "1", "--json"]
    assert main([*base, "-o", str(tmp_path / "a.laz")]) == 0
    assert main([*base, "-o", str(tmp_path / "b.laz"), "--line-bias", "2:0,0,0.25"]) == 0
    capsys.readouterr()
    a, b = read_cloud(tmp_path / "a.laz"), read_cloud(tmp_path / "b.laz")
    two = b.attrs["point_source_id"] == 2
    assert two.any() and (~two).any()
    dz = b.xyz[:, 2] - a.xyz[:, 2]
    np.testing.assert_allclose(dz[two], 0.25, atol=2e-3)  # LAS z scale 1 mm
    np.testing.assert_allclose(dz[~two], 0.0, atol=2e-3)
    for bad in ("2", "2:0,0", "x:0,0,1", "2:0,0,nan", "0:0,0,1"):
        assert main([*base, "-o", str(tmp_path / "c.laz"), "--line-bias", bad]) == 2
    assert "--line-bias" in capsys.readouterr().err
    assert main([*base, "-o", str(tmp_path / "c.laz"), "--line-bias", "9:0,0,1"]) == 1  # no line 9 flown
