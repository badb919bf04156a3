"""Swath overlap (interswath DZ) and intraswath precision: known shifts on synthetic strips,
rough areas left out, feet, the DZ images, and a simulated flight with one line biased."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from workstation.core.cloud import Cloud
from workstation.core.errors import InvalidInputError
from workstation.core.units import METRES, US_SURVEY_FOOT, Units
from workstation.qc.context import QCGrid
from workstation.qc.swath import SUMS, SwathParams, SwathPass, _SparseSums

X0, Y0 = 500_000.0, 4_000_000.0
SLOPE_X, SLOPE_Y = np.tan(np.radians(4.0)), np.tan(np.radians(2.0))  # a tilted plane, under 10°
NOISE = 0.02
CELL = 0.7  # ~2 x ANPS of 8 points/m² per strip


def _plane(x, y):
    return 250.0 + SLOPE_X * (x - X0) + SLOPE_Y * (y - Y0)


def _strip(rng, sid, x0, x1, dz, density=8.0, y1=60.0, noise=NOISE):
    """A swath of single returns over [x0, x1] x [0, y1] m, ``dz`` above the tilted plane."""
    n = int(density * (x1 - x0) * y1)
    x, y = X0 + rng.uniform(x0, x1, n), Y0 + rng.uniform(0, y1, n)
    return np.column_stack([x, y, _plane(x, y) + dz + rng.normal(0, noise, n)]), np.full(n, sid, np.uint16)


def _cloud(parts, returns=None, **extra):
    xyz = np.vstack([p[0] for p in parts])
    sid = np.concatenate([p[1] for p in parts])
    n = len(sid)
    nr = np.ones(n, np.uint8) if returns is None else returns
    return Cloud(xyz, {"point_source_id": sid, "number_of_returns": nr, "return_number": np.ones(n, np.uint8), **extra})


def _grid(cloud, cell=CELL, units=METRES):
    lo, hi = cloud.bounds
    return QCGrid.over((lo[0], lo[1], hi[0], hi[1]), cell, units)


def _three_strips(rng):
    # 1 and 2 overlap on x 30-50 m, 2 and 3 on x 70-90 m, 1 and 3 nowhere; strip 2 is 7 cm high
    return _cloud([_strip(rng, 1, 0, 50, 0.0), _strip(rng, 2, 30, 90, 0.07), _strip(rng, 3, 70, 120, 0.0)])


def test_shifted_strip_over_tilted_plane_gives_its_offset():
    c = _three_strips(np.random.default_rng(1))
    p = SwathPass(_grid(c))
    p.add(c, "a.laz")
    r = p.result()
    assert [(s["a"], s["b"]) for s in r["swaths"]] == [(1, 2), (2, 3)]
    s12, s23 = r["swaths"]
    # mean_dz is swath b minus swath a: strip 2 above strip 1, strip 3 below strip 2
    assert s12["mean_dz"] == pytest.approx(0.07, abs=0.005) and s23["mean_dz"] == pytest.approx(-0.07, abs=0.005)
    for s in (s12, s23):
        assert s["rmsdz"] == pytest.approx(0.07, abs=0.005)
        assert 0.07 < s["max_abs_dz"] < 0.07 + 5 * NOISE
        # DZ in nearly every cell of the 20 m x 60 m overlap (the windows at its edges may fall short)
        assert 0.8 * 20 * 60 / CELL**2 < s["cells"] <= 21 * 61 / CELL**2 and s["enough_cells"]
    assert r["rmsdz_all"] == pytest.approx(0.07, abs=0.005)
    assert r["cell_m"] == pytest.approx(CELL) and r["swath_ids"] == [1, 2, 3]
    # the residual RMS of the planes is the noise (n - 3 degrees of freedom, perpendicular: x cos 4.5°)
    for s in r["intraswath"]:
        assert s["precision_m"] == pytest.approx(NOISE * 0.997, rel=0.025) and s["p95_m"] < 1.5 * NOISE
        assert s["cells"] > 0.9 * s["fitted_cells"]
    assert [f.field for f in p.findings()] == []  # 7 cm is within the QL2 limits


def test_streaming_in_chunks_gives_the_same_result():
    c = _three_strips(np.random.default_rng(2))
    one = SwathPass(_grid(c))
    one.add(c, "a.laz")
    many = SwathPass(_grid(c))
    many._sums.min_merge = 1000  # merge often
    order = np.random.default_rng(0).permutation(c.n)
    for part in np.array_split(order, 17):
        many.add(c[np.sort(part)], "a.laz")
    a, b = one.result(), many.result()
    assert [s["cells"] for s in a["swaths"]] == [s["cells"] for s in b["swaths"]]
    for s, t in zip(a["swaths"], b["swaths"]):
        assert s["rmsdz"] == pytest.approx(t["rmsdz"], abs=1e-9)


def test_sparse_sums_merge_adds_equal_keys():
    rng = np.random.default_rng(3)
    acc = _SparseSums(2, min_merge=10)
    keys = rng.integers(0, 50, 400)
    vals = rng.normal(size=(2, 400))
    for i in range(0, 400, 37):
        acc.add(keys[i:i + 37], vals[:, i:i + 37])
    acc.merge()
    u = np.unique(keys)
    np.testing.assert_array_equal(acc.keys, u)
    np.testing.assert_allclose(acc.sums[0], [vals[0, keys == k].sum() for k in u])


def test_rough_and_steep_areas_and_multiple_returns_are_left_out(tmp_path):
    from workstation.io.geotiff import read_raster

    rng = np.random.default_rng(4)
    xyz, sid = _strip(rng, 2, 30, 90, 0.07)
    # a wood on x 35-45 m, y 10-30 m in strip 2: canopy single returns 0-15 m up and two-return pulses
    wood = (xyz[:, 0] - X0 > 35) & (xyz[:, 0] - X0 < 45) & (xyz[:, 1] - Y0 > 10) & (xyz[:, 1] - Y0 < 30)
    xyz[wood, 2] += rng.uniform(0, 15, wood.sum())
    returns = np.where(wood & (rng.random(len(sid)) < 0.5), 2, 1).astype(np.uint8)
    # a flat-topped hedge on x 35-45 m, y 33-42 m: strip 2 sees only its top, 0.3 m up, in two-return pulses
    hedge = (xyz[:, 0] - X0 > 35) & (xyz[:, 0] - X0 < 45) & (xyz[:, 1] - Y0 > 33) & (xyz[:, 1] - Y0 < 42)
    xyz[hedge, 2] += 0.3
    returns[hedge] = 2
    one = _strip(rng, 1, 0, 50, 0.0)
    # a steep (30°) ramp on y 45-60 m in both strips: planar but not flat terrain
    parts = []
    for p_xyz, p_sid in (one, (xyz, sid)):
        ramp = p_xyz[:, 1] - Y0 > 45
        p_xyz = p_xyz.copy()
        p_xyz[ramp, 2] += np.tan(np.radians(30)) * (p_xyz[ramp, 1] - Y0 - 45) + 0.5 * (p_sid[ramp] == 2)
        parts.append((p_xyz, p_sid))
    c = _cloud(parts, returns=np.concatenate([np.ones(len(one[1]), np.uint8), returns]))
    p = SwathPass(_grid(c))
    p.add(c, "a.laz")
    (s,) = p.result()["swaths"]
    # without the exclusions the wood (metres), the hedge (+0.3 m) and the ramp (+0.5 m on strip 2) would dominate
    assert s["rmsdz"] == pytest.approx(0.07, abs=0.005) and s["max_abs_dz"] < 0.16
    dz = read_raster(p.write(tmp_path, "EPSG:32611")["dz_values"]).array
    rows = (np.arange(dz.shape[0]) + 0.5) * CELL  # metres south of the grid top
    top = _grid(c).y1 - Y0
    ys = top - rows
    xs = _grid(c).x0 - X0 + (np.arange(dz.shape[1]) + 0.5) * CELL
    in_wood = (xs[None, :] > 36.5) & (xs[None, :] < 43.5) & (ys[:, None] > 11.5) & (ys[:, None] < 28.5)
    on_ramp = (xs[None, :] > 31.5) & (xs[None, :] < 48.5) & (ys[:, None] > 46.5)
    on_hedge = (xs[None, :] > 36.5) & (xs[None, :] < 43.5) & (ys[:, None] > 34.5) & (ys[:, None] < 40.5)
    open_overlap = (xs[None, :] > 31.5) & (xs[None, :] < 48.5) & (ys[:, None] > 1.5) & (ys[:, None] < 43.5) & ~(
        (xs[None, :] > 33) & (xs[None, :] < 47) & (ys[:, None] > 8) & (ys[:, None] < 44))
    assert np.isnan(dz[in_wood]).all() and np.isnan(dz[on_ramp]).all() and np.isnan(dz[on_hedge]).all()
    assert np.isfinite(dz[open_overlap]).mean() > 0.95


def test_feet_coordinates_give_metres():
    rng = np.random.default_rng(5)
    c = _three_strips(rng)
    k = 1 / US_SURVEY_FOOT
    feet = Cloud(c.xyz * k, dict(c.attrs))
    units = Units(US_SURVEY_FOOT, US_SURVEY_FOOT, "US survey foot", "US survey foot")
    p = SwathPass(_grid(feet, CELL * k, units))
    p.add(feet, "ft.laz")
    r = p.result()
    assert r["cell_m"] == pytest.approx(CELL)
    s12, s23 = r["swaths"]
    assert s12["rmsdz"] == pytest.approx(0.07, abs=0.005) and s12["mean_dz"] > 0 > s23["mean_dz"]
    assert r["intraswath"][0]["precision_m"] == pytest.approx(NOISE * 0.997, rel=0.025)
    # and a cell in feet with heights in metres (a CRS whose vertical unit differs)
    mixed = Cloud(np.column_stack([c.xyz[:, :2] * k, c.xyz[:, 2]]), dict(c.attrs))
    p = SwathPass(_grid(mixed, CELL * k, Units(US_SURVEY_FOOT, 1.0, "US survey foot", "metre")))
    p.add(mixed, "mixed.laz")
    assert p.result()["swaths"][0]["rmsdz"] == pytest.approx(0.07, abs=0.005)


def test_dz_image_colours_and_values(tmp_path):
    from workstation.io.geotiff import read_raster

    c = _three_strips(np.random.default_rng(6))
    for limits, colour in (((0.08, 0.16), (0, 176, 80)), ((0.04, 0.16), (255, 220, 0)), ((0.03, 0.05), (220, 0, 0))):
        p = SwathPass(_grid(c), SwathParams(rmsdz_limit_m=limits[0], max_dz_limit_m=limits[1]))
        p.add(c, "a.laz")
        out = p.write(tmp_path / str(limits[0]), "EPSG:32611")
        rgb = read_raster(out["dz"]).array
        val = read_raster(out["dz_values"]).array
        assert rgb.shape == (3, *val.shape) and rgb.dtype == np.uint8
        have = np.isfinite(val)
        assert np.nanmedian(val) == pytest.approx(0.07, abs=0.01)
        typical = have & (np.abs(val - 0.07) < 0.01)
        assert (rgb[:, typical].T == colour).all()
        assert (rgb[:, ~have] == 0).all()
        # overlap only: x 30-50 and 70-90 m have DZ, strip 1 alone (x < 30 m) none
        assert have.sum() == sum(s["cells"] for s in p.result()["swaths"])


def test_findings_name_the_pair_and_the_missing_ids():
    rng = np.random.default_rng(7)
    c = _cloud([_strip(rng, 1, 0, 50, 0.0), _strip(rng, 2, 30, 90, 0.15), _strip(rng, 3, 89, 120, 0.0)])
    p = SwathPass(_grid(c))
    p.add(c, "a.laz")
    f = {x.field: x for x in p.findings()}
    assert f["swaths 1-2 RMSDz"].severity == "error" and "+0.15" in f["swaths 1-2 RMSDz"].message
    assert f["swaths 2-3 DZ"].severity == "info"  # a 1 m wide overlap: too few cells, flagged
    assert not p.result()["swaths"][1]["enough_cells"]
    bare = Cloud(c.xyz, {"number_of_returns": np.ones(c.n, np.uint8)})
    p = SwathPass(_grid(bare))
    p.add(bare, "noids.laz")
    f = p.findings()
    assert [(x.file, x.field) for x in f] == [("noids.laz", "point_source_id"), (None, "swath_overlap")]
    assert p.result()["swaths"] == [] and p.result()["rmsdz_all"] is None


def test_a_noisy_swath_is_told_from_rough_ground():
    rng = np.random.default_rng(8)
    c = _cloud([_strip(rng, 1, 0, 50, 0.0), _strip(rng, 2, 30, 90, 0.0, noise=0.10), _strip(rng, 3, 70, 120, 0.0)])
    p = SwathPass(_grid(c))
    p.add(c, "a.laz")
    share = {s["id"]: s["rough_where_others_smooth"] for s in p.result()["intraswath"]}
    # 10 cm noise on strip 2: rough nearly everywhere strips 1 and 3 are smooth; they never are rough there
    assert share[2] > 0.9 and share[1] < 0.05 and share[3] < 0.05
    assert [f.field for f in p.findings() if f.severity == "warning"] == ["swath 2 precision"]


def test_params_are_checked():
    for bad in (dict(window=2), dict(window=0), dict(min_points=3), dict(max_slope_deg=90), dict(roughness_m=0),
                dict(rmsdz_limit_m=float("nan"))):
        with pytest.raises(InvalidInputError):
            SwathParams(**bad)
    assert SwathParams().roughness == SwathParams().precision_limit_m == 0.06
    assert len(SUMS) == 10


# --- the goal: a simulated flight with one line shifted by a known amount --------------------

@pytest.fixture(scope="module")
def flight():
    """demo_small (150 m) flown by the default ALS survey at 60 kHz: two lines, 1 and 2."""
    from workstation.lidar.scene import build_scene
    from workstation.lidar.survey import default_survey, survey_trajectory

    scene = build_scene("demo_small", 0)
    cfg = default_survey("als")
    cfg = replace(cfg, scanner=replace(cfg.scanner, prf=60_000))
    return scene, cfg, survey_trajectory(scene, cfg, 0)


def _swath_qc(cloud):
    first = cloud.attrs["return_number"] == 1
    lo, hi = cloud.bounds
    anps = np.sqrt((hi[0] - lo[0]) * (hi[1] - lo[1]) / first.sum())
    p = SwathPass(QCGrid.over((lo[0], lo[1], hi[0], hi[1]), 2 * anps, METRES))
    p.add(cloud, "sim.laz")
    return p.result()


def _fly(flight, errors, seed=0, with_truth=False):
    from workstation.lidar.georef import GeorefChain
    from workstation.lidar.simulate import simulate

    scene, cfg, traj = flight
    mount = GeorefChain(cfg.lever_arm, tuple(np.radians(cfg.boresight_deg)))
    return simulate(scene, traj, cfg.scanner, cfg.sensor, errors, mount=mount, seed=seed, with_truth=with_truth).cloud


def test_simulated_line_bias_is_measured_within_a_centimetre(flight):
    from workstation.lidar.simulate import ErrorModel

    # every default error on but the GNSS noise, which gives each line its own random offset
    # (4 cm 1-sigma up): that is a real strip error, measured in the next test
    errors = ErrorModel(gnss_noise_m=(0.0, 0.0, 0.0))
    biased = _swath_qc(_fly(flight, replace(errors, line_bias_m=((2, 0.0, 0.0, 0.10),))))
    plain = _swath_qc(_fly(flight, errors))
    (b,), (u,) = biased["swaths"], plain["swaths"]
    assert (b["a"], b["b"]) == (1, 2) and b["enough_cells"]
    assert b["rmsdz"] == pytest.approx(0.10, abs=0.01) and b["mean_dz"] == pytest.approx(0.10, abs=0.01)
    assert u["rmsdz"] <= 0.02
    assert all(s["precision_m"] < 0.04 for s in plain["intraswath"])


def test_simulated_default_errors_dz_is_the_true_line_to_line_error(flight):
    from workstation.lidar.simulate import ErrorModel

    c = _fly(flight, ErrorModel(), seed=2, with_truth=True)  # a seed whose GNSS noise splits the lines by ~4 cm
    (s,) = _swath_qc(c)["swaths"]
    a = c.attrs
    err = c.xyz[:, 2] - a["true_z"]
    ok = a["number_of_returns"] == 1
    truth = err[ok & (a["point_source_id"] == 2)].mean() - err[ok & (a["point_source_id"] == 1)].mean()
    assert abs(truth) > 0.02  # the lines really are apart
    assert s["mean_dz"] == pytest.approx(truth, abs=0.01)
    assert s["rmsdz"] == pytest.approx(abs(truth), abs=0.01)


@pytest.mark.realdata
def test_bcts_tile_three_lines(shared_data):
    from workstation.io.crs import crs_units
    from workstation.io.registry import iter_chunks
    from workstation.qc.density import density

    path = shared_data / "lidar" / "bcts_1.laz"
    chunks = list(iter_chunks(path, 200_000))
    units = crs_units(chunks[0].crs)
    nps = density(np.vstack([c.xyz[c.attrs["return_number"] == 1, :2] for c in chunks]), 1.0, units.h)["nps"]
    lo = np.min([c.bounds[0] for c in chunks], axis=0)
    hi = np.max([c.bounds[1] for c in chunks], axis=0)
    p = SwathPass(QCGrid.over((lo[0], lo[1], hi[0], hi[1]), 2 * nps, units))
    for c in chunks:
        p.add(c, path.name)
    r = p.result()
    assert r["swath_ids"] == [66, 67, 68]
    assert [(s["a"], s["b"]) for s in r["swaths"]] == [(66, 67), (66, 68), (67, 68)]
    for s in r["swaths"]:
        # a QL2-grade delivery: every pair within the USGS RMSDz limit, measured on hundreds of cells
        assert s["enough_cells"] and s["cells"] > 500 and 0.005 < s["rmsdz"] < 0.08
    for s in r["intraswath"]:
        assert 0.01 < s["precision_m"] < 0.06 and s["rough_where_others_smooth"] < 0.5
