"""Flight planning formulas, the inverse problem, and plan vs simulated density; scan patterns."""

from __future__ import annotations

import math

import numpy as np
import pytest

from workstation.core.errors import InvalidInputError
from workstation.lidar.planning import FlightParams, plan_flight, solve_for_density
from workstation.lidar.platforms import FlightSpec, Oscillation, flight_lines, turn_length
from workstation.lidar.scanners import ScanPattern
from workstation.lidar.scene import plane_scene
from workstation.lidar.simulate import ErrorModel, Sensor, simulate


def test_plan_formulas():
    p = FlightParams(altitude=1000, speed=60, prf=300_000, scan_frequency=50, fov_deg=40, overlap=0.3,
                     area_width=2000, area_length=3000, run_in=500)
    plan = plan_flight(p, divergence_mrad=0.25)
    B = 2000 * math.tan(math.radians(20))
    assert plan.swath_width == pytest.approx(B)
    assert plan.spacing_along == pytest.approx(60 / 100)  # zigzag: two lines per mirror cycle
    assert plan.spacing_across == pytest.approx(B * 100 / 300_000)
    assert plan.density == pytest.approx(1 / (plan.spacing_along * plan.spacing_across))
    assert plan.nps == pytest.approx(1 / math.sqrt(plan.density))
    assert plan.flight_lines == math.ceil((2000 - B) / (0.7 * B)) + 1 == 4
    R = 60 ** 2 / (9.80665 * math.tan(math.radians(20)))
    assert plan.turn_radius == pytest.approx(R)
    assert plan.total_time_s == pytest.approx(4 * 4000 / 60 + 3 * turn_length(0.7 * B, R) / 60)
    assert plan.footprint_diameter == pytest.approx(0.25)
    assert plan.pulses_in_air == 3  # 300 kHz at ~1064 m slant range


def test_turns_semicircle_and_bulb():
    # wide spacing: two quarter circles and a straight leg
    assert turn_length(500.0, 100.0) == pytest.approx(math.pi * 100 + 300)
    # spacing = 2R: a semicircle; narrower: a longer three-arc procedure turn
    assert turn_length(200.0, 100.0) == pytest.approx(math.pi * 100)
    assert turn_length(50.0, 100.0) > math.pi * 100


@pytest.mark.parametrize("solve", ["prf", "speed", "altitude"])
def test_inverse_reaches_target_density(solve):
    q = solve_for_density(12.5, FlightParams(), solve)
    assert plan_flight(q).density == pytest.approx(12.5)


def test_bad_params_raise():
    with pytest.raises(InvalidInputError):
        FlightParams(fov_deg=200)
    with pytest.raises(InvalidInputError):
        solve_for_density(-1, FlightParams())


@pytest.mark.parametrize("pattern", ["zigzag", "polygon", "palmer"])
def test_simulated_density_matches_plan_within_5_percent(pattern):
    H, v, prf, f, fov = 250.0, 40.0, 60_000.0, 30.0, 40.0
    plan = plan_flight(FlightParams(altitude=H, speed=v, prf=prf, scan_frequency=f, fov_deg=fov, pattern=pattern,
                                    area_width=100, area_length=200))
    spec = FlightSpec(altitude=H, speed=v, swath=plan.swath_width, n_lines=1, run_in=40.0, heading_deg=0.0,
                      oscillation=Oscillation.none())
    traj = flight_lines((-20, 20, -100, 100), 100.0, spec, np.random.default_rng(0))
    res = simulate(plane_scene(600, 100.0), traj, ScanPattern(pattern, prf=prf, scan_frequency=f, fov_deg=fov),
                   Sensor(subrays=1), ErrorModel.none(), seed=0)
    y = res.cloud.xyz[:, 1] - 5_000_000
    L = 150.0
    n = np.sum(np.abs(y) < L / 2)
    density = n / (L * plan.swath_width)
    assert density == pytest.approx(plan.density, rel=0.05)
    x = res.cloud.xyz[:, 0] - 500_000
    assert x.max() - x.min() == pytest.approx(plan.swath_width, rel=0.01)


def test_scan_patterns_flags_and_lines():
    prf, f = 10_000.0, 10.0
    k = np.arange(int(prf))  # one second
    z = ScanPattern("zigzag", prf=prf, scan_frequency=f, fov_deg=40).angles(k)
    assert np.degrees(z.primary).min() == pytest.approx(-20, abs=0.1) and np.degrees(z.primary).max() == pytest.approx(20, abs=0.1)
    assert z.edge.sum() == 20 and set(np.unique(z.direction)) == {0, 1}  # 2 lines per cycle, both directions
    inc = np.diff(z.primary) > 0
    assert np.all(z.direction[:-1][inc] == 1)
    p = ScanPattern("polygon", prf=prf, scan_frequency=f, fov_deg=40).angles(k)
    assert p.edge.sum() == 10 and np.all(p.direction == 1)
    pal = ScanPattern("palmer", prf=prf, scan_frequency=f, fov_deg=40, palmer_along_deg=5).angles(k)
    ell = (pal.primary / np.radians(20)) ** 2 + (pal.secondary / np.radians(5)) ** 2
    np.testing.assert_allclose(ell, 1.0, atol=1e-9)
    s = ScanPattern("spherical", prf=1e6, h_step_deg=10, v_step_deg=10, v_min_deg=-30, v_max_deg=90)
    a = s.angles(np.arange(s.pulses_in(0)))
    assert s.tls_shape == (36, 13) and len(np.unique(a.secondary)) == 36
    d = s.directions(a.primary, a.secondary)
    np.testing.assert_allclose(np.linalg.norm(d, axis=1), 1.0)
    assert d[:, 2].min() == pytest.approx(-1.0)  # straight up (z down frame)
